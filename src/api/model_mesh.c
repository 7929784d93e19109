/* semquad public API: the mesh of several faces of a model as one
 * conforming mesh (sq_model_mesh; docs/domains.md).  One face is
 * sq_face_mesh; several go through the domain stage (src/domain). */
#include "api_private.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

void sq_api_domain_free(sq_api_domain **d)
{
    if (!d || !*d) return;
    free((*d)->face);
    free((*d)->road);
    free((*d)->area);
    free((*d)->curves);
    free((*d)->quad_face);
    for (int k = 0; (*d)->q && k < (*d)->nfaces; k++) sq_quad_mesh_free(&(*d)->q[k]);
    free((*d)->q);
    free(*d);
    *d = NULL;
}

/* The faces a model mesh takes without a list: every planar face (a
 * broken one among them is refused with its reason, as alone); none
 * planar: the default face, refused as sq_face_mesh refuses it. */
static sq_status planar_faces(const sq_model *m, int **faces, int *n, sq_error *err)
{
    int nf = cad_model_num_faces(m->cad);
    *faces = malloc(sizeof(int) * ((size_t)nf + 1));
    if (!*faces) return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    *n = 0;
    for (int f = 0; f < nf; f++)
        if (cad_model_face_planar(m->cad, f)) (*faces)[(*n)++] = f;
    if (*n == 0) (*faces)[(*n)++] = -1;
    return SQ_OK;
}

void sq_api_faces_close(sq_api_faces *f)
{
    for (int k = 0; k < f->n; k++) {
        sq_api_face_close(&f->face[k]);
        sq_face_info_free(&f->info[k]);
        sq_quad_mesh_free(&f->q[k]);
    }
    free(f->face), free(f->cad), free(f->info), free(f->q);
}

sq_status sq_api_faces_load(const sq_model *m, const int *faces, int n, const sq_options *o,
                            sq_api_faces *f, sq_error *err)
{
    f->n = 0;
    f->face = calloc((size_t)n, sizeof *f->face);
    f->cad = calloc((size_t)n, sizeof *f->cad);
    f->info = calloc((size_t)n, sizeof *f->info);
    f->q = calloc((size_t)n, sizeof *f->q);
    if (!f->face || !f->cad || !f->info || !f->q) return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    for (int k = 0; k < n; k++) {
        for (int j = 0; j < k; j++)
            if (faces[j] == faces[k]) return SQ_FAIL(err, SQ_ERR_USAGE, "--face %d named twice", faces[k]);
        SQ_TRY(sq_api_face_open(m, faces[k], o, &f->face[k], err));
        f->n = k + 1;
        f->cad[k] = f->face[k].cad;
        SQ_TRY(sq_face_info_compute(f->cad[k], &f->info[k], err));
        sq_status st = sq_face_check_cusps(&f->info[k], err);
        if (st != SQ_OK) {
            sq_api_cusp_hint(m->cad, &f->info[k], err);
            return st;
        }
    }
    return SQ_OK;
}

double sq_api_domain_tolerance(const sq_model *m, double size)
{
    return fmax(cad_model_heal_tolerance(m->cad), 1e-6 * size);
}

/* Face k's held edges (its shared curves), allocated; NULL: out of memory. */
static int *held_edges(const sq_domain *d, const sq_api_faces *f, int k)
{
    int ne = cad_face_num_edges(f->cad[k]);
    int *held = calloc((size_t)ne + 1, sizeof(int));
    for (int e = 0; held && e < ne; e++) held[e] = d->curves[d->curve_of[k][e]].face[1] >= 0;
    return held;
}

/* Face k's mesh h taken into f->q[k] (h freed), its road noted. */
static void take_face(sq_api_faces *f, int k, sq_mesh **h, const char **road)
{
    road[k] = !strcmp((*h)->road.name, "split") ? "split" : "layout";
    sq_quad_mesh_free(&f->q[k]);
    f->q[k] = (*h)->q;
    (*h)->q = NULL;
    sq_mesh_free(h);
}

