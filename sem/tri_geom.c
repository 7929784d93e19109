/* semquad sem/ — geometric factors of a curved isoparametric element.
 *
 * x(r,s) = sum_n g_n l_n(r,s) (tri_mesh.h), so J = sum_n g_n (grad l_n)^T.
 * det J is a polynomial of degree 2(order-1); the scaled Jacobian samples it
 * at the element's nodes and at the points of a degree-2*order collapsed
 * rule, which cover the interior and the collapsed corner region well. */
#include "tri_geom.h"

#include "gauss.h"
#include "tri_quad.h"

#include <math.h>
#include <stdlib.h>

#define SEM_MAX_NODES ((SEM_MAX_ORDER + 1) * (SEM_MAX_ORDER + 2) / 2)
#define SEM_MAX_SAMPLES (SEM_MAX_NODES + (SEM_MAX_ORDER + 1) * (SEM_MAX_ORDER + 1))

struct sem_tri_geom_sampler {
    int nn;      /* Lagrange nodes */
    int npts;    /* sample points */
    double *dlr; /* nn*npts: dl_n/dr at point p, row n (node-major so the
                    per-element sums are axpy's over points, which vectorise) */
    double *dls; /* nn*npts: dl_n/ds */
    double *w;   /* npts - nn: weights of the rule points (after the nodes) */
};

double sem_tri_geom_map(const sem_tri_lagrange *lag, const double *gxy, double r, double s,
                        double x[2], double jac[4])
{
    double l[SEM_MAX_NODES], lr[SEM_MAX_NODES], ls[SEM_MAX_NODES];
    const int n = sem_tri_lagrange_num_nodes(lag);
    sem_tri_lagrange_eval(lag, r, s, x ? l : NULL, lr, ls);
    double xr = 0.0, xs = 0.0, yr = 0.0, ys = 0.0;
    for (int k = 0; k < n; ++k) {
        const double gx = gxy[2 * k], gy = gxy[2 * k + 1];
        xr += gx * lr[k];
        xs += gx * ls[k];
        yr += gy * lr[k];
        ys += gy * ls[k];
    }
    if (x) {
        double px = 0.0, py = 0.0;
        for (int k = 0; k < n; ++k) {
            px += gxy[2 * k] * l[k];
            py += gxy[2 * k + 1] * l[k];
        }
        x[0] = px;
        x[1] = py;
    }
    if (jac) {
        jac[0] = xr;
        jac[1] = xs;
        jac[2] = yr;
        jac[3] = ys;
    }
    return xr * ys - xs * yr;
}

sq_status sem_tri_geom_sampler_create(const sem_tri_lagrange *lag, sem_tri_geom_sampler **out,
                                      sq_error *err)
{
    if (!out) return SQ_FAIL(err, SQ_ERR_USAGE, "tri_geom_sampler_create: NULL output");
    *out = NULL;
    if (!lag) return SQ_FAIL(err, SQ_ERR_USAGE, "tri_geom_sampler_create: NULL basis");
    const int P = sem_tri_lagrange_order(lag), nn = sem_tri_lagrange_num_nodes(lag);
    const double *nodes = sem_tri_lagrange_nodes(lag);
    sem_tri_quad *q = NULL;
    SQ_TRY(sem_tri_quad_create(2 * P, &q, err));
    sem_tri_geom_sampler *S = calloc(1, sizeof *S);
    if (!S) {
        sem_tri_quad_free(&q);
        return SQ_FAIL(err, SQ_ERR_INTERNAL, "tri_geom_sampler_create: out of memory");
    }
    S->nn = nn;
    S->npts = nn + q->npts;
    S->dlr = malloc(sizeof(double) * (size_t)S->npts * (size_t)nn);
    S->dls = malloc(sizeof(double) * (size_t)S->npts * (size_t)nn);
    S->w = malloc(sizeof(double) * (size_t)q->npts);
    if (!S->dlr || !S->dls || !S->w) {
        sem_tri_quad_free(&q);
        sem_tri_geom_sampler_free(&S);
        return SQ_FAIL(err, SQ_ERR_INTERNAL, "tri_geom_sampler_create: out of memory");
    }
    double lr[SEM_MAX_NODES], ls[SEM_MAX_NODES];
    for (int p = 0; p < S->npts; ++p) {
        const double *rs = p < nn ? nodes + 2 * p : q->rs + 2 * (p - nn);
        sem_tri_lagrange_eval(lag, rs[0], rs[1], NULL, lr, ls);
        for (int k = 0; k < nn; ++k) {
            S->dlr[(size_t)k * S->npts + p] = lr[k];
            S->dls[(size_t)k * S->npts + p] = ls[k];
        }
    }
    for (int p = 0; p < q->npts; ++p)
        S->w[p] = q->w[p];
    sem_tri_quad_free(&q);
    *out = S;
    return SQ_OK;
}

