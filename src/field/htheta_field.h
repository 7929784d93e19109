/* semquad — the cross field of an imposed singularity pattern, end to end
 * (Jezdimirović 2021 §4–5): pattern check (Gauss–Bonnet), triangulation
 * with the points as vertices and graded "bicycle-spoke" refinement around
 * them (§4, Fig. 6), H (eq. 12), branch cut (§5.2.1), θ (eq. 15), jumps of
 * θ around the points and holes, boundary alignment on every loop
 * (holonomy, §5.2.3), and the cross field {θ + kπ/2} of size e^H (eq. 16,
 * 21) behind the layout stage's interface (cross_field.h). */
#ifndef SQ_HTHETA_FIELD_H
#define SQ_HTHETA_FIELD_H

#include "cross_field.h"
#include "pattern.h"
#include "theta_field.h"
#include "triangulate.h"

typedef struct {
    int order;          /* P of H and θ (default 8) */
    sq_tri_options tri; /* triangulation (order min(P, 12) unless set) */
    double grading;     /* element size at the singular points and singular
                           corners relative to the triangulation size, growing
                           in proportion to the distance (default 1e-3) */
    double point_grading; /* the same at the imposed points alone (<= 0: grading).
                             H and θ carry the points' log and arg terms in
                             closed form, so their smooth remainders need no
                             refinement there; the singular corners are point
                             sources of H and do */
    double align_tol_deg; /* misalignment above this breaks holonomy (default 0.01) */
} sq_htheta_options;

void sq_htheta_options_default(sq_htheta_options *opt);

typedef struct {
    double x, y;
    int valence;
    sq_origin origin;
    int vertex;      /* mesh vertex */
    double c;        /* (π/2)(4 − V) */
    double jump;     /* measured jump of θ around the point */
} sq_htheta_point;

typedef struct {
    int loop;              /* 0 outer, 1.. holes */
    double jump;           /* measured jump of θ around the loop (holes; 0 for loop 0) */
    double expected_jump;  /* −(∮ κ_g + Σ s_i) over the loop (holes) */
    double turning;        /* turning of the loop's tangent, walked counter-clockwise */
    double misalignment;   /* θ − tangent angle on the loop, mod π/2, in (−π/4, π/4] (rad) */
    double spread;         /* largest deviation from it along the loop (rad) */
    int aligned;           /* |misalignment| <= align_tol */
} sq_htheta_loop;

typedef struct {
    sq_face_info info;
    sq_pattern_balance balance; /* quads per vertex, Gauss–Bonnet sums */
    int npoints;
    sq_htheta_point *points;
    sq_triangulation tri;
    sem_locator *loc;
    int *vloops; /* per mesh vertex: boundary loop or -1 */
    /* per element: its size with the spoke grading at the imposed points
     * undone (what the tracer ties its step, capture and meeting radii to;
     * see sq_htheta_cross_field) */
    double *trace_size;
    sq_h_field h;
    sq_theta_field theta;
    int nloops;
    sq_htheta_loop *loops;
    double align_tol; /* rad */
    double size_scale; /* c of the sizes e^H c (bounded e^H; see sq_htheta_cross_field) */
    double t_triangulate, t_solve;
    /* H's solver, which θ solves with too: one matrix per triangle and
     * one factorization */
    sem_poisson_work work;
} sq_htheta;

/* SQ_ERR_PATTERN for a pattern refused by sq_pattern_check (nothing is
 * solved then).  A loop that is not aligned is reported, not an error:
 * see sq_htheta_check_alignment. */
sq_status sq_htheta_compute(const cad_face *face, const sq_pattern *pattern,
                            const sq_htheta_options *opt, sq_htheta *out, sq_error *err);
void sq_htheta_free(sq_htheta *f); /* frees, zeroes the struct */

/* The holonomy gate of the later stages: SQ_ERR_PATTERN naming the first
 * misaligned loop and its misalignment in degrees, unless allow_misaligned
 * (then SQ_OK). */
sq_status sq_htheta_check_alignment(const sq_htheta *f, int allow_misaligned, sq_error *err);

/* H, ∇H, θ, ∇θ at a physical point (any output may be NULL); *elem hint in
 * (-1: none), element out.  Returns 0, or 1 outside the triangulation. */
int sq_htheta_eval(const sq_htheta *f, const double x[2], int *elem, double *H, double gH[2],
                   double *theta, double gtheta[2]);

/* The cross field {θ + kπ/2} with size e^H (eq. 16, 21), bounded to a
 * factor 4 either way and scaled by size_scale so that the root mean
 * square of its inverse over the face is 1.  Its element
 * sizes are trace_size: the graded spokes resolve H's logarithmic and θ's
 * angular singularity for the solves only; left in, they shrink the
 * tracer's capture radius and meeting distance around exactly the points
 * where separatrices end and meet, 5-40 times below the guiding field's
 * (whose triangulation is not graded at interior points), and the two-step
 * pipeline changes the layout's topology (nautilus: 27 patches against 19).
 * The tracer limits its own step near singular points (trace.h). */
sq_cross_field sq_htheta_cross_field(const sq_htheta *f);

/* Per-patch parametrization gradients (eqs. 18–20): ∇U = e^{−H}(cos θ,
 * sin θ), ∇V = e^{−H}(−sin θ, cos θ) at x; curl[2] (may be NULL) gets
 * curl ∇U and curl ∇V = e^{−H}[cos θ (θ_x + H_y) + sin θ (θ_y − H_x)] and
 * e^{−H}[cos θ (θ_y − H_x) − sin θ (θ_x + H_y)]: zero for an exact
 * harmonic conjugate.  Returns 0, or 1 outside. */
int sq_htheta_param_gradients(const sq_htheta *f, const double x[2], int *elem, double gu[2],
                              double gv[2], double curl[2]);

#endif
