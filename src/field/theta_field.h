/* semquad — the θ field of an imposed singularity pattern (Jezdimirović
 * 2021 eq. 15, docs/conventions.md "θ field"): ∇θ = n × ∇H, i.e.
 * θ_x = −H_y, θ_y = H_x, θ fixed at one boundary point to the tangent
 * angle there.
 *
 * design:
 *  1. with H = H_s + H_r (h_field.h), θ = θ_s + θ_r where
 *     θ_s = Σ_j (c_j / 2π) arg_L(x − X_j) is the harmonic conjugate of H_s
 *     in closed form, arg_L the branch of the angle that is continuous on
 *     the face minus the branch cut L (branches chosen element by element
 *     across uncut edges from a seed element);
 *  2. H_r is harmonic in the face, so θ_r has no period around interior
 *     points, only around the holes: walking counter-clockwise round hole
 *     h it grows by Φ_h, minus the flux of H_r out of the face through
 *     the hole (h_field.h loop_flux).  θ_r = θ_r' + Σ_h (Φ_h / 2π)
 *     arg_L(x − p_h), p_h a point well inside hole h, the arg terms in
 *     closed form like θ_s;
 *  3. θ_r' is single-valued: least squares min ‖∇θ_r' − (n × ∇H_r −
 *     Σ_h (Φ_h / 2π) ∇arg(x − p_h))‖² in H's CG space on the uncut mesh,
 *     whose normal equation is the pure-Neumann problem −Δθ_r' = 0 with
 *     ∂θ_r'/∂ν = (n × ∇H_r)·ν − Σ_h (Φ_h / 2π) ∂arg(x − p_h)/∂ν: H's
 *     stiffness matrix, solved with H's factor (no matrix or factor of its
 *     own); the data balance (n × ∇H_r is divergence-free, arg harmonic in
 *     the face);
 *  4. a constant so that θ equals the tangent angle at the midpoint of one
 *     boundary element edge on the first edge of the outer loop.
 * The jumps of θ across L are those of the arg terms (θ_r' is continuous),
 * measured at the midpoints of the cut edges. */
#ifndef SQ_THETA_FIELD_H
#define SQ_THETA_FIELD_H

#include "branch_cut.h"
#include "h_field.h"

typedef struct {
    const sem_tri_mesh *mesh; /* H's mesh, borrowed */
    const sq_h_field *h;      /* borrowed */
    sq_branch_cut cut;
    int narg;                 /* arg terms: the singular points, then one per hole */
    double *axy;              /* 2*narg: their centres X_j, p_h */
    double *acoef;            /* narg, in axy's block: c_j / 2π, Φ_h / 2π */
    double *aref;             /* narg*ntris: arg_L(centroid − centre) */
    sem_field *tr;            /* θ_r' on mesh */
    sem_field_evaluator *ev;  /* on tr */
    double theta0;            /* the constant of step 4 */
    double anchor[2];         /* the boundary point of step 4 */
    long ndofs;               /* θ_r''s unknowns: H's */
} sq_theta_field;

/* loops: sq_mesh_vertex_loops of mesh; sing[h->npoints]: mesh vertex of
 * each singular point; loc: locator of mesh.  Solves with H's solver
 * (h->solver), which the caller frees after. */
sq_status sq_theta_field_solve(const cad_face *face, const sem_tri_mesh *mesh,
                               const sem_locator *loc, const sq_h_field *h, const int *loops,
                               int nloops, const int *sing, sq_theta_field *out, sq_error *err);
void sq_theta_field_free(sq_theta_field *t); /* frees, zeroes the struct */

/* θ (returned) and ∇θ (grad[2], may be NULL) at (r, s) of element e, on
 * the branch continuous in the face minus L. */
double sq_theta_field_eval_ref(const sq_theta_field *t, int e, double r, double s, double grad[2]);

/* Jump of θ around mesh vertex v (a singular point): the growth of θ
 * walking once counter-clockwise around v inside the face minus L, i.e.
 * the sum over the edges of L at v of θ on the side reached last minus θ
 * on the side left first, at the edges' midpoints (DESIGN.md: (π/2)(4 − V)).
 * 0 if no edge of L meets v. */
double sq_theta_jump_around_vertex(const sq_theta_field *t, int v);

/* The same around boundary loop `loop` (a hole): edges of L with one end
 * on the loop.  loops: as given to the solve. */
double sq_theta_jump_around_loop(const sq_theta_field *t, const int *loops, int loop);

#endif
