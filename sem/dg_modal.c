/* semquad sem/ — fast modal (Dubiner) tabulation and modal geometry.
 *
 * Same construction as tri_basis.c: with u = 2r - 1 + s, t = 1 - s,
 * b = 2s - 1, phi_pq = c_pq Q_p(u,t) P_q^{(2p+1,0)}(b), where
 * (k+1) Q_{k+1} = (2k+1) u Q_k - k t^2 Q_{k-1} (Legendre recurrence times
 * t^{k+1}, no division by 1 - s) and the Jacobi three-term recurrence of
 * Karniadakis & Sherwin 2005, Appendix A. */
#include "dg_modal.h"

#include "tri_basis.h"
#include "tri_lagrange.h"
#include "tri_nodes.h"
#include "tri_quad.h"

#include <math.h>
#include <stdlib.h>

void sem_dubiner_tab_init(sem_dubiner_tab *T, int P)
{
    if (P < 0) P = 0;
    if (P > SEM_MAX_ORDER) P = SEM_MAX_ORDER;
    T->P = P;
    T->nmodes = sem_tri_num_nodes(P);
    for (int p = 0; p <= P; ++p) {
        const double al = 2.0 * p + 1.0;
        for (int q = 0; p + q <= P; ++q) {
            T->c[p][q] = sqrt(2.0 * al * (p + q + 1.0));
            /* coefficients taking P_k, P_{k-1} to P_{k+1}, k = q >= 1 */
            const int k = q;
            const double k2a = 2.0 * k + al;
            const double a1 = 2.0 * (k + 1) * (k + al + 1.0) * k2a;
            const double a2 = (k2a + 1.0) * al * al;
            const double a3 = (k2a + 1.0) * (k2a + 2.0) * k2a;
            const double a4 = 2.0 * (k + al) * k * (k2a + 2.0);
            T->ja[p][q] = a2 / a1;
            T->jb[p][q] = a3 / a1;
            T->jc[p][q] = a4 / a1;
        }
    }
}

void sem_dubiner_tab_eval(const sem_dubiner_tab *T, double r, double s, double *phi, double *dr,
                          double *ds)
{
    const int P = T->P;
    const double u = 2.0 * r - 1.0 + s, t = 1.0 - s, t2 = t * t, b = 2.0 * s - 1.0;
    double qm = 0.0, qmr = 0.0, qms = 0.0, q = 1.0, qr = 0.0, qs = 0.0;
    const int deriv = dr && ds;
    for (int p = 0; p <= P; ++p) {
        if (p > 0) {
            const int k = p - 1;
            const double A = (2.0 * k + 1.0) / (k + 1.0), C = (double)k / (k + 1.0);
            const double qn = A * u * q - C * t2 * qm;
            const double qnr = A * (2.0 * q + u * qr) - C * t2 * qmr;
            const double qns = A * (q + u * qs) - C * (t2 * qms - 2.0 * t * qm);
            qm = q;
            qmr = qr;
            qms = qs;
            q = qn;
            qr = qnr;
            qs = qns;
        }
        const double al = 2.0 * p + 1.0;
        double j0 = 1.0, jd0 = 0.0;
        double j1 = 0.5 * (al + (al + 2.0) * b), jd1 = 0.5 * (al + 2.0);
        /* mode (p,n) has index n*(P+1) - n(n-1)/2 + p: row stride shrinks */
        int m = p, stride = P + 1;
        const double *c = T->c[p];
        for (int n = 0; n + p <= P; ++n) {
            double jv, jd;
            if (n == 0) {
                jv = j0;
                jd = jd0;
            } else if (n == 1) {
                jv = j1;
                jd = jd1;
            } else {
                const int k = n - 1;
                const double A = T->ja[p][k] + T->jb[p][k] * b;
                jv = A * j1 - T->jc[p][k] * j0;
                jd = T->jb[p][k] * j1 + A * jd1 - T->jc[p][k] * jd0;
                j0 = j1;
                jd0 = jd1;
                j1 = jv;
                jd1 = jd;
            }
            phi[m] = c[n] * q * jv;
            if (deriv) {
                dr[m] = c[n] * qr * jv;
                ds[m] = c[n] * (qs * jv + 2.0 * q * jd);
            }
            m += stride;
            --stride;
        }
    }
}

