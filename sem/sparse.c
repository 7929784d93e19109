/* semquad sem/ — sparse SPD systems with CHOLMOD (Davis, SuiteSparse):
 * the lower triangle (stype -1) assembled from triplets (duplicates summed
 * by the compression) or in place in a known block pattern, analysed
 * (fill-reducing ordering) and factored, then solved for as many
 * right-hand sides as needed.  The cholmod_common lives in the object: no
 * global state, and CHOLMOD is told not to print. */
#include "sparse.h"

#include "lib_lock.h"

#include <cholmod.h>
#include <stdlib.h>
#include <string.h>

typedef SuiteSparse_long sslong;

struct sem_sparse {
    long n;
    cholmod_common cc;
    int cc_started;
    int assembling;     /* values may be added; no factorization to solve with */
    cholmod_triplet *T; /* triplet assembly under way */
    cholmod_sparse *A;  /* block or pattern assembly, or the pattern of the last factorization */
    int pattern;        /* assembled in a pattern given to sem_sparse_create_pattern */
    long nblocks;       /* block pattern (0: triplets or a given pattern) */
    int bs;
    sslong *bptr, *brow; /* block columns: as given to sem_sparse_create_blocks */
    cholmod_factor *L;
    cholmod_dense *b; /* n x 1 right-hand side workspace */
};

static sq_status start(long n, sem_sparse **out, sq_error *err)
{
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
    /* Supernodal only from 100 flops per factor entry (CHOLMOD's default:
     * 40): below, its dense kernels on small supernodes lose to the
     * simplicial code on one BLAS thread — the relaxation's Hessians (55-75:
     * naca0012's mesh stage 0.28 -> 0.18 s), the H/theta fields (63-87), the
     * DG guiding field at P = 4 (57-125) — while the DG field at P = 8
     * (170-375) is twice as fast supernodal. */
    a->cc.supernodal_switch = 100;
    a->assembling = 1;
    *out = a;
    return SQ_OK;
}

sq_status sem_sparse_create(long n, long nnz_hint, sem_sparse **out, sq_error *err)
{
    if (!out) return SQ_FAIL(err, SQ_ERR_USAGE, "sparse_create: NULL output");
    *out = NULL;
    if (n <= 0) return SQ_FAIL(err, SQ_ERR_USAGE, "sparse_create: size %ld <= 0", n);
    if (nnz_hint < n) nnz_hint = n;
    sem_sparse *a = NULL;
    SQ_TRY(start(n, &a, err));
    a->T = cholmod_l_allocate_triplet((size_t)n, (size_t)n, (size_t)nnz_hint, -1, CHOLMOD_REAL,
                                      &a->cc);
    if (!a->T) {
        sem_sparse_free(&a);
        return SQ_FAIL(err, SQ_ERR_INTERNAL, "sparse_create: out of memory (%ld entries)",
                       nnz_hint);
    }
    *out = a;
    return SQ_OK;
}

/* A lower-triangular pattern of n columns (of blocks or of entries):
 * column j's rows ascending from j itself. */
static sq_status check_columns(const char *fn, long n, const long *ptr, const long *row,
                               sq_error *err)
{
    if (ptr[0] != 0) return SQ_FAIL(err, SQ_ERR_USAGE, "%s: pointer of column 0 != 0", fn);
    for (long j = 0; j < n; ++j) {
        if (ptr[j + 1] <= ptr[j] || row[ptr[j]] != j)
            return SQ_FAIL(err, SQ_ERR_USAGE, "%s: column %ld does not start with its diagonal",
                           fn, j);
        for (long p = ptr[j] + 1; p < ptr[j + 1]; ++p)
            if (row[p] <= row[p - 1] || row[p] >= n)
                return SQ_FAIL(err, SQ_ERR_USAGE, "%s: rows of column %ld not ascending in %ld..%ld",
                               fn, j, j, n - 1);
    }
    return SQ_OK;
}

