/* semquad — from a face to a valid quad layout: guiding field and its
 * critical points (field_analysis.h), separatrices (trace.h), layout graph
 * and corrections (layout.h).  What `semquad layout` and `semquad mesh`
 * run. */
#ifndef SQ_LAYOUT_PIPELINE_H
#define SQ_LAYOUT_PIPELINE_H

#include "field_analysis.h"
#include "layout.h"

typedef struct {
    sq_field_options field;
    sq_trace_options trace;
} sq_layout_options;

void sq_layout_options_default(sq_layout_options *opt);

typedef struct {
    sq_field_analysis analysis;
    int nsing;
    sq_singularity *sing;   /* the pattern traced from */
    int *vertex_quads;      /* per face vertex */
    sq_separatrix_set traced; /* as traced, before corrections */
    sq_trace_stats trace_stats;
    sq_layout layout;
    int valid;              /* layout passed sq_layout_check */
    double t_trace, t_layout; /* seconds */
} sq_layout_result;

/* On SQ_ERR_LAYOUT the result still holds the last layout (for pictures
 * and reports); free it in every case. */
sq_status sq_layout_run(const cad_face *face, const sq_layout_options *opt, sq_layout_result *out,
                        sq_error *err);
void sq_layout_result_free(sq_layout_result *r); /* frees, zeroes the struct */

#endif
