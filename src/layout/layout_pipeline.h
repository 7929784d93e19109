/* semquad — from a face to a valid quad layout: guiding field and its
 * critical points (field_analysis.h), separatrices (trace.h), layout graph
 * and corrections (layout.h).  What `semquad layout` and `semquad mesh`
 * run. */
#ifndef SQ_LAYOUT_PIPELINE_H
#define SQ_LAYOUT_PIPELINE_H

#include "field_analysis.h"
#include "htheta_field.h"
#include "layout.h"

#include <stddef.h>

typedef struct {
    sq_field_options field;   /* the guiding field (also for `natural`) */
    sq_trace_options trace;
    /* NULL: trace the guiding field (Marcon 2019); "natural" or the path of
     * a pattern file: trace the H/θ cross field of that pattern
     * (Jezdimirović 2021) */
    const char *singularities;
    sq_htheta_options htheta;
    /* 0, or a lower order of H and θ tried first: the full htheta.order
     * only where that one gives no valid layout */
    int htheta_first_order;
    int allow_misaligned;     /* trace even if a hole breaks holonomy */
} sq_layout_options;

/* What the field stage was, for reports. */
typedef struct {
    const char *kind;  /* "guiding" or "H-theta" */
    sem_method method;
    int order, triangles;
    long dofs;
    double t_triangulate, t_solve, t_critical;
} sq_field_summary;

void sq_layout_options_default(sq_layout_options *opt);
/* The defaults with the fields of `semquad mesh`: cheaper settings that
 * give the examples the same meshes (layout_pipeline.c). */
void sq_layout_options_for_mesh(sq_layout_options *opt);

/* How the default route chose its pattern (Jezdimirović 2021 §4: the
 * two-step approach when the guiding field's points are poor). */
typedef struct {
    int gauss_bonnet_min; /* |4χ − Σ_c (2 − n_c)|, n_c the quads at vertex c: the
                             least number of interior irregular vertices */
    int cancelled_pairs;  /* valence-3/valence-5 pairs of the natural points left out
                             of the pattern traced (their indices sum to 0) */
    int unresolved;       /* critical points whose index no circle gave (dropped) */
    int two_step;         /* the default route left the guiding field's own points */
    int pattern;          /* traced from: 0 the natural points (guiding field, or
                             H/θ of the split ones), 1 near pairs cancelled,
                             2 the Gauss–Bonnet-minimal pattern (every pair cancelled),
                             3 a pattern file */
    char reason[200];     /* why the two-step route was taken */
    char kept_why[600];   /* why the pattern traced keeps pairs over the minimum (room
                             for a whole sq_error message: no UTF-8 cut) */
} sq_layout_report;

/* A valence-3/valence-5 pair of the pattern traced over the Gauss–Bonnet
 * minimum (the nearest first, as the minimal pattern would cancel them). */
typedef struct {
    double x3, y3, x5, y5; /* the valence-3 and the valence-5 point */
    double distance;
} sq_kept_pair;

typedef struct {
    sq_field_analysis analysis; /* guiding field (zeroed for a pattern file) */
    int ndegenerate;            /* degenerate critical points split (degenerate_split.h):
                                   the layout is then traced on the H/θ field */
    sq_htheta htheta;           /* H/θ path only */
    const sq_face_info *info;   /* the face, from whichever stage ran */
    sq_field_summary field;
    int nsing;
    sq_singularity *sing;   /* the pattern traced from */
    int *vertex_quads;      /* per face vertex: quads there (n) */
    sq_separatrix_set traced; /* as traced, before corrections */
    sq_trace_stats trace_stats;
    sq_layout layout;
    int valid;              /* layout passed sq_layout_check */
    double t_trace, t_layout; /* seconds */
    sq_layout_report report;
    int nkept;
    sq_kept_pair *kept;     /* (nsing − gauss_bonnet_min)/2 pairs, report.kept_why */
} sq_layout_result;

/* On SQ_ERR_LAYOUT the result still holds the last layout (for pictures
 * and reports); free it in every case.  SQ_ERR_PATTERN for a refused
 * pattern or (without allow_misaligned) a hole that breaks holonomy. */
sq_status sq_layout_run(const cad_face *face, const sq_layout_options *opt, sq_layout_result *out,
                        sq_error *err);
void sq_layout_result_free(sq_layout_result *r); /* frees, zeroes the struct */

/* A line for the user when the pattern is not the guiding field's own
 * (a degenerate field twisted, degenerate critical points split, the
 * two-step route and why); returns 0 (buf untouched) if none. */
int sq_layout_note(const sq_layout_result *r, char *buf, size_t n);

#endif
