/* semquad sem/ — sparse SPD systems with CHOLMOD (Davis, SuiteSparse):
 * lower-triangle triplets (stype -1), summed into a compressed matrix,
 * analysed (fill-reducing ordering) and factored once, then solved for as
 * many right-hand sides as needed.  The cholmod_common lives in the object:
 * no global state, and CHOLMOD is told not to print. */
#include "sparse.h"

#include <cholmod.h>
#include <stdlib.h>
#include <string.h>

struct sem_sparse {
    long n;
    cholmod_common cc;
    int cc_started;
    cholmod_triplet *T; /* assembly; freed once factored */
    cholmod_factor *L;
    cholmod_dense *b;   /* n x 1 right-hand side workspace */
};

sq_status sem_sparse_create(long n, long nnz_hint, sem_sparse **out, sq_error *err)
{
    if (!out) return SQ_FAIL(err, SQ_ERR_USAGE, "sparse_create: NULL output");
    *out = NULL;
    if (n <= 0) return SQ_FAIL(err, SQ_ERR_USAGE, "sparse_create: size %ld <= 0", n);
    if (nnz_hint < n) nnz_hint = n;
    sem_sparse *a = calloc(1, sizeof *a);
    if (!a) return SQ_FAIL(err, SQ_ERR_INTERNAL, "sparse_create: out of memory");
    a->n = n;
    cholmod_l_start(&a->cc);
    a->cc_started = 1;
    a->cc.print = 0;            /* a library never prints */
    a->cc.error_handler = NULL; /* errors are read from cc.status */
    /* LL' also in the simplicial case: an LDL' factorization would accept
     * an indefinite matrix, which must be reported instead. */
    a->cc.final_ll = 1;
    a->T = cholmod_l_allocate_triplet((size_t)n, (size_t)n, (size_t)nnz_hint, -1, CHOLMOD_REAL,
                                      &a->cc);
    if (!a->T) {
        sem_sparse_free(&a);
        return SQ_FAIL(err, SQ_ERR_INTERNAL, "sparse_create: out of memory (%ld entries)", nnz_hint);
    }
    *out = a;
    return SQ_OK;
}

void sem_sparse_free(sem_sparse **pa)
{
    if (!pa || !*pa) return;
    sem_sparse *a = *pa;
    if (a->cc_started) {
        if (a->T) cholmod_l_free_triplet(&a->T, &a->cc);
        if (a->L) cholmod_l_free_factor(&a->L, &a->cc);
        if (a->b) cholmod_l_free_dense(&a->b, &a->cc);
        cholmod_l_finish(&a->cc);
    }
    free(a);
    *pa = NULL;
}

sq_status sem_sparse_add(sem_sparse *a, long i, long j, double v, sq_error *err)
{
    if (!a || !a->T) return SQ_FAIL(err, SQ_ERR_USAGE, "sparse_add: matrix already factored");
    if (i < 0 || j < 0 || i >= a->n || j >= a->n)
        return SQ_FAIL(err, SQ_ERR_USAGE, "sparse_add: entry (%ld,%ld) outside %ld x %ld", i, j,
                       a->n, a->n);
    if (i < j) return SQ_OK; /* upper triangle: the symmetric twin is added */
    cholmod_triplet *T = a->T;
    if (T->nnz == T->nzmax) {
        if (!cholmod_l_reallocate_triplet(2 * T->nzmax, T, &a->cc))
            return SQ_FAIL(err, SQ_ERR_INTERNAL, "sparse_add: out of memory (%zu entries)",
                           2 * T->nzmax);
    }
    const size_t k = T->nnz++;
    ((SuiteSparse_long *)T->i)[k] = i;
    ((SuiteSparse_long *)T->j)[k] = j;
    ((double *)T->x)[k] = v;
    return SQ_OK;
}

sq_status sem_sparse_factor(sem_sparse *a, sq_error *err)
{
    if (!a || !a->T) return SQ_FAIL(err, SQ_ERR_USAGE, "sparse_factor: nothing to factor");
    /* Duplicates are summed by the conversion. */
    cholmod_sparse *A = cholmod_l_triplet_to_sparse(a->T, a->T->nnz, &a->cc);
    if (!A) return SQ_FAIL(err, SQ_ERR_INTERNAL, "sparse_factor: out of memory (compressing)");
    cholmod_l_free_triplet(&a->T, &a->cc);
    a->L = cholmod_l_analyze(A, &a->cc);
    if (!a->L) {
        cholmod_l_free_sparse(&A, &a->cc);
        return SQ_FAIL(err, SQ_ERR_INTERNAL, "sparse_factor: analysis failed (CHOLMOD status %d)",
                       a->cc.status);
    }
    const int ok = cholmod_l_factorize(A, a->L, &a->cc);
    cholmod_l_free_sparse(&A, &a->cc);
    if (!ok || a->cc.status == CHOLMOD_NOT_POSDEF || a->L->minor < a->L->n) {
        const long minor = (long)a->L->minor;
        const int status = a->cc.status;
        cholmod_l_free_factor(&a->L, &a->cc);
        if (status == CHOLMOD_NOT_POSDEF || minor < a->n)
            return SQ_FAIL(err, SQ_ERR_INTERNAL,
                           "sparse_factor: matrix (n = %ld) is not positive definite (pivot %ld)",
                           a->n, minor);
        return SQ_FAIL(err, SQ_ERR_INTERNAL, "sparse_factor: factorization failed (CHOLMOD status %d)",
                       status);
    }
    a->b = cholmod_l_allocate_dense((size_t)a->n, 1, (size_t)a->n, CHOLMOD_REAL, &a->cc);
    if (!a->b) {
        cholmod_l_free_factor(&a->L, &a->cc);
        return SQ_FAIL(err, SQ_ERR_INTERNAL, "sparse_factor: out of memory");
    }
    return SQ_OK;
}

sq_status sem_sparse_solve(sem_sparse *a, const double *b, double *x, sq_error *err)
{
    if (!a || !a->L) return SQ_FAIL(err, SQ_ERR_USAGE, "sparse_solve: matrix not factored");
    memcpy(a->b->x, b, sizeof(double) * (size_t)a->n);
    cholmod_dense *X = cholmod_l_solve(CHOLMOD_A, a->L, a->b, &a->cc);
    if (!X) return SQ_FAIL(err, SQ_ERR_INTERNAL, "sparse_solve: CHOLMOD solve failed (status %d)",
                           a->cc.status);
    memcpy(x, X->x, sizeof(double) * (size_t)a->n);
    cholmod_l_free_dense(&X, &a->cc);
    return SQ_OK;
}

long sem_sparse_size(const sem_sparse *a) { return a ? a->n : 0; }
