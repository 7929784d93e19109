/* semquad sem/ — C0 modal basis on the triangle (cg_basis.h;
 * Karniadakis & Sherwin 2005, §3.2.3, eq. 3.2.x for the boundary/interior
 * decomposition in collapsed coordinates). */
#include "cg_basis.h"

#include "gauss.h"
#include "tri_basis.h"
#include "tri_quad.h"

#include <stdlib.h>
#include <string.h>

#define CGB_NMAX ((SEM_MAX_ORDER + 1) * (SEM_MAX_ORDER + 2) / 2)

void sem_cg_basis_eval_collapsed(int P, double r, double s, double *psi)
{
    const double x2 = 2.0 * s - 1.0;
    /* at the collapsed vertex every mode with a (1-b) factor vanishes and a
     * is arbitrary */
    const double a = (1.0 - x2) > 1e-300 ? 2.0 * (2.0 * r) / (1.0 - x2) - 1.0 : -1.0;
    const double b = x2;
    const double am = 0.5 * (1.0 - a), ap = 0.5 * (1.0 + a);
    const double bm = 0.5 * (1.0 - b), bp = 0.5 * (1.0 + b);
    psi[0] = am * bm;
    psi[1] = ap * bm;
    psi[2] = bp;
    if (P < 2) return;
    double bmp = bm; /* bm^(p+1) */
    for (int p = 1; p <= P - 1; ++p) {
        bmp *= bm;
        const double pa = am * ap * sem_jacobi(p - 1, 1.0, 1.0, a, NULL);
        psi[sem_cg_edge_mode(P, 0, p)] = pa * bmp;
        psi[sem_cg_edge_mode(P, 1, p)] = ap * bm * bp * sem_jacobi(p - 1, 1.0, 1.0, b, NULL);
        psi[sem_cg_edge_mode(P, 2, p)] = am * bm * bp * sem_jacobi(p - 1, 1.0, 1.0, -b, NULL);
    }
    int m = 3 * P;
    bmp = bm;
    for (int p = 1; p <= P - 2; ++p) {
        bmp *= bm;
        const double pa = am * ap * sem_jacobi(p - 1, 1.0, 1.0, a, NULL) * bmp * bp;
        for (int q = 1; p + q <= P - 1; ++q)
            psi[m++] = pa * sem_jacobi(q - 1, 2.0 * p + 1.0, 1.0, b, NULL);
    }
}

sq_status sem_cg_basis_create(int P, sem_cg_basis **out, sq_error *err)
{
    if (!out) return SQ_FAIL(err, SQ_ERR_USAGE, "cg_basis_create: NULL output");
    *out = NULL;
    if (P < 1 || P > SEM_MAX_ORDER)
        return SQ_FAIL(err, SQ_ERR_USAGE, "cg_basis_create: order %d outside 1..%d", P,
                       SEM_MAX_ORDER);
    sem_cg_basis *b = calloc(1, sizeof *b);
    if (!b) return SQ_FAIL(err, SQ_ERR_INTERNAL, "cg_basis_create: out of memory");
    b->P = P;
    b->nloc = (P + 1) * (P + 2) / 2;
    b->nb = 3 * P;
    b->ni = (P - 1) * (P - 2) / 2;
    const int n = b->nloc;
    b->C = calloc((size_t)n * n, sizeof(double));
    sem_tri_quad *q = NULL;
    sq_status st = SQ_OK;
    if (!b->C) {
        st = SQ_FAIL(err, SQ_ERR_INTERNAL, "cg_basis_create: out of memory");
        goto fail;
    }
    /* C[i][m] = ∫_T psi_i phi_m: both of degree <= P, the Dubiner modes
     * orthonormal, so a rule of degree 2P gives the exact expansion. */
    if ((st = sem_tri_quad_create(2 * P, &q, err)) != SQ_OK) goto fail;
    for (int k = 0; k < q->npts; ++k) {
        double psi[CGB_NMAX], phi[CGB_NMAX];
        sem_cg_basis_eval_collapsed(P, q->rs[2 * k], q->rs[2 * k + 1], psi);
        sem_tri_dubiner(P, q->rs[2 * k], q->rs[2 * k + 1], phi, NULL, NULL);
        for (int i = 0; i < n; ++i) {
            const double wi = q->w[k] * psi[i];
            for (int m = 0; m < n; ++m) b->C[(size_t)i * n + m] += wi * phi[m];
        }
    }
    sem_tri_quad_free(&q);
    *out = b;
    return SQ_OK;
fail:
    sem_tri_quad_free(&q);
    sem_cg_basis_free(&b);
    return st;
}

void sem_cg_basis_free(sem_cg_basis **b)
{
    if (!b || !*b) return;
    free((*b)->C);
    free(*b);
    *b = NULL;
}

void sem_cg_basis_eval(const sem_cg_basis *b, double r, double s, double *psi, double *dr,
                       double *ds)
{
    double phi[CGB_NMAX], pr[CGB_NMAX], ps[CGB_NMAX];
    const int n = b->nloc;
    sem_tri_dubiner(b->P, r, s, phi, dr ? pr : NULL, ds ? ps : NULL);
    for (int i = 0; i < n; ++i) {
        const double *c = b->C + (size_t)i * n;
        double v = 0.0, x = 0.0, y = 0.0;
        for (int m = 0; m < n; ++m) {
            v += c[m] * phi[m];
            if (dr) x += c[m] * pr[m];
            if (ds) y += c[m] * ps[m];
        }
        if (psi) psi[i] = v;
        if (dr) dr[i] = x;
        if (ds) ds[i] = y;
    }
}