/* Face k by its own roads (as o says) at the domain's size, the vertices
 * on its shared curves held, at least minc[k][e] chords on its edges, its
 * vertices on edge e slid onto ep[e]; its mesh into f->q[k]. */
static sq_status mesh_one(const sq_model *m, const sq_domain *d, sq_api_faces *f, int k,
                          const sq_options *o, int *const *minc, const sq_edge_points *ep,
                          const char **road, sq_error *err)
{
    int *held = held_edges(d, f, k);
    if (!held) return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    sq_mesh *h = NULL;
    sq_status st = sq_api_face_mesh(m, f->face[k].index, o, held, minc[k], ep, &h, err);
    free(held);
    if (st == SQ_OK) take_face(f, k, &h, road);
    return st;
}

/* The faces with (shares 1) or without (0) a shared curve, each by its
 * own roads (as o says) at the domain's size, the vertices on its shared
 * curves held, at least minc[k][e] chords on its edges (minc NULL: none),
 * on threads (sq_api_faces_mesh); their meshes taken into f->q. */
static sq_status mesh_each(const sq_model *m, const sq_domain *d, sq_api_faces *f,
                           const sq_options *o, int shares, int *const *minc, const char **road,
                           sq_error *err)
{
    int n = 0, *sel = calloc((size_t)f->n, sizeof(int));
    int *number = calloc((size_t)f->n, sizeof(int)); /* sel's CAD face numbers */
    int **held = calloc((size_t)f->n, sizeof *held), **mc = calloc((size_t)f->n, sizeof *mc);
    sq_mesh **h = calloc((size_t)f->n, sizeof *h);
    sq_status st = sel && number && held && mc && h ? SQ_OK
                                                   : SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    for (int k = 0; k < f->n && st == SQ_OK; k++) {
        if (sq_domain_face_shares(d, k) != shares) continue;
        if (!(held[n] = held_edges(d, f, k))) {
            st = SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
            break;
        }
        mc[n] = minc ? minc[k] : NULL;
        sel[n] = k, number[n++] = f->face[k].index;
    }
    if (st == SQ_OK) st = sq_api_faces_mesh(m, n, number, o, shares ? held : NULL, mc, h, err);
    for (int i = 0; i < n && st == SQ_OK; i++) take_face(f, sel[i], &h[i], road);
    for (int i = 0; i < f->n && held; i++) free(held[i]);
    for (int i = 0; i < f->n && h; i++) sq_mesh_free(&h[i]);
    free(sel), free(number), free(held), free(mc), free(h);
    return st;
}

/* Where the faces' layouts put their corners on a shared curve or a
 * periodic pair at places of their own (each face's own field: a disc and
 * the square around it), the counts agree but the vertices do not meet:
 * each face is meshed again, at the same counts, with its vertices there
 * slid onto those of the face before it, and a pair's image side within
 * one face onto its master's (docs/domains.md). */
static sq_status slide_faces(const sq_model *m, const sq_domain *dm, sq_api_faces *f,
                             const sq_options *o, int *const *minc, const char **road,
                             sq_error *err)
{
    sq_status st = SQ_OK;
    for (int k = 0; k < f->n && st == SQ_OK; k++) {
        if (!sq_domain_face_shares(dm, k)) continue;
        int ne = cad_face_num_edges(f->cad[k]), any = 0;
        sq_edge_points *ep = calloc((size_t)ne + 1, sizeof *ep);
        if (!ep) return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
        st = sq_domain_layout_points(dm, k, f->q, ep, &any, err);
        if (st == SQ_OK && any) st = mesh_one(m, dm, f, k, o, minc, ep, road, err);
        sq_domain_layout_points_free(ep, ne);
        free(ep);
    }
    return st;
}

