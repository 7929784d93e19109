/* semquad sem/ — one-dimensional Gauss rules and Jacobi polynomials.
 *
 * Gauss–Jacobi nodes come from GSL's fixed-rule (Golub–Welsch) solver, are
 * polished by Newton on P_n^{(alpha,beta)} and get their weights from the
 * closed form (Karniadakis & Sherwin 2005, Appendix B, Gauss–Jacobi weights), which
 * keeps the relative accuracy of small weights near the end points that an
 * eigenvector-based weight loses. */
#include "gauss.h"

#include <gsl/gsl_integration.h>
#include <math.h>
#include <stdlib.h>

double sem_jacobi(int n, double alpha, double beta, double x, double *dp)
{
    /* Three-term recurrence (Karniadakis & Sherwin 2005, Appendix A); the
     * derivative follows by differentiating the recurrence term by term. */
    if (n <= 0) {
        if (dp) *dp = 0.0;
        return 1.0;
    }
    const double ab = alpha + beta;
    double p0 = 1.0, d0 = 0.0;
    double p1 = 0.5 * ((alpha - beta) + (ab + 2.0) * x);
    double d1 = 0.5 * (ab + 2.0);
    for (int k = 1; k < n; ++k) {
        const double k2ab = 2.0 * k + ab;
        const double a1 = 2.0 * (k + 1) * (k + ab + 1.0) * k2ab;
        const double a2 = (k2ab + 1.0) * (alpha * alpha - beta * beta);
        const double a3 = (k2ab + 1.0) * (k2ab + 2.0) * k2ab;
        const double a4 = 2.0 * (k + alpha) * (k + beta) * (k2ab + 2.0);
        const double p2 = ((a2 + a3 * x) * p1 - a4 * p0) / a1;
        const double d2 = (a3 * p1 + (a2 + a3 * x) * d1 - a4 * d0) / a1;
        p0 = p1;
        p1 = p2;
        d0 = d1;
        d1 = d2;
    }
    if (dp) *dp = d1;
    return p1;
}

static int cmp_double(const void *a, const void *b)
{
    const double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

sq_status sem_gauss_jacobi(int n, double alpha, double beta, double *x, double *w, sq_error *err)
{
    if (n < 1 || !(alpha > -1.0) || !(beta > -1.0) || !x || !w)
        return SQ_FAIL(err, SQ_ERR_USAGE, "gauss_jacobi: bad arguments n=%d alpha=%g beta=%g", n,
                       alpha, beta);

    /* GSL's weight on [a,b] is (b-x)^alpha (x-a)^beta: with a=-1, b=1 it is
     * ours.  The arguments are checked above, so GSL's error handler (a
     * process-wide setting we leave to the application) can only be reached
     * if memory runs out. */
    gsl_integration_fixed_workspace *ws =
        gsl_integration_fixed_alloc(gsl_integration_fixed_jacobi, (size_t)n, -1.0, 1.0, alpha, beta);
    if (!ws)
        return SQ_FAIL(err, SQ_ERR_INTERNAL, "gauss_jacobi: GSL failed for n=%d alpha=%g beta=%g", n,
                       alpha, beta);
    const double *gx = gsl_integration_fixed_nodes(ws);
    for (int i = 0; i < n; ++i) x[i] = gx[i];
    gsl_integration_fixed_free(ws);
    qsort(x, (size_t)n, sizeof *x, cmp_double);

    /* Newton polish; the eigenvalue start is already within a few ulps. */
    for (int i = 0; i < n; ++i) {
        for (int it = 0; it < 3; ++it) {
            double dp;
            const double p = sem_jacobi(n, alpha, beta, x[i], &dp);
            if (dp == 0.0) break;
            const double dx = p / dp;
            if (!(fabs(dx) < 1e-8)) break; /* not in the basin: keep GSL's value */
            x[i] -= dx;
            if (fabs(dx) < 1e-17) break;
        }
    }
    if (alpha == beta) /* exact symmetry of symmetric rules */
        for (int i = 0; i < n / 2; ++i) {
            const double m = 0.5 * (x[n - 1 - i] - x[i]);
            x[i] = -m;
            x[n - 1 - i] = m;
        }
    if (n % 2 == 1 && alpha == beta) x[n / 2] = 0.0;

    /* w_i = 2^{a+b+1} G(n+a+1) G(n+b+1) / (n! G(n+a+b+1)) / ((1-x_i^2) P_n'(x_i)^2)
     * (Karniadakis & Sherwin 2005, Appendix B).  The Gamma ratio is built as
     * a product of n ratios (one rounding each) rather than exp of a sum of
     * lgamma's, whose cancellation costs ~1e-14. */
    double c = exp2(alpha + beta + 1.0) * tgamma(alpha + 2.0) * tgamma(beta + 2.0) / tgamma(alpha + beta + 2.0);
    for (int k = 1; k < n; ++k)
        c *= (k + alpha + 1.0) * (k + beta + 1.0) / ((k + 1.0) * (k + alpha + beta + 1.0));
    for (int i = 0; i < n; ++i) {
        double dp;
        sem_jacobi(n, alpha, beta, x[i], &dp);
        w[i] = c / ((1.0 - x[i] * x[i]) * dp * dp);
        if (!isfinite(w[i]) || !(w[i] > 0.0))
            return SQ_FAIL(err, SQ_ERR_INTERNAL, "gauss_jacobi: bad weight %g at node %d (n=%d)", w[i],
                           i, n);
    }
    return SQ_OK;
}

sq_status sem_gauss_lobatto(int n, double *x, double *w, sq_error *err)
{
    if (n < 2 || !x || !w) return SQ_FAIL(err, SQ_ERR_USAGE, "gauss_lobatto: bad arguments n=%d", n);
    /* Interior nodes: roots of P'_{n-1} = c P^{(1,1)}_{n-2}; weights
     * 2 / (n(n-1) P_{n-1}(x_i)^2) (Karniadakis & Sherwin 2005, Appendix B,
     * Gauss–Lobatto–Legendre). */
    x[0] = -1.0;
    x[n - 1] = 1.0;
    if (n > 2) {
        double *iw = w + 1; /* scratch: overwritten below */
        SQ_TRY(sem_gauss_jacobi(n - 2, 1.0, 1.0, x + 1, iw, err));
    }
    for (int i = 0; i < n; ++i) {
        const double p = sem_jacobi(n - 1, 0.0, 0.0, x[i], NULL);
        w[i] = 2.0 / ((double)n * (n - 1) * p * p);
    }
    return SQ_OK;
}
