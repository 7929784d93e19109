#include "size_report.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

void sq_size_report_free(sq_size_report *r)
{
    if (!r) return;
    free(r->edge);
    memset(r, 0, sizeof *r);
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* Boundary side b of m: its length along its nodes and its integral of
 * ds / h (trapezoid rule over the node polyline, as the chords' measure);
 * h's extremes at its nodes widen *lo, *hi. */
static void side_measure(const sq_quad_mesh *m, const sq_size_field *f, double far, int b,
                         double *len, double *cells, double *lo, double *hi)
{
    int Q = m->order;
    const int *conn = &m->conn[(size_t)m->bnd_quad[b] * (size_t)((Q + 1) * (Q + 1))];
    *len = *cells = 0.0;
    double prev = 0.0;
    for (int s = 0; s <= Q; s++) {
        const double *x = &m->xy[2 * conn[sq_quad_side_node(Q, m->bnd_side[b], s)]];
        double h = sq_size_field_eval(f, x, far);
        *lo = fmin(*lo, h);
        *hi = fmax(*hi, h);
        if (s > 0) {
            const double *p = &m->xy[2 * conn[sq_quad_side_node(Q, m->bnd_side[b], s - 1)]];
            double d = hypot(x[0] - p[0], x[1] - p[1]);
            *len += d;
            *cells += 0.5 * d * (1.0 / prev + 1.0 / h);
        }
        prev = h;
    }
}

/* The distinct patches of the quads along CAD edge t (p: scratch, one per
 * boundary side). */
static int patches_along(const sq_quad_mesh *m, int t, int *p)
{
    int n = 0;
    for (int b = 0; b < m->nbnd; b++)
        if (m->bnd_tag[b] == t) p[n++] = m->patch[m->bnd_quad[b]];
    return sq_sort_unique(p, n);
}

static void edge_sizes(const sq_quad_mesh *m, const sq_size_field *f, double far, int t,
                       int *scratch, sq_edge_sizes *e)
{
    memset(e, 0, sizeof *e);
    e->patch_sides = patches_along(m, t, scratch);
    e->edge = t;
    e->target_min = e->achieved_min = e->ratio_min = HUGE_VAL;
    e->target_max = e->achieved_max = e->ratio_max = -HUGE_VAL;
    for (int b = 0; b < m->nbnd; b++) {
        if (m->bnd_tag[b] != t) continue;
        double len, cells;
        side_measure(m, f, far, b, &len, &cells, &e->target_min, &e->target_max);
        e->segments++;
        e->cells += cells;
        e->achieved_min = fmin(e->achieved_min, len);
        e->achieved_max = fmax(e->achieved_max, len);
        e->ratio_min = fmin(e->ratio_min, cells);
        e->ratio_max = fmax(e->ratio_max, cells);
    }
}

/* The longest side (between corners) / h at the centre of every quad,
 * sorted into r[nquads]. */
static void quad_ratios(const sq_quad_mesh *m, const sq_size_field *f, double far, double *r)
{
    int Q = m->order;
    static const int CI[4] = {0, 1, 1, 0}, CJ[4] = {0, 0, 1, 1};
    for (int q = 0; q < m->nquads; q++) {
        const int *conn = &m->conn[(size_t)q * (size_t)((Q + 1) * (Q + 1))];
        double c[4][2], longest = 0.0, mid[2] = {0.0, 0.0};
        for (int k = 0; k < 4; k++)
            for (int d = 0; d < 2; d++) {
                c[k][d] = m->xy[2 * conn[sq_quad_node(Q, CI[k] * Q, CJ[k] * Q)] + d];
                mid[d] += 0.25 * c[k][d];
            }
        for (int k = 0; k < 4; k++)
            longest = fmax(longest, hypot(c[(k + 1) % 4][0] - c[k][0], c[(k + 1) % 4][1] - c[k][1]));
        r[q] = longest / sq_size_field_eval(f, mid, far);
    }
    qsort(r, (size_t)m->nquads, sizeof(double), cmp_double);
}

sq_status sq_size_report_compute(const sq_quad_mesh *m, const sq_size_field *f, double far,
                                 sq_size_report *out, sq_error *err)
{
    memset(out, 0, sizeof *out);
    int *used = calloc((size_t)m->ntags + 1, sizeof(int)),
        *scratch = malloc(sizeof(int) * ((size_t)m->nbnd + 1));
    double *r = malloc(sizeof(double) * ((size_t)m->nquads + 1));
    out->edge = malloc(sizeof(sq_edge_sizes) * ((size_t)m->ntags + 1));
    if (!used || !scratch || !r || !out->edge) {
        free(used);
        free(scratch);
        free(r);
        sq_size_report_free(out);
        return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    }
    for (int b = 0; b < m->nbnd; b++)
        if (m->bnd_tag[b] >= 0 && m->bnd_tag[b] < m->ntags) used[m->bnd_tag[b]] = 1;
    for (int t = 0; t < m->ntags; t++)
        if (used[t]) edge_sizes(m, f, far, t, scratch, &out->edge[out->nedges++]);
    if (m->nquads > 0) {
        quad_ratios(m, f, far, r);
        out->quad_ratio_min = r[0];
        out->quad_ratio_median = r[m->nquads / 2];
        out->quad_ratio_max = r[m->nquads - 1];
    }
    free(used);
    free(scratch);
    free(r);
    return SQ_OK;
}
