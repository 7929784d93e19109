#include "quad_split.h"

#include "triangulate.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Design 1.  With the angle bound, about area / size^2 vertices are
 * expected: four times that (and a floor for the boundary's own points)
 * before the bound is lowered, so a sliver does not run CGAL to the quad
 * budget first.  The bounds tried: 20 degrees, then 5 (a needle or a thin
 * part resolved with fewer, flatter triangles), then none, with the
 * boundary's segments kept as they are: CGAL's Gabriel refinement of the
 * segments at a corner of angle a grades them geometrically with ratio
 * about 1 + a (millions of points at the 0.0004 degree corner of a
 * sliver), while a triangle with that corner split in three quads is
 * valid (scaled Jacobian sin a > 0). */
typedef struct {
    const sq_size_field *sizes;
    double size;
} split_sizes;

/* The triangles' size where the user set sizes: SQ_SPLIT_TRI_SIZE h(x),
 * as at the uniform size. */
static double split_size(const double xy[2], void *ctx)
{
    const split_sizes *s = ctx;
    return SQ_SPLIT_TRI_SIZE * sq_size_field_eval(s->sizes, xy, s->size);
}

static sq_status triangulate(const cad_face *face, const sq_face_info *info, double size,
                             const sq_mesher_options *opt, sq_triangulation *tri, sq_error *err)
{
    static const double min_angle[] = {20.0, 5.0, 0.0};
    sq_tri_options to;
    sq_tri_options_default(&to);
    to.order = 1;
    to.size = SQ_SPLIT_TRI_SIZE * size;
    to.edge_points = opt->edge_points;
    split_sizes us = {opt->sizes, size};
    if (opt->sizes) {
        to.user_size = split_size;
        to.user_ctx = &us;
    }
    double budget = opt->max_quads > 0.0 ? opt->max_quads / 6.0 : 2e7;
    /* with the user's sizes area / size^2 says nothing of the count: the
     * quad budget alone bounds it */
    double expected = opt->sizes ? budget
                                 : 4.0 * fabs(info->area) / (to.size * to.size) + SQ_TRI_MAX_VERTICES;
    sq_status st = SQ_OK;
    for (int k = 0; k < 3; k++) {
        to.min_angle_deg = min_angle[k];
        to.keep_segments = min_angle[k] == 0.0;
        to.max_vertices = (int)fmin(k < 2 ? fmin(budget, expected) : budget, 2e7) + 3;
        st = sq_triangulate(face, &to, tri, err);
        if (st != SQ_ERR_GEOMETRY) break;
    }
    return st;
}

/* Arc length halfway along boundary edge k of triangle e (bs from
 * sq_triangulate: along the curve's direction of travel, so a segment
 * that ends before it starts crosses a closed curve's closing point). */
static double mid_arc(const cad_face *face, const sq_triangulation *tri, int e, int k)
{
    int c = tri->mesh->btag[3 * e + k];
    double s0 = tri->bs[6 * e + 2 * k], s1 = tri->bs[6 * e + 2 * k + 1];
    double L = cad_face_edge_length(face, c);
    if (s1 < s0) s1 += L;
    double s = 0.5 * (s0 + s1);
    return s > L ? s - L : s;
}

typedef struct {
    int nv, nq;
    double *xy;
    int *quad, *block, *side_tag;
} split_mesh;

static void split_mesh_free(split_mesh *s)
{
    free(s->xy);
    free(s->quad);
    free(s->block);
    free(s->side_tag);
    memset(s, 0, sizeof *s);
}

/* The edge of triangle n that is triangle e's edge k (it runs the other
 * way), or -1. */
static int edge_across(const sem_tri_mesh *m, int e, int k, int n)
{
    int a = m->tri[3 * e + k];
    for (int kk = 0; kk < 3; kk++)
        if (m->tri[3 * n + (kk + 1) % 3] == a) return kk;
    return -1;
}

/* The midpoint vertex of every triangle edge but the pairs' diagonals
 * (diag[e]: that edge of e, or -1), once per edge (the lower triangle of
 * the two makes it): mid[3e+k]. */
static sq_status midpoints(const cad_face *face, const sq_triangulation *tri, const int *diag,
                           split_mesh *s, int *mid, sq_error *err)
{
    const sem_tri_mesh *m = tri->mesh;
    for (int e = 0; e < m->ntris; e++)
        for (int k = 0; k < 3; k++) {
            int n = m->neigh[3 * e + k];
            if (k == diag[e]) continue;
            if (n >= 0 && n < e) {
                int kk = edge_across(m, e, k, n);
                if (kk < 0)
                    return SQ_FAIL(err, SQ_ERR_INTERNAL, "triangles %d and %d share no edge", e, n);
                mid[3 * e + k] = mid[3 * n + kk];
                continue;
            }
            int v = s->nv++;
            const double *A = &m->vxy[2 * m->tri[3 * e + k]];
            const double *B = &m->vxy[2 * m->tri[3 * e + (k + 1) % 3]];
            s->xy[2 * v] = 0.5 * (A[0] + B[0]);
            s->xy[2 * v + 1] = 0.5 * (A[1] + B[1]);
            if (n < 0)
                SQ_TRY(cad_face_edge_eval(face, m->btag[3 * e + k], mid_arc(face, tri, e, k),
                                          &s->xy[2 * v], NULL, NULL, err));
            mid[3 * e + k] = v;
        }
    return SQ_OK;
}

/* The quad of the two triangles across e's edge k, counter-clockwise
 * from that edge's first vertex: a, d (n's vertex off the edge), b, c
 * (e's), with the triangle edges under its sides in es[4] (as 3t+k). */
static void pair_quad(const sem_tri_mesh *m, int e, int k, int n, int kk, int c[4], int es[4])
{
    c[0] = m->tri[3 * e + k], c[1] = m->tri[3 * n + (kk + 2) % 3];
    c[2] = m->tri[3 * e + (k + 1) % 3], c[3] = m->tri[3 * e + (k + 2) % 3];
    es[0] = 3 * n + (kk + 1) % 3, es[1] = 3 * n + (kk + 2) % 3;
    es[2] = 3 * e + (k + 1) % 3, es[3] = 3 * e + (k + 2) % 3;
}

typedef struct {
    double eta;
    int e, k;
} pair_cand;

/* best first; the lower triangle and edge at a tie, so the order is the
 * same on every machine */
static int cand_cmp(const void *x, const void *y)
{
    const pair_cand *a = x, *b = y;
    if (a->eta != b->eta) return a->eta > b->eta ? -1 : 1;
    return a->e != b->e ? (a->e < b->e ? -1 : 1) : (a->k < b->k ? -1 : a->k > b->k);
}

/* Design 2, first half: triangles paired across interior edges into
 * quads, greedily, the best shaped first (Gmsh's recombination does it by
 * a matching; the greedy pass leaves a few more triangles).  A pair must
 * be a quad of corner angles within 30-150 deg (eta >= 1/3): split in
 * four it gives quads no worse than a triangle's three.  diag[e]: the edge
 * of e shared with its mate, or -1. */
#define SQ_PAIR_MIN_ETA (1.0 / 3.0)

static sq_status pair_triangles(const sem_tri_mesh *m, int *diag, sq_error *err)
{
    pair_cand *cand = malloc(sizeof *cand * (3 * (size_t)m->ntris + 1));
    if (!cand) return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    size_t nc = 0;
    for (int e = 0; e < m->ntris; e++) {
        diag[e] = -1;
        for (int k = 0; k < 3; k++) {
            int n = m->neigh[3 * e + k], kk = n > e ? edge_across(m, e, k, n) : -1, c[4], es[4];
            if (kk < 0) continue;
            pair_quad(m, e, k, n, kk, c, es);
            const double *xy[4] = {&m->vxy[2 * c[0]], &m->vxy[2 * c[1]], &m->vxy[2 * c[2]],
                                   &m->vxy[2 * c[3]]};
            double eta = sq_quad_corner_eta(xy); /* <= 0 where it is not convex */
            if (eta >= SQ_PAIR_MIN_ETA) cand[nc++] = (pair_cand){eta, e, k};
        }
    }
    qsort(cand, nc, sizeof *cand, cand_cmp);
    for (size_t i = 0; i < nc; i++) {
        int e = cand[i].e, k = cand[i].k, n = m->neigh[3 * e + k];
        if (diag[e] >= 0 || diag[n] >= 0) continue;
        diag[e] = k, diag[n] = edge_across(m, e, k, n);
    }
    free(cand);
    return SQ_OK;
}

/* The quads at the corners of one polygon (a triangle's 3 or a pair's 4
 * corners c, midpoints md of the sides from corner i to i+1, tags tg of
 * those sides) about its centre: corner i, the midpoint after it, the
 * centre, the midpoint before it, counter-clockwise as the polygon. */
static void corner_quads(split_mesh *s, const double *vxy, int nc, const int *c, const int *md,
                         const int *tg, int block)
{
    int g = s->nv++;
    s->xy[2 * g] = s->xy[2 * g + 1] = 0.0;
    for (int i = 0; i < nc; i++)
        for (int d = 0; d < 2; d++) s->xy[2 * g + d] += vxy[2 * c[i] + d] / nc;
    for (int i = 0; i < nc; i++) {
        int q = s->nq++, ip = (i + nc - 1) % nc;
        int *qc = &s->quad[4 * q], *qt = &s->side_tag[4 * q];
        qc[0] = c[i], qc[1] = md[i], qc[2] = g, qc[3] = md[ip];
        qt[0] = tg[i], qt[1] = qt[2] = -1, qt[3] = tg[ip];
        s->block[q] = block;
    }
}

/* Design 2, second half: each pair split in four quads, each triangle
 * left alone in three. */
static sq_status split(const cad_face *face, const sq_triangulation *tri, split_mesh *s,
                       sq_error *err)
{
    const sem_tri_mesh *m = tri->mesh;
    size_t nvmax = (size_t)m->nverts + 4 * (size_t)m->ntris + 1;
    s->xy = malloc(sizeof(double) * 2 * nvmax);
    s->quad = malloc(sizeof(int) * 12 * ((size_t)m->ntris + 1));
    s->block = malloc(sizeof(int) * 3 * ((size_t)m->ntris + 1));
    s->side_tag = malloc(sizeof(int) * 12 * ((size_t)m->ntris + 1));
    int *mid = malloc(sizeof(int) * 3 * ((size_t)m->ntris + 1));
    int *diag = malloc(sizeof(int) * ((size_t)m->ntris + 1));
    if (!s->xy || !s->quad || !s->block || !s->side_tag || !mid || !diag) {
        free(mid), free(diag);
        return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    }
    memcpy(s->xy, m->vxy, sizeof(double) * 2 * (size_t)m->nverts);
    s->nv = m->nverts;
    sq_status st = pair_triangles(m, diag, err);
    if (st == SQ_OK) st = midpoints(face, tri, diag, s, mid, err);
    for (int e = 0; e < m->ntris && st == SQ_OK; e++) {
        int c[4], es[4], md[4], tg[4], k = diag[e], n = k >= 0 ? m->neigh[3 * e + k] : -1;
        if (n >= 0 && n < e) continue; /* the pair's lower triangle made it */
        if (n >= 0) {
            pair_quad(m, e, k, n, diag[n], c, es);
        } else {
            for (int i = 0; i < 3; i++) c[i] = m->tri[3 * e + i], es[i] = 3 * e + i;
        }
        int nc = n >= 0 ? 4 : 3;
        for (int i = 0; i < nc; i++) md[i] = mid[es[i]], tg[i] = m->btag[es[i]];
        corner_quads(s, m->vxy, nc, c, md, tg, e);
    }
    free(mid), free(diag);
    return st;
}

sq_status sq_split_triangulate(const cad_face *face, const sq_face_info *info,
                               const sq_mesher_options *opt, sq_triangulation *tri, sq_error *err)
{
    memset(tri, 0, sizeof *tri);
    double size = sq_mesher_size(opt, info->area);
    if (opt->max_quads > 0.0) SQ_TRY(sq_mesher_check_size(info->area, size, opt->max_quads, err));
    SQ_TRY(triangulate(face, info, size, opt, tri, err));
    double nquads = 3.0 * tri->mesh->ntris;
    if (opt->max_quads > 0.0 && nquads > opt->max_quads) {
        sq_triangulation_free(tri);
        return SQ_FAIL(err, SQ_ERR_USAGE,
                       "the split road at size %g gives %.3g quads, more than --max-quads %.3g; "
                       "try a size of %.3g or more",
                       size, nquads, opt->max_quads, size * sqrt(nquads / opt->max_quads));
    }
    return SQ_OK;
}

sq_status sq_mesh_split_triangulation(const cad_face *face, const sq_face_info *info,
                                      const sq_triangulation *tri, const sq_mesher_options *opt,
                                      sq_quad_mesh **out, sq_error *err)
{
    *out = NULL;
    split_mesh s = {0};
    sq_status st = split(face, tri, &s, err);
    if (st == SQ_OK) {
        sq_linear_quads lq = {s.nv, s.nq, s.xy, s.quad, s.block, s.side_tag};
        st = sq_mesh_linear_quads(face, info, &lq, opt, out, err);
    }
    split_mesh_free(&s);
    return st;
}

sq_status sq_mesh_split(const cad_face *face, const sq_face_info *info,
                        const sq_mesher_options *opt, sq_quad_mesh **out, sq_error *err)
{
    *out = NULL;
    sq_triangulation tri;
    SQ_TRY(sq_split_triangulate(face, info, opt, &tri, err));
    sq_status st = sq_mesh_split_triangulation(face, info, &tri, opt, out, err);
    sq_triangulation_free(&tri);
    return st;
}
