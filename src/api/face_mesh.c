/* semquad public API: the mesh of a face (`semquad mesh`): the layout
 * road (field, layout, patches), or the split road (quad_split.h) when it
 * fails or is asked for. */
#include "api_private.h"
#include "periodic.h"
#include "quad_split.h"
#include "write_msh.h"
#include "write_nektar.h"
#include "write_quad_svg.h"
#include "write_quad_vtu.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* without --size: halvings of the default size tried when quads fold */
#define DEFAULT_SIZE_HALVINGS 3

/* cad.h: a segment of CAD_CUSP_MIN_SEGMENT of the face's size at least
 * blunts a cusp; the 2D box's diagonal bounds that size from above. */
void sq_api_cusp_hint(const cad_model *model, const sq_face_info *fi, sq_error *err)
{
    size_t len = strlen(err->msg);
    double tol = cad_model_heal_tolerance(model);
    double need = CAD_CUSP_MIN_SEGMENT * hypot(fi->bbox[2] - fi->bbox[0], fi->bbox[3] - fi->bbox[1]);
    if (tol <= 0)
        snprintf(err->msg + len, sizeof err->msg - len, "; --no-heal keeps it (healing blunts it)");
    else
        snprintf(err->msg + len, sizeof err->msg - len,
                 "; healing could not blunt it within the tolerance %.3g (--heal-tolerance %.2g "
                 "would, if the edges part by that within half their length)",
                 tol, fmax(1.05 * need, tol * 1.5));
}

/* Falls back on the split road (quad_split.h): what the layout road could
 * not do on a face the split road may mesh; not a usage, input or output
 * error, not a pattern the user imposed, not boundary layers (which need
 * the layout's chords). */
static int split_road_allowed(const sq_layout_options *lo, const sq_mesher_options *mo)
{
    return !lo->singularities && mo->nbl == 0;
}

static int takes_split_road(sq_status st, const sq_layout_options *lo, const sq_mesher_options *mo)
{
    return (st == SQ_ERR_LAYOUT || st == SQ_ERR_INTERNAL || st == SQ_ERR_GEOMETRY ||
            st == SQ_ERR_PATTERN) &&
           split_road_allowed(lo, mo);
}

static void layout_progress(const sq_options *o, const sq_layout_result *r,
                            const sq_mesh_timings *t)
{
    sq_api_log(o, SQ_LOG_INFO, "%s field %s P=%d on %d triangles (%.3f s)", r->field.kind,
               r->field.method == SEM_CG ? "CG" : "DG", r->field.order, r->field.triangles,
               t->triangulate + t->solve);
    sq_api_log(o, SQ_LOG_INFO, "%d singular points, %d separatrices, %d quad patches (%.3f s)",
               r->nsing, r->layout.stats.separatrices, r->layout.stats.quad_patches,
               t->critical_points + t->trace + t->layout);
}

sq_status sq_api_mesh_quality(sq_mesh *h, sq_error *err)
{
    size_t n = (size_t)(h->q->nquads ? h->q->nquads : 1);
    free(h->sjac);
    free(h->eta);
    h->sjac = malloc(n * sizeof *h->sjac);
    h->eta = malloc(n * sizeof *h->eta);
    if (!h->sjac || !h->eta) return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    return sq_quad_mesh_quality(h->q, h->eta, h->sjac, h->threads, &h->quality, err);
}

/* Mesh by `mesh(ctx, &m)` at mo's size; without a size the default,
 * sqrt(area)/8, can be too coarse for a small curved feature (an aerofoil
 * in a large box: its curved quads fold): halve it, a few times, rather
 * than fail. */
typedef sq_status (*mesh_fn)(void *ctx, const sq_mesher_options *mo, sq_quad_mesh **m, sq_error *err);

static sq_status mesh_halving(mesh_fn mesh, void *ctx, sq_mesher_options mo, double default_size,
                              const sq_options *o, sq_mesh *h, sq_error *err)
{
    sq_quad_mesh **m = &h->q;
    sq_quad_quality *q = &h->quality;
    sq_status st = SQ_OK;
    for (int k = 0;; k++) {
        if (k > 0) {
            mo.size = default_size / (double)(1 << k);
            sq_api_log(o, SQ_LOG_NOTE, "%d quads fold at size %.4g; trying %.4g", q->inverted,
                       2.0 * mo.size, mo.size);
            sq_quad_mesh_free(m);
        }
        st = mesh(ctx, &mo, m, err);
        h->far_size = mo.size > 0.0 ? mo.size : default_size;
        if (st == SQ_OK) st = sq_api_mesh_quality(h, err);
        if (o->size > 0.0 || st != SQ_OK || q->inverted == 0 || k == DEFAULT_SIZE_HALVINGS) break;
    }
    if (st == SQ_OK && q->inverted > 0)
        st = SQ_FAIL(err, SQ_ERR_LAYOUT,
                     "%d quads have a non-positive Jacobian (min scaled Jacobian %.3g); try a "
                     "smaller --size",
                     q->inverted, q->min_scaled_jacobian);
    if (st != SQ_OK) sq_quad_mesh_free(m);
    return st;
}

