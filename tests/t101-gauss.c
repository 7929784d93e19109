/* t101: Gauss–Jacobi and Gauss–Lobatto–Legendre rules integrate exactly the
 * polynomials they claim, and no more (a polynomial of degree one higher,
 * vanishing at every node, has a positive integral); Jacobi polynomials and
 * their derivatives match closed forms. */
#include "gauss.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

/* Unit round-off.  The rules come from GSL's eigenvalues polished by Newton
 * on the three-term recurrence and from closed-form weights (sem/gauss.c),
 * no BLAS: a node is off by a few U, a weight (a product of n ratios and
 * P_n' by an n-step recurrence) by about 4 n U relative. */
#define U (DBL_EPSILON / 2)

static int failures;

static void check(const char *what, int n, int k, double value, double expected, double tol)
{
    if (!(fabs(value - expected) <= tol)) {
        printf("t101 %s (n=%d, k=%d): value %.17g expected %.17g tolerance %g\n", what, n, k, value,
               expected, tol);
        ++failures;
    }
}

/* int_{-1}^{1} (1-x)^a (1+x)^b ((1+x)/2)^k dx = 2^{a+b+1} B(b+k+1, a+1):
 * a positive basis of monomials, so relative errors are meaningful. */
static double moment(double a, double b, int k)
{
    /* B(b+k+1, a+1) = B(b+1, a+1) prod_{j<k} (b+j+1)/(a+b+j+2): one rounding
     * per factor, unlike exp of a sum of lgamma's. */
    double m = exp2(a + b + 1.0) * tgamma(a + 1.0) * tgamma(b + 1.0) / tgamma(a + b + 2.0);
    for (int j = 0; j < k; ++j) m *= (b + j + 1.0) / (a + b + j + 2.0);
    return m;
}

/* Squared norm h_n of P_n^{(a,b)}. */
static double jacobi_norm(int n, double a, double b)
{
    return exp((a + b + 1.0) * log(2.0) - log(2.0 * n + a + b + 1.0) + lgamma(n + a + 1.0) +
               lgamma(n + b + 1.0) - lgamma(n + a + b + 1.0) - lgamma(n + 1.0));
}

