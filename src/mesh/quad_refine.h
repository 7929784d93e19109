/* semquad — a finished quad mesh refined for a convergence study
 * (docs/convergence-families.md): every quad split n × n (n = 2: one level
 * of a nested family; n = 1: the same quads) into children of order Q.
 *
 * A child is the sub-map of its parent's own high-order map x(u, v) over
 * [a/n, (a+1)/n] × [b/n, (b+1)/n], so the parent's vertices stay vertices
 * (copied: the family is nested to the bit) and a child of a curved quad
 * keeps its curve.  Sides on a CAD edge are placed on the curve instead,
 * at the same arc-length fractions (GLL or equispaced) the mesher uses
 * (quad_raise.c), so a level's new boundary vertex is the curve point
 * midway in arc length; the difference between the curve and the parent's
 * map along such a side is blended into the child's interior by
 * transfinite interpolation (Gordon & Hall 1973), linear along the
 * children's sides inside the parent, so a new interior vertex is exactly
 * x(1/2, 1/2) or x(1/2, 0) of its parent.  Nothing is relaxed again:
 * that would move the parent's vertices.  Inside the face a child's det J
 * is the parent's, scaled by 1/n², at the same points, so children of a
 * quad proven valid are valid; children along a curve differ from the
 * sub-map by the curve's interpolation error, O(h^(Q+1)), and the caller
 * proves them again (sq_quad_mesh_quality). */
#ifndef SQ_QUAD_REFINE_H
#define SQ_QUAD_REFINE_H

#include "cad.h"
#include "quad_mesh.h"

/* Children per side n (1 or 2), order Q (1..10; nodes placed as m's);
 * the parents shared among `threads` threads (0: the processors online),
 * each writing its own nodes: the same mesh for every count. */
sq_status sq_quad_mesh_refine(const cad_face *face, const sq_quad_mesh *m, int n, int order,
                              int threads, sq_quad_mesh **out, sq_error *err);

#endif