typedef struct {
    const cad_face *face;
    const sq_layout_result *r;
    const sq_periodic *per; /* NULL: none */
    double tol;             /* of the link, relative to the size */
} layout_ctx;

/* With periodic pairs the layout's mesh is kept only where its nodes on
 * each pair agree (periodic.h design 2): SQ_ERR_LAYOUT sends the face to
 * the next route. */
static sq_status mesh_by_layout(void *ctx, const sq_mesher_options *mo, sq_quad_mesh **m,
                                sq_error *err)
{
    const layout_ctx *c = ctx;
    SQ_TRY(sq_mesh_layout(c->face, c->r->info, &c->r->layout, mo, m, err));
    if (!c->per) return SQ_OK;
    sq_status st =
        sq_periodic_link(c->per, *m, sq_mesher_size(mo, c->r->layout.face_area), c->tol, err);
    if (st != SQ_OK) sq_quad_mesh_free(m);
    return st;
}

typedef struct {
    const cad_face *face;
    const sq_face_info *info;
    const sq_periodic *per; /* NULL: none */
} split_ctx;

/* With periodic pairs: the face as a domain of one face whose interfaces
 * are the pairs, its triangulations exchanging their vertices
 * (domain.h design 2), then the partners linked. */
static sq_status mesh_by_split(void *ctx, const sq_mesher_options *mo, sq_quad_mesh **m,
                               sq_error *err)
{
    const split_ctx *c = ctx;
    if (!c->per) return sq_mesh_split(c->face, c->info, mo, m, err);
    sq_domain d;
    int rounds = 0;
    sq_mesher_options o = *mo;
    o.size = sq_mesher_size(mo, c->info->area);
    SQ_TRY(sq_periodic_domain(&c->face, c->info, c->per, &d, err));
    sq_status st = sq_domain_mesh_split(&d, &o, m, &rounds, err);
    sq_domain_free(&d);
    if (st == SQ_OK) st = sq_periodic_link(c->per, *m, o.size, SQ_PERIODIC_NODE_REL_TOL, err);
    if (st != SQ_OK) sq_quad_mesh_free(m);
    return st;
}

/* The layout the repairs left invalid, made all-quad (sq_layout_all_quad)
 * unless a pattern was imposed (its points are the user's: the last
 * resort would add others).  On success road.reason says what was
 * invalid; on failure err says both. */
static sq_status all_quad_layout(sq_mesh *h, const sq_layout_options *lo, const sq_options *o,
                                 sq_error *err)
{
    sq_layout_result *r = &h->r;
    if (lo->singularities || !r->info || r->layout.npatches == 0) return SQ_ERR_LAYOUT;
    char invalid[sizeof err->msg];
    snprintf(invalid, sizeof invalid, "%s", err->msg);
    sq_error e2 = {0};
    sq_status st = sq_layout_all_quad(h->face.cad, r->info, &r->layout, &e2);
    if (st == SQ_ERR_LAYOUT)
        return SQ_FAIL(err, st, "%s; the all-quad last resort: %s", invalid, e2.msg);
    if (st != SQ_OK) {
        *err = e2;
        return st;
    }
    h->all_quad = 1;
    snprintf(h->road.reason, sizeof h->road.reason,
             "the all-quad last resort (%d patch splits: cuts, chords, quads around a centre); "
             "the layout was invalid: %.300s",
             r->layout.stats.all_quad_splits, invalid);
    sq_api_log(o, SQ_LOG_NOTE, "the layout is invalid (%s); all-quad last resort: %d patch "
               "splits into quads", invalid, r->layout.stats.all_quad_splits);
    return SQ_OK;
}

/* The layout road: field, layout (sq_layout_run), quads (sq_mesh_layout). */
static sq_status layout_road(sq_mesh *h, const sq_layout_options *lo, sq_mesher_options *mo,
                             const sq_options *o, sq_error *err)
{
    sq_layout_result *r = &h->r;
    sq_mesh_timings *t = &h->t;
    sq_status st = sq_layout_run(h->face.cad, lo, r, err);
    char split[512];
    if ((st == SQ_OK || st == SQ_ERR_LAYOUT) && sq_layout_note(r, split, sizeof split))
        sq_api_log(o, SQ_LOG_NOTE, "%s", split);
    if (st == SQ_ERR_LAYOUT && mo->nbl == 0) st = all_quad_layout(h, lo, o, err); /* not --bl */
    if (st != SQ_OK) return st;
    t->triangulate = r->field.t_triangulate;
    t->solve = r->field.t_solve;
    t->critical_points = r->field.t_critical;
    t->trace = r->t_trace;
    t->layout = r->t_layout;
    layout_progress(o, r, t);
    double t1 = sq_now();
    /* sizes from e^H where the H/θ field was traced */
    sq_cross_field cf;
    if (!strcmp(r->field.kind, "H-theta")) {
        cf = sq_htheta_cross_field(&r->htheta);
        mo->field = &cf;
    }
    /* a layout of the identified domain puts a crossing and its image
     * within a quarter of the size; the others, the image's nodes set */
    const double tol = h->per.nidentified && !mo->slid.npairs ? SQ_IDENTIFIED_CROSSING_REL_TOL
                                                              : SQ_PERIODIC_NODE_REL_TOL;
    layout_ctx c = {h->face.cad, r, h->per.npairs ? &h->per : NULL, tol};
    st = mesh_halving(mesh_by_layout, &c, *mo, sq_mesher_default_size(r->layout.face_area), o, h,
                      err);
    mo->field = NULL;
    if (st != SQ_OK && h->all_quad) {
        char msg[sizeof err->msg];
        snprintf(msg, sizeof msg, "%s", err->msg);
        st = SQ_FAIL(err, st, "%s (on %.300s)", msg, h->road.reason);
    }
    t->mesh = sq_now() - t1;
    return st;
}