sq_status sem_modal_geometry(const sem_tri_mesh *mesh, double **out, sq_error *err)
{
    if (!out) return SQ_FAIL(err, SQ_ERR_USAGE, "modal_geometry: NULL output");
    *out = NULL;
    if (!mesh || mesh->order < 1 || mesh->order > SEM_MAX_ORDER)
        return SQ_FAIL(err, SQ_ERR_USAGE, "modal_geometry: bad mesh");
    const int go = mesh->order, nm = sem_tri_num_nodes(go), nn = mesh->nodes_per_tri;
    sem_tri_lagrange *lag = NULL;
    sem_tri_quad *q = NULL;
    double *lq = NULL, *pq = NULL, *gm = NULL, *xq = NULL;
    sq_status st = SQ_OK;
    if ((st = sem_tri_lagrange_create(go, &lag, err)) != SQ_OK) goto done;
    /* x phi_m has degree 2*order: the projection is exact. */
    if ((st = sem_tri_quad_create(2 * go, &q, err)) != SQ_OK) goto done;
    const int nq = q->npts;
    lq = malloc(sizeof(double) * (size_t)nq * (size_t)nn);
    pq = malloc(sizeof(double) * (size_t)nq * (size_t)nm);
    xq = malloc(sizeof(double) * 2 * (size_t)nq);
    gm = calloc(2 * (size_t)nm * (size_t)mesh->ntris + 1, sizeof(double));
    if (!lq || !pq || !xq || !gm) {
        st = SQ_FAIL(err, SQ_ERR_INTERNAL, "modal_geometry: out of memory (%d triangles)",
                     mesh->ntris);
        goto done;
    }
    /* lq node by node (lq[n nq + k] = l_n at point k) for sem_map_points */
    for (int k = 0; k < nq; ++k) {
        double l[SEM_MAX_MODES];
        sem_tri_lagrange_eval(lag, q->rs[2 * k], q->rs[2 * k + 1], l, NULL, NULL);
        for (int n = 0; n < nn; ++n) lq[(size_t)n * nq + k] = l[n];
        sem_tri_dubiner(go, q->rs[2 * k], q->rs[2 * k + 1], pq + (size_t)k * nm, NULL, NULL);
        for (int m = 0; m < nm; ++m) pq[(size_t)k * nm + m] *= q->w[k];
    }
    const double *X = xq, *Y = xq + nq;
    for (int e = 0; e < mesh->ntris; ++e) {
        sem_map_points(nn, mesh->gxy + 2 * (size_t)nn * e, lq, nq, xq, xq + nq);
        /* the coefficients summed point by point, x and y apart (contiguous
         * sums that vectorise), then interleaved */
        double ox[SEM_MAX_MODES] = {0}, oy[SEM_MAX_MODES] = {0};
        for (int k = 0; k < nq; ++k) {
            const double *restrict w = pq + (size_t)k * nm;
            const double xk = X[k], yk = Y[k];
            for (int m = 0; m < nm; ++m) {
                ox[m] += xk * w[m];
                oy[m] += yk * w[m];
            }
        }
        double *o = gm + 2 * (size_t)nm * e;
        for (int m = 0; m < nm; ++m) o[2 * m] = ox[m], o[2 * m + 1] = oy[m];
    }
done:
    free(lq);
    free(xq);
    free(pq);
    sem_tri_quad_free(&q);
    sem_tri_lagrange_free(&lag);
    if (st == SQ_OK)
        *out = gm;
    else
        free(gm);
    return st;
}
