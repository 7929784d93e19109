/* t201: sparse SPD systems with CHOLMOD.
 *  - the 1D Laplacian tridiag(-1, 2, -1) of size 200 plus a dense-ish
 *    coupling, assembled from full symmetric entries (the upper triangle is
 *    ignored) with duplicates summed: A x = b for a known x, twice (one
 *    factorization, two right-hand sides, b and x aliased), to the
 *    solve's round-off bound (see Tolerances below);
 *  - [[1, 2], [2, 1]] (indefinite) is reported as not positive definite;
 *  - out-of-range entries are refused;
 *  - reset and refactor: a second matrix of the same pattern (values
 *    changed) and a third of another pattern, solved as well;
 *  - a block pattern (5 blocks of 3, a path 0-1-2-3-4 plus 0-4): blocks
 *    added from either side (the transposed one), single entries, the
 *    same solve and again after a reset; entries and blocks
 *    outside the pattern and a malformed pattern are refused;
 *  - block positions (sem_sparse_block_positions): a block given from
 *    either side lands where sem_sparse_add_block puts it, the upper
 *    triangle of a diagonal block nowhere;
 *  - conjugate gradients preconditioned by an earlier factorization
 *    (sem_sparse_pcg): with the matrix's own factorization one iteration;
 *    after the values changed (assembled through the positions) the known
 *    x to kappa rtol in at most n iterations; no iteration allowed: not
 *    converged; refused before any factorization; a factorization of the
 *    new values still possible after it;
 *  - a given pattern (sem_sparse_create_pattern): the same entries added
 *    in the same order as triplets give the same solution to the bit (the
 *    same compressed matrix and CHOLMOD analysis: what lets the CG solver
 *    assemble in place and keep its output); entries outside the pattern
 *    and a malformed pattern are refused; reset and assembled again
 *    through sem_sparse_values / sem_sparse_entry. */
#include "sparse.h"
#include "test_util.h"

#include <float.h>

#define N 200

/* Tolerances.  Errors are measured normwise, max |y - x| / max |x|.  A
 * Cholesky solve (CHOLMOD, whose BLAS kernels differ by CPU) is backward
 * stable, |dA| <= (3n+1) U |R^T||R| (Higham 2002, Thm 10.4), so its
 * relative error is at most kappa (3n+1) U; every matrix here has kappa_2
 * <= 5 (diagonal 4 + c .. 17 against off-diagonal row sums, plus the
 * arrow's 0.5 sqrt(19) for the N = 200 one), i.e. 5 (3n+1) U: 2.7e-13 at
 * n = 200, 2e-14 at n = 12.  PCG stops at a residual rtol ||b||, an error
 * of kappa rtol. */
#define U (DBL_EPSILON / 2)
#define CHOL_TOL(n) (5.0 * (3 * (n) + 1) * U)

/* Normwise relative error of solving A x = b for a known x (A dense, n x n):
 * with the factorization, or (pcg != NULL: rtol, maxit in, iterations and
 * converged out) by sem_sparse_pcg. */
typedef struct {
    double rtol;
    int maxit, iters, converged;
} pcg_run;

static double solve_with(sem_sparse *a, int n, const double *A, pcg_run *pcg, int *fails)
{
    double x[32], b[32], y[32];
    sq_error err = {0};
    for (int i = 0; i < n; ++i)
        x[i] = 1.0 + 0.1 * i - 0.02 * i * i;
    for (int i = 0; i < n; ++i) {
        b[i] = 0.0;
        for (int j = 0; j < n; ++j)
            b[i] += A[i * n + j] * x[j];
    }
    sq_status st = pcg ? sem_sparse_pcg(a, b, y, pcg->rtol, pcg->maxit, &pcg->iters,
                                        &pcg->converged, &err)
                       : sem_sparse_solve(a, b, y, &err);
    if (st != SQ_OK) {
        printf("t201: %s failed: %s\n", pcg ? "pcg" : "solve", err.msg);
        ++*fails;
        return 1.0;
    }
    double e = 0.0, xm = 0.0;
    for (int i = 0; i < n; ++i) {
        e = fmax(e, fabs(y[i] - x[i]));
        xm = fmax(xm, fabs(x[i]));
    }
    return e / xm;
}

static double solve_error(sem_sparse *a, int n, const double *A, int *fails)
{
    return solve_with(a, n, A, NULL, fails);
}