sq_status sem_sparse_create_blocks(long nblocks, int bs, const long *bptr, const long *brow,
                                   sem_sparse **out, sq_error *err)
{
    if (!out) return SQ_FAIL(err, SQ_ERR_USAGE, "sparse_create_blocks: NULL output");
    *out = NULL;
    if (nblocks <= 0 || bs <= 0 || !bptr || !brow || nblocks > 2000000000L / bs)
        return SQ_FAIL(err, SQ_ERR_USAGE, "sparse_create_blocks: %ld blocks of size %d", nblocks,
                       bs);
    SQ_TRY(check_columns("sparse_create_blocks", nblocks, bptr, brow, err));
    const long n = nblocks * bs, nbe = bptr[nblocks];
    const size_t nnz = (size_t)nblocks * bs * (bs + 1) / 2 + (size_t)(nbe - nblocks) * bs * bs;
    sem_sparse *a = NULL;
    SQ_TRY(start(n, &a, err));
    a->nblocks = nblocks;
    a->bs = bs;
    a->bptr = malloc(sizeof(sslong) * (size_t)(nblocks + 1));
    a->brow = malloc(sizeof(sslong) * (size_t)nbe);
    a->A = cholmod_l_allocate_sparse((size_t)n, (size_t)n, nnz, 1, 1, -1, CHOLMOD_REAL, &a->cc);
    if (!a->bptr || !a->brow || !a->A) {
        sem_sparse_free(&a);
        return SQ_FAIL(err, SQ_ERR_INTERNAL, "sparse_create_blocks: out of memory (%zu entries)",
                       nnz);
    }
    for (long j = 0; j <= nblocks; ++j)
        a->bptr[j] = bptr[j];
    for (long p = 0; p < nbe; ++p)
        a->brow[p] = brow[p];
    /* column c of block column j: the diagonal block's rows c.., then the
     * off-diagonal blocks' rows, all ascending */
    sslong *Ap = a->A->p, *Ai = a->A->i;
    size_t k = 0;
    for (long j = 0; j < nblocks; ++j)
        for (int jj = 0; jj < bs; ++jj) {
            Ap[j * bs + jj] = (sslong)k;
            for (int r = jj; r < bs; ++r)
                Ai[k++] = j * bs + r;
            for (long p = bptr[j] + 1; p < bptr[j + 1]; ++p)
                for (int r = 0; r < bs; ++r)
                    Ai[k++] = brow[p] * bs + r;
        }
    Ap[n] = (sslong)k;
    memset(a->A->x, 0, sizeof(double) * nnz);
    *out = a;
    return SQ_OK;
}

sq_status sem_sparse_create_pattern(long n, const long *ptr, const long *row, sem_sparse **out,
                                    sq_error *err)
{
    if (!out) return SQ_FAIL(err, SQ_ERR_USAGE, "sparse_create_pattern: NULL output");
    *out = NULL;
    if (n <= 0 || !ptr || !row)
        return SQ_FAIL(err, SQ_ERR_USAGE, "sparse_create_pattern: size %ld or no pattern", n);
    SQ_TRY(check_columns("sparse_create_pattern", n, ptr, row, err));
    const size_t nnz = (size_t)ptr[n];
    sem_sparse *a = NULL;
    SQ_TRY(start(n, &a, err));
    a->pattern = 1;
    a->A = cholmod_l_allocate_sparse((size_t)n, (size_t)n, nnz, 1, 1, -1, CHOLMOD_REAL, &a->cc);
    if (!a->A) {
        sem_sparse_free(&a);
        return SQ_FAIL(err, SQ_ERR_INTERNAL, "sparse_create_pattern: out of memory (%zu entries)",
                       nnz);
    }
    sslong *Ap = a->A->p, *Ai = a->A->i;
    for (long j = 0; j <= n; ++j)
        Ap[j] = ptr[j];
    for (size_t p = 0; p < nnz; ++p)
        Ai[p] = row[p];
    memset(a->A->x, 0, sizeof(double) * nnz);
    *out = a;
    return SQ_OK;
}

