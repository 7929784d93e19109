/* t205: h-convergence of CG on the unit square (n x n structured, n = 4, 8,
 * 16, 32), u = e^x sin y with Dirichlet data: the observed L2 rate between
 * the two finest meshes is within 0.3 of P+1 and the H1 rate within 0.3 of
 * P, for P = 1..4. */
#include "poisson.h"
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
    for (int P = 1; P <= 4; ++P) {
        double l2[4], h1[4];
        for (int k = 0; k < 4; ++k) {
            const int n = 4 << k;
            sem_tri_mesh *m = tm_square(n, 1);
            if (!m) return printf("t205: mesh\n"), 1;
            sem_poisson *s = NULL;
            sem_field *u = NULL;
            SQ_TEST_OK(sem_poisson_create(m, P, SEM_CG, NULL, NULL, &s, &err), err);
            SQ_TEST_OK(sem_field_create(m, P, 1, &u, &err), err);
            sem_poisson_data d = {NULL, NULL, bnd, NULL, 0, NULL};
            SQ_TEST_OK(sem_poisson_solve(s, &d, u, &err), err);
            tm_errors(u, exact, NULL, &l2[k], &h1[k]);
            if (getenv("T2XX_VERBOSE"))
                printf("P=%d n=%2d ndofs=%6ld L2=%.3e H1=%.3e%s", P, n, sem_poisson_ndofs(s), l2[k],
                       h1[k], k ? "" : "\n");
            if (k && getenv("T2XX_VERBOSE"))
                printf("  rates %.2f %.2f\n", log2(l2[k - 1] / l2[k]), log2(h1[k - 1] / h1[k]));
            sem_field_free(&u);
            sem_poisson_free(&s);
            sem_tri_mesh_free(&m);
        }
        char where[32];
        snprintf(where, sizeof where, "t205 P=%d", P);
        fails += sq_check_abs(where, "L2 rate", log2(l2[2] / l2[3]), P + 1, 0.3);
        fails += sq_check_abs(where, "H1 rate", log2(h1[2] / h1[3]), P, 0.3);
    }
    return fails ? 1 : 0;
}
