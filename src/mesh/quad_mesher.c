/* semquad — the layout road (quad_mesher.h): a valid layout's chords
 * quantized, its patches meshed and glued; then, on either road's vertex
 * mesh, untangling, relaxation, boundary layers and order Q. */
#include "quad_mesher_private.h"
#include "quad_refine.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* a relaxed mesh is kept at once when its curved quads are at least this
 * far from folding (smallest scaled Jacobian over their nodes) */
#define SJ_ACCEPT 0.2

void sq_mesher_options_default(sq_mesher_options *opt)
{
    memset(opt, 0, sizeof *opt);
    opt->order = 4;
    opt->nodes = SQ_NODES_GLL;
    opt->bl_ratio = 1.2;
    opt->max_quads = SQ_MAX_QUADS;
}

sq_status sq_mesher_check_size(double area, double size, double max_quads, sq_error *err)
{
    double quads = fabs(area) / (size * size);
    if (!(quads <= max_quads))
        return SQ_FAIL(err, SQ_ERR_USAGE,
                       "--size %g gives about %.3g quads, more than --max-quads %.3g: a size of "
                       "%.3g or more fits",
                       size, quads, max_quads, sqrt(fabs(area) / max_quads));
    return SQ_OK;
}

/* keep[i] = 1 at the vertices of sides on opt->held_edges (*keep
 * allocated if NULL). */
static sq_status held_keep(const sq_mesher_options *opt, const qm_vmesh *v, int **keep,
                           sq_error *err)
{
    if (!opt->held_edges) return SQ_OK;
    if (!*keep && !(*keep = calloc((size_t)v->nv + 1, sizeof(int))))
        return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    for (int q = 0; q < v->nq; q++)
        for (int k = 0; k < 4; k++) {
            int t = v->side_tag[4 * q + k];
            if (t >= 0 && opt->held_edges[t])
                (*keep)[v->quad[4 * q + k]] = (*keep)[v->quad[4 * q + (k + 1) % 4]] = 1;
        }
    return SQ_OK;
}

static int is_quad(const sq_layout_patch *p) { return p->ncorners == 4 && p->ncycles == 1; }

/* What the Laplace moves of qm_smooth cannot open (a quad at a reflex
 * corner whose transfinite interior node sits past the corner, a thin
 * band of quads along a curve) untangled from its folded state, the
 * singular points free (sq_quad_untangle): *untangled its vertices (2 nv,
 * the caller frees), NULL unless every corner came out convex; v's
 * vertices are left where the untangling stopped. */
static sq_status untangle(const cad_face *face, const sq_face_info *info, qm_vmesh *v,
                          const int *keep, const sq_mesher_options *opt, sq_relax_work **work,
                          double **untangled, sq_error *err)
{
    *untangled = NULL;
    int folded = 0;
    for (int q = 0; q < v->nq; q++) folded += !qm_quad_valid(v, q);
    if (!folded) return SQ_OK;
    sq_status st = qm_relax(face, info, v, keep, 1, 1, opt, work, &folded, err);
    if (st != SQ_OK || folded) return st;
    size_t n = sizeof(double) * 2 * ((size_t)v->nv + 1);
    if (!(*untangled = malloc(n))) return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    memcpy(*untangled, v->xy, n);
    return SQ_OK;
}

/* From the vertices start: relaxed with the singular points free to even
 * out their angles (stopped where it folds a curved boundary quad), then
 * held where they are, then not relaxed at all; each attempt raised to
 * order Q and kept in *out when its smallest scaled Jacobian beats
 * *best_sj; stops at the first of at least SJ_ACCEPT.  The second is the
 * first again where there is no singular point to hold and the first did
 * not fold: skipped. */
