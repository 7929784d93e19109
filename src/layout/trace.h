/* semquad — tracing separatrices through a cross field (Marcon 2019 §2.4,
 * §3.3, Algorithm 1).
 *
 * design:
 *  1. start directions: V at each singular point of valence V, n - 1 into
 *     the interior at each face vertex taking n >= 2 quads; each converged
 *     with Algorithm 1 (bisection on the mismatch between the ray direction
 *     and the cross branch along it), initial guesses 2π/V apart (corners:
 *     the interior angle over n);
 *  2. all separatrices advanced together with 4th-order Adams–Bashforth
 *     (order ramped 1 -> 4 at the start), the branch of the cross nearest to
 *     the previous direction chosen at every evaluation (so jump lines of ψ
 *     are crossed continuously), step tied to the local element size;
 *  3. a separatrix stops on the boundary (the crossing with the CAD curve
 *     found exactly and the end snapped onto it), at a singular point
 *     (capture radius: the end snapped onto it), or on meeting another one
 *     head-on: each front's newest segment within the meeting distance of a
 *     segment of the other line running the opposite way (so fronts with
 *     different steps cannot jump past each other), the other's start ahead,
 *     and the other front likewise near this line, or the other line
 *     already past this one's start (a front passing a singular point or
 *     corner against one of its arms meets that arm).  The meeting distance
 *     is max(merge_distance, SQ_TRACE_PASS_STEPS) steps; each line is then
 *     brought to the other's start (advanced, or cut at its closest approach
 *     if already past) and the two are blended with Marcon's cos^2/sin^2
 *     weights so both start angles are kept and the result has no kink; a
 *     pair that cannot reach each other's start is not merged.
 *     `merge_distance` > SQ_TRACE_PASS_STEPS is aggressive merging (§3.3.1);
 *  4. a separatrix longer than max_length ends SQ_END_OPEN (a limit cycle
 *     for the layout's correction to cut);
 *  5. with identified edges (periodic boundaries, identified_edges.h), a
 *     separatrix that ends on one of them (not at a corner) is continued by
 *     a new one from the image of its end on the partner edge, in the image
 *     of its direction, which starts there (SQ_END_BOUNDARY) and carries the
 *     length so far (the bound of 4 applies to the chain). */
#ifndef SQ_TRACE_H
#define SQ_TRACE_H

#include "cross_field.h"
#include "face_info.h"
#include "identified_edges.h"
#include "separatrix.h"
#include "singularity.h"
#include "sq_progress.h"

/* Two lines that are one separatrix traced from both ends (each front runs
 * back along the other line, or past its start, in the opposite direction)
 * meet within max(merge_distance, SQ_TRACE_PASS_STEPS) steps, even with
 * normal merging (Marcon 2019 §3.3: they would otherwise pass each other).
 * Two singular points joined by one separatrix are such a pair, and their
 * fronts may pass each other by several steps: on nautilus (points 1 and 2)
 * they meet from 3.9 steps on the guiding field and from 4.7 on the H/θ
 * field of the same points (0.036-0.044 apart, steps 0.008-0.011); 6 keeps
 * both a quarter above their threshold, so the two-step pipeline keeps the
 * guiding layout's topology (19 patches; at 4: 19 against 27, t416). */
#define SQ_TRACE_PASS_STEPS 6.0

typedef struct {
    double step_rel;       /* step = step_rel * local element size (default 0.05) */
    double capture_rel;    /* capture radius at singular points, in steps (default 2) */
    double merge_distance; /* in steps: fronts closer than this meet (default 1) */
    double max_length;     /* length bound; <= 0: 4 * perimeter of the face */
    double tol;            /* Algorithm 1 tolerance on the angle (default 1e-9) */
    sq_progress progress;  /* "trace": lines finished of all (default silent) */
    sq_identification periodic; /* identified edges (none: npairs 0): a separatrix
                                   ending on one re-enters through its partner */
} sq_trace_options;

/* Counters filled by sq_trace_separatrices (may be NULL). */
typedef struct {
    int traced;   /* separatrices started */
    int merges;   /* pairs merged (each pair becomes one) */
    long steps;   /* integration steps (field evaluations along the lines) */
} sq_trace_stats;

void sq_trace_options_default(sq_trace_options *opt);

/* vertex_quads[info->nvertices]: quads at each face vertex (n). */
sq_status sq_trace_separatrices(const sq_cross_field *field, const cad_face *face,
                                const sq_face_info *info, const int *vertex_quads, int nsing,
                                const sq_singularity *sing, const sq_trace_options *opt,
                                sq_separatrix_set *out, sq_error *err);

/* Same, with counters (stats may be NULL). */
sq_status sq_trace_separatrices_stats(const sq_cross_field *field, const cad_face *face,
                                      const sq_face_info *info, const int *vertex_quads,
                                      int nsing, const sq_singularity *sing,
                                      const sq_trace_options *opt, sq_separatrix_set *out,
                                      sq_trace_stats *stats, sq_error *err);

/* Marcon 2019 Algorithm 1: from the guess alpha0, the direction alpha of a
 * ray from p0 such that the cross at p0 + c (cos alpha, sin alpha) has a
 * branch along the ray (fixed-point iteration, |Δα| <= tol), each change
 * of the ray scaled by gain (1: the paper's iteration; 4/V at a valence-V
 * point, see trace_start.c). */
sq_status sq_trace_start_direction(const sq_cross_field *field, const double p0[2], double c,
                                   double alpha0, double gain, double tol, double *alpha,
                                   sq_error *err);

/* One streamline from p0 with start direction alpha0 (not refined), with the
 * stopping rules above except meeting (no other lines); sing[] are singular
 * points it may end on (p0 itself is left first).  out->start is
 * SQ_END_OPEN/-1; the caller may set it.  out->xy is allocated. */
sq_status sq_trace_streamline(const sq_cross_field *field, const cad_face *face,
                              const sq_face_info *info, int nsing, const sq_singularity *sing,
                              const sq_trace_options *opt, const double p0[2], double alpha0,
                              sq_separatrix *out, long *steps, sq_error *err);

/* Continue separatrix k of set from its last point along the field (used by
 * layout repairs), with the same stopping rules; other separatrices of the
 * set are obstacles it may end on. */
sq_status sq_trace_continue(const sq_cross_field *field, const cad_face *face,
                            const sq_face_info *info, int nsing, const sq_singularity *sing,
                            const sq_trace_options *opt, sq_separatrix_set *set, int k,
                            sq_error *err);

#endif
