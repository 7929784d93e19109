/* semquad — every intersection of the separatrices of a set with one
 * another and with themselves: exact segment-segment intersections, chunks
 * of segments rejected by their bounding boxes. */
#include "layout_internal.h"

#include <math.h>
#include <stdlib.h>

#define CHUNK 16

typedef struct {
    int sep, j0, j1; /* segments j0..j1-1 */
    double bb[4];
} chunk;

static sq_status hit_push(lay_hit **h, int *n, int *cap, lay_hit v, sq_error *err)
{
    lay_hit *q = lay_grow(*h, cap, *n + 1, sizeof **h);
    if (!q) return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    *h = q;
    q[(*n)++] = v;
    return SQ_OK;
}

/* min and max of two finite numbers (fmin and fmax are library calls here) */
static inline double lo(double a, double b) { return a < b ? a : b; }
static inline double hi(double a, double b) { return a > b ? a : b; }

static int end_of(const sq_separatrix *s, double x, double y, double tol)
{
    if (hypot(x - s->xy[0], y - s->xy[1]) <= tol) return 0;
    if (hypot(x - s->xy[2 * s->npts - 2], y - s->xy[2 * s->npts - 1]) <= tol) return 1;
    return -1;
}

sq_status lay_intersections(const sq_separatrix_set *set, double tol, lay_hit **hits, int *nhits,
                            sq_error *err)
{
    *hits = NULL;
    *nhits = 0;
    int nch = 0, cap = 0;
    chunk *ch = NULL;
    for (int i = 0; i < set->n; i++) {
        const sq_separatrix *s = &set->s[i];
        for (int j0 = 0; j0 + 1 < s->npts; j0 += CHUNK) {
            int j1 = j0 + CHUNK < s->npts - 1 ? j0 + CHUNK : s->npts - 1;
            chunk c = {i, j0, j1, {HUGE_VAL, HUGE_VAL, -HUGE_VAL, -HUGE_VAL}};
            for (int j = j0; j <= j1; j++) {
                c.bb[0] = fmin(c.bb[0], s->xy[2 * j] - tol);
                c.bb[1] = fmin(c.bb[1], s->xy[2 * j + 1] - tol);
                c.bb[2] = fmax(c.bb[2], s->xy[2 * j] + tol);
                c.bb[3] = fmax(c.bb[3], s->xy[2 * j + 1] + tol);
            }
            chunk *q = lay_grow(ch, &cap, nch + 1, sizeof *ch);
            if (!q) {
                free(ch);
                return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
            }
            ch = q;
            ch[nch++] = c;
        }
    }
    int hcap = 0;
    sq_status st = SQ_OK;
    const double eps = 1e-12;
    for (int ci = 0; ci < nch && st == SQ_OK; ci++)
        for (int cj = ci; cj < nch && st == SQ_OK; cj++) {
            const chunk *A = &ch[ci], *B = &ch[cj];
            if (A->bb[0] > B->bb[2] || B->bb[0] > A->bb[2] || A->bb[1] > B->bb[3] ||
                B->bb[1] > A->bb[3])
                continue;
            const sq_separatrix *sa = &set->s[A->sep], *sb = &set->s[B->sep];
            for (int a = A->j0; a < A->j1 && st == SQ_OK; a++)
                for (int b = (ci == cj ? a + 1 : B->j0); b < B->j1 && st == SQ_OK; b++) {
                    if (A->sep == B->sep && abs(a - b) <= 1) continue;
                    const double *p = &sa->xy[2 * a], *q = &sb->xy[2 * b];
                    double r[2] = {p[2] - p[0], p[3] - p[1]}, s[2] = {q[2] - q[0], q[3] - q[1]};
                    /* A hit below lies on both segments' lines within tol +
                     * eps x length of each segment, so within their bounding
                     * boxes grown by that much (the 1-norms bound the
                     * lengths): pairs whose grown boxes are apart are skipped
                     * before the hypot calls that dominate the cost. */
                    double g = tol + eps * (fabs(r[0]) + fabs(r[1]) + fabs(s[0]) + fabs(s[1]));
                    if (lo(p[0], p[2]) - g > hi(q[0], q[2]) ||
                        lo(q[0], q[2]) - g > hi(p[0], p[2]) ||
                        lo(p[1], p[3]) - g > hi(q[1], q[3]) || lo(q[1], q[3]) - g > hi(p[1], p[3]))
                        continue;
                    double den = r[0] * s[1] - r[1] * s[0];
                    double lr = hypot(r[0], r[1]), ls = hypot(s[0], s[1]);
                    if (fabs(den) <= 1e-14 * lr * ls || lr == 0.0 || ls == 0.0) continue;
                    double w[2] = {q[0] - p[0], q[1] - p[1]};
                    double t = (w[0] * s[1] - w[1] * s[0]) / den;
                    double u = (w[0] * r[1] - w[1] * r[0]) / den;
                    double et = eps + tol / lr, eu = eps + tol / ls;
                    if (t < -et || t > 1 + et || u < -eu || u > 1 + eu) continue;
                    t = fmin(fmax(t, 0.0), 1.0);
                    u = fmin(fmax(u, 0.0), 1.0);
                    lay_hit h;
                    h.a = A->sep;
                    h.b = B->sep;
                    h.pa = a + t;
                    h.pb = b + u;
                    h.x = p[0] + t * r[0];
                    h.y = p[1] + t * r[1];
                    h.enda = end_of(sa, h.x, h.y, tol);
                    h.endb = end_of(sb, h.x, h.y, tol);
                    h.cosang = fabs(r[0] * s[0] + r[1] * s[1]) / (lr * ls);
                    if (h.enda >= 0 && h.endb >= 0) continue; /* a shared end node */
                    /* a polyline vertex on the other curve is seen by the two
                     * segments beside it: keep one */
                    int dup = 0;
                    for (int k = *nhits - 1; k >= 0 && k >= *nhits - 8; k--) {
                        const lay_hit *o = &(*hits)[k];
                        if (o->a == h.a && o->b == h.b && hypot(o->x - h.x, o->y - h.y) <= tol)
                            dup = 1;
                    }
                    if (!dup) st = hit_push(hits, nhits, &hcap, h, err);
                }
        }
    free(ch);
    if (st != SQ_OK) {
        free(*hits);
        *hits = NULL;
        *nhits = 0;
        return st;
    }
    /* vertices shared by segments of different chunks: drop the remaining
     * duplicates (same pair of curves, same point) */
    int m = 0;
    for (int k = 0; k < *nhits; k++) {
        int dup = 0;
        for (int o = 0; o < m && !dup; o++) {
            const lay_hit *x = &(*hits)[o], *y = &(*hits)[k];
            dup = ((x->a == y->a && x->b == y->b) || (x->a == y->b && x->b == y->a)) &&
                  hypot(x->x - y->x, x->y - y->y) <= tol;
        }
        if (!dup) (*hits)[m++] = (*hits)[k];
    }
    *nhits = m;
    return SQ_OK;
}