static sq_status relax_attempts(const cad_face *face, const sq_face_info *info, qm_vmesh *v,
                                const double *start, const int *keep,
                                const sq_mesher_options *opt, sq_relax_work **work,
                                double *best_sj, sq_quad_mesh **out, sq_error *err)
{
    sq_status st = SQ_OK;
    int folded = 0;
    for (int attempt = 0; attempt < 3 && st == SQ_OK && *best_sj < SJ_ACCEPT; attempt++) {
        if (attempt == 1 && !folded && !qm_has_free_singular(v, keep)) continue;
        sq_quad_mesh *m = NULL;
        memcpy(v->xy, start, sizeof(double) * 2 * (size_t)v->nv);
        folded = 0;
        if (attempt < 2)
            st = qm_relax(face, info, v, keep, attempt == 0, 0, opt, work, &folded, err);
        if (folded) continue;
        /* the relaxation balances shapes against sizes and moves the
         * layers' nodes along their lines by up to a third of a cell: the
         * lines re-graded from the wall to a few cells into the core, where
         * the relaxed grid meets the metric again */
        if (st == SQ_OK && opt->nbl > 0 && attempt < 2)
            st = qm_regrade_walls(opt, sq_mesher_size(opt, info->area), opt->bl_layers, v, NULL,
                                  err);
        if (st == SQ_OK) st = qm_raise_order(face, v, opt->order, opt->nodes, opt, &m, err);
        sq_quad_quality qq;
        if (st == SQ_OK) st = sq_quad_mesh_quality(m, NULL, NULL, opt->threads, &qq, err);
        if (st == SQ_OK && qq.min_scaled_jacobian > *best_sj) {
            *best_sj = qq.min_scaled_jacobian;
            sq_quad_mesh_free(out);
            *out = m;
            m = NULL;
        }
        sq_quad_mesh_free(&m);
    }
    return st;
}

/* Design 3 from the glued vertex mesh on: untangling, relaxation, order Q.
 * keep (NULL, or nv flags, taken over): vertices the relaxation holds,
 * more added for opt->held_edges.  *out is NULL unless SQ_OK. */
static sq_status finish(const cad_face *face, const sq_face_info *info, qm_vmesh *v,
                        const sq_mesher_options *opt, int *keep, sq_quad_mesh **out,
                        sq_error *err)
{
    sq_status st = held_keep(opt, v, &keep, err);
    /* untangling, where transfinite interpolation folded a quad: Laplace
     * moves that keep every quad valid, then from the folded state */
    int folded = 0;
    for (int q = 0; q < v->nq && st == SQ_OK; q++) folded += !qm_quad_valid(v, q);
    if (st == SQ_OK && folded) st = qm_smooth(face, info, v, keep, err);
    double *smoothed = st == SQ_OK ? malloc(sizeof(double) * 2 * ((size_t)v->nv + 1)) : NULL;
    if (st == SQ_OK && !smoothed) st = SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    if (st == SQ_OK) memcpy(smoothed, v->xy, sizeof(double) * 2 * (size_t)v->nv);
    sq_relax_work *work = NULL; /* the first relaxation's Hessian, for the next */
    double *untangled = NULL;
    if (st == SQ_OK && folded) st = untangle(face, info, v, keep, opt, &work, &untangled, err);
    /* the attempts from the untangled mesh, then (unless one reached
     * SJ_ACCEPT) from the smoothed one, whose corners on a curve may be
     * non-convex as chords while the curved quads are valid (a narrow gap
     * between a hole and a corner): the first attempt of at least
     * SJ_ACCEPT, else the one with the largest smallest scaled Jacobian
     * (each attempt starts from its buffer, whatever the untangling left
     * in v) */
    double best_sj = -HUGE_VAL;
    if (st == SQ_OK && untangled)
        st = relax_attempts(face, info, v, untangled, keep, opt, &work, &best_sj, out, err);
    if (st == SQ_OK)
        st = relax_attempts(face, info, v, smoothed, keep, opt, &work, &best_sj, out, err);
    sq_relax_work_free(&work);
    if (st != SQ_OK) sq_quad_mesh_free(out);
    free(untangled);
    free(smoothed);
    free(keep);
    return st;
}

