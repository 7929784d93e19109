/* Newton on (u, v) = 0 (sq_field_newton_local, critical_points.h) stops
 * where it stops gaining, at zeros of multiplicity m = 1..4 (issue 14: the
 * disc's guiding field has a zero of index 4; Newton used to wander at the
 * round-off floor to its 120-step cap, ~100 evaluations per start).
 *
 * Field: w = u + iv = (z - z0)^m, z = r + is, z0 = 0.3 + 0.2i, projected
 * on the Dubiner basis of order 4 of one reference triangle (exact up to
 * round-off: degree m <= 4), Newton from z0 + 0.1 e^{0.7i}.
 * Tolerances from the quantity's own error:
 *  - the round-off of w at the zero, dw = nmodes eps sum_k |c_k phi_k|
 *    (a sum of nmodes products, each exact to eps), times 10 for the
 *    modes' own evaluation: the returned |w| is below it (no gain was
 *    left: the residual is at round-off);
 *  - |w| = |z - z0|^m, so the zero is determined to dw^(1/m) only (a
 *    perturbation dw splits it into m roots of that radius): the root is
 *    within 2 dw^(1/m) of z0 (1e-14 for m = 1, ~1e-4 for m = 4);
 *  - the evaluations: near the zero Newton's step is (z - z0)/m, which
 *    multiplies |w| by rho = ((m-1)/m)^m (1/4, 0.30, 0.32 for m = 2, 3, 4;
 *    0 for m = 1: quadratic), so reaching the returned |w| from |w0| =
 *    0.1^m takes log(|w0| / |w|) / log(1 / rho) steps; allowed: that
 *    plus 4 (the step that shows no gain, the rounding of the count);
 *    for m = 1, 2 steps plus those 4.  The search used to wander at the round-off floor until
 *    its 120-step cap. */
#include "critical_points.h"
#include "test_util.h"
#include "tri_basis.h"
#include "tri_quad.h"

#include <complex.h>
#include <float.h>

#define P 4
#define NM ((P + 1) * (P + 2) / 2)

static double complex target(int m, double r, double s)
{
    return cpow(r + I * s - (0.3 + 0.2 * I), m);
}

/* L2 projection on the orthonormal basis (exact quadrature of degree 2P). */
static void project(sem_field *f, int m, const sem_tri_quad *q)
{
    double phi[NM];
    memset(f->coef, 0, sizeof(double) * NM * 2);
    for (int k = 0; k < q->npts; k++) {
        const double r = q->rs[2 * k], s = q->rs[2 * k + 1];
        const double complex w = target(m, r, s);
        sem_tri_dubiner(P, r, s, phi, NULL, NULL);
        for (int j = 0; j < NM; j++) {
            f->coef[2 * j] += q->w[k] * phi[j] * creal(w);
            f->coef[2 * j + 1] += q->w[k] * phi[j] * cimag(w);
        }
    }
}

static int study(const sem_field *f, int m)
{
    char ctx[32];
    snprintf(ctx, sizeof ctx, "multiplicity %d", m);
    double r = 0.3 + 0.1 * cos(0.7), s = 0.2 + 0.1 * sin(0.7), uv[2], phi[NM], mag = 0.0;
    int evals = 0;
    int fails = sq_check_int(ctx, "converged", sq_field_newton_local(f, 0, &r, &s, &evals), 0);
    sem_field_eval_ref(f, 0, r, s, uv, NULL, NULL);
    sem_tri_dubiner(P, 0.3, 0.2, phi, NULL, NULL);
    for (int j = 0; j < NM; j++)
        mag += (fabs(f->coef[2 * j]) + fabs(f->coef[2 * j + 1])) * fabs(phi[j]);
    const double dw = 10.0 * NM * DBL_EPSILON * mag, tol = 2.0 * pow(dw, 1.0 / m);
    fails += sq_check_abs(ctx, "|(u, v)| at the root", hypot(uv[0], uv[1]), 0.0, dw);
    fails += sq_check_abs(ctx, "distance to the zero", hypot(r - 0.3, s - 0.2), 0.0, tol);
    const double res = fmax(hypot(uv[0], uv[1]), DBL_MIN), rho = pow((m - 1.0) / m, m);
    const double steps = m == 1 ? 2.0 : ceil(log(pow(0.1, m) / res) / log(1.0 / rho));
    if (!(evals <= steps + 4.0)) {
        printf("%s: %d evaluations of (u, v), expected at most %g\n", ctx, evals, steps + 4.0);
        fails++;
    }
    if (getenv("SQ_VERBOSE"))
        printf("m=%d: %d evaluations (bound %g), |w| %.2e (dw %.2e), distance %.2e (tol %.2e)\n", m,
               evals, steps + 4.0, hypot(uv[0], uv[1]), dw, hypot(r - 0.3, s - 0.2), tol);
    return fails;
}

int main(void)
{
    sq_error err;
    sem_tri_mesh *mesh = NULL;
    sem_field *f = NULL;
    sem_tri_quad *q = NULL;
    SQ_TEST_OK(sem_tri_mesh_create(1, 3, 1, &mesh, &err), err);
    const double xy[6] = {0.0, 0.0, 1.0, 0.0, 0.0, 1.0};
    memcpy(mesh->vxy, xy, sizeof xy);
    memcpy(mesh->gxy, xy, sizeof xy);
    for (int k = 0; k < 3; k++)
        mesh->tri[k] = k;
    SQ_TEST_OK(sem_field_create(mesh, P, 2, &f, &err), err);
    SQ_TEST_OK(sem_tri_quad_create(2 * P, &q, &err), err);
    int fails = 0;
    for (int m = 1; m <= 4; m++) {
        project(f, m, q);
        fails += study(f, m);
    }
    sem_tri_quad_free(&q);
    sem_field_free(&f);
    sem_tri_mesh_free(&mesh);
    return fails ? 1 : 0;
}