void sem_tri_geom_sampler_free(sem_tri_geom_sampler **s)
{
    if (!s || !*s) return;
    free((*s)->dlr);
    free((*s)->dls);
    free((*s)->w);
    free(*s);
    *s = NULL;
}

/* det J at every sample point (det[S->npts]) */
static void sample_det(const sem_tri_geom_sampler *S, const double *gxy, double *det)
{
    /* At most SEM_MAX_NODES nodes plus (SEM_MAX_ORDER+1)^2 rule points. */
    double xr[SEM_MAX_SAMPLES], xs[SEM_MAX_SAMPLES], yr[SEM_MAX_SAMPLES], ys[SEM_MAX_SAMPLES];
    const int nn = S->nn, np = S->npts;
    for (int p = 0; p < np; ++p)
        xr[p] = xs[p] = yr[p] = ys[p] = 0.0;
    /* two nodes per sweep: the sums load and store their partial values
     * half as often, and add in the same node order (left to right) */
    int k = 0;
    for (; k + 1 < nn; k += 2) {
        const double gx = gxy[2 * k], gy = gxy[2 * k + 1], hx = gxy[2 * k + 2], hy = gxy[2 * k + 3];
        const double *restrict lr = S->dlr + (size_t)k * np, *restrict ls = S->dls + (size_t)k * np;
        const double *restrict mr = lr + np, *restrict ms = ls + np;
        for (int p = 0; p < np; ++p) {
            xr[p] = xr[p] + gx * lr[p] + hx * mr[p];
            xs[p] = xs[p] + gx * ls[p] + hx * ms[p];
            yr[p] = yr[p] + gy * lr[p] + hy * mr[p];
            ys[p] = ys[p] + gy * ls[p] + hy * ms[p];
        }
    }
    for (; k < nn; ++k) {
        const double gx = gxy[2 * k], gy = gxy[2 * k + 1];
        const double *restrict lr = S->dlr + (size_t)k * np, *restrict ls = S->dls + (size_t)k * np;
        for (int p = 0; p < np; ++p) {
            xr[p] += gx * lr[p];
            xs[p] += gx * ls[p];
            yr[p] += gy * lr[p];
            ys[p] += gy * ls[p];
        }
    }
    for (int p = 0; p < np; ++p)
        det[p] = xr[p] * ys[p] - xs[p] * yr[p];
}

/* min det J / max det J of the samples (negative when none is positive) */
static double ratio_of(const sem_tri_geom_sampler *S, const double *det)
{
    double jmin = HUGE_VAL, jmax = -HUGE_VAL;
    for (int p = 0; p < S->npts; ++p) {
        const double d = det[p];
        if (isnan(d)) return NAN; /* non-finite geometry nodes */
        if (d < jmin) jmin = d;
        if (d > jmax) jmax = d;
    }
    if (jmax > 0.0) return jmin / jmax;
    /* Every sample non-positive (e.g. a clockwise element): min/max would
     * be positive, so report the ratio with a negative sign instead. */
    if (jmax < 0.0) return jmin / -jmax; /* <= -1 */
    return jmin < 0.0 ? -1.0 : 0.0;
}

double sem_tri_geom_sampler_scaled_jacobian(const sem_tri_geom_sampler *S, const double *gxy)
{
    double det[SEM_MAX_SAMPLES];
    sample_det(S, gxy, det);
    return ratio_of(S, det);
}

double sem_tri_geom_sampler_measure(const sem_tri_geom_sampler *S, const double *gxy, double *area)
{
    double det[SEM_MAX_SAMPLES];
    sample_det(S, gxy, det);
    double a = 0.0; /* the rule's points follow the nodes */
    for (int p = S->nn; p < S->npts; ++p)
        a += S->w[p - S->nn] * det[p];
    *area = a;
    return ratio_of(S, det);
}

double sem_tri_geom_scaled_jacobian(const sem_tri_lagrange *lag, const double *gxy)
{
    sem_tri_geom_sampler *S = NULL;
    if (sem_tri_geom_sampler_create(lag, &S, NULL) != SQ_OK) return NAN;
    const double sj = sem_tri_geom_sampler_scaled_jacobian(S, gxy);
    sem_tri_geom_sampler_free(&S);
    return sj;
}
