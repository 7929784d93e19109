#include "size_report.h"

#include "quad_edges.h"

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

/* ---- boundary layers ---- */

void sq_bl_report_free(sq_bl_report *r)
{
    if (!r) return;
    free(r->edge);
    memset(r, 0, sizeof *r);
}

/* Mean distance from wall `edge` of the corners of side k of quad q. */
static sq_status side_distance(const sq_quad_mesh *m, const cad_face *face, int edge, int q, int k,
                               double *d, sq_error *err)
{
    *d = 0.0;
    for (int c = 0; c < 2; c++) {
        double dist;
        SQ_TRY(cad_face_edge_project(face, edge, &m->xy[2 * sq_quad_corner_node(m, q, (k + c) % 4)],
                                     NULL, NULL, &dist, err));
        *d += 0.5 * dist;
    }
    return SQ_OK;
}

/* The cells of the column from boundary side b (on wall `edge`), up to
 * `cells` of them or the boundary: the tops' distances top[] from the
 * wall; their count. */
static sq_status column(const sq_quad_mesh *m, const sq_quad_edges *e, const int *other,
                        const cad_face *face, int edge, int b, int cells, double *top, int *count,
                        sq_error *err)
{
    int q = m->bnd_quad[b], k = m->bnd_side[b];
    *count = 0;
    while (*count < cells) {
        int far = (k + 2) % 4, s = 4 * q + far, ed = e->side_edge[s];
        SQ_TRY(side_distance(m, face, edge, q, far, &top[(*count)++], err));
        int next = e->owner[ed] == s ? other[ed] : e->owner[ed];
        if (e->tag[ed] >= 0 || next < 0) break;
        q = next / 4, k = next % 4;
    }
    return SQ_OK;
}

/* One wall's figures into r (asked: first height, ratio, layers n, the
 * tolerance tol on the thickness t). */
static sq_status wall_report(const sq_quad_mesh *m, const sq_quad_edges *e, const int *other,
                             const cad_face *face, int n, double t, double tol, double *top,
                             double *first, sq_bl_edge_report *r, sq_error *err)
{
    r->first_min = r->ratio_min = r->thickness_min = HUGE_VAL;
    r->first_max = r->ratio_max = r->thickness_max = -HUGE_VAL;
    r->layers = n + 1;
    for (int b = 0; b < m->nbnd; b++) {
        if (m->bnd_tag[b] != r->edge) continue;
        int count, in = 0;
        SQ_TRY(column(m, e, other, face, r->edge, b, n + 1, top, &count, err));
        first[r->columns++] = top[0];
        for (int j = 1; j < count && j < n; j++) {
            double ratio = (top[j] - top[j - 1]) / (j > 1 ? top[j - 1] - top[j - 2] : top[0]);
            r->ratio_min = fmin(r->ratio_min, ratio);
            r->ratio_max = fmax(r->ratio_max, ratio);
        }
        while (in < count && top[in] <= t + tol) in++;
        r->layers = in < r->layers ? in : r->layers;
        if (in > 0) {
            r->thickness_min = fmin(r->thickness_min, top[in - 1]);
            r->thickness_max = fmax(r->thickness_max, top[in - 1]);
        }
    }
    if (r->ratio_min == HUGE_VAL) r->ratio_min = r->ratio_max = 0.0; /* one layer */
    if (r->thickness_min == HUGE_VAL) r->thickness_min = r->thickness_max = 0.0;
    if (r->columns == 0) {
        r->first_min = r->first_max = 0.0, r->layers = 0;
        return SQ_OK;
    }
    qsort(first, (size_t)r->columns, sizeof *first, cmp_double);
    r->first_min = first[0];
    r->first_max = first[r->columns - 1];
    r->first_median = first[r->columns / 2];
    return SQ_OK;
}

sq_status sq_bl_report_compute(const sq_quad_mesh *m, const cad_face *face, const int *edges,
                               int n, double first, double ratio, int layers, sq_bl_report *out,
                               sq_error *err)
{
    memset(out, 0, sizeof *out);
    out->first = first, out->ratio = ratio, out->layers = layers;
    out->thickness = ratio == 1.0 ? first * layers
                                  : first * (pow(ratio, layers) - 1.0) / (ratio - 1.0);
    sq_quad_edges e = {0};
    SQ_TRY(sq_quad_edges_build(m, 1, &e, err));
    int *other = malloc(sizeof(int) * ((size_t)e.nedges + 1));
    double *top = malloc(sizeof(double) * ((size_t)layers + 2));
    double *firsts = malloc(sizeof(double) * ((size_t)m->nbnd + 1));
    out->edge = calloc((size_t)n + 1, sizeof *out->edge);
    sq_status st = other && top && firsts && out->edge
                       ? SQ_OK
                       : SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    /* each edge's second side, -1 on the boundary */
    for (int k = 0; st == SQ_OK && k < e.nedges; k++) other[k] = -1;
    for (int s = 0; st == SQ_OK && s < 4 * m->nquads; s++)
        if (e.owner[e.side_edge[s]] != s) other[e.side_edge[s]] = s;
    /* half the last layer: the next cell is r times it at least */
    double tol = 0.5 * first * pow(ratio, layers - 1);
    for (int w = 0; st == SQ_OK && w < n; w++) {
        out->edge[w].edge = edges[w];
        st = wall_report(m, &e, other, face, layers, out->thickness, tol, top, firsts,
                         &out->edge[w], err);
    }
    out->nedges = n;
    free(other), free(top), free(firsts);
    sq_quad_edges_free(&e);
    if (st != SQ_OK) sq_bl_report_free(out);
    return st;
}
