#include "degenerate_split.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static int is_singular(const sq_critical_point *p) { return p->valence != 4 && !p->near_boundary; }

/* Direction from p to the nearest point of the face's boundary; 0 (the x
 * axis) if the boundary is a circle about p (sampled distances within 1e-6
 * of each other: every direction is nearest). */
static sq_status nearest_boundary_angle(const cad_face *face, const double p[2], double *angle,
                                        sq_error *err)
{
    double best = HUGE_VAL, lo = HUGE_VAL, hi = 0.0;
    for (int e = 0; e < cad_face_num_edges(face); e++) {
        double foot[2], d, L = cad_face_edge_length(face, e);
        SQ_TRY(cad_face_edge_project(face, e, p, NULL, foot, &d, err));
        if (d < best) best = d, *angle = atan2(foot[1] - p[1], foot[0] - p[0]);
        for (int k = 0; k < 64; k++) {
            double x[2];
            SQ_TRY(cad_face_edge_eval(face, e, L * k / 64.0, x, NULL, NULL, err));
            lo = fmin(lo, hypot(x[0] - p[0], x[1] - p[1]));
            hi = fmax(hi, hypot(x[0] - p[0], x[1] - p[1]));
        }
    }
    if (hi - lo <= 1e-6 * lo) *angle = 0.0;
    return SQ_OK;
}

sq_status sq_elementary_points(const cad_face *face, const sq_field_analysis *a,
                               sq_singularity **pts, int *npts, int *ndegenerate, sq_error *err)
{
    int n = 0, cap = 0, ndeg = 0;
    for (int k = 0; k < a->npoints; k++)
        if (is_singular(&a->points[k]))
            cap += abs(a->points[k].index) > 1 ? abs(a->points[k].index) : 1;
    sq_singularity *s = malloc(sizeof *s * ((size_t)cap + 1));
    if (!s) return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    for (int k = 0; k < a->npoints; k++) {
        const sq_critical_point *p = &a->points[k];
        if (!is_singular(p)) continue;
        const int m = p->index, nm = abs(m);
        if (nm <= 1) {
            s[n++] = (sq_singularity){p->x, p->y, p->valence, SQ_ORIGIN_CRITICAL};
            continue;
        }
        double reach = p->dist_boundary;
        for (int o = 0; o < a->npoints; o++)
            if (o != k && is_singular(&a->points[o]))
                reach = fmin(reach, hypot(a->points[o].x - p->x, a->points[o].y - p->y));
        const double r = SQ_SPLIT_FRACTION * reach;
        double phi = 0.0;
        if (m == 4) {
            const double c[2] = {p->x, p->y};
            sq_status st = nearest_boundary_angle(face, c, &phi, err);
            if (st != SQ_OK) {
                free(s);
                return st;
            }
        } else {
            phi = atan2(p->coef[1], p->coef[0]) / (4 - m);
        }
        for (int j = 0; j < nm; j++) {
            const double t = phi + 2.0 * M_PI * j / nm;
            s[n++] = (sq_singularity){p->x + r * cos(t), p->y + r * sin(t), m > 0 ? 3 : 5,
                                      SQ_ORIGIN_SPLIT};
        }
        ndeg++;
    }
    *pts = s;
    *npts = n;
    if (ndegenerate) *ndegenerate = ndeg;
    return SQ_OK;
}

/* The nearest valence-3/valence-5 pair closer than near among the points
 * not used (used NULL: all); 0 if none. */
static int nearest_pair(const sq_singularity *s, int n, const char *used, double near, int *bi,
                        int *bj)
{
    double bd = near;
    *bi = *bj = -1;
    for (int i = 0; i < n; i++)
        for (int j = 0; j < n; j++)
            if (s[i].valence == 3 && s[j].valence == 5 && !(used && (used[i] || used[j]))) {
                const double d = hypot(s[i].x - s[j].x, s[i].y - s[j].y);
                if (d < bd) bd = d, *bi = i, *bj = j;
            }
    return *bi >= 0;
}

int sq_cancel_pairs(sq_singularity *s, int *n, double near)
{
    int count = 0, bi, bj;
    while (nearest_pair(s, *n, NULL, near, &bi, &bj)) {
        /* remove both, keeping the order of the others */
        const int lo = bi < bj ? bi : bj, hi = bi < bj ? bj : bi;
        memmove(&s[hi], &s[hi + 1], sizeof *s * (size_t)(*n - hi - 1));
        memmove(&s[lo], &s[lo + 1], sizeof *s * (size_t)(*n - 2 - lo));
        *n -= 2;
        count++;
    }
    return count;
}

sq_status sq_list_pairs(const sq_singularity *s, int n, int max, int (*pairs)[2], int *npairs,
                        sq_error *err)
{
    char *used = calloc((size_t)n + 1, 1);
    if (!used) return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    int bi, bj;
    *npairs = 0;
    while (*npairs < max && nearest_pair(s, n, used, HUGE_VAL, &bi, &bj)) {
        used[bi] = used[bj] = 1;
        pairs[*npairs][0] = bi;
        pairs[*npairs][1] = bj;
        ++*npairs;
    }
    free(used);
    return SQ_OK;
}