void sem_sparse_free(sem_sparse **pa)
{
    if (!pa || !*pa) return;
    sem_sparse *a = *pa;
    if (a->cc_started) {
        if (a->T) cholmod_l_free_triplet(&a->T, &a->cc);
        if (a->A) cholmod_l_free_sparse(&a->A, &a->cc);
        if (a->L) cholmod_l_free_factor(&a->L, &a->cc);
        if (a->b) cholmod_l_free_dense(&a->b, &a->cc);
        cholmod_l_finish(&a->cc);
    }
    free(a->bptr);
    free(a->brow);
    free(a);
    *pa = NULL;
}

static sq_status not_assembling(const sem_sparse *a, const char *fn, sq_error *err)
{
    if (!a) return SQ_FAIL(err, SQ_ERR_USAGE, "%s: NULL matrix", fn);
    if (!a->assembling)
        return SQ_FAIL(err, SQ_ERR_USAGE,
                       "%s: matrix already factored (sem_sparse_reset starts a new assembly)", fn);
    return SQ_OK;
}

/* Where key is in the ascending v[lo..hi]; -1 if it is not. */
static long find_sorted(const sslong *v, long lo, long hi, long key)
{
    while (lo <= hi) {
        const long mid = (lo + hi) / 2;
        if (v[mid] == key) return mid;
        if (v[mid] < key)
            lo = mid + 1;
        else
            hi = mid - 1;
    }
    return -1;
}

/* Where block (bi, bj), bi >= bj, is stored: 0 for the diagonal block, else
 * its position p in brow (bptr[bj] < p < bptr[bj + 1]); -1 if it is not in
 * the pattern. */
static long block_slot(const sem_sparse *a, long bi, long bj)
{
    if (bi == bj) return 0;
    return find_sorted(a->brow, a->bptr[bj] + 1, a->bptr[bj + 1] - 1, bi);
}

/* Index in A->x of the block's first row in column c of block column bj
 * (slot from block_slot, >= 0). */
static long slot_entry(const sem_sparse *a, long bj, long slot, long c)
{
    const sslong *Ap = a->A->p;
    const int jj = (int)(c - bj * a->bs);
    if (slot == 0) return (long)Ap[c] - jj; /* row bj bs of the diagonal block */
    return (long)Ap[c] + (a->bs - jj) + (slot - a->bptr[bj] - 1) * (long)a->bs;
}

sq_status sem_sparse_block_positions(const sem_sparse *a, long bi, long bj, long *pos,
                                     sq_error *err)
{
    if (!a || !a->nblocks || !pos)
        return SQ_FAIL(err, SQ_ERR_USAGE, "sparse_block_positions: not a block matrix");
    if (bi < 0 || bj < 0 || bi >= a->nblocks || bj >= a->nblocks)
        return SQ_FAIL(err, SQ_ERR_USAGE,
                       "sparse_block_positions: block (%ld,%ld) outside %ld x %ld", bi, bj,
                       a->nblocks, a->nblocks);
    const int bs = a->bs;
    const long R = bi > bj ? bi : bj, C = bi > bj ? bj : bi, slot = block_slot(a, R, C);
    if (slot < 0)
        return SQ_FAIL(err, SQ_ERR_USAGE,
                       "sparse_block_positions: block (%ld,%ld) outside the block pattern", bi, bj);
    for (int r = 0; r < bs; ++r)
        for (int c = 0; c < bs; ++c) {
            /* the stored entry (row rr, column cc of block (R, C)) */
            const int rr = bi >= bj ? r : c, cc = bi >= bj ? c : r;
            pos[r * bs + c] = R == C && rr < cc ? -1 : slot_entry(a, C, slot, C * bs + cc) + rr;
        }
    return SQ_OK;
}

long sem_sparse_entry(const sem_sparse *a, long i, long j)
{
    if (!a || !a->pattern || i < j || j < 0 || i >= a->n) return -1;
    const sslong *Ap = a->A->p;
    return find_sorted(a->A->i, (long)Ap[j], (long)Ap[j + 1] - 1, i);
}

