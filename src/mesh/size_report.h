/* semquad — how closely a finished quad mesh follows the user's size
 * field (docs/sizes.md, "The report"): per CAD edge, the target size h
 * along it and the achieved lengths of the quad sides on it, and the
 * quads' sizes against h at their centres; and what its boundary layers
 * achieved against those asked: per wall, the heights of the cells in
 * each column of quads leaving it. */
#ifndef SQ_SIZE_REPORT_H
#define SQ_SIZE_REPORT_H

#include "cad.h"
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

typedef struct {
    int edge;                                     /* the wall (CAD edge) */
    int columns;                                  /* its quad sides: one column each */
    double first_min, first_median, first_max;    /* first cells' heights */
    double ratio_min, ratio_max;                  /* a layer's height over the one before */
    int layers;                                   /* cells inside the asked thickness: least */
    double thickness_min, thickness_max;          /* height of the top of those cells */
} sq_bl_edge_report;

typedef struct {
    double first, ratio, thickness; /* asked: first height, ratio, first (r^n - 1) / (r - 1) */
    int layers;
    int nedges;
    sq_bl_edge_report *edge; /* nedges, in the order asked */
} sq_bl_report;

/* The layers of mesh m on face's CAD edges edges[n], asked as first
 * height `first`, growth ratio and `layers` cells.  A column runs from a
 * quad on the wall through the quads across its opposite sides; a cell's
 * height is the rise of its far side's mean distance from the wall over
 * its near side's.  A cell is inside the asked thickness T while its top
 * is below T plus half the last layer's height. */
sq_status sq_bl_report_compute(const sq_quad_mesh *m, const cad_face *face, const int *edges,
                               int n, double first, double ratio, int layers, sq_bl_report *out,
                               sq_error *err);
void sq_bl_report_free(sq_bl_report *r); /* NULL-safe; zeroes *r */

#endif
