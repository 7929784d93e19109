/* Shared by the layout tests (t510–t514) that build separatrices by hand. */
#ifndef SQ_T51X_LAYOUT_H
#define SQ_T51X_LAYOUT_H

#include "cad.h"
#include "separatrix.h"

#include <math.h>
#include <stddef.h>
#include <stdlib.h>

/* The boundary end nearest to p: CAD edge and arc length; the foot point
 * itself in snapped (may be NULL). */
static inline sq_sep_end nearest_foot(const cad_face *f, const double p[2], double snapped[2])
{
    int best = -1;
    double bs = 0, bd = HUGE_VAL, q[2] = {p[0], p[1]};
    for (int e = 0; e < cad_face_num_edges(f); e++) {
        double s, d, x[2];
        cad_face_edge_project(f, e, p, &s, x, &d, NULL);
        if (d < bd) bd = d, best = e, bs = s, q[0] = x[0], q[1] = x[1];
    }
    if (snapped) snapped[0] = q[0], snapped[1] = q[1]; /* may be p itself */
    return (sq_sep_end){SQ_END_BOUNDARY, best, bs};
}

/* A straight separatrix of n points from a to b with the given ends. */
static inline void straight(sq_separatrix *s, const double a[2], const double b[2], int n,
                            sq_sep_end e0, sq_sep_end e1)
{
    s->npts = n;
    s->xy = malloc(2 * (size_t)n * sizeof *s->xy);
    for (int j = 0; j < n; j++) {
        double t = (double)j / (n - 1);
        s->xy[2 * j] = a[0] + t * (b[0] - a[0]);
        s->xy[2 * j + 1] = a[1] + t * (b[1] - a[1]);
    }
    s->start = e0;
    s->end = e1;
    s->merged = 0;
}

#endif