int main(void)
{
    const double ab[][2] = {{0, 0}, {1, 0}, {1, 1}, {2, 0}, {0.5, -0.5}, {-0.5, -0.5}};
    double x[64], w[64];
    double worst = 0.0;
    for (size_t c = 0; c < sizeof ab / sizeof ab[0]; ++c) {
        const double a = ab[c][0], b = ab[c][1];
        for (int n = 1; n <= 24; ++n) {
            if (sem_gauss_jacobi(n, a, b, x, w, NULL) != SQ_OK) {
                printf("t101 gauss_jacobi(n=%d, %g, %g) failed\n", n, a, b);
                return 1;
            }
            for (int i = 1; i < n; ++i)
                if (!(x[i] > x[i - 1])) check("nodes ascending", n, i, x[i], x[i - 1], 0);
            /* exact through degree 2n-1 */
            for (int k = 0; k <= 2 * n - 1; ++k) {
                double q = 0.0;
                for (int i = 0; i < n; ++i) q += w[i] * pow(0.5 * (1.0 + x[i]), k);
                const double e = moment(a, b, k), rel = fabs(q - e) / e;
                if (rel > worst) worst = rel;
                /* n positive terms, each with its weight's 4 n U, the
                 * sum's n U and t^k's k U (a node's few U, times k):
                 * (5 n + k) U, at most 1.9e-14 for n <= 24. */
                check("Gauss-Jacobi moment (relative)", n, k, q / e, 1.0, (5.0 * n + k) * U);
            }
            /* not exact for degree 2n: P_n^2 vanishes at the nodes */
            double q = 0.0;
            for (int i = 0; i < n; ++i) {
                const double p = sem_jacobi(n, a, b, x[i], NULL);
                q += w[i] * p * p;
            }
            const double h = jacobi_norm(n, a, b);
            /* 1 if the rule were exact; at a node P_n is a few U n^2 max|P_n|,
             * so Q/h is round-off squared: 1e-12 only separates 0 from 1. */
            check("Gauss-Jacobi degree 2n not exact: Q[P_n^2]/h_n", n, 2 * n, q / h, 0.0, 1e-12);
        }
    }
    if (getenv("SQ_VERBOSE")) printf("t101 worst Gauss-Jacobi relative moment error %.3g\n", worst);

    /* Gauss–Lobatto–Legendre */
    for (int n = 2; n <= 24; ++n) {
        if (sem_gauss_lobatto(n, x, w, NULL) != SQ_OK) {
            printf("t101 gauss_lobatto(n=%d) failed\n", n);
            return 1;
        }
        check("GLL x[0]", n, 0, x[0], -1.0, 0.0);
        check("GLL x[n-1]", n, 0, x[n - 1], 1.0, 0.0);
        for (int k = 0; k <= 2 * n - 3; ++k) {
            double q = 0.0;
            for (int i = 0; i < n; ++i) q += w[i] * pow(0.5 * (1.0 + x[i]), k);
            /* as for Gauss-Jacobi: (5 n + k) U */
            check("GLL moment (relative)", n, k, q * (k + 1.0) / 2.0, 1.0, (5.0 * n + k) * U);
            double qm = 0.0; /* centred monomials x^k */
            for (int i = 0; i < n; ++i) qm += w[i] * pow(x[i], k);
            /* absolute: odd k cancel to 0 (symmetric rule: exactly, up to the
             * sum's order); terms |w x^k| <= w sum to 2, so (5 n + k) U * 2 */
            check("GLL x^k", n, k, qm, k % 2 ? 0.0 : 2.0 / (k + 1.0), (5.0 * n + k) * U * 2.0);
        }
        /* degree 2n-2: (1-x^2) P'_{n-1}(x)^2 vanishes at every GLL node */
        double q = 0.0, e = 0.0;
        for (int i = 0; i < n; ++i) {
            double dp;
            sem_jacobi(n - 1, 0, 0, x[i], &dp);
            q += w[i] * (1.0 - x[i] * x[i]) * dp * dp;
        }
        /* its integral, by a Gauss–Legendre rule exact for it */
        double gx[64], gw[64];
        sem_gauss_jacobi(n, 0, 0, gx, gw, NULL);
        for (int i = 0; i < n; ++i) {
            double dp;
            sem_jacobi(n - 1, 0, 0, gx[i], &dp);
            e += gw[i] * (1.0 - gx[i] * gx[i]) * dp * dp;
        }
        if (!(e > 0.1)) check("GLL tightness: integral positive", n, 2 * n - 2, e, 1.0, 0.9);
        /* 1 if exact; P'_{n-1} vanishes at the nodes up to round-off, squared */
        check("GLL degree 2n-2 not exact: Q/integral", n, 2 * n - 2, q / e, 0.0, 1e-12);
    }

    /* Jacobi polynomials: closed forms and the derivative identity
     * d/dx P_n^{(a,b)} = (n+a+b+1)/2 P_{n-1}^{(a+1,b+1)}.  Low degrees: a
     * few operations on |t| <= 1, values <= 3: 8 U * 3.  The
     * identity compares two n-step recurrences (n <= 16), each step a few U
     * of terms no larger than M_n = max |d/dx P_n| on [-1, 1] (sampled):
     * 4 n U M_n (2e-11 at n = 16, M_16 = 2.7e3). */
    double M[17] = {0};
    for (int n = 1; n <= 16; ++n)
        for (double t = -1.0; t <= 1.0; t += 1.0 / 64) {
            double d;
            sem_jacobi(n, 1.5, 0.5, t, &d);
            M[n] = fmax(M[n], fabs(d));
        }
    for (double t = -1.0; t <= 1.0; t += 0.125) {
        double d;
        const double p2 = sem_jacobi(2, 0, 0, t, &d);
        check("P_2", 2, 0, p2, 1.5 * t * t - 0.5, 24 * U);
        check("P_2'", 2, 0, d, 3.0 * t, 24 * U);
        const double p1 = sem_jacobi(1, 1, 0, t, &d);
        check("P_1^(1,0)", 1, 0, p1, 0.5 * (1.0 + 3.0 * t), 24 * U);
        for (int n = 1; n <= 16; ++n) {
            sem_jacobi(n, 1.5, 0.5, t, &d);
            const double ref = 0.5 * (n + 3.0) * sem_jacobi(n - 1, 2.5, 1.5, t, NULL);
            check("Jacobi derivative identity", n, 0, d, ref, 4.0 * n * U * M[n]);
        }
    }
    if (sem_gauss_jacobi(0, 0, 0, x, w, NULL) == SQ_OK || sem_gauss_jacobi(3, -1, 0, x, w, NULL) == SQ_OK ||
        sem_gauss_lobatto(1, x, w, NULL) == SQ_OK) {
        printf("t101 bad arguments accepted\n");
        ++failures;
    }
    return failures ? 1 : 0;
}
