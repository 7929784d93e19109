#include "tri_curve.h"

#include "gauss.h"
#include "tri_nodes.h"

#include <stdlib.h>
#include <string.h>

/* 1D Lagrange polynomials through the GLL points xi[0..P] at t. */
static void lagrange_1d(int P, const double *xi, double t, double *h)
{
    for (int i = 0; i <= P; i++) {
        double v = 1.0;
        for (int j = 0; j <= P; j++)
            if (j != i) v *= (t - xi[j]) / (xi[i] - xi[j]);
        h[i] = v;
    }
}

/* Displacement of the GLL points of curved edge k of element e from the
 * straight edge: d[2*(P+1)]. */
static sq_status edge_displacement(const cad_face *face, const sem_tri_mesh *m, const double *bs,
                                   int e, int k, const double *xi, double *d, sq_error *err)
{
    int P = m->order;
    const double *A = &m->vxy[2 * m->tri[3 * e + k]];
    const double *B = &m->vxy[2 * m->tri[3 * e + (k + 1) % 3]];
    double sa = bs[6 * e + 2 * k], sb = bs[6 * e + 2 * k + 1];
    for (int i = 0; i <= P; i++) {
        double f = 0.5 * (1.0 + xi[i]), X[2];
        SQ_TRY(cad_face_edge_eval(face, m->btag[3 * e + k], sa + (sb - sa) * f, X, NULL, NULL,
                                  err));
        d[2 * i] = X[0] - (A[0] + f * (B[0] - A[0]));
        d[2 * i + 1] = X[1] - (A[1] + f * (B[1] - A[1]));
    }
    /* The ends are the element's own vertices. */
    d[0] = d[1] = d[2 * P] = d[2 * P + 1] = 0.0;
    return SQ_OK;
}

sq_status sq_tri_curve(const cad_face *face, sem_tri_mesh *mesh, const double *bs,
                       const sem_tri_geom_sampler *sampler, double *jac_min, double *area,
                       sq_error *err)
{
    int P = mesh->order, nn = mesh->nodes_per_tri;
    double *rs = malloc(sizeof(double) * 2 * (size_t)nn);
    double *xi = malloc(sizeof(double) * (size_t)(P + 1));
    double *w = malloc(sizeof(double) * (size_t)(P + 1));
    double *d = malloc(sizeof(double) * 2 * (size_t)(P + 1));
    double *h = malloc(sizeof(double) * (size_t)(P + 1));
    sq_status st = SQ_OK;
    if (!rs || !xi || !w || !d || !h) {
        st = SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
        goto done;
    }
    if ((st = sem_tri_nodes(P, rs, err)) != SQ_OK) goto done;
    if (P >= 1 && (st = sem_gauss_lobatto(P + 1, xi, w, err)) != SQ_OK) goto done;
    *area = 0.0;
    for (int e = 0; e < mesh->ntris && st == SQ_OK; e++) {
        const int *v = &mesh->tri[3 * e];
        double *g = &mesh->gxy[2 * (size_t)nn * (size_t)e];
        for (int n = 0; n < nn; n++) {
            double r = rs[2 * n], s = rs[2 * n + 1], lam[3] = {1.0 - r - s, r, s};
            for (int c = 0; c < 2; c++)
                g[2 * n + c] = lam[0] * mesh->vxy[2 * v[0] + c] + lam[1] * mesh->vxy[2 * v[1] + c] +
                               lam[2] * mesh->vxy[2 * v[2] + c];
        }
        for (int k = 0; k < 3 && P > 1; k++) {
            if (mesh->btag[3 * e + k] < 0) continue;
            if ((st = edge_displacement(face, mesh, bs, e, k, xi, d, err)) != SQ_OK) break;
            /* Blending: the edge displacement D(t), t = lam_B - lam_A, scaled
             * by 4 lam_A lam_B / (1 - t^2), which is 1 on the edge and 0 on
             * the two other edges (Szabó & Babuška 1991, §12.3). */
            for (int n = 0; n < nn; n++) {
                double r = rs[2 * n], s = rs[2 * n + 1], lam[3] = {1.0 - r - s, r, s};
                double la = lam[k], lb = lam[(k + 1) % 3];
                if (la <= 1e-14 || lb <= 1e-14) continue;
                double t = lb - la, f = 4.0 * la * lb / ((1.0 - t) * (1.0 + t));
                lagrange_1d(P, xi, t, h);
                for (int i = 1; i < P; i++) {
                    g[2 * n] += f * h[i] * d[2 * i];
                    g[2 * n + 1] += f * h[i] * d[2 * i + 1];
                }
            }
        }
        double a = 0.0;
        if (st == SQ_OK) jac_min[e] = sem_tri_geom_sampler_measure(sampler, g, &a);
        *area += a;
    }
done:
    free(rs);
    free(xi);
    free(w);
    free(d);
    free(h);
    return st;
}