static sq_status split_road(sq_mesh *h, const sq_mesher_options *mo, const sq_options *o,
                            sq_error *err)
{
    split_ctx c = {h->face.cad, &h->info, h->per.npairs ? &h->per : NULL};
    double t1 = sq_now();
    sq_status st = mesh_halving(mesh_by_split, &c, *mo, sq_mesher_default_size(h->info.area), o, h,
                                err);
    h->t.mesh = sq_now() - t1;
    if (st != SQ_OK && h->road.reason[0]) {
        char split_msg[sizeof err->msg];
        snprintf(split_msg, sizeof split_msg, "%s", err->msg);
        st = SQ_FAIL(err, st, "%s (the split road; the layout road: %s)", split_msg,
                     h->road.reason);
    }
    return st;
}

/* Route 1b of periodic pairs (docs/domains.md): the face's own layout,
 * no edge identified, each pair's curves given one chord total and the
 * image's vertices set to the images of the master's (sq_mesher_options
 * .slid), for translations and rotations alike; the kinks that are one
 * regular point of the identified domain bends (sq_periodic_bends). */
static sq_status slid_layout_road(sq_mesh *h, const sq_layout_options *lo,
                                  const sq_mesher_options *mo, const sq_options *o, sq_error *err)
{
    const sq_periodic *per = &h->per;
    sq_identified_pair *pairs = malloc(sizeof *pairs * (size_t)per->npairs);
    if (!pairs) return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    for (int k = 0; k < per->npairs; k++) {
        pairs[k].a = per->pairs[k].a, pairs[k].b = per->pairs[k].b;
        memcpy(pairs[k].affine, per->pairs[k].affine, sizeof pairs[k].affine);
    }
    sq_bend *bends = NULL;
    int nbends = 0;
    sq_status st = sq_periodic_bends(h->face.cad, &h->info, per, &bends, &nbends, err);
    if (st != SQ_OK) {
        free(pairs);
        return st;
    }
    sq_layout_options own = *lo;
    own.field.periodic = own.trace.periodic = (sq_identification){0, NULL};
    own.field.bends = bends, own.field.nbends = nbends;
    sq_mesher_options so = *mo;
    so.periodic = (sq_identification){0, NULL};
    so.slid = (sq_identification){per->npairs, pairs};
    sq_layout_result_free(&h->r);
    sq_quad_mesh_free(&h->q);
    h->all_quad = 0;
    h->road.reason[0] = '\0';
    st = layout_road(h, &own, &so, o, err);
    free(pairs), free(bends);
    return st;
}

/* Periodic pairs whose layout (route 1) failed: route 1b, its reason in
 * road.reason whether it meshes or not. */
static sq_status periodic_route_1b(sq_mesh *h, const sq_layout_options *lo,
                                   sq_mesher_options *mo, const sq_options *o, sq_error *err)
{
    char first[sizeof err->msg];
    snprintf(first, sizeof first, "%s", err->msg);
    sq_api_log(o, SQ_LOG_NOTE, "periodic: the layout road failed (%s); trying the face's own "
               "layout with the image curves' vertices slid onto their masters' images", first);
    sq_status st = slid_layout_road(h, lo, mo, o, err);
    char all_quad[sizeof h->road.reason]; /* the last resort's reason, if it was taken */
    snprintf(all_quad, sizeof all_quad, "%s", h->road.reason);
    if (st == SQ_OK)
        snprintf(h->road.reason, sizeof h->road.reason,
                 "periodic route 1b: the face's own layout, each pair's image vertices slid onto "
                 "the images of its master's (the identified domain's layout, route 1: "
                 "%.200s)%s%.150s",
                 first, all_quad[0] ? "; " : "", all_quad);
    else
        snprintf(h->road.reason, sizeof h->road.reason,
                 "periodic: the face's own layout with slid vertices (route 1b): %.220s; the "
                 "identified domain's layout (route 1): %.180s", err->msg, first);
    return st;
}

/* The mesh one road made, set aside while the other one runs. */
typedef struct {
    sq_quad_mesh *q;
    sq_quad_quality quality;
    double *sjac, *eta;
} road_mesh;

static road_mesh take_mesh(sq_mesh *h)
{
    road_mesh m = {h->q, h->quality, h->sjac, h->eta};
    h->q = NULL;
    h->sjac = h->eta = NULL;
    return m;
}

