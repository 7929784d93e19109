/* semquad sem/ — nodal Lagrange basis on the sem_tri_nodes() set.
 *
 * l_n(node_m) = delta_nm; built from the Dubiner basis by inverting its
 * Vandermonde matrix with LAPACK. */
#ifndef SEM_TRI_LAGRANGE_H
#define SEM_TRI_LAGRANGE_H

#include "sq_status.h"

typedef struct sem_tri_lagrange sem_tri_lagrange; /* opaque */

sq_status sem_tri_lagrange_create(int P, sem_tri_lagrange **out, sq_error *err);
void sem_tri_lagrange_free(sem_tri_lagrange **lag);
int sem_tri_lagrange_order(const sem_tri_lagrange *lag);
int sem_tri_lagrange_num_nodes(const sem_tri_lagrange *lag);
const double *sem_tri_lagrange_nodes(const sem_tri_lagrange *lag); /* rs, lattice order */

/* Values and reference derivatives of every Lagrange function at (r,s);
 * arrays of length num_nodes, any may be NULL. */
void sem_tri_lagrange_eval(const sem_tri_lagrange *lag, double r, double s, double *l,
                           double *dr, double *ds);

#endif
