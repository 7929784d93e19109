/* t104: the collapsed Gauss rule on T integrates r^a s^b exactly
 * (a! b! / (a+b+2)!) for a+b <= degree, degree = 0..32; points lie inside
 * T and weights are positive and sum to 1/2. */
#include "tri_quad.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

/* Unit round-off.  The rule is a product of two Gauss-Jacobi rules of n
 * points (n^2 = npts): each weight is off by 2 * 4 n U relative (t101), a
 * point by a few U; no BLAS. */
#define U (DBL_EPSILON / 2)

static int failures;

static void check(const char *what, int d, int a, int b, double value, double expected, double tol)
{
    if (!(fabs(value - expected) <= tol)) {
        printf("t104 %s (degree %d, r^%d s^%d): value %.17g expected %.17g tolerance %g\n", what, d, a, b,
               value, expected, tol);
        ++failures;
    }
}

/* a! b! / (a+b+2)! as a product of ratios, no overflow */
static double exact(int a, int b)
{
    double v = 1.0 / ((a + b + 1.0) * (a + b + 2.0));
    for (int j = 1; j <= b; ++j) v *= (double)j / (a + j);
    return v;
}

int main(void)
{
    double worst = 0.0;
    for (int d = 0; d <= 32; ++d) {
        sem_tri_quad *q = NULL;
        if (sem_tri_quad_create(d, &q, NULL) != SQ_OK) {
            printf("t104 quad_create(%d) failed\n", d);
            return 1;
        }
        double ws = 0.0;
        for (int k = 0; k < q->npts; ++k) {
            const double r = q->rs[2 * k], s = q->rs[2 * k + 1];
            if (!(r > 0 && s > 0 && r + s < 1 && q->w[k] > 0))
                check("point inside T with positive weight", d, k, 0, r + s, 0.5, 0.5);
            ws += q->w[k];
        }
        const double n = sqrt(q->npts);
        /* npts positive terms: (npts + 8 n) U of the sum 1/2 */
        check("sum of weights", d, 0, 0, ws, 0.5, (q->npts + 8 * n) * U * 0.5);
        for (int a = 0; a <= d; ++a)
            for (int b = 0; a + b <= d; ++b) {
                double v = 0.0;
                for (int k = 0; k < q->npts; ++k)
                    v += q->w[k] * pow(q->rs[2 * k], a) * pow(q->rs[2 * k + 1], b);
                const double e = exact(a, b);
                worst = fmax(worst, fabs(v / e - 1.0));
                /* positive terms: the sum's npts U, the weights' 8 n U, the
                 * monomial's (a + b) few U from the points' */
                check("monomial (relative)", d, a, b, v / e, 1.0, (q->npts + 8 * n + 4 * (a + b)) * U);
            }
        sem_tri_quad_free(&q);
        if (q) {
            printf("t104 free did not NULL the pointer\n");
            ++failures;
        }
    }
    /* a rule of n^2 points, n = degree/2+1, is not exact one degree past 2n-1 */
    sem_tri_quad *q = NULL;
    if (sem_tri_quad_create(5, &q, NULL) != SQ_OK) return 1;
    double v = 0.0;
    for (int k = 0; k < q->npts; ++k) v += q->w[k] * pow(q->rs[2 * k + 1], 6);
    if (!(fabs(v / exact(0, 6) - 1.0) > 1e-6)) {
        printf("t104 degree-5 rule unexpectedly exact for s^6: %.17g vs %.17g\n", v, exact(0, 6));
        ++failures;
    }
    sem_tri_quad_free(&q);
    sem_tri_quad_free(NULL);
    if (sem_tri_quad_create(-1, &q, NULL) != SQ_ERR_USAGE || q) {
        printf("t104 negative degree accepted\n");
        ++failures;
    }
    if (getenv("SQ_VERBOSE")) printf("t104 worst relative monomial error %.3g\n", worst);
    return failures ? 1 : 0;
}