/* Layout-road rounds of one quantization over the faces: a curve shared
 * (or a pair) whose two sides got different chord counts asks both faces
 * for the larger next round.  Counts only grow; a face whose layout
 * splits such an edge cannot take the count, and the rounds stop there. */
#define MAX_CHORD_ROUNDS 8

static int sides_on(const sq_quad_mesh *q, int e)
{
    int n = 0;
    for (int s = 0; s < q->nbnd; s++) n += q->bnd_tag[s] == e;
    return n;
}

/* The chord counts of both sides of every interface of dm: 0 when they
 * agree; else the larger asked of both in minc, 1 if that raised a
 * request, -1 if not (a face did not take what it was asked). */
static int agree_chords(const sq_domain *dm, sq_quad_mesh *const *q, int *const *minc)
{
    int differ = 0, raised = 0;
    for (int c = 0; c < dm->ncurves; c++) {
        const sq_domain_curve *cv = &dm->curves[c];
        if (cv->face[1] < 0) continue;
        int n0 = sides_on(q[cv->face[0]], cv->edge[0]), n1 = sides_on(q[cv->face[1]], cv->edge[1]);
        int want = n0 > n1 ? n0 : n1, *m0 = &minc[cv->face[0]][cv->edge[0]],
            *m1 = &minc[cv->face[1]][cv->edge[1]];
        if (n0 == n1) continue;
        differ = 1;
        raised |= want > *m0 || want > *m1;
        *m0 = *m1 = want;
    }
    return !differ ? 0 : raised ? 1 : -1;
}

/* The faces' meshes merged as d says and the pairs linked; *merged NULL
 * and err where they do not meet. */
static sq_status merge_linked(const sq_domain *d, const sq_api_faces *f, const int *faces,
                              double size, const sq_periodic *per, sq_quad_mesh **merged,
                              sq_error *err)
{
    sq_status st = sq_domain_merge(d, f->q, faces, size, merged, err);
    if (st == SQ_OK && per->npairs)
        st = sq_periodic_link(per, *merged, size, SQ_PERIODIC_NODE_REL_TOL, err);
    if (st != SQ_OK) sq_quad_mesh_free(merged);
    return st;
}

/* The faces sharing curves (in dm: shared curves and periodic pairs) by
 * the layout road, each alone with its shared curves' vertices held and
 * the chord counts agreed between rounds, merged as d says, the pairs
 * linked: conforming where their layouts put the same corners on each
 * shared curve and pair (three rectangles in a row, the ring's four
 * sectors); *merged NULL and err where they do not. */
static sq_status try_layouts(const sq_model *m, const sq_domain *dm, const sq_domain *d,
                             sq_api_faces *f, const sq_options *o, const int *faces,
                             const sq_periodic *per, const char **road, sq_quad_mesh **merged,
                             sq_error *err)
{
    sq_options ol = *o;
    ol.road = "layout";
    int **minc = calloc((size_t)f->n, sizeof *minc), changed = 1, r = 0;
    sq_status st = minc ? SQ_OK : SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    for (int k = 0; k < f->n && st == SQ_OK; k++)
        if (!(minc[k] = calloc((size_t)cad_face_num_edges(f->cad[k]) + 1, sizeof **minc)))
            st = SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    for (; st == SQ_OK && changed == 1 && r < MAX_CHORD_ROUNDS; r++) {
        for (int k = 0; k < f->n; k++)
            if (sq_domain_face_shares(dm, k)) sq_quad_mesh_free(&f->q[k]);
        st = mesh_each(m, dm, f, &ol, 1, minc, road, err);
        if (st == SQ_OK) changed = agree_chords(dm, f->q, minc);
    }
    if (st == SQ_OK && changed)
        st = SQ_FAIL(err, SQ_ERR_LAYOUT, "the faces' chord counts on a shared curve differ after "
                     "%d rounds (a layout splits it at corners of its own)", r);
    if (st == SQ_OK && merge_linked(d, f, faces, o->size, per, merged, err) != SQ_OK) {
        st = slide_faces(m, dm, f, &ol, minc, road, err);
        if (st == SQ_OK) st = merge_linked(d, f, faces, o->size, per, merged, err);
    }
    for (int k = 0; minc && k < f->n; k++) free(minc[k]);
    free(minc);
    if (st == SQ_OK) return SQ_OK;
    sq_quad_mesh_free(merged);
    for (int k = 0; k < f->n; k++)
        if (sq_domain_face_shares(dm, k)) sq_quad_mesh_free(&f->q[k]);
    return st;
}

