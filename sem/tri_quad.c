/* semquad sem/ — collapsed Gauss quadrature on the reference triangle.
 *
 * With r = (1+a)(1-b)/4, s = (1+b)/2 (a, b in [-1,1]) dr ds = (1-b)/8 da db,
 * so int_T f = 1/8 int int f (1-b) da db (Karniadakis & Sherwin 2005, §4.1).
 * A monomial r^i s^j has degree i in a and, once the factor (1-b) is put in
 * the weight, degree i+j in b: n Gauss–Legendre points in a and n
 * Gauss–Jacobi(1,0) points in b, n = ceil((degree+1)/2), are exact. */
#include "tri_quad.h"

#include "gauss.h"

#include <stdlib.h>

sq_status sem_tri_quad_create(int degree, sem_tri_quad **out, sq_error *err)
{
    if (!out) return SQ_FAIL(err, SQ_ERR_USAGE, "tri_quad_create: NULL output");
    *out = NULL;
    if (degree < 0 || degree > 200)
        return SQ_FAIL(err, SQ_ERR_USAGE, "tri_quad_create: degree %d outside 0..200", degree);
    const int n = degree / 2 + 1; /* smallest n with 2n - 1 >= degree */
    sq_status st = SQ_OK;
    sem_tri_quad *q = calloc(1, sizeof *q);
    double *buf = malloc(sizeof(double) * 4 * (size_t)n);
    if (!q || !buf) {
        st = SQ_FAIL(err, SQ_ERR_INTERNAL, "tri_quad_create: out of memory");
        goto fail;
    }
    double *xa = buf, *wa = buf + n, *xb = buf + 2 * n, *wb = buf + 3 * n;
    if ((st = sem_gauss_jacobi(n, 0.0, 0.0, xa, wa, err)) != SQ_OK) goto fail;
    if ((st = sem_gauss_jacobi(n, 1.0, 0.0, xb, wb, err)) != SQ_OK) goto fail;
    q->npts = n * n;
    q->rs = malloc(sizeof(double) * 2 * (size_t)q->npts);
    q->w = malloc(sizeof(double) * (size_t)q->npts);
    if (!q->rs || !q->w) {
        st = SQ_FAIL(err, SQ_ERR_INTERNAL, "tri_quad_create: out of memory");
        goto fail;
    }
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const int k = j * n + i;
            q->rs[2 * k] = 0.25 * (1.0 + xa[i]) * (1.0 - xb[j]);
            q->rs[2 * k + 1] = 0.5 * (1.0 + xb[j]);
            q->w[k] = 0.125 * wa[i] * wb[j];
        }
    free(buf);
    *out = q;
    return SQ_OK;

fail:
    free(buf);
    sem_tri_quad_free(&q);
    return st;
}

void sem_tri_quad_free(sem_tri_quad **q)
{
    if (!q || !*q) return;
    free((*q)->rs);
    free((*q)->w);
    free(*q);
    *q = NULL;
}
