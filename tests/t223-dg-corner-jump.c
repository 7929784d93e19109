/* t223: DG with Dirichlet data that jumps at a corner (Marcon 2019
 * §2.2.1: the guiding field's boundary data jumps at corners whose angle
 * is not a multiple of π/2, which is why DG is used there).
 * Unit square, u = 1 on the bottom side, u = 0 on the left side; the exact
 * solution is the harmonic function u = 1 - (2/π) atan2(y, x) of the
 * quarter plane, whose values are imposed on the two other sides.  The
 * discontinuity at (0,0) is not in H^1, yet the weakly imposed data keep
 * the method consistent: the L2 error away from the corner (|x| > 0.25)
 * falls steadily as P grows (algebraically, about P^-1.7: the corner
 * pollutes the whole domain), and the error over the whole square falls too
 * (slowly: the solution is singular). */
#include "field.h"
#include "poisson.h"
#include "test_meshes.h"
#include "test_util.h"

static void exact(const double x[2], void *ctx, double *u, double g[2])
{
    (void)ctx;
    const double r2 = x[0] * x[0] + x[1] * x[1];
    *u = 1.0 - (2.0 / TM_PI) * atan2(x[1], x[0]);
    /* d atan2(y,x) = (-y, x)/r^2 */
    g[0] = r2 > 0 ? (2.0 / TM_PI) * x[1] / r2 : 0.0;
    g[1] = r2 > 0 ? -(2.0 / TM_PI) * x[0] / r2 : 0.0;
}

static double bval(const double x[2], const double n[2], int tag, void *ctx)
{
    (void)n;
    (void)ctx;
    if (tag == 0) return 1.0; /* bottom: the jump is at the corner (0,0) */
    if (tag == 3) return 0.0; /* left */
    double u, g[2];
    exact(x, NULL, &u, g);
    return u;
}

int main(void)
{
    int fail = 0;
    sem_tri_mesh *m = tm_square(4, 1);
    if (!m) return 1;
    const double c[2] = {0.0, 0.0};
    double far[9] = {0}, all[9] = {0};
    for (int P = 2; P <= 8; P += 2) {
        sq_error e;
        sem_poisson *S = NULL;
        sem_field *u = NULL;
        SQ_TEST_OK(sem_poisson_create(m, P, SEM_DG, NULL, NULL, &S, &e), e);
        SQ_TEST_OK(sem_field_create(m, P, 1, &u, &e), e);
        const sem_poisson_data d = {NULL, NULL, bval, NULL, 0, NULL};
        SQ_TEST_OK(sem_poisson_solve(S, &d, u, &e), e);
        if (tm_errors_region(u, exact, NULL, c, 0.25, &far[P], NULL)) return 1;
        if (tm_errors_region(u, exact, NULL, c, 0.0, &all[P], NULL)) return 1;
        if (getenv("SQ_VERBOSE")) printf("P=%d L2 error |x|>0.25 %.3e, whole %.3e\n", P, far[P], all[P]);
        char what[32];
        snprintf(what, sizeof what, "P=%d", P);
        if (P >= 4) {
            fail += sq_check_abs(what, "far L2 error / at P-2", far[P] / far[P - 2], 0.0, 0.75);
            fail += sq_check_abs(what, "whole L2 error / at P-2", all[P] / all[P - 2], 0.0, 0.9);
        }
        sem_field_free(&u);
        sem_poisson_free(&S);
    }
    fail += sq_check_abs("P=8", "L2 error away from the corner", far[8], 0.0, 4e-4);
    sem_tri_mesh_free(&m);
    return fail ? 1 : 0;
}
