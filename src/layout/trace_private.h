/* semquad — tracing internals shared by trace*.c (not a public contract). */
#ifndef SQ_TRACE_PRIVATE_H
#define SQ_TRACE_PRIVATE_H

#include "trace.h"

typedef struct {
    const sq_cross_field *field;
    const cad_face *face;
    const sq_face_info *info;
    int nsing;
    const sq_singularity *sing;
    sq_trace_options opt;
    double scale;      /* diagonal of the face's bounding box */
    double max_length; /* resolved length bound */
    int nedges;
    long steps;
    /* obstacles for sq_trace_continue: separatrices of this set other than
     * obst_skip end a line that crosses them (NULL: none) */
    const sq_separatrix_set *obst;
    int obst_skip;
} sq_tracer;

/* One line being advanced (Marcon 2019 §3.3): its points, the unwrapped
 * direction at the front and the Adams–Bashforth history. */
typedef struct {
    double *xy;
    int npts, cap;
    double alpha;      /* direction at the front, unwrapped (branch continuity) */
    double f[4][2];    /* directions at the last points, newest first */
    double tau[4];     /* their parameter values */
    int nh;            /* history length (the AB order used next, capped at 4) */
    double h;          /* last step */
    double ht;         /* target step at the front (step_rel * element size) */
    double length;
    int elem;          /* element hint of the front */
    int start_sing;    /* singular point it started from, or -1 */
    int start_vertex;  /* face vertex it started from, or -1 */
    int active;
    sq_sep_end start, end;
    double start_angle, end_angle;
    double start_xy[2];
    double bb[4];      /* bounding box of xy (xmin, ymin, xmax, ymax; may
                          exceed it after a cut), for cheap meeting rejects */
} sq_walker;

sq_status sq_tracer_init(sq_tracer *tr, const sq_cross_field *field, const cad_face *face,
                         const sq_face_info *info, int nsing, const sq_singularity *sing,
                         const sq_trace_options *opt, sq_error *err);

/* Start a walker at p0 in direction alpha with first step h0. */
sq_status sq_walker_init(sq_tracer *tr, sq_walker *w, const double p0[2], double alpha, double h0,
                         sq_error *err);
void sq_walker_free(sq_walker *w);

/* One AB step; on a stop, w->active = 0 and w->end is set. */
sq_status sq_walker_step(sq_tracer *tr, sq_walker *w, sq_error *err);

/* Target step (step_rel * element size) at element elem. */
double sq_tracer_step_at(const sq_tracer *tr, int elem);

/* The field's direction at x, robust to point-location misses: the hint,
 * then a fresh search, then tiny offsets (1e-10 and 1e-8 of len).  Returns
 * 0, or 1 if x is outside. */
int sq_trace_eval(const sq_cross_field *field, const double x[2], double len, int *elem,
                  double *theta);

/* Append a point (amortized growth). */
sq_status sq_walker_push(sq_walker *w, const double p[2], sq_error *err);

/* Algorithm 1 start directions at singular point j (alpha[valence], in
 * [0, 2π)) and at face vertex k taking n quads (alpha[n - 1], increasing
 * from the outgoing edge); *h0 the radius used, also the first step. */
sq_status sq_trace_singular_starts(const sq_tracer *tr, int j, double *alpha, double *h0,
                                   sq_error *err);
sq_status sq_trace_corner_starts(const sq_tracer *tr, int k, int n, double *alpha, double *h0,
                                 sq_error *err);

#endif
