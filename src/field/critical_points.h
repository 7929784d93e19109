/* semquad — critical points of the guiding field and their valences
 * (Marcon 2019 §2.3 and §3.2; docs/conventions.md "Index and valence").
 *
 * design:
 *  1. flag every element where u and v both change sign on a lattice of
 *     order max(2P, 8) of its own polynomial (vertices and edges included);
 *  2. in each flagged element, Newton on (u, v) = 0 in reference coordinates
 *     with the polynomial's exact derivatives, from the lattice point of
 *     least |(u, v)| and from the centroid; an iterate that leaves the
 *     element is mapped to the physical plane and continued in the element
 *     that contains it (NekMesh drops such roots), so each root is found in
 *     the element that holds it;
 *  3. merge roots found more than once (shared edges and vertices) or
 *     closer than 1e-2 of the element size (round-off splits a zero of
 *     multiplicity m into m roots, and Newton converges only linearly to
 *     it: an iterate at the round-off floor of (u, v) is accepted, Newton
 *     stopping there once a step no longer halves |(u, v)|); roots
 *     closer to each other than 0.05 x their distance to the boundary are
 *     one point at their mean (the discretization error splits a multiple
 *     zero too: the disc's z^4 into four roots 0.01 apart at P = 4), its
 *     index taken on a circle enclosing them;
 *  4. index = winding number of (u, v) on a small circle around the point
 *     (unwrapped atan2, sampled until every step turns less than π/2);
 *     valence V = 4 - index (eq. 13, Table 1), indices ±2 included; a
 *     circle that cannot be read is shrunk and enlarged (inside the face,
 *     around no other point); a zero no circle resolves is flagged
 *     `unresolved` with index 0 (a 3/5 pair on top of each other);
 *  5. a zero of |index| > 1 (e.g. the disc's (u, v) ≈ z^4) is centred and
 *     its local expansion fitted from the Fourier modes of (u, v) on that
 *     circle (see coef), for splitting (degenerate_split.h). */
#ifndef SQ_CRITICAL_POINTS_H
#define SQ_CRITICAL_POINTS_H

#include "guiding_field.h"

typedef struct {
    double x, y;
    int elem;
    double r, s;          /* reference coordinates in elem */
    int index;            /* Poincaré index of (u, v) */
    int valence;          /* 4 - index */
    double dist_boundary; /* distance to the face's boundary */
    int near_boundary;    /* closer to the boundary than its element resolves
                             (h / (2 P^2)): index 0, starts no separatrix */
    double residual;      /* |(u, v)| at the point */
    int unresolved;       /* no index circle could be read: index 0 (see above) */
    /* |index| > 1 (a degenerate zero): c of u + iv ≈ c (z − z0)^index, or
     * c conj(z − z0)^|index| for a negative index, fitted on the index
     * circle, which also moves (x, y) to the zero's centre; else 0 */
    double coef[2];
} sq_critical_point;

sq_status sq_critical_points_find(const sq_guiding_field *g, const cad_face *face,
                                  sq_critical_point **pts, int *npts, sq_error *err);

/* Newton on (u, v) = 0 on element e's own polynomial from (r, s) (step 2
 * above; iterates may leave the element): a step below 1e-14, else the
 * least |(u, v)| once it is below 1e-13 and a step fails to halve it (no
 * gain but round-off: near a zero of multiplicity m a step multiplies
 * |(u, v)| by ((m-1)/m)^m <= 1/e).  *evals (may be NULL) is increased by
 * the evaluations of (u, v).  Returns 0 on convergence. */
int sq_field_newton_local(const sem_field *f, int e, double *r, double *s, int *evals);

/* Winding number of (u, v) on the circle of radius rho around c, sampled
 * adaptively; SQ_ERR_INTERNAL if part of the circle leaves the domain. */
sq_status sq_field_winding(const sq_guiding_field *g, const double c[2], double rho, int *index,
                           sq_error *err);

/* Distance from p to the boundary of the face (all its edges). */
sq_status sq_face_boundary_distance(const cad_face *face, const double p[2], double *dist,
                                    sq_error *err);

#endif