/* --periodic on a domain: the pairs among its boundary curves (logged),
 * and *s the domain whose interfaces also are the pairs. */
static sq_status find_pairs(const sq_domain *d, const sq_options *o, sq_periodic *per,
                            sq_domain *s, sq_error *err)
{
    SQ_TRY(sq_domain_periodic_find(d, o->periodic, per, err));
    sq_api_periodic_log(o, per);
    return sq_domain_periodic_split(d, per, s, err);
}

/* The split road over dm's sharing faces, merged as d says, the pairs
 * linked. */
static sq_status split_domain(const sq_domain *dm, const sq_domain *d, sq_api_faces *f,
                              const sq_mesher_options *mo, const int *faces, double size,
                              const sq_periodic *per, const char **road, int *rounds,
                              sq_quad_mesh **q, sq_error *err)
{
    SQ_TRY(sq_domain_mesh_split(dm, mo, f->q, rounds, err));
    for (int k = 0; k < f->n; k++)
        if (sq_domain_face_shares(dm, k)) road[k] = "split";
    return merge_linked(d, f, faces, size, per, q, err);
}

/* The layout road's merged mesh below the quality floor (a corner slid
 * along a shared curve squeezes a quad at a coarse size): the split road
 * is tried and the mesh whose worst scaled Jacobian is the larger kept,
 * the layout road's on a tie or when the split road fails, as for one
 * face (face_mesh.c). */
static sq_status floor_domain(const sq_domain *dm, const sq_domain *d, sq_api_faces *f,
                              const sq_mesher_options *mo, const int *faces, const sq_options *o,
                              const sq_periodic *per, const char **road, int *rounds,
                              sq_quad_mesh **q, sq_error *err)
{
    sq_quad_quality lq, sq;
    SQ_TRY(sq_quad_mesh_quality(*q, NULL, NULL, mo->threads, &lq, err));
    if (lq.min_scaled_jacobian >= o->min_quality) return SQ_OK;
    sq_api_log(o, SQ_LOG_NOTE, "the layout road's worst quad has scaled Jacobian %.3g < "
               "--min-quality %g; trying the split road", lq.min_scaled_jacobian, o->min_quality);
    const char **kept = malloc(sizeof *kept * ((size_t)f->n + 1));
    sq_quad_mesh **layout = calloc((size_t)f->n + 1, sizeof *layout); /* the faces' meshes q
                                                                         was merged from */
    if (!kept || !layout) {
        free(kept), free(layout);
        return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    }
    memcpy(kept, road, sizeof *kept * (size_t)f->n);
    for (int k = 0; k < f->n; k++)
        if (sq_domain_face_shares(dm, k)) layout[k] = f->q[k], f->q[k] = NULL;
    sq_quad_mesh *split = NULL;
    sq_error e2;
    sq_error_clear(&e2);
    int r2 = 0;
    sq_status s2 = split_domain(dm, d, f, mo, faces, mo->size, per, road, &r2, &split, &e2);
    if (s2 == SQ_OK) s2 = sq_quad_mesh_quality(split, NULL, NULL, mo->threads, &sq, &e2);
    if (s2 == SQ_OK && sq.min_scaled_jacobian > lq.min_scaled_jacobian) {
        sq_api_log(o, SQ_LOG_NOTE, "kept the split road (worst scaled Jacobian %.3g > %.3g)",
                   sq.min_scaled_jacobian, lq.min_scaled_jacobian);
        sq_quad_mesh_free(q);
        *q = split;
        *rounds = r2;
    } else {
        sq_api_log(o, SQ_LOG_NOTE, "kept the layout road (the split road %s)",
                   s2 == SQ_OK ? "is no better" : e2.msg);
        sq_quad_mesh_free(&split);
        memcpy(road, kept, sizeof *kept * (size_t)f->n);
        for (int k = 0; k < f->n; k++)
            if (layout[k]) sq_quad_mesh_free(&f->q[k]), f->q[k] = layout[k], layout[k] = NULL;
    }
    for (int k = 0; k < f->n; k++) sq_quad_mesh_free(&layout[k]);
    free(kept), free(layout);
    return SQ_OK;
}

