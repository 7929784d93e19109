/* semquad — the H field of an imposed singularity pattern (Jezdimirović
 * 2021 eq. 12, sign conventions of docs/conventions.md "H field"):
 *
 *   ΔH = Σ_j c_j δ(X_j) in Ω,  c_j = (π/2)(4 − V_j),
 *   ∂H/∂ν = κ_g on the smooth parts of ∂Ω (ν outward, κ_g > 0 turning left),
 *   ∂H/∂ν = s_i δ at corner i, s_i = n_i π/2 − α_i,   zero mean.
 *
 * design:
 *  1. split H = H_s + H_r with the singular part known in closed form,
 *     H_s = Σ_j (c_j / 2π) ln |x − X_j|  (Δ ln r = 2π δ), so that the
 *     Dirac sources are exact and the spectral solve only sees the smooth
 *     regular part;
 *  2. H_r: pure-Neumann CG solve of sem/poisson.h (−ΔH_r = 0) with
 *     ∂H_r/∂ν = κ_g − ∂H_s/∂ν on every boundary edge and the corner point
 *     fluxes s_i; Gauss–Bonnet makes the data balance exactly for a valid
 *     pattern: on each boundary element edge of a B-spline (any edge of
 *     varying curvature) where the rule does not resolve κ_g, the data is
 *     the exact turning of the tangent over the edge spread evenly, so that
 *     ∮ κ_g is the exact total turning; the quadrature residue of the data
 *     (reported) is removed as a constant shift of the flux;
 *  3. a constant makes the mean of H zero: H_r's is (the solver's), H_s's
 *     is integrated on the boundary by the divergence theorem. */
#ifndef SQ_H_FIELD_H
#define SQ_H_FIELD_H

#include "cad.h"
#include "face_info.h"
#include "field_eval.h"
#include "poisson.h"

typedef struct {
    const sem_tri_mesh *mesh; /* borrowed */
    int order;
    long ndofs;
    int npoints;
    double *xy; /* 2*npoints: singular points X_j */
    double *c;  /* npoints: c_j = (π/2)(4 − V_j) */
    int ncorner_sources; /* corners with s_i != 0 */
    sem_poisson *solver;     /* H_r's, whose element matrices θ's solver takes (NULL after) */
    sem_field *hr;           /* regular part H_r (zero mean) */
    sem_field_evaluator *ev; /* on hr */
    double shift;            /* constant in H (zero mean) */
    /* per boundary loop: the outward flux of H_r through it, ∮ ∂H_r/∂ν + Σ s_i
     * over the loop's edges and corners, of the data H_r was solved with
     * (the residue's shift included); minus it is the period of H_r's
     * conjugate around a hole (theta_field.h) */
    double *loop_flux;
    double imbalance;        /* ∮ g + Σ s_i before correction (quadrature residue) */
    double data_size;        /* ∮ |g| + Σ |s_i| */
} sq_h_field;

/* loc: locator of mesh (borrowed, kept by the evaluator).  quads[nvertices
 * of info]: n_i per face vertex. */
sq_status sq_h_field_solve(const cad_face *face, const sq_face_info *info,
                           const sem_tri_mesh *mesh, const sem_locator *loc, int order,
                           int npoints, const double *xy, const int *valence, const int *quads,
                           sq_h_field *out, sq_error *err);
void sq_h_field_free(sq_h_field *h); /* frees, zeroes the struct */

/* The singular part at x: value, gradient grad[2] (may be NULL). */
double sq_h_singular(const sq_h_field *h, const double x[2], double grad[2]);

/* H (returned), ∇H (grad[2], may be NULL) and the physical point x[2]
 * (may be NULL) at (r, s) of element e. */
double sq_h_field_eval_ref(const sq_h_field *h, int e, double r, double s, double x[2],
                           double grad[2]);

#endif
