/* t204: p-convergence of CG on a curved mesh: the unit disc from 5 blocks
 * of 2 x 2 cells (40 triangles, geometry order 8, boundary nodes on the
 * circle), u = e^x sin y (harmonic) with Dirichlet data, P = 1..12.
 * The L2 error decays exponentially (each step of 2 in P gains at least a
 * factor 10 in L2 and H1, while that stays above the solve's worst-case
 * round-off, sq_solve_roundoff) and is <= 1e-10 (or that round-off) at
 * P = 12. */
#include "poisson.h"
#include "sem_roundoff.h"
#include "test_meshes.h"
#include "test_util.h"

static void exact(const double x[2], void *ctx, double *u, double g[2])
{
    (void)ctx;
    const double e = exp(x[0]);
    *u = e * sin(x[1]);
    g[0] = e * sin(x[1]);
    g[1] = e * cos(x[1]);
}

static double bnd(const double x[2], const double n[2], int tag, void *ctx)
{
    (void)n, (void)tag, (void)ctx;
    return exp(x[0]) * sin(x[1]);
}

int main(void)
{
    int fails = 0;
    sq_error err = {0};
    sem_tri_mesh *m = tm_disc(1.0, getenv("T204_N") ? atoi(getenv("T204_N")) : 2,
                              getenv("T204_PG") ? atoi(getenv("T204_PG")) : 8);
    if (!m) return printf("t204: mesh\n"), 1;
    double l2[13], h1[13];
    for (int P = 1; P <= 12; ++P) {
        sem_poisson *s = NULL;
        sem_field *u = NULL;
        SQ_TEST_OK(sem_poisson_create(m, P, SEM_CG, NULL, NULL, &s, &err), err);
        SQ_TEST_OK(sem_field_create(m, P, 1, &u, &err), err);
        sem_poisson_data d = {NULL, NULL, bnd, NULL, 0, NULL};
        SQ_TEST_OK(sem_poisson_solve(s, &d, u, &err), err);
        tm_errors(u, exact, NULL, &l2[P], &h1[P]);
        if (getenv("T2XX_VERBOSE"))
            printf("P=%2d ndofs=%5ld L2=%.3e H1=%.3e\n", P, sem_poisson_ndofs(s), l2[P], h1[P]);
        sem_field_free(&u);
        sem_poisson_free(&s);
        /* 5 blocks of 2 x 2 cells: h ~ 1/2; |u| <= e */
        const double rf = sq_solve_roundoff(P, 2, exp(1.0));
        if (P >= 3 && l2[P - 2] > rf / 0.1) {
            char where[64];
            snprintf(where, sizeof where, "t204 P=%d vs P=%d", P, P - 2);
            fails += sq_check_abs(where, "L2 ratio", l2[P] / l2[P - 2], 0.0, 0.1);
            fails += sq_check_abs(where, "H1 ratio", h1[P] / h1[P - 2], 0.0, 0.1);
        }
    }
    /* discretisation errors (9e-12 and 6e-10, CPU-independent): the rate
     * of the ratio checks, 10x per two orders from P = 10's 9e-10 and 5e-8,
     * bounds them by 1e-10 and 1e-8 at P = 12; the round-off's worst case
     * (3.4e-10, 1e-14 measured) may exceed that */
    const double rf = sq_solve_roundoff(12, 2, exp(1.0));
    fails += sq_check_abs("t204 P=12", "L2 error", l2[12], 0.0, fmax(1e-10, rf));
    fails += sq_check_abs("t204 P=12", "H1 error", h1[12], 0.0, fmax(1e-8, 2.0 * 12 * 12 * 2 * rf));
    sem_tri_mesh_free(&m);
    return fails ? 1 : 0;
}