/* The identified domain's Gauss–Bonnet count on q, noted. */
static sq_status pairs_counted(const sq_periodic *per, sq_quad_mesh *q, const sq_options *o,
                               sq_error *err)
{
    SQ_TRY(sq_domain_periodic_identified(per, q, &q->periodic_chi, &q->periodic_index,
                                         &q->periodic_irregular, &q->periodic_mesh_index, err));
    sq_api_periodic_log_identified(o, q, "domain");
    return SQ_OK;
}

/* The domain's record in h->dom, its per-quad faces, and the faces'
 * meshes (taken from f) and size, for a family. */
sq_status sq_api_domain_new(sq_mesh *h, int nfaces, int ncurves, sq_error *err)
{
    sq_api_domain *a = calloc(1, sizeof *a);
    if (!(h->dom = a)) return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    a->nfaces = nfaces, a->ncurves = ncurves;
    a->face = malloc(sizeof(int) * (size_t)nfaces);
    a->road = malloc(sizeof(char *) * (size_t)nfaces);
    a->area = malloc(sizeof(double) * (size_t)nfaces);
    a->curves = malloc(sizeof *a->curves * ((size_t)ncurves + 1));
    a->quad_face = malloc(sizeof(int) * ((size_t)h->q->nquads + 1));
    a->q = calloc((size_t)nfaces, sizeof *a->q);
    if (!a->face || !a->road || !a->area || !a->curves || !a->quad_face || !a->q)
        return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    return SQ_OK;
}

static sq_status keep_domain(sq_mesh *h, const sq_domain *d, sq_api_faces *f,
                             const char **road, int rounds, double size, sq_error *err)
{
    SQ_TRY(sq_api_domain_new(h, f->n, d->ncurves, err));
    sq_api_domain *a = h->dom;
    for (int k = 0; k < f->n; k++)
        a->face[k] = f->face[k].index, a->road[k] = road[k], a->area[k] = f->info[k].area;
    for (int k = 0; k < f->n; k++) a->q[k] = f->q[k], f->q[k] = NULL;
    a->size = size;
    memcpy(a->curves, d->curves, sizeof *a->curves * (size_t)d->ncurves);
    a->ntags = d->ntags, a->rounds = rounds;
    for (int q = 0; q < h->q->nquads; q++) a->quad_face[q] = a->face[h->q->region[q]];
    return SQ_OK;
}

/* The user's sizes on a domain of several faces, each face meshed with
 * them in its own frame by its own edge numbers: edge-numbered sources
 * (--edge-size, --grow) and boundary layers (--bl) would name another
 * curve in every face, so they are refused (docs/sizes.md); points and
 * boxes are accepted where every face's frame is face 0's, the domain's
 * (faces of one plane drawn in one frame), which they are given in. */
