/* t221: p-convergence of the SIPG solver on a curved disc (radius 1, 90
 * curved triangles, geometry of order 4 with boundary nodes on the circle)
 * for two harmonic solutions, u = e^x sin y and u = Re (x+iy)^5, with
 * Dirichlet data imposed weakly: the L2 error decays exponentially in P
 * to the solve's round-off at P = 12 (Marcon 2019 §2.2.1, spectral accuracy).
 * Also checks sem_field_error against an independent quadrature. */
#include "field.h"
#include "field_error.h"
#include "poisson.h"
#include "sem_roundoff.h"
#include "test_meshes.h"
#include "test_util.h"

static void u_exp(const double x[2], void *ctx, double *u, double g[2])
{
    (void)ctx;
    const double ex = exp(x[0]);
    *u = ex * sin(x[1]);
    g[0] = ex * sin(x[1]);
    g[1] = ex * cos(x[1]);
}

static void u_re5(const double x[2], void *ctx, double *u, double g[2])
{
    (void)ctx;
    const double a = x[0], b = x[1];
    *u = a * a * a * a * a - 10 * a * a * a * b * b + 5 * a * b * b * b * b;
    g[0] = 5 * a * a * a * a - 30 * a * a * b * b + 5 * b * b * b * b;
    g[1] = -20 * a * a * a * b + 20 * a * b * b * b;
}

static double bval(const double x[2], const double n[2], int tag, void *ctx)
{
    (void)n;
    (void)tag;
    double u, g[2];
    ((sem_exact_fn)ctx)(x, NULL, &u, g);
    return u;
}

int main(void)
{
    int fail = 0;
    sem_tri_mesh *m = tm_disc(1.0, 3, 4);
    if (!m) return 1;
    sem_exact_fn sols[2] = {u_exp, u_re5};
    const char *names[2] = {"e^x sin y", "Re (x+iy)^5"};
    for (int k = 0; k < 2; ++k) {
        double err[13] = {0};
        for (int P = 2; P <= 12; ++P) {
            sq_error e;
            sem_poisson *S = NULL;
            sem_field *u = NULL;
            SQ_TEST_OK(sem_poisson_create(m, P, SEM_DG, NULL, NULL, &S, &e), e);
            SQ_TEST_OK(sem_field_create(m, P, 1, &u, &e), e);
            const sem_poisson_data d = {NULL, NULL, bval, (void *)sols[k], 0, NULL};
            SQ_TEST_OK(sem_poisson_solve(S, &d, u, &e), e);
            double l2, h1;
            SQ_TEST_OK(sem_field_error(u, 0, sols[k], NULL, 0, &l2, &h1, &e), e);
            if (getenv("SQ_VERBOSE")) printf("%s P=%2d L2 %.3e H1 %.3e\n", names[k], P, l2, h1);
            double l2b, h1b;
            if (tm_errors(u, (tm_exact_fn)sols[k], NULL, &l2b, &h1b)) return 1;
            char what[96];
            snprintf(what, sizeof what, "%s P=%d", names[k], P);
            /* two quadratures of the same error function: their own
             * truncation on the curved elements (1e-6 relative) plus the
             * sums' round-off relative to the field (|u| <= e): 1e-14, 1e-13
             * for the gradient (2 P^2 n times a few U) */
            fail += sq_check_abs(what, "sem_field_error L2 vs independent quadrature", l2, l2b, 1e-6 * l2b + 1e-14);
            fail += sq_check_abs(what, "sem_field_error H1 vs independent quadrature", h1, h1b, 1e-6 * h1b + 1e-13);
            err[P] = l2;
            /* exponential decay: every two orders at least a factor 8 while
             * that stays above the solve's round-off (sem_roundoff.h; the
             * disc of 5 blocks of 3 x 3 cells: h ~ 1/3, |u| <= e) */
            if (P >= 4 && err[P - 2] > sq_solve_roundoff(P, 3, exp(1.0)) / 0.125)
                fail += sq_check_abs(what, "L2 error / L2 error at P-2", err[P] / err[P - 2], 0.0, 0.125);
            sem_field_free(&u);
            sem_poisson_free(&S);
        }
        /* the discretisation error is below the round-off at P = 12 (3e-13
         * and 2e-12 measured; worst case 7.6e-10) */
        fail += sq_check_abs(names[k], "L2 error at P = 12", err[12], 0.0,
                             sq_solve_roundoff(12, 3, exp(1.0)));
    }
    sem_tri_mesh_free(&m);
    return fail ? 1 : 0;
}
