/* semquad tests — round-off scales for tolerances of sem/ quantities.
 *
 * The nodal basis is l = phi(x)^T V^{-1}, V the Vandermonde matrix of the
 * Dubiner modes at the nodes, inverted by LAPACK's LU (sem/tri_lagrange.c),
 * whose round-off depends on the BLAS kernel OpenBLAS picks for the CPU.
 * The inverse is off by about n kappa_1(V) U relative (Higham 2002, §14.3),
 * so anything interpolated, sum_k g_k l_k(x) or its derivatives, is off by
 * up to n kappa_1(V) U sum_k |g_k l_k(x)|: the first-order worst case
 * (kappa_1 <= 701 and n <= 153 for P <= 16: 1.2e-11 of the absolute sum at
 * P = 16, 1e-15 at P = 1; the errors measured with every OpenBLAS kernel
 * are 1e2 to 1e3 times smaller).  A broken basis or map is off by O(1). */
#ifndef SQ_SEM_ROUNDOFF_H
#define SQ_SEM_ROUNDOFF_H

#include "gauss.h"
#include "tri_basis.h"
#include "tri_lagrange.h"

#include <float.h>
#include <lapacke.h>
#include <math.h>

#define SQ_U (DBL_EPSILON / 2) /* unit round-off of IEEE double */

/* n kappa_1(V) U for the basis L (HUGE_VAL if V is singular). */
static inline double sq_lagrange_roundoff(const sem_tri_lagrange *L)
{
    enum { NM = (SEM_MAX_ORDER + 1) * (SEM_MAX_ORDER + 2) / 2 };
    static double V[NM * NM];
    lapack_int ipiv[NM];
    const int n = sem_tri_lagrange_num_nodes(L), P = sem_tri_lagrange_order(L);
    const double *rs = sem_tri_lagrange_nodes(L);
    for (int k = 0; k < n; ++k) sem_tri_dubiner(P, rs[2 * k], rs[2 * k + 1], V + (size_t)k * n, NULL, NULL);
    const double anorm = LAPACKE_dlange(LAPACK_ROW_MAJOR, '1', n, n, V, n);
    double rcond = 0.0;
    if (LAPACKE_dgetrf(LAPACK_ROW_MAJOR, n, n, V, n, ipiv) != 0 ||
        LAPACKE_dgecon(LAPACK_ROW_MAJOR, '1', n, V, n, anorm, &rcond) != 0 || !(rcond > 0))
        return HUGE_VAL;
    return n / rcond * SQ_U;
}

/* max over a lattice of step 1/20 on T of sum_k |dl_k/dr| + |dl_k/ds|: the
 * factor that turns e into the error of an interpolated derivative per unit
 * of the coordinates (2.7e4 at P = 16, 260 at P = 6). */
static inline double sq_lagrange_dsum(const sem_tri_lagrange *L)
{
    enum { NM = (SEM_MAX_ORDER + 1) * (SEM_MAX_ORDER + 2) / 2 };
    double l[NM], lr[NM], ls[NM], m = 0.0;
    const int n = sem_tri_lagrange_num_nodes(L);
    for (int i = 0; i <= 20; ++i)
        for (int j = 0; i + j <= 20; ++j) {
            sem_tri_lagrange_eval(L, i / 20.0, j / 20.0, l, lr, ls);
            double s = 0.0;
            for (int k = 0; k < n; ++k) s += fabs(lr[k]) + fabs(ls[k]);
            m = fmax(m, s);
        }
    return m;
}

/* Worst-case L2 round-off of a Poisson solve whose exact discrete solution
 * has size umax, on a mesh of n elements a side (h ~ 1/n), order P: the
 * Cholesky solve's kappa(K) U relative error (CHOLMOD; its BLAS kernel
 * differs by CPU), kappa(K) growing like P^4 / h^2 for these nodal bases
 * (the SIPG penalty scales like the stiffness), a factor 10 for the
 * assembly's sums: 10 P^4 n^2 U (1 + umax).  Measured errors are 1e2 to
 * 1e4 times smaller with every OpenBLAS kernel; H1 errors are at most
 * 2 P^2 n times this (inverse inequality). */
static inline double sq_solve_roundoff(int P, int n, double umax)
{
    return 10.0 * pow(P, 4) * n * n * SQ_U * (1.0 + umax);
}

#endif
