/* semquad — how closely a finished quad mesh follows the user's size
 * field (docs/sizes.md, "The report"): per CAD edge, the target size h
 * along it and the achieved lengths of the quad sides on it, and the
 * quads' sizes against h at their centres. */
#ifndef SQ_SIZE_REPORT_H
#define SQ_SIZE_REPORT_H

#include "quad_mesh.h"
#include "size_field.h"

typedef struct {
    int edge;                       /* CAD edge (boundary tag) */
    int segments;                   /* quad sides on it */
    double target_min, target_max;  /* h at its nodes */
    double achieved_min, achieved_max; /* its quad sides' lengths (node polylines) */
    double ratio_min, ratio_max;    /* per side, achieved / target: the side's integral of ds / h */
    double cells;                   /* the edge's integral of ds / h (ratio's sum over its sides) */
    int patch_sides;                /* layout patches along it: the pieces whose counts were
                                     * rounded each on its own */
} sq_edge_sizes;

typedef struct {
    int nedges;
    sq_edge_sizes *edge;            /* nedges, by CAD edge; edges without a quad side left out */
    /* every quad's longest side (between corners) against h at its
     * corners' mean: the smallest, median and largest ratio */
    double quad_ratio_min, quad_ratio_median, quad_ratio_max;
} sq_size_report;

/* The report of mesh m against field f read with far size `far` (*out
 * filled; the caller frees it with sq_size_report_free). */
sq_status sq_size_report_compute(const sq_quad_mesh *m, const sq_size_field *f, double far,
                                 sq_size_report *out, sq_error *err);
void sq_size_report_free(sq_size_report *r); /* NULL-safe; zeroes *r */

#endif