static void put_mesh(sq_mesh *h, road_mesh *m)
{
    sq_quad_mesh_free(&h->q);
    free(h->sjac);
    free(h->eta);
    h->q = m->q;
    h->quality = m->quality;
    h->sjac = m->sjac;
    h->eta = m->eta;
}

static void free_mesh(road_mesh *m)
{
    sq_quad_mesh_free(&m->q);
    free(m->sjac);
    free(m->eta);
}

/* The layout road's mesh is valid but below the quality floor (a
 * near-degenerate quad in a narrow gap or at a tiny edge, which the
 * layout's patches cannot avoid): the split road is tried and the mesh
 * whose worst scaled Jacobian is the larger is kept, the layout's on a
 * tie or when the split road fails. */
static void try_split_for_quality(sq_mesh *h, const sq_mesher_options *mo, const sq_options *o)
{
    double t_layout = h->t.mesh;
    road_mesh layout = take_mesh(h);
    double sj = layout.quality.min_scaled_jacobian;
    sq_api_log(o, SQ_LOG_NOTE,
               "the layout road's worst quad has scaled Jacobian %.3g < --min-quality %g; trying "
               "the split road",
               sj, o->min_quality);
    sq_error split_err = {0};
    sq_status st = split_road(h, mo, o, &split_err);
    h->t.mesh += t_layout;
    if (st == SQ_OK && h->quality.min_scaled_jacobian > sj) {
        sq_api_log(o, SQ_LOG_NOTE, "kept the split road (worst scaled Jacobian %.3g > %.3g)",
                   h->quality.min_scaled_jacobian, sj);
        h->road.name = "split";
        snprintf(h->road.reason, sizeof h->road.reason,
                 "worst quad's scaled Jacobian %.3g < --min-quality %g, the split road's %.3g", sj,
                 o->min_quality, h->quality.min_scaled_jacobian);
        free_mesh(&layout);
        return;
    }
    if (st == SQ_OK)
        sq_api_log(o, SQ_LOG_NOTE, "kept the layout road (the split road's worst scaled "
                   "Jacobian %.3g is no better)", h->quality.min_scaled_jacobian);
    else
        sq_api_log(o, SQ_LOG_NOTE, "kept the layout road (the split road failed: %s)",
                   split_err.msg);
    put_mesh(h, &layout);
}

/* The layout road's mesh on an all-quad last-resort layout: kept only
 * when it is at or above the quality floor and has fewer interior
 * irregular vertices than the split road's (the road that would mesh the
 * face otherwise), as many with a worst quad no worse, or when the split
 * road fails; else the split road's, with why in road.reason. */
static void compare_all_quad(sq_mesh *h, const sq_mesher_options *mo, const sq_options *o)
{
    double t_layout = h->t.mesh;
    road_mesh layout = take_mesh(h);
    const sq_quad_quality *lq = &layout.quality;
    sq_error split_err = {0};
    char lay_reason[sizeof h->road.reason];
    snprintf(lay_reason, sizeof lay_reason, "%s", h->road.reason);
    h->road.reason[0] = '\0'; /* a failed split road names it otherwise */
    sq_status st = split_road(h, mo, o, &split_err);
    h->t.mesh += t_layout;
    /* the layout road's also when the split road fails: a mesh either way */
    const sq_quad_quality *sq = &h->quality;
    int better = st != SQ_OK || (lq->min_scaled_jacobian >= o->min_quality &&
                                 (lq->irregular_interior < sq->irregular_interior ||
                                  (lq->irregular_interior == sq->irregular_interior &&
                                   lq->min_scaled_jacobian >= sq->min_scaled_jacobian)));
    char tail[200];
    if (st == SQ_OK)
        snprintf(tail, sizeof tail, "%d interior irregular vertices, worst scaled Jacobian %.3g; "
                 "the split road's %d, %.3g", lq->irregular_interior, lq->min_scaled_jacobian,
                 h->quality.irregular_interior, h->quality.min_scaled_jacobian);
    else
        snprintf(tail, sizeof tail, "%d interior irregular vertices, worst scaled Jacobian %.3g; "
                 "the split road failed", lq->irregular_interior, lq->min_scaled_jacobian);
    sq_api_log(o, SQ_LOG_NOTE, "kept the %s road: all-quad layout %s", better ? "layout" : "split",
               tail);
    if (better) {
        put_mesh(h, &layout); /* frees the split road's */
        snprintf(h->road.reason, sizeof h->road.reason, "%.300s: %s", lay_reason, tail);
        return;
    }
    free_mesh(&layout);
    h->road.name = "split";
    snprintf(h->road.reason, sizeof h->road.reason, "%.300s: %s", lay_reason, tail);
}

/* Both roads as the options say: the layout road first unless told
 * otherwise, the split road where it gives way or where its mesh is below
 * the quality floor and the split road's is better; an all-quad
 * last-resort layout's mesh against the split road's. */