static sq_status domain_sizes_check(const sq_domain *d, int n, const sq_options *o,
                                    sq_error *err)
{
    int located = 0;
    for (int i = 0; i < o->nsizes; i++) {
        if (o->sizes[i].kind == SQ_SIZE_EDGE)
            return SQ_FAIL(err, SQ_ERR_USAGE,
                           "size source %d (--edge-size, --grow, or an edge/grow line): a CAD edge "
                           "number names each face's own edge, not one curve of a domain of %d "
                           "faces; mesh one face (--face N), or use --refine/--refine-box",
                           i + 1, n);
        located = 1;
    }
    if (o->nbl > 0)
        return SQ_FAIL(err, SQ_ERR_USAGE,
                       "--bl on a domain of %d faces: a CAD edge number names each face's own "
                       "edge, not one curve of the domain; mesh the face with the wall (--face N)",
                       n);
    for (int f = 1; located && f < n; f++) {
        double A[6];
        int flip;
        sq_domain_frame(d, f, A, &flip);
        double off = fabs(A[0] - 1.0) + fabs(A[1]) + fabs(A[3]) + fabs(A[4] - 1.0);
        if (flip || off > 1e-12 || fabs(A[2]) + fabs(A[5]) > 1e-12 * o->size)
            return SQ_FAIL(err, SQ_ERR_USAGE,
                           "--refine/--refine-box on a domain of %d faces: face %d's frame is not "
                           "face 0's, in which the coordinates are given; mesh one face "
                           "(--face N)", n, f);
    }
    return SQ_OK;
}

/* Several faces: the domain's curves (and periodic pairs), the meshes of
 * its faces, merged (and linked). */
static sq_status mesh_domain(const sq_model *m, const int *faces, int n, const sq_options *o,
                             sq_mesh *h, sq_error *err)
{
    sq_api_faces f = {0};
    sq_domain d = {0}, ds = {0};
    sq_periodic per = {0};
    sq_mesher_options mo;
    sq_options os = *o;
    const char **road = calloc((size_t)n, sizeof *road);
    int rounds = 0;
    sq_status st = road ? sq_api_faces_load(m, faces, n, o, &f, err)
                        : SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    /* one size for all: the faces sharing a curve discretize it alike; by
     * default the smallest face's own default, so none is coarser than alone */
    if (st == SQ_OK && !(os.size > 0.0)) {
        os.size = HUGE_VAL;
        for (int k = 0; k < n; k++) os.size = fmin(os.size, sq_mesher_default_size(f.info[k].area));
    }
    if (st == SQ_OK) st = sq_api_mesher_options(&os, &mo, err);
    h->progress = mo.progress;
    if (st == SQ_OK) h->face = f.face[0], f.face[0].cad = NULL, f.cad[0] = h->face.cad;
    double tol = sq_api_domain_tolerance(m, os.size);
    if (st == SQ_OK) st = sq_domain_build(n, f.cad, f.info, tol, &d, err);
    if (st == SQ_OK) st = domain_sizes_check(&d, n, &os, err);
    if (st == SQ_OK && d.ninterfaces > 0)
        sq_api_log(o, SQ_LOG_NOTE, "%d faces share %d curves (docs/domains.md)", n, d.ninterfaces);
    if (st == SQ_OK && o->periodic) st = find_pairs(&d, o, &per, &ds, err);
    os.periodic = NULL; /* the domain's pairs, not each face's own */
    const sq_domain *dm = per.npairs ? &ds : &d; /* the pairs as interfaces too */
    sq_api_road want = SQ_API_ROAD_AUTO;
    if (st == SQ_OK) st = sq_api_parse_road(o->road, &want, err);
    if (st == SQ_OK) st = mesh_each(m, dm, &f, &os, 0, NULL, road, err);
    if (st == SQ_OK && want != SQ_API_ROAD_SPLIT) {
        sq_error e2;
        sq_error_clear(&e2);
        sq_status s2 = dm->ninterfaces
                           ? try_layouts(m, dm, &d, &f, &os, faces, &per, road, &h->q, &e2)
                           : sq_domain_merge(&d, f.q, faces, os.size, &h->q, &e2);
        if (s2 != SQ_OK && (want == SQ_API_ROAD_LAYOUT || !dm->ninterfaces)) *err = e2, st = s2;
        else if (s2 != SQ_OK)
            sq_api_log(o, SQ_LOG_NOTE, "the layout road gives no conforming mesh of the faces (%s); "
                                       "the faces sharing curves%s take the split road", e2.msg,
                       per.npairs ? " or periodic pairs" : "");
    }
    if (st == SQ_OK && h->q && dm->ninterfaces && want == SQ_API_ROAD_AUTO && o->min_quality > 0.0)
        st = floor_domain(dm, &d, &f, &mo, faces, o, &per, road, &rounds, &h->q, err);
    if (st == SQ_OK && !h->q)
        st = split_domain(dm, &d, &f, &mo, faces, os.size, &per, road, &rounds, &h->q, err);
    if (st == SQ_OK && per.npairs) st = pairs_counted(&per, h->q, o, err);
    if (st == SQ_OK) st = sq_api_file_names(h->q, m->cad, f.cad, d.curves, d.ncurves, err);
    if (st == SQ_OK) st = keep_domain(h, &d, &f, road, rounds, os.size, err);
    sq_periodic_free(&per);
    sq_domain_free(&ds);
    sq_domain_free(&d);
    sq_api_faces_close(&f);
    free(road);
    return st;
}