/* A = (4 + c) I + c' (path couplings) of size 12, assembled from triplets */
static void path_matrix(double c, double cp, int extra, double *A)
{
    memset(A, 0, sizeof(double) * 144);
    for (int i = 0; i < 12; ++i) {
        A[i * 12 + i] = 4.0 + c;
        if (i) A[i * 12 + i - 1] = A[(i - 1) * 12 + i] = cp;
    }
    if (extra) A[11 * 12 + 0] = A[0 * 12 + 11] = 0.7;
}

static int refactor_case(void)
{
    int fails = 0;
    sq_error err = {0};
    sem_sparse *a = NULL;
    double A[144];
    SQ_TEST_OK(sem_sparse_create(12, 4, &a, &err), err);
    fails +=
        sq_check_int("t201 reset before factor", "status", sem_sparse_reset(a, &err), SQ_ERR_USAGE);
    for (int round = 0; round < 3; ++round) {
        /* round 1: same pattern, other values; round 2: one more entry */
        path_matrix(round, -1.0 - 0.3 * round, round == 2, A);
        if (round) SQ_TEST_OK(sem_sparse_reset(a, &err), err);
        double b[12] = {0};
        fails += sq_check_int("t201 solve while assembling", "status",
                              sem_sparse_solve(a, b, b, &err), SQ_ERR_USAGE);
        for (int i = 0; i < 12; ++i)
            for (int j = 0; j <= i; ++j)
                if (A[i * 12 + j] != 0.0)
                    SQ_TEST_OK(sem_sparse_add(a, i, j, A[i * 12 + j], &err), err);
        SQ_TEST_OK(sem_sparse_factor(a, &err), err);
        fails += sq_check_abs("t201 refactor", "max relative error", solve_error(a, 12, A, &fails),
                              0.0, CHOL_TOL(12));
        fails += sq_check_int("t201 add after factor", "status", sem_sparse_add(a, 0, 0, 1.0, &err),
                              SQ_ERR_USAGE);
    }
    sem_sparse_free(&a);
    return fails;
}

/* The block pattern of block_case and pcg_case: 5 blocks of 3, a path
 * 0-1-2-3-4 plus 0-4; in its lower triangle, column j holds j and its
 * neighbours after it. */
enum { NB = 5, BS = 3, NN = NB * BS };
static const long BPTR[NB + 1] = {0, 3, 5, 7, 9, 10};
static const long BROW[10] = {0, 1, 4, 1, 2, 2, 3, 3, 4, 4};

static int block_case(void)
{
    int fails = 0;
    sq_error err = {0};
    sem_sparse *a = NULL;
    const long bad_ptr[3] = {0, 1, 2}, bad_row[2] = {1, 1};
    fails += sq_check_int("t201 malformed block pattern", "status",
                          sem_sparse_create_blocks(2, 2, bad_ptr, bad_row, &a, &err), SQ_ERR_USAGE);
    SQ_TEST_OK(sem_sparse_create_blocks(NB, BS, BPTR, BROW, &a, &err), err);
    fails += sq_check_int("t201 blocks", "size", sem_sparse_size(a), NN);
    for (int round = 0; round < 2; ++round) {
        double A[NN * NN] = {0};
        const int pairs[6][2] = {{0, 0}, {1, 0}, {0, 4}, {2, 1}, {3, 2}, {4, 3}};
        if (round) SQ_TEST_OK(sem_sparse_reset(a, &err), err);
        for (int b = 0; b < NB; ++b) { /* symmetric diagonal blocks, dominant */
            double M[BS * BS];
            for (int r = 0; r < BS; ++r)
                for (int c = 0; c < BS; ++c)
                    M[r * BS + c] = r == c ? 10.0 + b + round : 0.5 / (1 + r + c) + 0.1 * round;
            SQ_TEST_OK(sem_sparse_add_block(a, b, b, M, &err), err);
            for (int r = 0; r < BS; ++r)
                for (int c = 0; c < BS; ++c)
                    A[(b * BS + r) * NN + b * BS + c] += M[r * BS + c];
        }
        for (int k = 1; k < 6; ++k) { /* (0,4) given above the diagonal: stored transposed */
            const int bi = pairs[k][0], bj = pairs[k][1];
            double M[BS * BS];
            for (int r = 0; r < BS; ++r)
                for (int c = 0; c < BS; ++c)
                    M[r * BS + c] = 0.3 * sin(1.0 + k + 2 * r + 3.0 * c + round);
            SQ_TEST_OK(sem_sparse_add_block(a, bi, bj, M, &err), err);
            for (int r = 0; r < BS; ++r)
                for (int c = 0; c < BS; ++c) {
                    A[(bi * BS + r) * NN + bj * BS + c] += M[r * BS + c];
                    A[(bj * BS + c) * NN + bi * BS + r] += M[r * BS + c];
                }
        }
        /* single entries, summed into the blocks */
        SQ_TEST_OK(sem_sparse_add(a, 14, 1, 0.25, &err), err);
        A[14 * NN + 1] += 0.25;
        A[1 * NN + 14] += 0.25;
        SQ_TEST_OK(sem_sparse_add(a, 7, 7, 1.5, &err), err);
        A[7 * NN + 7] += 1.5;
        fails += sq_check_int("t201 entry outside the blocks", "status",
                              sem_sparse_add(a, 9, 0, 1.0, &err), SQ_ERR_USAGE);
        double M[BS * BS] = {0};
        fails += sq_check_int("t201 block outside the pattern", "status",
                              sem_sparse_add_block(a, 3, 0, M, &err), SQ_ERR_USAGE);
        SQ_TEST_OK(sem_sparse_factor(a, &err), err);
        fails += sq_check_abs(round ? "t201 blocks after reset" : "t201 blocks",
                              "max relative error", solve_error(a, NN, A, &fails), 0.0, CHOL_TOL(NN));
    }
    sem_sparse_free(&a);
    return fails;
}

