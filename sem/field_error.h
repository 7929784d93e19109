/* semquad sem/ — errors of a field against an exact solution. */
#ifndef SEM_FIELD_ERROR_H
#define SEM_FIELD_ERROR_H

#include "field.h"
#include "sq_status.h"

/* Exact solution: value *u and gradient grad[2] at x. */
typedef void (*sem_exact_fn)(const double x[2], void *ctx, double *u, double grad[2]);

/* L2 norm of u_h - u (*l2) and H1 seminorm |u_h - u|_1 (*h1, may be NULL)
 * of component comp of f over the (discrete, curved) domain, by a collapsed
 * rule of the given degree on every element (degree <= 0: 2P + 2 order + 4,
 * which resolves the polynomial part exactly and the rational curved
 * factors and smooth exact solutions far below the discretization error). */
sq_status sem_field_error(const sem_field *f, int comp, sem_exact_fn exact, void *ctx, int degree,
                          double *l2, double *h1, sq_error *err);

#endif
