/* semquad sem/ — quadrature on the reference triangle (collapsed
 * Gauss–Jacobi: Gauss–Legendre in one direction, Gauss–Jacobi(1,0) in the
 * other, Karniadakis & Sherwin §4.1). */
#ifndef SEM_TRI_QUAD_H
#define SEM_TRI_QUAD_H

#include "sq_status.h"

typedef struct {
    int npts;
    double *rs; /* 2*npts */
    double *w;  /* npts, sum = 1/2 (area of T) */
} sem_tri_quad;

/* A rule exact for polynomials of total degree <= degree on T. */
sq_status sem_tri_quad_create(int degree, sem_tri_quad **out, sq_error *err);
void sem_tri_quad_free(sem_tri_quad **q);

#endif