static int pcg_case(void)
{
    int fails = 0;
    sq_error err = {0};
    sem_sparse *a = NULL;
    /* the diagonal blocks and the others, (0,4) above the diagonal */
    const int pairs[10][2] = {{0, 0}, {1, 1}, {2, 2}, {3, 3}, {4, 4},
                              {1, 0}, {0, 4}, {2, 1}, {3, 2}, {4, 3}};
    SQ_TEST_OK(sem_sparse_create_blocks(NB, BS, BPTR, BROW, &a, &err), err);
    long pos[NB][NB][BS * BS];
    for (int bi = 0; bi < NB; ++bi)
        for (int bj = 0; bj < NB; ++bj)
            if (sem_sparse_block_positions(a, bi, bj, pos[bi][bj], &err) != SQ_OK)
                pos[bi][bj][0] = -2; /* outside the pattern */
    fails += sq_check_int("t201 positions outside the pattern", "position", pos[3][0][0], -2);
    fails += sq_check_int("t201 positions, upper diagonal entry", "position", pos[2][2][1], -1);
    int mismatch = 0;
    for (int r = 0; r < BS; ++r)
        for (int c = 0; c < BS; ++c)
            mismatch += pos[0][4][r * BS + c] != pos[4][0][c * BS + r] || pos[4][0][r * BS + c] < 0;
    fails += sq_check_int("t201 positions of a block and its transpose", "mismatches", mismatch, 0);
    int iters = 0, converged = 0;
    double b[NN] = {1.0}, y[NN];
    fails += sq_check_int("t201 pcg before a factorization", "status",
                          sem_sparse_pcg(a, b, y, 1e-12, 10, &iters, &converged, &err),
                          SQ_ERR_USAGE);
    for (int round = 0; round < 3; ++round) {
        /* round 0: factored; 1: the same values; 2: other values */
        const double v = round == 2 ? 1.0 : 0.0;
        double A[NN * NN] = {0};
        if (round) SQ_TEST_OK(sem_sparse_reset(a, &err), err);
        double *x = sem_sparse_values(a);
        fails += sq_check_int("t201 values while assembling", "present", x != NULL, 1);
        for (int k = 0; k < 10 && x; ++k) {
            const int bi = pairs[k][0], bj = pairs[k][1];
            for (int r = 0; r < BS; ++r)
                for (int c = 0; c < BS; ++c) {
                    double m = bi == bj ? (r == c ? 10.0 + bi + 3 * v : 0.4 / (1 + r + c))
                                        : 0.3 * sin(1.0 + k + 2 * r + 3.0 * c + v);
                    if (bi == bj && r < c) m = 0.4 / (1 + r + c); /* symmetric */
                    if (pos[bi][bj][r * BS + c] >= 0) x[pos[bi][bj][r * BS + c]] += m;
                    A[(bi * BS + r) * NN + bj * BS + c] = m;
                    A[(bj * BS + c) * NN + bi * BS + r] = m;
                }
        }
        if (round == 0) {
            SQ_TEST_OK(sem_sparse_factor(a, &err), err);
            fails += sq_check_abs("t201 positions", "max relative error",
                                  solve_error(a, NN, A, &fails), 0.0, CHOL_TOL(NN));
            continue;
        }
        pcg_run run = {1e-13, 50, 0, 0};
        double e = solve_with(a, NN, A, &run, &fails);
        const char *what = round == 1 ? "t201 pcg, exact preconditioner" : "t201 pcg";
        fails += sq_check_int(what, "converged", run.converged, 1);
        fails += sq_check_abs(what, "max relative error", e, 0.0, 5 * run.rtol + CHOL_TOL(NN));
        /* one step with the exact factorization leaves a residual of the
         * solve's backward error, (3 NN + 1) U |A||x| ~ 5e-15 ||b||, far below
         * rtol = 1e-13 */
        if (round == 1) fails += sq_check_int(what, "iterations", run.iters, 1);
        if (round == 2) {
            if (run.iters < 2 || run.iters > NN) {
                printf("t201 pcg: %d iterations, expected 2..%d\n", run.iters, NN);
                ++fails;
            }
            pcg_run none = {1e-13, 0, 0, 0};
            solve_with(a, NN, A, &none, &fails);
            fails += sq_check_int("t201 pcg, no iteration", "converged", none.converged, 0);
            SQ_TEST_OK(sem_sparse_factor(a, &err), err);
            fails += sq_check_abs("t201 factored after pcg", "max relative error",
                                  solve_error(a, NN, A, &fails), 0.0, CHOL_TOL(NN));
        }
    }
    sem_sparse_free(&a);
    return fails;
}