double *sem_sparse_values(sem_sparse *a)
{
    return a && (a->nblocks || a->pattern) && a->assembling ? a->A->x : NULL;
}

sq_status sem_sparse_add(sem_sparse *a, long i, long j, double v, sq_error *err)
{
    SQ_TRY(not_assembling(a, "sparse_add", err));
    if (i < 0 || j < 0 || i >= a->n || j >= a->n)
        return SQ_FAIL(err, SQ_ERR_USAGE, "sparse_add: entry (%ld,%ld) outside %ld x %ld", i, j,
                       a->n, a->n);
    if (i < j) return SQ_OK; /* upper triangle: the symmetric twin is added */
    if (a->pattern) {
        const long k = sem_sparse_entry(a, i, j);
        if (k < 0)
            return SQ_FAIL(err, SQ_ERR_USAGE, "sparse_add: entry (%ld,%ld) outside the pattern", i,
                           j);
        ((double *)a->A->x)[k] += v;
        return SQ_OK;
    }
    if (a->nblocks) {
        const long bi = i / a->bs, bj = j / a->bs, slot = block_slot(a, bi, bj);
        if (slot < 0)
            return SQ_FAIL(err, SQ_ERR_USAGE,
                           "sparse_add: entry (%ld,%ld) outside the block pattern", i, j);
        ((double *)a->A->x)[slot_entry(a, bj, slot, j) + (i - bi * a->bs)] += v;
        return SQ_OK;
    }
    cholmod_triplet *T = a->T;
    if (T->nnz == T->nzmax) {
        if (!cholmod_l_reallocate_triplet(2 * T->nzmax, T, &a->cc))
            return SQ_FAIL(err, SQ_ERR_INTERNAL, "sparse_add: out of memory (%zu entries)",
                           2 * T->nzmax);
    }
    const size_t k = T->nnz++;
    ((sslong *)T->i)[k] = i;
    ((sslong *)T->j)[k] = j;
    ((double *)T->x)[k] = v;
    return SQ_OK;
}

sq_status sem_sparse_add_block(sem_sparse *a, long bi, long bj, const double *M, sq_error *err)
{
    SQ_TRY(not_assembling(a, "sparse_add_block", err));
    if (!a->nblocks)
        return SQ_FAIL(err, SQ_ERR_USAGE, "sparse_add_block: the matrix has no block pattern");
    if (bi < 0 || bj < 0 || bi >= a->nblocks || bj >= a->nblocks || !M)
        return SQ_FAIL(err, SQ_ERR_USAGE, "sparse_add_block: block (%ld,%ld) outside %ld x %ld", bi,
                       bj, a->nblocks, a->nblocks);
    const int bs = a->bs;
    /* stored block (row R, column C); M or its transpose */
    const long R = bi > bj ? bi : bj, C = bi > bj ? bj : bi;
    const int tr = bi < bj;
    double *x = a->A->x;
    const long slot = block_slot(a, R, C);
    if (slot < 0)
        return SQ_FAIL(err, SQ_ERR_USAGE,
                       "sparse_add_block: block (%ld,%ld) outside the block pattern", bi, bj);
    for (int c = 0; c < bs; ++c) {
        const long k = slot_entry(a, C, slot, C * bs + c);
        for (int r = R == C ? c : 0; r < bs; ++r)
            x[k + r] += tr ? M[(size_t)c * bs + r] : M[(size_t)r * bs + c];
    }
    return SQ_OK;
}

/* CHOLMOD's analysis of A with the one ordering method given (perm for
 * CHOLMOD_GIVEN), its choice of methods left as it was. */
static cholmod_factor *analyze_by(sem_sparse *a, cholmod_sparse *A, sslong *perm, int ordering)
{
    const int nmethods = a->cc.nmethods, saved = a->cc.method[0].ordering;
    a->cc.nmethods = 1;
    a->cc.method[0].ordering = ordering;
    cholmod_factor *L = cholmod_l_analyze_p(A, perm, NULL, 0, &a->cc);
    a->cc.nmethods = nmethods;
    a->cc.method[0].ordering = saved;
    return L;
}