sq_status sq_model_mesh(const sq_model *m, const int *faces, int nfaces, const sq_options *o,
                        sq_mesh **out, sq_error *err)
{
    *out = NULL;
    sq_options def;
    o = sq_api_options(o, &def);
    SQ_TRY(sq_options_check(o, err));
    int *all = NULL;
    if (!faces || nfaces <= 0) {
        sq_status st = planar_faces(m, &all, &nfaces, err);
        if (st != SQ_OK) {
            free(all);
            return st;
        }
        faces = all;
    }
    if (nfaces == 1) {
        int f = faces[0];
        free(all);
        return sq_face_mesh(m, f, o, out, err);
    }
    sq_mesh *h = calloc(1, sizeof *h);
    sq_status st = h && (h->t_write = calloc(1, sizeof *h->t_write))
                       ? SQ_OK
                       : SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    if (st == SQ_OK) {
        h->t0 = sq_now();
        h->t.read = m->t_read;
        h->road.name = "domain";
        h->nbl = o->nbl;
        h->threads = o->threads;
    }
    if (st == SQ_OK) st = mesh_domain(m, faces, nfaces, o, h, err);
    if (st == SQ_OK) h->t.mesh = sq_now() - h->t0;
    if (st == SQ_OK) st = sq_api_mesh_quality(h, err);
    if (st == SQ_OK && h->quality.inverted > 0)
        st = SQ_FAIL(err, SQ_ERR_LAYOUT,
                     "%d quads have a non-positive Jacobian (min scaled Jacobian %.3g); try a "
                     "smaller --size",
                     h->quality.inverted, h->quality.min_scaled_jacobian);
    if (st == SQ_OK) st = sq_api_mesh_arrays(h, err);
    if (st == SQ_OK) st = sq_api_name_tags(h->q, o, err);
    if (st == SQ_OK) st = sq_api_name_faces(h->q, o, err);
    free(all);
    if (st != SQ_OK) {
        if (h) sq_mesh_free(&h);
        return st;
    }
    sq_api_log(o, SQ_LOG_INFO, "meshed %d faces as one mesh (%.3f s)", nfaces, h->t.mesh);
    *out = h;
    return SQ_OK;
}

int sq_mesh_num_faces(const sq_mesh *m) { return m->dom ? m->dom->nfaces : 1; }
const int *sq_mesh_quad_faces(const sq_mesh *m) { return m->dom ? m->dom->quad_face : NULL; }