sq_status sq_mesh_linear_quads(const cad_face *face, const sq_face_info *info,
                               const sq_linear_quads *lq, const sq_mesher_options *opt,
                               sq_quad_mesh **out, sq_error *err)
{
    *out = NULL;
    if (opt->order < 1 || opt->order > 10)
        return SQ_FAIL(err, SQ_ERR_USAGE, "quad order %d outside 1..10", opt->order);
    if (opt->nbl > 0)
        return SQ_FAIL(err, SQ_ERR_USAGE, "boundary layers need a quad layout (--bl)");
    qm_vmesh v = {lq->nv, lq->nq, malloc(sizeof(double) * 2 * ((size_t)lq->nv + 1)),
               calloc((size_t)lq->nv + 1, sizeof(int)), malloc(sizeof(int) * 4 * ((size_t)lq->nq + 1)),
               malloc(sizeof(int) * ((size_t)lq->nq + 1)), malloc(sizeof(int) * 4 * ((size_t)lq->nq + 1))};
    sq_status st = v.xy && v.foot && v.quad && v.patch && v.side_tag
                       ? SQ_OK
                       : SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    if (st == SQ_OK) {
        memcpy(v.xy, lq->xy, sizeof(double) * 2 * (size_t)lq->nv);
        memcpy(v.quad, lq->quad, sizeof(int) * 4 * (size_t)lq->nq);
        memcpy(v.patch, lq->block, sizeof(int) * (size_t)lq->nq);
        memcpy(v.side_tag, lq->side_tag, sizeof(int) * 4 * (size_t)lq->nq);
        st = finish(face, info, &v, opt, NULL, out, err);
    }
    qm_vmesh_free(&v);
    return st;
}

/* Design 5: where the quantization nseg gives more than
 * opt->relax_max_quads quads (not with boundary layers, held or periodic
 * edges: their nodes are not the refinement's), nseg replaced by the quantization at size
 * 2^k, k the least giving at most that many (RELAX_MAX_LEVELS at most);
 * *levels = k (0: nseg kept). */
#define RELAX_MAX_LEVELS 8
static sq_status coarse_quantization(const sq_layout *L, const double *elen, double size,
                                     const double *need, const sq_mesher_options *opt, int *nseg,
                                     int *levels, sq_error *err)
{
    *levels = 0;
    double quads = qm_quantized_quads(L, nseg);
    if (!(opt->relax_max_quads > 0.0) || quads <= opt->relax_max_quads || opt->nbl > 0 ||
        opt->held_edges || opt->periodic.npairs || opt->slid.npairs)
        return SQ_OK;
    while (quads > opt->relax_max_quads && *levels < RELAX_MAX_LEVELS) {
        ++*levels;
        SQ_TRY(qm_quantize(L, elen, ldexp(size, *levels), need, NULL, opt, nseg, err));
        quads = qm_quantized_quads(L, nseg);
    }
    return SQ_OK;
}

/* The relaxed coarse mesh *m split 2 x 2 `levels` times (design 5). */
static sq_status refine_levels(const cad_face *face, int levels, const sq_mesher_options *opt,
                               sq_quad_mesh **m, sq_error *err)
{
    int relaxed = (*m)->nquads;
    for (int k = 0; k < levels; k++) {
        sq_quad_mesh *fine = NULL;
        SQ_TRY(sq_quad_mesh_refine(face, *m, 2, (*m)->order, opt->threads, &fine, err));
        sq_quad_mesh_free(m);
        *m = fine;
        sq_progress_report(&opt->progress, "refine", k + 1, levels);
    }
    if (levels > 0) (*m)->relaxed_quads = relaxed;
    return SQ_OK;
}

double sq_mesher_default_size(double area) { return sqrt(fabs(area)) / 8.0; }

double sq_mesher_size(const sq_mesher_options *opt, double area)
{
    return opt->size > 0.0 ? opt->size : sq_mesher_default_size(area);
}

/* The layout road from the options o (whose sizes carry the boundary
 * layers' walls, sq_mesh_layout). */
