/* semquad — the θ field of an imposed singularity pattern (Jezdimirović
 * 2021 eq. 15, docs/conventions.md "θ field"): ∇θ = n × ∇H, i.e.
 * θ_x = −H_y, θ_y = H_x, in least squares on the face cut along the branch
 * cut L, θ fixed at one boundary point to the tangent angle there.
 *
 * design:
 *  1. with H = H_s + H_r (h_field.h), θ = θ_s + θ_r where
 *     θ_s = Σ_j (c_j / 2π) arg_L(x − X_j) is the harmonic conjugate of H_s
 *     in closed form, arg_L the branch of the angle that is continuous on
 *     the face minus L (branches chosen element by element across uncut
 *     edges from a seed element);
 *  2. θ_r: least squares min ‖∇θ_r − n × ∇H_r‖² with a CG space of the mesh
 *     cut open along L (sem/tri_mesh_cut.h).  Its normal equation is the
 *     pure-Neumann problem −Δθ_r = 0, ∂θ_r/∂ν = (n × ∇H_r)·ν on every edge
 *     of the cut mesh's boundary (both sides of L included), whose data
 *     balance exactly (n × ∇H_r is divergence-free);
 *  3. a constant so that θ equals the tangent angle at the midpoint of one
 *     boundary element edge on the first edge of the outer loop.
 * The jumps of θ across L (θ_r's jumps come out of the solve) are measured
 * at the midpoints of the cut edges. */
#ifndef SQ_THETA_FIELD_H
#define SQ_THETA_FIELD_H

#include "branch_cut.h"
#include "h_field.h"

typedef struct {
    const sem_tri_mesh *mesh; /* original mesh, borrowed */
    const sq_h_field *h;      /* borrowed */
    sq_branch_cut cut;
    sem_tri_mesh *cut_mesh;   /* same elements, vertices split along L */
    sem_field *tr;            /* θ_r on cut_mesh */
    sem_field_evaluator *ev;  /* on tr */
    double *aref;             /* npoints*ntris: arg_L(centroid − X_j) */
    double theta0;            /* the constant of step 3 */
    double anchor[2];         /* the boundary point of step 3 */
    long ndofs;
    sem_poisson_work work;    /* of θ_r's solver */
} sq_theta_field;

/* loops: sq_mesh_vertex_loops of mesh; sing[h->npoints]: mesh vertex of
 * each singular point; loc: locator of mesh.  H's solver (h->solver) is
 * taken over by θ's and freed: NULL after. */
sq_status sq_theta_field_solve(const cad_face *face, const sem_tri_mesh *mesh,
                               const sem_locator *loc, sq_h_field *h, const int *loops,
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