/* Fill-reducing ordering of a block pattern, each block's unknowns kept
 * together: from NESDIS_MIN_BLOCKS blocks nested dissection of the graph of
 * blocks (CHOLMOD's NESDIS: 10-20 % fewer flops than its default AMD on the
 * relaxation's Hessians and the DG matrices, grid-like graphs), CHOLMOD's
 * default choice where NESDIS is not available; below, AMD, whose analysis
 * costs less than NESDIS saves in the factorizations that follow (CPU
 * time of the mesh stage, AMD against NESDIS, a block a moving vertex of
 * the order-1 mesh: half_disc at --size 0.025, 4316 vertices, 61 against
 * 69 ms; two_holes at 0.1, 850, 10.2 against 11.8; the disc at 0.025,
 * 5208, 149 against 152; the annulus at 0.025, 6300, 154 against 133; the
 * DG guiding fields' solves of naca0012, polygon, obtuse_quad and triangle
 * within 5 %, AMD ahead). */
#define NESDIS_MIN_BLOCKS 5000
static sq_status block_ordering(sem_sparse *a, sslong *perm, sq_error *err)
{
    const long nb = a->nblocks, nbe = a->bptr[nb];
    cholmod_sparse *G = cholmod_l_allocate_sparse((size_t)nb, (size_t)nb, (size_t)nbe, 1, 1, -1,
                                                  CHOLMOD_PATTERN, &a->cc);
    if (!G) return SQ_FAIL(err, SQ_ERR_INTERNAL, "sparse_factor: out of memory (block graph)");
    memcpy(G->p, a->bptr, sizeof(sslong) * (size_t)(nb + 1));
    memcpy(G->i, a->brow, sizeof(sslong) * (size_t)nbe);
    cholmod_factor *Lb =
        analyze_by(a, G, NULL, nb < NESDIS_MIN_BLOCKS ? CHOLMOD_AMD : CHOLMOD_NESDIS);
    if (!Lb) Lb = cholmod_l_analyze(G, &a->cc);
    cholmod_l_free_sparse(&G, &a->cc);
    if (!Lb)
        return SQ_FAIL(err, SQ_ERR_INTERNAL,
                       "sparse_factor: ordering the block graph failed (CHOLMOD status %d)",
                       a->cc.status);
    const sslong *bp = Lb->Perm;
    for (long k = 0; k < nb; ++k)
        for (int r = 0; r < a->bs; ++r)
            perm[k * a->bs + r] = bp[k] * a->bs + r;
    cholmod_l_free_factor(&Lb, &a->cc);
    return SQ_OK;
}

static sq_status analyze(sem_sparse *a, sq_error *err)
{
    if (!a->nblocks) {
        a->L = cholmod_l_analyze(a->A, &a->cc);
    } else {
        sslong *perm = malloc(sizeof(sslong) * (size_t)a->n);
        if (!perm) return SQ_FAIL(err, SQ_ERR_INTERNAL, "sparse_factor: out of memory");
        sq_status st = block_ordering(a, perm, err);
        if (st != SQ_OK) {
            free(perm);
            return st;
        }
        a->L = analyze_by(a, a->A, perm, CHOLMOD_GIVEN);
        free(perm);
    }
    if (!a->L)
        return SQ_FAIL(err, SQ_ERR_INTERNAL, "sparse_factor: analysis failed (CHOLMOD status %d)",
                       a->cc.status);
    return SQ_OK;
}

static int same_pattern(const cholmod_sparse *A, const cholmod_sparse *B)
{
    if (A->ncol != B->ncol || ((const sslong *)A->p)[A->ncol] != ((const sslong *)B->p)[B->ncol])
        return 0;
    const size_t nz = (size_t)((const sslong *)A->p)[A->ncol];
    return !memcmp(A->p, B->p, sizeof(sslong) * (A->ncol + 1)) &&
           !memcmp(A->i, B->i, sizeof(sslong) * nz);
}

