/* semquad sem/ — one-dimensional Gauss rules and Jacobi polynomials. */
#ifndef SEM_GAUSS_H
#define SEM_GAUSS_H

#include "sq_status.h"

#define SEM_MAX_ORDER 16

/* Gauss–Jacobi rule with n points on [-1,1] for the weight
 * (1-x)^alpha (1+x)^beta: exact for polynomials of degree 2n-1.
 * x[n], w[n] ascending. */
sq_status sem_gauss_jacobi(int n, double alpha, double beta, double *x, double *w, sq_error *err);

/* Gauss–Lobatto–Legendre points (n >= 2, including -1 and 1) and weights on
 * [-1,1], ascending: exact for degree 2n-3. */
sq_status sem_gauss_lobatto(int n, double *x, double *w, sq_error *err);

/* Jacobi polynomial P_n^{(alpha,beta)}(x) and its derivative (dp may be NULL). */
double sem_jacobi(int n, double alpha, double beta, double x, double *dp);

#endif
