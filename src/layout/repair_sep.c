/* semquad — one separatrix of a layout being repaired: the position on it
 * nearest a point, its split into two at a node, the direction leaving an
 * end. */
#include "repair_private.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Nearest position (segment + t) on separatrix k to p. */
double lay_nearest_pos(const sq_separatrix *s, const double p[2], double *dist)
{
    double best = HUGE_VAL, pos = 0.0;
    for (int j = 0; j + 1 < s->npts; j++) {
        const double *a = &s->xy[2 * j], *b = a + 2;
        double v[2] = {b[0] - a[0], b[1] - a[1]}, l2 = v[0] * v[0] + v[1] * v[1];
        double t = l2 > 0 ? ((p[0] - a[0]) * v[0] + (p[1] - a[1]) * v[1]) / l2 : 0.0;
        t = fmin(fmax(t, 0.0), 1.0);
        double d = hypot(a[0] + t * v[0] - p[0], a[1] + t * v[1] - p[1]);
        if (d < best) {
            best = d;
            pos = j + t;
        }
    }
    if (dist) *dist = best;
    return pos;
}

/* Split separatrix k at position pos (point p) into two joined at singular
 * point `node`; the pieces replace k (k: first part, appended: second). */
sq_status lay_split_sep(sq_layout *L, int k, double pos, const double p[2], int node,
                        sq_error *err)
{
    sq_separatrix *s = &L->seps.s[k];
    int j = (int)floor(pos);
    if (j >= s->npts - 1) j = s->npts - 2;
    if (j < 0) j = 0;
    int n2 = s->npts - j; /* p + points j+1..npts-1 */
    double *b = malloc(2 * (size_t)n2 * sizeof *b);
    if (!b) return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    b[0] = p[0];
    b[1] = p[1];
    memcpy(b + 2, &s->xy[2 * (j + 1)], 2 * (size_t)(n2 - 1) * sizeof *b);
    sq_sep_end mid = {SQ_END_SINGULAR, node, 0.0}, oldend = s->end;
    sq_status st = lay_sep_push(&L->seps, b, n2, mid, oldend, err);
    free(b);
    if (st != SQ_OK) return st;
    s = &L->seps.s[k]; /* the set may have moved */
    s->npts = j + 2;
    s->xy[2 * (j + 1)] = p[0];
    s->xy[2 * (j + 1) + 1] = p[1];
    s->end = mid;
    return SQ_OK;
}

/* Direction of separatrix s leaving node position p (at its start or end). */
void lay_leave_dir(const sq_separatrix *s, int at_end, double d[2], double scale)
{
    int n = s->npts;
    const double *p0 = at_end ? &s->xy[2 * n - 2] : s->xy;
    d[0] = d[1] = 0.0;
    for (int j = 1; j < n; j++) {
        const double *q = &s->xy[2 * (at_end ? n - 1 - j : j)];
        d[0] = q[0] - p0[0];
        d[1] = q[1] - p0[1];
        if (hypot(d[0], d[1]) > 1e-6 * scale) break;
    }
    double l = hypot(d[0], d[1]);
    if (l > 0) {
        d[0] /= l;
        d[1] /= l;
    }
}

int lay_node_end(const sq_layout *L, int v, sq_sep_end *end)
{
    const sq_layout_node *c = &L->nodes[v];
    switch (c->kind) {
    case SQ_LNODE_CORNER:
        *end = (sq_sep_end){SQ_END_CORNER, c->id, 0.0};
        return 1;
    case SQ_LNODE_FOOT:
        *end = (sq_sep_end){SQ_END_BOUNDARY, c->id, c->s};
        return 1;
    case SQ_LNODE_SINGULAR:
        *end = (sq_sep_end){SQ_END_SINGULAR, c->id, 0.0};
        return 1;
    default:
        return 0;
    }
}