/* tridiag(-1, 7, -1) + 0.5 (e_0 e_k^T + e_k e_0^T), k = 10, 20, ..: kappa
 * below 5 as the matrices above */
#define NP 30 /* solve_with holds up to 32 */
static double pattern_entry(int i, int j)
{
    if (i == j) return 7.0;
    if (i - j == 1 || j - i == 1) return -1.0;
    if ((j == 0 && i % 10 == 0) || (i == 0 && j % 10 == 0)) return 0.5;
    return 0.0;
}

static int pattern_case(void)
{
    int fails = 0;
    sq_error err = {0};
    long ptr[NP + 1], row[3 * NP], k = 0;
    static double A[NP * NP];
    for (int j = 0; j < NP; ++j) {
        ptr[j] = k;
        for (int i = j; i < NP; ++i)
            if (pattern_entry(i, j) != 0.0) row[k++] = i;
    }
    ptr[NP] = k;
    for (int i = 0; i < NP; ++i)
        for (int j = 0; j < NP; ++j)
            A[i * NP + j] = pattern_entry(i, j);
    sem_sparse *t = NULL, *p = NULL;
    const long bad[3] = {0, 1, 2}, badrow[2] = {0, 0}; /* column 1 starts at row 0 */
    fails += sq_check_int("t201 malformed pattern", "status",
                          sem_sparse_create_pattern(2, bad, badrow, &p, &err), SQ_ERR_USAGE);
    SQ_TEST_OK(sem_sparse_create(NP, 10, &t, &err), err);
    SQ_TEST_OK(sem_sparse_create_pattern(NP, ptr, row, &p, &err), err);
    fails += sq_check_int("t201 pattern, entry outside", "index", sem_sparse_entry(p, 5, 0), -1);
    fails += sq_check_int("t201 pattern, upper entry", "index", sem_sparse_entry(p, 0, 10), -1);
    fails += sq_check_int("t201 pattern, entry (10,0)", "found", sem_sparse_entry(p, 10, 0) >= 0, 1);
    fails += sq_check_int("t201 pattern, add outside", "status", sem_sparse_add(p, 5, 0, 1.0, &err),
                          SQ_ERR_USAGE);
    /* each entry as two additions (0.1 and the rest), rows then columns */
    for (int i = 0; i < NP; ++i)
        for (int j = 0; j < NP; ++j) {
            const double v = A[i * NP + j];
            if (v == 0.0) continue;
            SQ_TEST_OK(sem_sparse_add(t, i, j, 0.1, &err), err);
            SQ_TEST_OK(sem_sparse_add(p, i, j, 0.1, &err), err);
            SQ_TEST_OK(sem_sparse_add(t, i, j, v - 0.1, &err), err);
            SQ_TEST_OK(sem_sparse_add(p, i, j, v - 0.1, &err), err);
        }
    SQ_TEST_OK(sem_sparse_factor(t, &err), err);
    SQ_TEST_OK(sem_sparse_factor(p, &err), err);
    double b[NP], xt[NP], xp[NP];
    for (int i = 0; i < NP; ++i)
        b[i] = cos(0.3 * i);
    SQ_TEST_OK(sem_sparse_solve(t, b, xt, &err), err);
    SQ_TEST_OK(sem_sparse_solve(p, b, xp, &err), err);
    fails += sq_check_int("t201 pattern against triplets", "bytes differing",
                          memcmp(xt, xp, sizeof xt) != 0, 0);
    fails += sq_check_abs("t201 pattern", "max relative error", solve_error(p, NP, A, &fails), 0.0,
                          CHOL_TOL(NP));
    /* again through the values, 2 A */
    SQ_TEST_OK(sem_sparse_reset(p, &err), err);
    double *x = sem_sparse_values(p);
    fails += sq_check_int("t201 pattern values", "present", x != NULL, 1);
    for (int j = 0; x && j < NP; ++j)
        for (int i = j; i < NP; ++i)
            if (A[i * NP + j] != 0.0) x[sem_sparse_entry(p, i, j)] += 2.0 * A[i * NP + j];
    for (int i = 0; i < NP * NP; ++i)
        A[i] *= 2.0;
    SQ_TEST_OK(sem_sparse_factor(p, &err), err);
    fails += sq_check_abs("t201 pattern after reset", "max relative error",
                          solve_error(p, NP, A, &fails), 0.0, CHOL_TOL(NP));
    sem_sparse_free(&t);
    sem_sparse_free(&p);
    return fails;
}