static sq_status mesh_layout(const cad_face *face, const sq_face_info *info, const sq_layout *L,
                             const sq_mesher_options *opt, sq_quad_mesh **out, sq_error *err)
{
    double size = sq_mesher_size(opt, L->face_area);
    int S = qm_size_samples(opt);
    int *nseg = malloc(sizeof(int) * ((size_t)L->nedges + 1));
    double *elen = malloc(sizeof(double) * ((size_t)L->nedges + 1));
    double *cum = malloc(sizeof(double) * ((size_t)L->nedges * (S + 1) + 1));
    sq_status st = nseg && elen && cum ? SQ_OK : SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    if (st == SQ_OK) st = qm_size_measure(L, face, opt, elen, cum, err);
    double *need = st == SQ_OK && opt->sizes
                       ? malloc(sizeof(double) * 2 * ((size_t)L->npatches + 1))
                       : NULL;
    if (st == SQ_OK && opt->sizes && !need) st = SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    if (st == SQ_OK && need) st = qm_interior_measure(L, face, opt, size, need, err);
    int *partner = st == SQ_OK && opt->periodic.npairs
                       ? malloc(sizeof(int) * ((size_t)L->nedges + 1))
                       : NULL;
    if (st == SQ_OK && opt->periodic.npairs && !partner)
        st = SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    if (st == SQ_OK && partner) qm_periodic_partners(L, face, opt, size, partner);
    if (st == SQ_OK) st = qm_quantize(L, elen, size, need, partner, opt, nseg, err);
    free(partner);
    /* the quantization can exceed area / size^2 (one segment at least per
     * chord, sides matched): check its own count before allocating */
    double nquads = st == SQ_OK ? qm_quantized_quads(L, nseg) : 0.0;
    if (st == SQ_OK && opt->max_quads > 0.0 && nquads > opt->max_quads)
        st = SQ_FAIL(err, SQ_ERR_USAGE,
                     "the layout's chords at size %g give %.3g quads, more than --max-quads %.3g; "
                     "try a size of %.3g or more",
                     size, nquads, opt->max_quads, size * sqrt(nquads / opt->max_quads));
    int levels = 0;
    if (st == SQ_OK) st = coarse_quantization(L, elen, size, need, opt, nseg, &levels, err);
    free(need);
    qm_vmesh v = {0};
    if (st == SQ_OK) st = qm_assemble(L, face, opt, nseg, cum, &v, err);
    /* boundary layers: every line leaving a wall graded by the metric, the
     * irregular vertices where such lines end held by the relaxation (an
     * O-grid's corners: the spokes' counts were set for their length) */
    int *keep = NULL;
    if (st == SQ_OK && opt->nbl > 0) st = qm_regrade_walls(opt, size, 0, &v, &keep, err);
    if (st == SQ_OK && opt->slid.npairs) st = qm_slide_periodic(face, opt, &v, err);
    if (st == SQ_OK && opt->edge_points) st = qm_slide_shared(face, opt, &v, err);
    if (st == SQ_OK) st = finish(face, info, &v, opt, keep, out, err);
    else free(keep);
    qm_vmesh_free(&v);
    if (st == SQ_OK) st = refine_levels(face, levels, opt, out, err);
    if (st != SQ_OK) sq_quad_mesh_free(out);
    free(nseg);
    free(elen);
    free(cum);
    return st;
}

sq_status sq_mesh_layout(const cad_face *face, const sq_face_info *info, const sq_layout *L,
                         const sq_mesher_options *opt, sq_quad_mesh **out, sq_error *err)
{
    *out = NULL;
    int Q = opt->order;
    if (Q < 1 || Q > 10) return SQ_FAIL(err, SQ_ERR_USAGE, "quad order %d outside 1..10", Q);
    for (int q = 0; q < L->npatches; q++)
        if (!is_quad(&L->patches[q]))
            return SQ_FAIL(err, SQ_ERR_LAYOUT, "patch %d is not a quad (%d corners)", q,
                           L->patches[q].ncorners);
    if (opt->nbl <= 0) return mesh_layout(face, info, L, opt, out, err);
    /* boundary layers: a size normal to the walls that grows from the
     * first height by the ratio, read by every stage as the user's sizes
     * are (docs/sizes.md, "A boundary layer that blends in") */
    sq_mesher_options o = *opt;
    sq_size_field *walls = NULL;
    SQ_TRY(sq_size_field_walls(face, opt->sizes, opt->bl_edges, opt->nbl, opt->bl_first,
                               opt->bl_ratio, opt->bl_layers,
                               opt->bl_gradation > 1.0 ? opt->bl_gradation : SQ_SIZE_GRADATION,
                               &walls, err));
    o.sizes = walls;
    sq_status st = mesh_layout(face, info, L, &o, out, err);
    sq_size_field_free(&walls);
    return st;
}
