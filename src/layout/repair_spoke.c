/* semquad — spokes of the patch splits: separatrices from a node inserted in
 * a patch to the arc-length midpoints of its sides (the sides' midpoints, the
 * patch's centroid, straight or bent spokes ending on the boundary or in a
 * T-junction). */
#include "repair_private.h"

#include <math.h>
#include <stdlib.h>

/* The point at fraction t of the arc length of the half-edges half[a..b)
 * of patch P: the edge and the fraction along it (from its n0). */
static void chain_point(const sq_layout *L, const sq_layout_patch *P, int a, int b, double t,
                        int *edge, double *frac)
{
    double tot = 0.0;
    for (int k = a; k < b; k++) tot += L->edges[P->half[k % P->nhalf].edge].length;
    double acc = 0.0;
    for (int k = a; k < b; k++) {
        const sq_layout_half *h = &P->half[k % P->nhalf];
        double l = L->edges[h->edge].length;
        if (acc + l >= t * tot || k == b - 1) {
            double f = l > 0 ? (t * tot - acc) / l : 0.5;
            *edge = h->edge;
            *frac = h->reversed ? 1.0 - f : f;
            return;
        }
        acc += l;
    }
}

/* Area centroid of the patch's outer cycle (Green's theorem on its
 * polylines); 0 if the cycle has no area. */
int lay_patch_centroid(const sq_layout *L, const sq_layout_patch *P, double cen[2])
{
    int end = P->ncycles > 0 ? P->cycle_start[1] : P->nhalf;
    double A = 0.0, cx = 0.0, cy = 0.0;
    for (int k = 0; k < end; k++) {
        const sq_layout_edge *E = &L->edges[P->half[k].edge];
        for (int j = 0; j + 1 < E->npts; j++) {
            int j0 = P->half[k].reversed ? E->npts - 1 - j : j;
            int j1 = P->half[k].reversed ? j0 - 1 : j0 + 1;
            const double *u = &E->xy[2 * j0], *v = &E->xy[2 * j1];
            double c = u[0] * v[1] - v[0] * u[1];
            A += c;
            cx += (u[0] + v[0]) * c;
            cy += (u[1] + v[1]) * c;
        }
    }
    if (!(fabs(A) > 0)) return 0;
    cen[0] = cx / (3.0 * A);
    cen[1] = cy / (3.0 * A);
    return 1;
}

/* The point at fraction t of the arc length of side k of patch P (corner k
 * to corner k + 1; t = 0.5 its midpoint): the
 * edge, the fraction along it and the point. */
sq_status lay_side_point(lay_repair *r, const sq_layout_patch *P, int k, double t, int *edge,
                         double *frac, double xy[2], sq_error *err)
{
    int a = P->corner_half[k], b = P->corner_half[(k + 1) % P->ncorners];
    if (b <= a) b += P->nhalf;
    chain_point(r->L, P, a, b, t, edge, frac);
    return sq_layout_edge_point(r->L, r->face, *edge, *frac, xy, err);
}

/* Separatrix from `start` along the path xy[np] (each segment cut into 16
 * pieces), ending in `end`. */
static sq_status path_sep(sq_layout *L, sq_sep_end start, const double *xy, int np,
                          sq_sep_end end, sq_error *err)
{
    enum { PIECES = 16 };
    int n = (np - 1) * PIECES + 1;
    double *q = malloc(2 * (size_t)n * sizeof *q);
    if (!q) return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    for (int i = 0; i + 1 < np; i++)
        for (int j = 0; j < PIECES + (i + 2 == np); j++) {
            double t = (double)j / PIECES;
            const double *a = &xy[2 * i], *b = a + 2;
            q[2 * (i * PIECES + j)] = a[0] + t * (b[0] - a[0]);
            q[2 * (i * PIECES + j) + 1] = a[1] + t * (b[1] - a[1]);
        }
    sq_status st = lay_sep_push(&L->seps, q, n, start, end, err);
    free(q);
    return st;
}

/* Straight separatrix from `start` (at a) to b, ending in `end`. */
sq_status lay_straight_sep(sq_layout *L, sq_sep_end start, const double a[2], const double b[2],
                           sq_sep_end end, sq_error *err)
{
    double xy[4] = {a[0], a[1], b[0], b[1]};
    return path_sep(L, start, xy, 2, end, err);
}

/* An inserted node within this many times the repairs' tolerance of a
 * spoke's end takes it, in the all-quad last resort: two patches splitting
 * the two sides of one piece (a cut across a two-corner patch) share its
 * midpoint, as a midpoint subdivision does. */
#define SHARED_END_TOL 1e3

/* The end of a new separatrix at point p of layout edge `edge` (fraction
 * frac): a foot on the boundary; on a separatrix a new T-junction (the
 * separatrix split there), or, in the all-quad last resort, an inserted
 * node already there. */
sq_status lay_edge_end(lay_repair *r, int edge, double frac, const double p[2], sq_sep_end *end,
                       sq_error *err)
{
    sq_layout *L = r->L;
    const sq_layout_edge *E = &L->edges[edge];
    if (E->cad_edge >= 0) {
        *end = (sq_sep_end){SQ_END_BOUNDARY, E->cad_edge, E->s0 + frac * (E->s1 - E->s0)};
        return SQ_OK;
    }
    for (int k = 0; r->all_quad && k < L->nsing; k++)
        if (L->role[k] != SQ_LROLE_INPUT &&
            hypot(L->sing[k].x - p[0], L->sing[k].y - p[1]) <= SHARED_END_TOL * r->tol) {
            *end = (sq_sep_end){SQ_END_SINGULAR, k, 0.0};
            L->sing[k].valence++;
            return SQ_OK;
        }
    double q[2] = {p[0], p[1]}, dist;
    /* the edge's separatrix, unless an earlier spoke split it before q */
    int sep = E->sep;
    double pos = lay_nearest_pos(&L->seps.s[sep], q, &dist);
    for (int k = 0; k < L->seps.n && dist > r->tol; k++) {
        double d, ps = lay_nearest_pos(&L->seps.s[k], q, &d);
        if (d < dist) sep = k, pos = ps, dist = d;
    }
    SQ_TRY(lay_sing_push(L, q[0], q[1], 3, SQ_LROLE_TJUNCTION, err));
    *end = (sq_sep_end){SQ_END_SINGULAR, L->nsing - 1, 0.0};
    return lay_split_sep(L, sep, pos, q, L->nsing - 1, err);
}

/* A spoke from `start` (an inserted node, or a patch corner) along
 * path[np] (from it to point p on layout edge `edge` at fraction frac;
 * NULL: straight from cen), ending as lay_edge_end says: a T-junction is
 * repaired next (the "patches influenced" of Jezdimirović §6.3). */
sq_status lay_add_spoke(lay_repair *r, sq_sep_end start, const double cen[2], const double *path,
                        int np, int edge, double frac, const double p[2], sq_error *err)
{
    sq_sep_end end;
    SQ_TRY(lay_edge_end(r, edge, frac, p, &end, err));
    if (path) return path_sep(r->L, start, path, np, end, err);
    return lay_straight_sep(r->L, start, cen, p, end, err);
}
