/* semquad sem/ — global sparse symmetric positive definite systems,
 * factored by CHOLMOD and solved for many right-hand sides.
 *
 * Three ways to assemble the lower triangle:
 *  - triplets (sem_sparse_create): any entries, duplicates summed;
 *  - a pattern known in advance (sem_sparse_create_pattern): values are
 *    summed in place in the compressed matrix, CHOLMOD's default ordering;
 *  - a block pattern known in advance (sem_sparse_create_blocks): values
 *    are summed in place in the compressed matrix, and the fill-reducing
 *    ordering is computed on the (much smaller) graph of blocks.
 * After a factorization, sem_sparse_reset starts a new assembly of a
 * matrix with the same pattern; its factorization reuses the symbolic
 * analysis (Newton iterations, repeated solves). */
#ifndef SEM_SPARSE_H
#define SEM_SPARSE_H

#include "sq_status.h"

typedef struct sem_sparse sem_sparse; /* opaque */

/* An n x n symmetric matrix to be assembled from about nnz_hint entries. */
sq_status sem_sparse_create(long n, long nnz_hint, sem_sparse **out, sq_error *err);

/* An (nblocks bs) x (nblocks bs) symmetric matrix made of bs x bs blocks:
 * block column j holds, in its lower triangle, the block rows
 * brow[bptr[j]] < ... < brow[bptr[j+1]-1], the first being j itself (the
 * diagonal block).  All values start at zero. */
sq_status sem_sparse_create_blocks(long nblocks, int bs, const long *bptr, const long *brow,
                                   sem_sparse **out, sq_error *err);
/* An n x n symmetric matrix of the lower-triangular pattern: column j
 * holds the rows row[ptr[j]] < ... < row[ptr[j+1]-1], the first being j
 * (the diagonal).  All values start at zero; they are summed in place
 * (sem_sparse_add, or sem_sparse_values with sem_sparse_entry), with no
 * triplets to compress, and factored with the analysis CHOLMOD makes of a
 * compressed triplet matrix of this pattern (the same ordering, the same
 * factor as sem_sparse_create's when the same entries are added in the
 * same order). */
sq_status sem_sparse_create_pattern(long n, const long *ptr, const long *row, sem_sparse **out,
                                    sq_error *err);
void sem_sparse_free(sem_sparse **a); /* NULL-safe, NULLs *a */

/* Add v to A(i,j), duplicates summed.  A is symmetric and stored by its
 * lower triangle: entries with i < j are ignored, so a whole symmetric
 * element matrix can be scattered as it is.  With a block pattern, (i,j)
 * must lie in one of its blocks. */
sq_status sem_sparse_add(sem_sparse *a, long i, long j, double v, sq_error *err);

/* Add the block M (bs x bs, row-major: M[r bs + c] goes to A(bi bs + r,
 * bj bs + c)) of a matrix made with sem_sparse_create_blocks.  For bi = bj
 * only M's lower triangle is read; for bi != bj the block stands for
 * itself and its transpose, whichever of the two is stored. */
sq_status sem_sparse_add_block(sem_sparse *a, long bi, long bj, const double *M, sq_error *err);

/* Where the entries of block (bi, bj) of a matrix made with
 * sem_sparse_create_blocks are summed: pos[r bs + c] is the index, in the
 * array of sem_sparse_values, of the entry that M[r bs + c] of
 * sem_sparse_add_block goes to, or -1 where that entry is not read (the
 * upper triangle of a diagonal block).  For assembling the same pattern
 * many times (Newton iterations): the positions looked up once, then
 * values[pos[k]] += M[k]. */
sq_status sem_sparse_block_positions(const sem_sparse *a, long bi, long bj, long *pos,
                                     sq_error *err);

/* The index, in the array of sem_sparse_values, of entry (i, j), i >= j,
 * of a matrix made with sem_sparse_create_pattern; -1 if it is not in the
 * pattern. */
long sem_sparse_entry(const sem_sparse *a, long i, long j);

/* The values of a block or pattern matrix being assembled, NULL otherwise. */
double *sem_sparse_values(sem_sparse *a);

/* Compress and factor (Cholesky, CHOLMOD's supernodal/simplicial choice).
 * SQ_ERR_INTERNAL if A is not positive definite. */
sq_status sem_sparse_factor(sem_sparse *a, sq_error *err);

/* After a sem_sparse_factor: forget the values and start assembling anew
 * (also in the middle of an assembly); the next sem_sparse_factor keeps
 * the symbolic analysis if the pattern (after duplicates are summed) has
 * not changed. */
sq_status sem_sparse_reset(sem_sparse *a, sq_error *err);

/* Solve A x = b (b and x of length n, may alias) with the factorization. */
sq_status sem_sparse_solve(sem_sparse *a, const double *b, double *x, sq_error *err);

/* Solve A x = b, A the values of a block matrix assembled since
 * sem_sparse_reset (all of them added), by conjugate gradients
 * preconditioned with the last factorization (of an earlier matrix of the
 * same pattern): cheaper than factoring anew while A has changed little
 * (Newton iterations).  Stops once |b - A x| <= rtol |b| (*converged = 1)
 * or after maxit iterations (*converged = 0, x the last iterate);
 * *iters the iterations done.  The assembly stays open: sem_sparse_factor
 * may follow. */
sq_status sem_sparse_pcg(sem_sparse *a, const double *b, double *x, double rtol, int maxit,
                         int *iters, int *converged, sq_error *err);

long sem_sparse_size(const sem_sparse *a);

#endif
