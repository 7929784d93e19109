/* t201: sparse SPD systems with CHOLMOD.
 *  - the 1D Laplacian tridiag(-1, 2, -1) of size 200 plus a dense-ish
 *    coupling, assembled from full symmetric entries (the upper triangle is
 *    ignored) with duplicates summed: A x = b for a known x, twice (one
 *    factorization, two right-hand sides, b and x aliased), to 1e-12;
 *  - [[1, 2], [2, 1]] (indefinite) is reported as not positive definite;
 *  - out-of-range entries are refused. */
#include "sparse.h"
#include "test_util.h"

#define N 200

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
    for (int k = 10; k < N; k += 10) A[0][k] = A[k][0] = 0.5;
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
        for (int i = 0; i < N; ++i) x[i] = rhs ? cos(0.3 * i) : 1.0 + 0.01 * i * i;
        for (int i = 0; i < N; ++i) {
            b[i] = 0.0;
            for (int j = 0; j < N; ++j) b[i] += A[i][j] * x[j];
        }
        SQ_TEST_OK(sem_sparse_solve(a, b, b, &err), err); /* aliased */
        double e = 0.0;
        for (int i = 0; i < N; ++i) e = fmax(e, fabs(b[i] - x[i]) / fmax(1.0, fabs(x[i])));
        fails += sq_check_abs("t201 SPD solve", "max relative error", e, 0.0, 1e-12);
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
    return fails ? 1 : 0;
}
