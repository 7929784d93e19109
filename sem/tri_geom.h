/* semquad sem/ — geometric factors of a curved isoparametric element. */
#ifndef SEM_TRI_GEOM_H
#define SEM_TRI_GEOM_H

#include "sq_status.h"
#include "tri_lagrange.h"

/* Map of element with geometry nodes gxy[2*nodes] (lattice order) at (r,s):
 * x[2] (may be NULL) and Jacobian matrix J = [[x_r, x_s],[y_r, y_s]] as
 * jac[4] = {x_r, x_s, y_r, y_s} (may be NULL).  Returns det J. */
double sem_tri_geom_map(const sem_tri_lagrange *lag, const double *gxy, double r, double s,
                        double x[2], double jac[4]);

/* Scaled Jacobian of the element: min det J / max det J over the element's
 * own nodes and the points of a rule of degree 2*order (1 for a straight
 * triangle; <= 0 means invalid; if det J <= 0 everywhere, e.g. a clockwise
 * element, the result is min/|max| <= -1, or 0 when det J = 0 throughout).
 * NaN if the nodes are not finite or memory ran out (test !(sj > 0)). */
double sem_tri_geom_scaled_jacobian(const sem_tri_lagrange *lag, const double *gxy);

/* The same with the basis derivatives at the sample points tabulated once
 * (for many elements of one order): create from lag, then call per element
 * (read-only, thread-safe, no allocation). */
typedef struct sem_tri_geom_sampler sem_tri_geom_sampler; /* opaque */
sq_status sem_tri_geom_sampler_create(const sem_tri_lagrange *lag, sem_tri_geom_sampler **out,
                                      sq_error *err);
void sem_tri_geom_sampler_free(sem_tri_geom_sampler **s); /* NULL-safe, NULLs *s */
double sem_tri_geom_sampler_scaled_jacobian(const sem_tri_geom_sampler *s, const double *gxy);
/* The scaled Jacobian and, into *area, the signed area of the element (det
 * J integrated by the sampler's rule of degree 2*order: exact for
 * straight-sided elements, spectral on curved), from one sampling of det J
 * (the curved triangulation checks every element and sums the face's area). */
double sem_tri_geom_sampler_measure(const sem_tri_geom_sampler *s, const double *gxy,
                                    double *area);

#endif