sq_status sem_sparse_factor(sem_sparse *a, sq_error *err)
{
    SQ_TRY(not_assembling(a, "sparse_factor", err));
    if (!a->nblocks && !a->pattern) {
        /* Duplicates are summed by the conversion. */
        cholmod_sparse *A = cholmod_l_triplet_to_sparse(a->T, a->T->nnz, &a->cc);
        if (!A) return SQ_FAIL(err, SQ_ERR_INTERNAL, "sparse_factor: out of memory (compressing)");
        cholmod_l_free_triplet(&a->T, &a->cc);
        if (a->L && !same_pattern(a->A, A)) cholmod_l_free_factor(&a->L, &a->cc);
        if (a->A) cholmod_l_free_sparse(&a->A, &a->cc);
        a->A = A;
    }
    a->assembling = 0;
    if (!a->L) {
        sem_lib_lock(); /* nested dissection runs METIS (lib_lock.h) */
        const sq_status st = analyze(a, err);
        sem_lib_unlock();
        SQ_TRY(st);
    }
    sem_lib_lock(); /* CHOLMOD's supernodal factorization calls BLAS and LAPACK */
    const int ok = cholmod_l_factorize(a->A, a->L, &a->cc);
    sem_lib_unlock();
    if (!ok || a->cc.status == CHOLMOD_NOT_POSDEF || a->L->minor < a->L->n) {
        const long minor = (long)a->L->minor;
        const int status = a->cc.status;
        cholmod_l_free_factor(&a->L, &a->cc);
        if (status == CHOLMOD_NOT_POSDEF || minor < a->n)
            return SQ_FAIL(err, SQ_ERR_INTERNAL,
                           "sparse_factor: matrix (n = %ld) is not positive definite (pivot %ld)",
                           a->n, minor);
        return SQ_FAIL(err, SQ_ERR_INTERNAL,
                       "sparse_factor: factorization failed (CHOLMOD status %d)", status);
    }
    if (!a->b) {
        a->b = cholmod_l_allocate_dense((size_t)a->n, 1, (size_t)a->n, CHOLMOD_REAL, &a->cc);
        if (!a->b) {
            cholmod_l_free_factor(&a->L, &a->cc);
            return SQ_FAIL(err, SQ_ERR_INTERNAL, "sparse_factor: out of memory");
        }
    }
    return SQ_OK;
}

sq_status sem_sparse_reset(sem_sparse *a, sq_error *err)
{
    if (!a || !a->L)
        return SQ_FAIL(err, SQ_ERR_USAGE, "sparse_reset: no factorization to start again from");
    if (a->nblocks || a->pattern) {
        memset(a->A->x, 0, sizeof(double) * a->A->nzmax);
    } else {
        if (a->T) cholmod_l_free_triplet(&a->T, &a->cc);
        a->T = cholmod_l_allocate_triplet((size_t)a->n, (size_t)a->n, a->A->nzmax, -1, CHOLMOD_REAL,
                                          &a->cc);
        if (!a->T) return SQ_FAIL(err, SQ_ERR_INTERNAL, "sparse_reset: out of memory");
    }
    a->assembling = 1;
    return SQ_OK;
}

sq_status sem_sparse_solve(sem_sparse *a, const double *b, double *x, sq_error *err)
{
    if (!a || !a->L || a->assembling)
        return SQ_FAIL(err, SQ_ERR_USAGE, "sparse_solve: matrix not factored");
    memcpy(a->b->x, b, sizeof(double) * (size_t)a->n);
    sem_lib_lock();
    cholmod_dense *X = cholmod_l_solve(CHOLMOD_A, a->L, a->b, &a->cc);
    sem_lib_unlock();
    if (!X)
        return SQ_FAIL(err, SQ_ERR_INTERNAL, "sparse_solve: CHOLMOD solve failed (status %d)",
                       a->cc.status);
    memcpy(x, X->x, sizeof(double) * (size_t)a->n);
    cholmod_l_free_dense(&X, &a->cc);
    return SQ_OK;
}