static sq_status run_roads(sq_mesh *h, sq_api_road road, const sq_layout_options *lo,
                           sq_mesher_options *mo, const sq_options *o, sq_error *err)
{
    h->road.name = road == SQ_API_ROAD_SPLIT ? "split" : "layout";
    sq_status st = SQ_OK;
    if (road != SQ_API_ROAD_SPLIT) st = layout_road(h, lo, mo, o, err);
    if (road != SQ_API_ROAD_SPLIT && h->per.npairs && takes_split_road(st, lo, mo))
        st = periodic_route_1b(h, lo, mo, o, err);
    if (road == SQ_API_ROAD_AUTO && takes_split_road(st, lo, mo)) {
        if (!h->per.npairs) snprintf(h->road.reason, sizeof h->road.reason, "%s", err->msg);
        sq_api_log(o, SQ_LOG_NOTE, "the layout road failed (%s); meshing by the split road",
                   err->msg);
        h->road.name = "split";
        sq_quad_mesh_free(&h->q);
        st = SQ_OK;
    }
    if (st == SQ_OK && !strcmp(h->road.name, "split")) return split_road(h, mo, o, err);
    if (st == SQ_OK && road == SQ_API_ROAD_AUTO && split_road_allowed(lo, mo) && h->all_quad)
        compare_all_quad(h, mo, o);
    else if (st == SQ_OK && road == SQ_API_ROAD_AUTO && split_road_allowed(lo, mo) &&
             h->quality.min_scaled_jacobian < o->min_quality)
        try_split_for_quality(h, mo, o);
    return st;
}

sq_status sq_api_mesh_arrays(sq_mesh *h, sq_error *err)
{
    const sq_quad_mesh *q = h->q;
    h->xyz = calloc(1, sizeof *h->xyz);
    h->bnd = malloc(3 * (size_t)(q->nbnd ? q->nbnd : 1) * sizeof *h->bnd);
    if (!h->xyz || !h->bnd) return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    for (int s = 0; s < q->nbnd; s++) {
        h->bnd[3 * s] = q->bnd_quad[s];
        h->bnd[3 * s + 1] = q->bnd_side[s];
        h->bnd[3 * s + 2] = q->bnd_tag[s];
    }
    cad_face_frame(h->face.cad, h->origin, h->xdir, h->ydir);
    return SQ_OK;
}

sq_status sq_face_mesh(const sq_model *model, int face, const sq_options *o, sq_mesh **out,
                       sq_error *err)
{
    sq_options def;
    SQ_TRY(sq_api_name_faces(NULL, sq_api_options(o, &def), err)); /* refused before the work */
    SQ_TRY(sq_api_face_mesh(model, face, o, NULL, NULL, NULL, out, err));
    const cad_face *cad = (*out)->face.cad;
    sq_status st = sq_api_file_names((*out)->q, model->cad, &cad, NULL, 0, err);
    if (st == SQ_OK) st = sq_api_name_tags((*out)->q, sq_api_options(o, &def), err);
    if (st != SQ_OK) sq_mesh_free(out);
    return st;
}

/* The pair's transform, as a phrase. */
static void transform_text(const sq_periodic_pair *r, char *buf, size_t n)
{
    if (r->rotation)
        snprintf(buf, n, "rotation by %.9g deg about (%.9g, %.9g)", r->angle_deg, r->centre[0],
                 r->centre[1]);
    else
        snprintf(buf, n, "translation by (%.9g, %.9g)", r->shift[0], r->shift[1]);
}

void sq_api_periodic_log(const sq_options *o, const sq_periodic *per)
{
    char t[160];
    for (int k = 0; k < per->npairs; k++) {
        const sq_periodic_pair *r = &per->pairs[k];
        transform_text(r, t, sizeof t);
        sq_api_log(o, SQ_LOG_NOTE, "periodic: edge %d is the image of edge %d under the %s (gap "
                   "%.2g, tolerance %.2g)", r->b, r->a, t, r->gap, per->tol);
    }
    for (int k = 0; k < per->ncandidates; k++) {
        const sq_periodic_pair *r = &per->candidates[k];
        transform_text(r, t, sizeof t);
        sq_api_log(o, SQ_LOG_NOTE, "periodic: edges %d and %d also match (%s), not taken: "
                   "--periodic %d:%d takes them", r->a, r->b, t, r->a, r->b);
    }
}

sq_status sq_api_periodic_find(const cad_face *face, const sq_face_info *info,
                               const sq_options *o, sq_periodic *per, sq_layout_options *lo,
                               sq_error *err)
{
    SQ_TRY(sq_periodic_find(face, info, o->periodic, per, err));
    sq_api_periodic_log(o, per);
    lo->field.periodic = lo->trace.periodic = (sq_identification){per->nidentified, per->identified};
    return SQ_OK;
}

/* --periodic on the mesh: the pairs found, their edges held. */
static sq_status periodic_find(sq_mesh *h, sq_mesher_options *mo, sq_layout_options *lo,
                               const sq_options *o, sq_error *err)
{
    SQ_TRY(sq_api_periodic_find(h->face.cad, &h->info, o, &h->per, lo, err));
    int ne = cad_face_num_edges(h->face.cad);
    if (!(h->per_held = malloc(sizeof(int) * ((size_t)ne + 1))))
        return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    sq_periodic_held(&h->per, h->per_held, ne);
    mo->held_edges = h->per_held;
    mo->periodic = lo->field.periodic;
    return SQ_OK;
}