int main(void)
{
    int fails = 0;
    sq_error err = {0};
    sem_sparse *a = NULL;
    SQ_TEST_OK(sem_sparse_create(N, 10, &a, &err), err); /* small hint: forces growth */
    fails += sq_check_int("t201", "size", sem_sparse_size(a), N);
    /* A = tridiag(-1,2,-1) + 0.5 (e_0 e_k^T + e_k e_0^T) for k = 10, 20, ...
     * + 5 I, each diagonal entry split into two additions */
    static double A[N][N];
    for (int i = 0; i < N; ++i) {
        A[i][i] = 7.0;
        if (i > 0) A[i][i - 1] = A[i - 1][i] = -1.0;
    }
    for (int k = 10; k < N; k += 10)
        A[0][k] = A[k][0] = 0.5;
    for (int i = 0; i < N; ++i)
        for (int j = 0; j < N; ++j) {
            if (A[i][j] == 0.0) continue;
            if (i == j) {
                SQ_TEST_OK(sem_sparse_add(a, i, j, 3.0, &err), err);
                SQ_TEST_OK(sem_sparse_add(a, i, j, A[i][j] - 3.0, &err), err);
            } else {
                SQ_TEST_OK(sem_sparse_add(a, i, j, A[i][j], &err), err);
            }
        }
    fails += sq_check_int("t201 out of range", "status", sem_sparse_add(a, N, 0, 1.0, &err),
                          SQ_ERR_USAGE);
    SQ_TEST_OK(sem_sparse_factor(a, &err), err);
    for (int rhs = 0; rhs < 2; ++rhs) {
        double x[N], b[N];
        for (int i = 0; i < N; ++i)
            x[i] = rhs ? cos(0.3 * i) : 1.0 + 0.01 * i * i;
        for (int i = 0; i < N; ++i) {
            b[i] = 0.0;
            for (int j = 0; j < N; ++j)
                b[i] += A[i][j] * x[j];
        }
        SQ_TEST_OK(sem_sparse_solve(a, b, b, &err), err); /* aliased */
        double e = 0.0, xm = 0.0;
        for (int i = 0; i < N; ++i) {
            e = fmax(e, fabs(b[i] - x[i]));
            xm = fmax(xm, fabs(x[i]));
        }
        fails += sq_check_abs("t201 SPD solve", "max relative error", e / xm, 0.0, CHOL_TOL(N));
    }
    sem_sparse_free(&a);
    sem_sparse_free(&a); /* NULL-safe */

    SQ_TEST_OK(sem_sparse_create(2, 3, &a, &err), err);
    SQ_TEST_OK(sem_sparse_add(a, 0, 0, 1.0, &err), err);
    SQ_TEST_OK(sem_sparse_add(a, 1, 0, 2.0, &err), err);
    SQ_TEST_OK(sem_sparse_add(a, 1, 1, 1.0, &err), err);
    fails += sq_check_int("t201 indefinite", "status", sem_sparse_factor(a, &err), SQ_ERR_INTERNAL);
    if (!strstr(err.msg, "not positive definite")) {
        printf("t201 indefinite: message '%s' does not say 'not positive definite'\n", err.msg);
        ++fails;
    }
    double b2[2] = {1, 1};
    fails += sq_check_int("t201 solve unfactored", "status", sem_sparse_solve(a, b2, b2, &err),
                          SQ_ERR_USAGE);
    sem_sparse_free(&a);

    fails += refactor_case();
    fails += block_case();
    fails += pcg_case();
    fails += pattern_case();
    return fails ? 1 : 0;
}
