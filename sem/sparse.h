/* semquad sem/ — global sparse symmetric positive definite systems:
 * triplet assembly, CHOLMOD factorization once, solves for many right-hand
 * sides. */
#ifndef SEM_SPARSE_H
#define SEM_SPARSE_H

#include "sq_status.h"

typedef struct sem_sparse sem_sparse; /* opaque */

/* An n x n symmetric matrix to be assembled from about nnz_hint entries. */
sq_status sem_sparse_create(long n, long nnz_hint, sem_sparse **out, sq_error *err);
void sem_sparse_free(sem_sparse **a); /* NULL-safe, NULLs *a */

/* Add v to A(i,j), duplicates summed.  A is symmetric and stored by its
 * lower triangle: entries with i < j are ignored, so a whole symmetric
 * element matrix can be scattered as it is. */
sq_status sem_sparse_add(sem_sparse *a, long i, long j, double v, sq_error *err);

/* Compress and factor (Cholesky, CHOLMOD's supernodal/simplicial choice).
 * SQ_ERR_INTERNAL if A is not positive definite. */
sq_status sem_sparse_factor(sem_sparse *a, sq_error *err);

/* Solve A x = b (b and x of length n, may alias) with the factorization. */
sq_status sem_sparse_solve(sem_sparse *a, const double *b, double *x, sq_error *err);

long sem_sparse_size(const sem_sparse *a);

#endif