/* The identified domain's Gauss–Bonnet count against the mesh's. */
static sq_status periodic_identified(sq_mesh *h, const sq_options *o, sq_error *err)
{
    sq_quad_mesh *q = h->q;
    SQ_TRY(sq_periodic_identified(&h->info, &h->per, q, &q->periodic_chi, &q->periodic_index,
                                  &q->periodic_irregular, &q->periodic_mesh_index, err));
    sq_api_periodic_log_identified(o, q, h->road.name);
    return SQ_OK;
}

void sq_api_periodic_log_identified(const sq_options *o, const sq_quad_mesh *q, const char *road)
{
    sq_api_log(o, SQ_LOG_NOTE, "periodic: the identified domain has chi %d; its interior vertices "
               "need a net index %d (at least %d irregular); the mesh has %d irregular there "
               "(net index %d), by the %s road",
               q->periodic_chi, q->periodic_index, abs(q->periodic_index), q->periodic_irregular,
               q->periodic_mesh_index, road);
}

sq_status sq_api_face_mesh(const sq_model *model, int face, const sq_options *o,
                           const int *held_edges, const int *min_chords,
                           const sq_edge_points *edge_points, sq_mesh **out, sq_error *err)
{
    *out = NULL;
    sq_options def;
    o = sq_api_options(o, &def);
    sq_api_road road;
    sq_layout_options lo;
    sq_mesher_options mo;
    SQ_TRY(sq_api_parse_road(o->road, &road, err));
    SQ_TRY(sq_api_layout_options(o, 1, &lo, err));
    SQ_TRY(sq_api_mesher_options(o, &mo, err));
    mo.held_edges = held_edges;
    mo.min_chords = min_chords;
    mo.edge_points = edge_points;
    sq_mesh *h = calloc(1, sizeof *h);
    if (!h || !(h->t_write = calloc(1, sizeof *h->t_write))) {
        free(h);
        return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    }
    h->t0 = sq_now();
    h->t.read = model->t_read;
    h->progress = mo.progress;
    h->threads = o->threads;
    sq_status st = sq_api_face_open(model, face, o, &h->face, err);
    char *healed = NULL;
    if (st == SQ_OK) st = sq_model_heal_summary(model, h->face.index, &healed, err);
    if (healed) sq_api_log(o, SQ_LOG_INFO, "%s", healed);
    free(healed);
    if (st == SQ_OK) sq_api_log(o, SQ_LOG_INFO, "read %s (%.3f s)", model->path, model->t_read);
    if (st == SQ_OK) st = sq_face_info_compute(h->face.cad, &h->info, err);
    if (st == SQ_OK && (st = sq_face_check_cusps(&h->info, err)) != SQ_OK)
        sq_api_cusp_hint(model->cad, &h->info, err);
    /* a size that would exhaust memory is refused before any work */
    if (st == SQ_OK && o->size > 0.0)
        st = sq_mesher_check_size(h->info.area, mo.size, mo.max_quads, err);
    if (st == SQ_OK && (o->nsizes > 0 || o->curvature_elements > 0.0))
        st = sq_size_field_create(h->face.cad, o->sizes, o->nsizes, o->size_gradation,
                                  o->curvature_elements, &h->sizes, err);
    mo.sizes = h->sizes;
    if (st == SQ_OK && o->periodic && !held_edges) st = periodic_find(h, &mo, &lo, o, err);
    if (st == SQ_OK) st = run_roads(h, road, &lo, &mo, o, err);
    if (st == SQ_OK && h->per.npairs) st = periodic_identified(h, o, err);
    if (st == SQ_OK) st = sq_api_mesh_arrays(h, err);
    if (st != SQ_OK) {
        sq_mesh_free(&h);
        return st;
    }
    sq_api_log(o, SQ_LOG_INFO, "meshed (%.3f s)", h->t.mesh);
    h->nbl = o->nbl;
    if (o->nbl > 0 && !(h->bl_edges = malloc(sizeof(int) * (size_t)o->nbl))) {
        sq_mesh_free(&h);
        return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    }
    if (o->nbl > 0) memcpy(h->bl_edges, o->bl_edges, sizeof(int) * (size_t)o->nbl);
    h->bl_first = mo.bl_first, h->bl_ratio = mo.bl_ratio, h->bl_layers = mo.bl_layers;
    *out = h;
    return SQ_OK;
}

/* What made quad q, for the stage to blame: the road and its patch (the
 * layout road) or triangle block (the split road), the CAD edge under one
 * of its sides (a curve that bends too much for the size), and boundary
 * layers. */