/* Preconditioned conjugate gradients (Hestenes & Stiefel 1952; Saad,
 * Iterative Methods for Sparse Linear Systems, 2nd ed., Algorithm 9.1) on
 * the values assembled so far, preconditioned by the last factorization:
 * each iteration one product with A and one solve with L. */
sq_status sem_sparse_pcg(sem_sparse *a, const double *b, double *x, double rtol, int maxit,
                         int *iters, int *converged, sq_error *err)
{
    *iters = 0;
    *converged = 0;
    if (!a || !a->L || !a->assembling || !a->nblocks)
        return SQ_FAIL(err, SQ_ERR_USAGE,
                       "sparse_pcg: needs a block matrix being assembled after a factorization");
    const size_t n = (size_t)a->n;
    cholmod_dense *R = cholmod_l_allocate_dense(n, 1, n, CHOLMOD_REAL, &a->cc),
                  *P = cholmod_l_allocate_dense(n, 1, n, CHOLMOD_REAL, &a->cc),
                  *Q = cholmod_l_allocate_dense(n, 1, n, CHOLMOD_REAL, &a->cc), *Z = NULL, *Y = NULL,
                  *E = NULL;
    sq_status st = SQ_OK;
    if (!R || !P || !Q) st = SQ_FAIL(err, SQ_ERR_INTERNAL, "sparse_pcg: out of memory");
    double *r = R ? R->x : NULL, *p = P ? P->x : NULL, *q = Q ? Q->x : NULL, bb = 0, rz = 0;
    for (size_t i = 0; i < n && st == SQ_OK; ++i) {
        x[i] = 0;
        r[i] = b[i];
        bb += b[i] * b[i];
    }
    double one[2] = {1, 0}, zero[2] = {0, 0};
    for (int it = 0; st == SQ_OK; ++it) {
        double rr = 0;
        for (size_t i = 0; i < n; ++i)
            rr += r[i] * r[i];
        if (rr <= rtol * rtol * bb) {
            *converged = 1;
            break;
        }
        if (it == maxit) break;
        sem_lib_lock();
        const int solved = cholmod_l_solve2(CHOLMOD_A, a->L, R, NULL, &Z, NULL, &Y, &E, &a->cc);
        sem_lib_unlock();
        if (!solved) {
            st = SQ_FAIL(err, SQ_ERR_INTERNAL, "sparse_pcg: CHOLMOD solve failed (status %d)",
                         a->cc.status);
            break;
        }
        const double *z = Z->x, rz0 = rz;
        rz = 0;
        for (size_t i = 0; i < n; ++i)
            rz += r[i] * z[i];
        const double beta = it ? rz / rz0 : 0.0;
        for (size_t i = 0; i < n; ++i)
            p[i] = it ? z[i] + beta * p[i] : z[i];
        if (!cholmod_l_sdmult(a->A, 0, one, zero, P, Q, &a->cc)) {
            st = SQ_FAIL(err, SQ_ERR_INTERNAL, "sparse_pcg: CHOLMOD product failed (status %d)",
                         a->cc.status);
            break;
        }
        double pq = 0;
        for (size_t i = 0; i < n; ++i)
            pq += p[i] * q[i];
        if (!(pq > 0)) break; /* not positive definite along p: not converged */
        const double alpha = rz / pq;
        for (size_t i = 0; i < n; ++i) {
            x[i] += alpha * p[i];
            r[i] -= alpha * q[i];
        }
        *iters = it + 1;
    }
    cholmod_l_free_dense(&R, &a->cc);
    cholmod_l_free_dense(&P, &a->cc);
    cholmod_l_free_dense(&Q, &a->cc);
    cholmod_l_free_dense(&Z, &a->cc);
    cholmod_l_free_dense(&Y, &a->cc);
    cholmod_l_free_dense(&E, &a->cc);
    return st;
}

long sem_sparse_size(const sem_sparse *a) { return a ? a->n : 0; }
