/* semquad sem/ — nodal Lagrange basis on the sem_tri_nodes() set.
 *
 * With V_nm = phi_m(x_n) (Dubiner modes phi_m, nodes x_n), the nodal
 * functions are l_n = sum_m (V^{-1})_mn phi_m, since then
 * l_n(x_k) = (V V^{-1})_kn = delta_kn (Hesthaven & Warburton 2008, §6.1).
 * We keep V^{-1} row-major and evaluate l = sum_m phi_m(x) (row m of
 * V^{-1}): a sequence of axpy's whose inner loop vectorises without
 * reassociating sums. */
#include "tri_lagrange.h"

#include "lib_lock.h"
#include "gauss.h"
#include "tri_basis.h"
#include "tri_nodes.h"

#include <lapacke.h>
#include <stdlib.h>

#define SEM_MAX_NODES ((SEM_MAX_ORDER + 1) * (SEM_MAX_ORDER + 2) / 2)

struct sem_tri_lagrange {
    int P;
    int n;      /* number of nodes = number of modes */
    double *rs; /* 2n: node coordinates, lattice order */
    double *vinv; /* n*n: row-major V^{-1}, vinv[m*n + k] = (V^{-1})_{mk} */
};

sq_status sem_tri_lagrange_create(int P, sem_tri_lagrange **out, sq_error *err)
{
    if (!out) return SQ_FAIL(err, SQ_ERR_USAGE, "tri_lagrange_create: NULL output");
    *out = NULL;
    if (P < 1 || P > SEM_MAX_ORDER)
        return SQ_FAIL(err, SQ_ERR_USAGE, "tri_lagrange_create: order %d outside 1..%d", P,
                       SEM_MAX_ORDER);
    const int n = sem_tri_num_nodes(P);
    sem_tri_lagrange *L = calloc(1, sizeof *L);
    double *V = malloc(sizeof(double) * (size_t)n * (size_t)n);
    lapack_int *ipiv = malloc(sizeof(lapack_int) * (size_t)n);
    sq_status st = SQ_OK;
    if (!L || !V || !ipiv) {
        st = SQ_FAIL(err, SQ_ERR_INTERNAL, "tri_lagrange_create: out of memory");
        goto fail;
    }
    L->P = P;
    L->n = n;
    L->rs = malloc(sizeof(double) * 2 * (size_t)n);
    L->vinv = malloc(sizeof(double) * (size_t)n * (size_t)n);
    if (!L->rs || !L->vinv) {
        st = SQ_FAIL(err, SQ_ERR_INTERNAL, "tri_lagrange_create: out of memory");
        goto fail;
    }
    if ((st = sem_tri_nodes(P, L->rs, err)) != SQ_OK) goto fail;

    /* Row-major V: row k holds phi_m(x_k). */
    for (int k = 0; k < n; ++k) sem_tri_dubiner(P, L->rs[2 * k], L->rs[2 * k + 1], V + (size_t)k * n, NULL, NULL);
    sem_lib_lock();
    lapack_int info = LAPACKE_dgetrf(LAPACK_ROW_MAJOR, n, n, V, n, ipiv);
    if (info == 0) info = LAPACKE_dgetri(LAPACK_ROW_MAJOR, n, V, n, ipiv);
    sem_lib_unlock();
    if (info != 0) {
        st = SQ_FAIL(err, SQ_ERR_INTERNAL, "tri_lagrange_create: Vandermonde inversion failed (info %d, P=%d)",
                     (int)info, P);
        goto fail;
    }
    for (size_t k = 0; k < (size_t)n * (size_t)n; ++k) L->vinv[k] = V[k];
    free(V);
    free(ipiv);
    *out = L;
    return SQ_OK;

fail:
    free(V);
    free(ipiv);
    sem_tri_lagrange_free(&L);
    return st;
}

void sem_tri_lagrange_free(sem_tri_lagrange **lag)
{
    if (!lag || !*lag) return;
    free((*lag)->rs);
    free((*lag)->vinv);
    free(*lag);
    *lag = NULL;
}

int sem_tri_lagrange_order(const sem_tri_lagrange *lag) { return lag->P; }
int sem_tri_lagrange_num_nodes(const sem_tri_lagrange *lag) { return lag->n; }
const double *sem_tri_lagrange_nodes(const sem_tri_lagrange *lag) { return lag->rs; }

void sem_tri_lagrange_eval(const sem_tri_lagrange *lag, double r, double s, double *l, double *dr,
                           double *ds)
{
    /* Modes on the stack (P <= SEM_MAX_ORDER is checked at creation): no
     * allocation, and the object stays read-only so threads may share it. */
    double phi[SEM_MAX_NODES], pr[SEM_MAX_NODES], ps[SEM_MAX_NODES];
    const int n = lag->n;
    sem_tri_dubiner(lag->P, r, s, l ? phi : NULL, dr ? pr : NULL, ds ? ps : NULL);
    if (l && dr && ds) { /* the common case, fused */
        for (int k = 0; k < n; ++k) l[k] = dr[k] = ds[k] = 0.0;
        for (int m = 0; m < n; ++m) {
            const double *restrict row = lag->vinv + (size_t)m * n;
            const double a = phi[m], b = pr[m], c = ps[m];
            double *restrict lo = l, *restrict ro = dr, *restrict so = ds;
            for (int k = 0; k < n; ++k) {
                lo[k] += a * row[k];
                ro[k] += b * row[k];
                so[k] += c * row[k];
            }
        }
        return;
    }
    double *outs[3] = {l, dr, ds};
    const double *ins[3] = {phi, pr, ps};
    for (int o = 0; o < 3; ++o) {
        double *restrict y = outs[o];
        if (!y) continue;
        const double *x = ins[o];
        for (int k = 0; k < n; ++k) y[k] = 0.0;
        for (int m = 0; m < n; ++m) {
            const double *restrict row = lag->vinv + (size_t)m * n;
            const double a = x[m];
            for (int k = 0; k < n; ++k) y[k] += a * row[k];
        }
    }
}