static void blame(const sq_mesh *h, int q, char *buf, size_t n)
{
    const sq_quad_mesh *m = h->q;
    int edge = -1;
    for (int s = 0; s < m->nbnd && edge < 0; s++)
        if (m->bnd_quad[s] == q) edge = m->bnd_tag[s];
    int len = snprintf(buf, n, "made by the %s road (%s %d)", h->road.name,
                       strcmp(h->road.name, "split") ? "patch" : "block", m->patch[q]);
    if (len < 0 || (size_t)len >= n) return;
    if (edge >= 0)
        len += snprintf(buf + len, n - (size_t)len, ", on CAD edge %d", edge);
    else
        len += snprintf(buf + len, n - (size_t)len, ", inside the face");
    if (len < 0 || (size_t)len >= n) return;
    snprintf(buf + len, n - (size_t)len, ", %s",
             h->nbl ? "with boundary layers" : "no boundary layers");
}

sq_status sq_mesh_check_quality(const sq_mesh *m, const sq_options *o, sq_error *err)
{
    sq_options def;
    o = sq_api_options(o, &def);
    SQ_TRY(sq_options_check(o, err)); /* min_quality in 0..1 among them */
    const sq_quad_quality *q = &m->quality;
    if (o->min_quality == 0.0 || q->min_scaled_jacobian >= o->min_quality) return SQ_OK;
    char why[256];
    blame(m, q->worst_quad, why, sizeof why);
    return SQ_FAIL(err, SQ_ERR_QUALITY,
                   "worst quad %d, centre (%.6g, %.6g), has scaled Jacobian %.3g < --min-quality "
                   "%g; %s; a smaller --size refines it, --min-quality 0 accepts it",
                   q->worst_quad, q->worst_xy[0], q->worst_xy[1], q->min_scaled_jacobian,
                   o->min_quality, why);
}

void sq_mesh_free(sq_mesh **m)
{
    if (!m || !*m) return;
    sq_mesh *h = *m;
    if (h->xyz) free(*h->xyz);
    free(h->xyz);
    free(h->sjac);
    free(h->eta);
    free(h->bnd);
    free(h->t_write);
    sq_quad_mesh_free(&h->q);
    sq_size_field_free(&h->sizes);
    sq_layout_result_free(&h->r);
    sq_face_info_free(&h->info);
    sq_api_face_close(&h->face);
    sq_api_domain_free(&h->dom);
    sq_periodic_free(&h->per);
    free(h->per_held);
    free(h->bl_edges);
    free(h);
    *m = NULL;
}

int sq_mesh_face(const sq_mesh *m) { return m->face.index; }
int sq_mesh_order(const sq_mesh *m) { return m->q->order; }
const char *sq_mesh_road(const sq_mesh *m) { return m->road.name; }
int sq_mesh_num_nodes(const sq_mesh *m) { return m->q->nnodes; }
const double *sq_mesh_nodes(const sq_mesh *m)
{
    const sq_quad_mesh *q = m->q;
    if (*m->xyz || !(*m->xyz = malloc(3 * (size_t)(q->nnodes ? q->nnodes : 1) * sizeof **m->xyz)))
        return *m->xyz;
    for (int k = 0; k < q->nnodes; k++) {
        (*m->xyz)[3 * k] = q->xy[2 * k];
        (*m->xyz)[3 * k + 1] = q->xy[2 * k + 1];
        (*m->xyz)[3 * k + 2] = 0.0;
    }
    return *m->xyz;
}
int sq_mesh_num_quads(const sq_mesh *m) { return m->q->nquads; }
const int *sq_mesh_quads(const sq_mesh *m) { return m->q->conn; }
int sq_mesh_num_boundary_sides(const sq_mesh *m) { return m->q->nbnd; }
const int *sq_mesh_boundary_sides(const sq_mesh *m) { return m->bnd; }
int sq_mesh_num_tags(const sq_mesh *m) { return m->q->ntags; }
const double *sq_mesh_scaled_jacobians(const sq_mesh *m) { return m->sjac; }
const double *sq_mesh_eta(const sq_mesh *m) { return m->eta; }
double sq_mesh_area(const sq_mesh *m) { return m->quality.area; }

void sq_mesh_frame(const sq_mesh *m, double origin[3], double xdir[3], double ydir[3])
{
    memcpy(origin, m->origin, sizeof m->origin);
    memcpy(xdir, m->xdir, sizeof m->xdir);
    memcpy(ydir, m->ydir, sizeof m->ydir);
}

/* The mesh writers, by the output's extension. */
typedef sq_status (*mesh_writer)(const char *path, const sq_quad_mesh *m,
                                 const sq_progress *progress, sq_error *err);
static const struct {
    const char *name, *ext;
    mesh_writer write;
} mesh_formats[] = {{"msh", ".msh", sq_write_msh},
                    {"xml", ".xml", sq_write_nektar},
                    {"vtu", ".vtu", sq_write_quad_vtu},
                    {"svg", ".svg", sq_write_quad_svg},
                    {"msh-binary", NULL, sq_write_msh_binary},
                    {"xml-compressed", NULL, sq_write_nektar_compressed}};

/* The writer of format ("msh", "xml", ..., "msh-binary", "xml-compressed"),
 * or of path's extension when format is NULL (the last two only by name). */
