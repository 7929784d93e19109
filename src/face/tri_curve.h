/* semquad — raise a straight triangulation of a face to order P with its
 * boundary edges on the CAD curves. */
#ifndef SQ_TRI_CURVE_H
#define SQ_TRI_CURVE_H

#include "cad.h"
#include "tri_geom.h"
#include "tri_mesh.h"

/* Fill mesh->gxy (mesh->order = P) from the corner vertices: interior edges
 * straight, an element edge k with btag >= 0 follows CAD edge btag from arc
 * length bs[6e+2k] to bs[6e+2k+1], its nodes at the Gauss–Lobatto–Legendre
 * arc-length positions, and the displacement blended into the element.
 * On return jac_min[e] holds each element's scaled Jacobian and *area the
 * mesh's area (the elements' det J integrated), from one sampling by
 * sampler, which the caller made from the Lagrange basis of order P (once
 * for all its meshes of that order). */
sq_status sq_tri_curve(const cad_face *face, sem_tri_mesh *mesh, const double *bs,
                       const sem_tri_geom_sampler *sampler, double *jac_min, double *area,
                       sq_error *err);

#endif
