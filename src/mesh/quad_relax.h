/* semquad — global relaxation of a quad mesh's vertices towards an
 * orthogonal (conformal up to a stretch) map.
 *
 * The vertices minimize the discrete Winslow energy of the map from the
 * mesh's parameter space (every quad a unit square) to the plane, the sum
 * over quad corners of |J|_F^2 / det J with J = [e1 e2] the corner's edges
 * (the Dirichlet energy of the inverse map, Winslow 1966; infinite at a
 * corner that is not convex), with the vertices on the face boundary free
 * to slide along their CAD curve.  Among maps of a patch onto
 * itself with its corners fixed, the minimizer is a conformal map followed
 * by an affine stretch (the patch's conformal modulus against its chord
 * counts), so grid lines cross at right angles away from the corners and
 * meet the boundary orthogonally — the natural boundary condition of the
 * sliding vertices.  Projected Newton: each step solves with the sum of
 * the corners' Hessians made positive semi-definite (closed form), the
 * boundary vertices moving along their tangent (one sparse SPD system:
 * conjugate gradients preconditioned by an earlier step's CHOLMOD
 * factorization, factored anew when they do not converge in a few
 * iterations), then projects them back onto the curve; a compass search
 * on the worst quads follows.
 *
 * The caller fixes what must not move (singular points, face corners,
 * boundary-layer vertices); a boundary vertex slides only when both of its
 * boundary sides lie on one CAD edge.  A step that would make a quad
 * non-convex at a corner is shortened until none does, so a valid mesh
 * stays valid.
 *
 * With the user's sizes (sizes non-NULL) a grid graded by them (transfinite,
 * its sides' nodes equidistributing the integral of 1/h) keeps its
 * grading.  Each corner's energy is then a shape + size measure of
 * Knupp's target-matrix paradigm (Knupp 2012, Eng. Comput. 28:419):
 * with T = J W^-1, |T|_F^2 / det T + SIZE_WEIGHT (tau + 1 / tau), tau =
 * det T, the shape term plus a size term in the spirit of TMOP's shape +
 * size metrics (Dobrev et al. 2019, SIAM J. Sci. Comput. 41:B50).  The
 * target W = c diag(l1, l2) is a rectangle with the quad's mean side
 * lengths at the start in the corner's two directions, shrunk by
 * c = min(1, h / max(l1, l2)) where the size h at the quad's centre is
 * smaller (a refinement the sides' grading did not reach): minimal for a
 * right-angled corner of that aspect ratio and area.  The shape term is
 * the Winslow energy of the corner's edges scaled to (s e1, e2 / s),
 * s^2 = l2 / l1, and the size term depends on det J alone, so the
 * derivatives follow by the chain rule, the size term's Hessian made
 * semi-definite on its own.  Why not W = h(x) I: the shape term is
 * invariant under scaling, so with that target it is Winslow's energy,
 * whose minimizer undoes the grading; and absolute areas h^2 do not add
 * up to the face where a sheet's count is raised across coarse regions.
 * Weighting Winslow's corners by h (variable diffusion) keeps less of the
 * grading, as docs/sizes.md measures. */
#ifndef SQ_QUAD_RELAX_H
#define SQ_QUAD_RELAX_H

#include "cad.h"
#include "size_field.h"
#include "sq_progress.h"
#include "sq_status.h"

typedef struct {
    int nv, nq;
    double *xy;          /* 2*nv, updated in place */
    const int *quad;     /* 4*nq corner vertices, counter-clockwise */
    const int *side_tag; /* 4*nq: CAD edge under side k (vertex k to k+1), or -1 */
    const int *fixed;    /* nv: 1 = does not move */
    /* give up as soon as the curve under a boundary side crosses the line
     * of its quad's opposite side where it did not at the start (the
     * relaxation folded a curved quad): folded = 1 and xy where the
     * relaxation stopped */
    int stop_on_fold;
    int folded;
    sq_progress progress; /* "relax": Newton steps of the most allowed (default silent) */
    /* the user's size field (NULL: none, Winslow's energy) and the far
     * size it is read with: the target-matrix energy below */
    const sq_size_field *sizes;
    double far;
} sq_relax_mesh;

/* What one relaxation prepares (unknowns, the Hessian's pattern, its
 * analysis and last factorization) for the next relaxation of the same
 * mesh, opaque. */
typedef struct sq_relax_work sq_relax_work;

/* Relax m.  work: NULL, or where the work is kept between relaxations of
 * one mesh (*work NULL at first; made, reused while the mesh is the same
 * and no vertex fixed at first is free, else made anew); the caller frees
 * it with sq_relax_work_free. */
sq_status sq_quad_relax(const cad_face *face, sq_relax_mesh *m, sq_relax_work **work,
                        sq_error *err);
/* Untangle m, a mesh with folded (non-convex) corners, which
 * sq_quad_relax cannot start from: the relaxation's energy with each
 * corner's area D replaced by a positive stand-in chi(D, eps), minimized
 * for decreasing eps until every corner is convex (Garanzha et al. 2021);
 * the same vertices move, the same way, as in sq_quad_relax (work as
 * there).  m->folded = 1 when corners are still not convex after its
 * rounds (xy where it stopped). */
sq_status sq_quad_untangle(const cad_face *face, sq_relax_mesh *m, sq_relax_work **work,
                           sq_error *err);
void sq_relax_work_free(sq_relax_work **work); /* NULL-safe, NULLs *work */
/* What the last relaxation with this work did: its Newton iterations (at
 * most 60, a retry with a fresh factorization included) and its compass search's
 * evaluations of the quads around one vertex, so that a test can bound the
 * relaxation's work on a mesh, which no time measurement on a shared
 * machine does. */
void sq_relax_work_stats(const sq_relax_work *work, int *newton_steps, long *polls);

#endif