static mesh_writer writer_of(const char *path, const char *format)
{
    for (size_t k = 0; k < sizeof mesh_formats / sizeof *mesh_formats; k++) {
        const char *ext = mesh_formats[k].ext;
        if (format ? !strcmp(format, mesh_formats[k].name) : ext && sq_api_ends_with(path, ext))
            return mesh_formats[k].write;
    }
    return NULL;
}

int sq_mesh_format_known(const char *path) { return writer_of(path, NULL) != NULL; }

sq_status sq_mesh_write(const sq_mesh *m, const char *path, sq_error *err)
{
    return sq_mesh_write_format(m, path, NULL, err);
}

sq_status sq_mesh_write_format(const sq_mesh *m, const char *path, const char *format,
                               sq_error *err)
{
    mesh_writer write = writer_of(path, format);
    if (!write && format)
        return SQ_FAIL(err, SQ_ERR_USAGE, "unknown mesh format '%s' (use msh, msh-binary, xml, xml-compressed or vtu)", format);
    if (!write)
        return SQ_FAIL(err, SQ_ERR_USAGE, "%s: unknown mesh format (use .msh, .xml or .vtu)", path);
    double t = sq_now();
    /* text MSH, the format of large meshes, is formatted on threads */
    sq_status st = write == sq_write_msh
                       ? sq_write_msh_threads(path, m->q, m->threads, &m->progress, err)
                       : write(path, m->q, &m->progress, err);
    *m->t_write += sq_now() - t;
    return st;
}

/* The timings as of now: total from the start of the read. */
static sq_mesh_timings timings(const sq_mesh *m)
{
    sq_mesh_timings t = m->t;
    t.write = *m->t_write;
    t.total = m->t.read + (sq_now() - m->t0);
    return t;
}

/* The report's "sizes" key: the mesh against the user's sizes, when set
 * (rep filled), and its "boundary_layers" key, when asked (bl filled; the
 * caller frees both); neither: *sz NULL. */
static sq_status report_sizes(const sq_mesh *m, sq_size_report *rep, sq_bl_report *bl,
                              sq_report_sizes *out, const sq_report_sizes **sz, sq_error *err)
{
    *sz = NULL;
    memset(rep, 0, sizeof *rep);
    memset(bl, 0, sizeof *bl);
    memset(out, 0, sizeof *out);
    if (!m->sizes && !m->bl_edges) return SQ_OK;
    if (m->sizes) SQ_TRY(sq_size_report_compute(m->q, m->sizes, m->far_size, rep, err));
    if (m->bl_edges)
        SQ_TRY(sq_bl_report_compute(m->q, m->face.cad, m->bl_edges, m->nbl, m->bl_first,
                                    m->bl_ratio, m->bl_layers, bl, err));
    out->report = m->sizes ? rep : NULL;
    out->bl = m->bl_edges ? bl : NULL;
    out->far = m->far_size;
    *sz = out;
    return SQ_OK;
}

sq_status sq_mesh_report(const sq_mesh *m, char **json, sq_error *err)
{
    sq_mesh_timings t = timings(m);
    if (m->dom) return sq_api_domain_report(m, &t, json, err);
    sq_size_report rep;
    sq_bl_report bl;
    sq_report_sizes rs;
    const sq_report_sizes *sz;
    sq_status st0 = report_sizes(m, &rep, &bl, &rs, &sz, err);
    if (st0 != SQ_OK) {
        sq_size_report_free(&rep);
        sq_bl_report_free(&bl);
        return st0;
    }
    sq_api_text txt;
    sq_status st = sq_api_text_open(&txt, err);
    if (st == SQ_OK) {
        sq_print_mesh_report(txt.fp, m->face.model->path, m->face.model->cad, m->face.index,
                             &m->info, &m->road, &m->r, m->q, &m->quality, sz, &t);
        st = sq_api_text_close(&txt, json, err);
    }
    sq_size_report_free(&rep);
    sq_bl_report_free(&bl);
    return st;
}

sq_status sq_mesh_write_report(const sq_mesh *m, const char *path, sq_error *err)
{
    sq_mesh_timings t = timings(m);
    if (m->dom) return sq_api_domain_write_report(m, &t, path, err);
    sq_size_report rep;
    sq_bl_report bl;
    sq_report_sizes rs;
    const sq_report_sizes *sz;
    sq_status st = report_sizes(m, &rep, &bl, &rs, &sz, err);
    if (st == SQ_OK)
        st = sq_write_mesh_report(path, m->face.model->path, m->face.model->cad, m->face.index,
                                  &m->info, &m->road, &m->r, m->q, &m->quality, sz, &t, err);
    sq_size_report_free(&rep);
    sq_bl_report_free(&bl);
    return st;
}

sq_status sq_mesh_describe(const sq_mesh *m, char **text, sq_error *err)
{
    char line[256];
    sq_quad_quality_line(m->q, &m->quality, line, sizeof line);
    sq_api_text x;
    SQ_TRY(sq_api_text_open(&x, err));
    fprintf(x.fp, "%s\n", line);
    return sq_api_text_close(&x, text, err);
}
