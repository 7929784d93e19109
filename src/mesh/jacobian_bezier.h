/* semquad — proven bounds of det J of a curved quad, from its Bézier
 * (Bernstein) coefficients (Johnen, Remacle & Geuzaine 2013, "Geometrical
 * validity of curvilinear finite elements", J. Comput. Phys. 233).
 *
 * The element map of an order-Q quad is x(u, v) = sum_ij x_ij l_i(u) l_j(v)
 * on [0,1]^2 (quad_mesh.h).  x_u has degree Q-1 in u and Q in v, y_v degree
 * Q in u and Q-1 in v (and x_v, y_u the other way round), so
 *
 *   det J = x_u y_v - x_v y_u  lies in P_{2Q-1}(u) ⊗ P_{2Q-1}(v):
 *
 * (2Q)^2 Bernstein coefficients c_kl.  They are formed exactly from the
 * Bernstein coefficients of x and y (derivative and product rules of the
 * Bernstein basis, Johnen 2013 §3), not sampled.  Since the Bernstein
 * functions are non-negative and sum to one, min_kl c_kl <= det J <=
 * max_kl c_kl on the element (Johnen 2013, eq. (9)); the four corner
 * coefficients are values of det J.  Where the bounds are not sharp the
 * patch is cut in four by de Casteljau's algorithm (Johnen 2013 §4): the
 * sub-patches' coefficients converge to det J quadratically in their size.
 *
 * Refinement (the sub-patch with the least lower bound first, then the one
 * with the largest upper bound) stops when
 *   - the sign of the minimum is decided: the lower bound exceeds the
 *     round-off bound of the coefficients (the quad is proven valid) or a
 *     value of det J is below it (proven invalid, to round-off), and
 *   - both bounds are within SQ_JAC_TOL * max|det J sampled| (or twice the
 *     round-off bound, if larger) of the extreme sampled values,
 * or when a sub-patch of depth SQ_JAC_MAX_DEPTH would be cut, or after
 * SQ_JAC_MAX_SPLITS cuts (`capped`: the bounds hold but may not be sharp). */
#ifndef SQ_JACOBIAN_BEZIER_H
#define SQ_JACOBIAN_BEZIER_H

#include "quad_mesh.h"

/* Relative sharpness of the bounds: with it, the ratio bound min/max below
 * is within 2 SQ_JAC_TOL / (1 - SQ_JAC_TOL) of the true ratio (a 1e-6
 * resolution of a quality measure that is compared with floors of 1e-2 and
 * more; Gmsh's AnalyseMeshQuality stops at 1e-3). */
#define SQ_JAC_TOL 1e-6
/* A sub-patch of depth d has side 2^-d: at depth 12 the gap between its
 * coefficients and det J has shrunk by about 4^-12 = 6e-8 from the first
 * (Johnen 2013 §4, quadratic convergence), below what SQ_JAC_TOL asks for
 * any element whose det J does not vanish to high order. */
#define SQ_JAC_MAX_DEPTH 12
/* Cuts per element at most (each cut replaces one sub-patch by four). */
#define SQ_JAC_MAX_SPLITS 1000

/* Bounds of det J of one quad, in the map of [0,1]^2 (quad_mesh.h). */
typedef struct {
    double min_lo; /* proven: det J >= min_lo everywhere on the quad */
    double min_up; /* the least value of det J found (det J at (u_min, v_min)) */
    double max_lo; /* the largest value of det J found */
    double max_up; /* proven: det J <= max_up everywhere */
    double u_min, v_min;
    double roundoff; /* bound of the round-off of every coefficient (absolute) */
    int splits;      /* de Casteljau cuts made */
    int capped;      /* 1 if a cap stopped the refinement before the tolerance */
} sq_jac_bounds;

/* The Jacobian ratio of the bounds (NekMesh's scaled Jacobian, Gmsh's
 * minJ/maxJ): min_lo / max(max_up, -min_lo), a proven lower bound of
 * min det J / max |det J|; in [-1, 1], > 0 iff the quad is proven valid. */
double sq_jac_ratio(const sq_jac_bounds *b);

/* 1 if the quad is proven valid: min_lo exceeds the round-off bound. */
int sq_jac_valid(const sq_jac_bounds *b);

/* Tables and work space for quads of one order and node placement. */
typedef struct sq_jac_bezier sq_jac_bezier;

sq_status sq_jac_bezier_create(int order, sq_node_kind nodes, sq_jac_bezier **out, sq_error *err);
void sq_jac_bezier_free(sq_jac_bezier **jb); /* NULL-safe, NULLs *jb */

/* The bounds of det J of the quad whose nodes (Q+1)^2, in lattice order,
 * are xy[2 * node[k]], xy[2 * node[k] + 1] (k = j (Q+1) + i). */
sq_status sq_jac_bezier_bounds(sq_jac_bezier *jb, const double *xy, const int *node,
                               sq_jac_bounds *b, sq_error *err);

/* The Bernstein coefficients of det J of that quad, (2Q)^2 values,
 * c[l * 2Q + k] for b_k(u) b_l(v) of degree 2Q-1; returns a bound of
 * their round-off (sq_jac_bounds.roundoff). */
double sq_jac_bezier_coefficients(const sq_jac_bezier *jb, const double *xy, const int *node,
                                  double *c);

#endif
