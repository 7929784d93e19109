/* t222: h-convergence of the SIPG solver on structured meshes of the unit
 * square (n = 4, 8, 16 cells per side), u = e^x sin y with Dirichlet data:
 * the observed L2 rate between the two finest meshes is within 0.3 of
 * P + 1 for P = 1..4 (Arnold, Brezzi, Cockburn & Marini 2002: optimal L2
 * order for the symmetric interior penalty method), and the H1 rate within
 * 0.3 of P. */
#include "field.h"
#include "field_error.h"
#include "poisson.h"
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

static double bval(const double x[2], const double n[2], int tag, void *ctx)
{
    (void)n;
    (void)tag;
    (void)ctx;
    double u, g[2];
    u_exp(x, NULL, &u, g);
    return u;
}

int main(void)
{
    int fail = 0;
    const int sizes[3] = {4, 8, 16};
    for (int P = 1; P <= 4; ++P) {
        double l2[3], h1[3];
        for (int i = 0; i < 3; ++i) {
            sq_error e;
            sem_tri_mesh *m = tm_square(sizes[i], 1);
            if (!m) return 1;
            sem_poisson *S = NULL;
            sem_field *u = NULL;
            SQ_TEST_OK(sem_poisson_create(m, P, SEM_DG, NULL, NULL, &S, &e), e);
            SQ_TEST_OK(sem_field_create(m, P, 1, &u, &e), e);
            const sem_poisson_data d = {NULL, NULL, bval, NULL, 0, NULL};
            SQ_TEST_OK(sem_poisson_solve(S, &d, u, &e), e);
            SQ_TEST_OK(sem_field_error(u, 0, u_exp, NULL, 0, &l2[i], &h1[i], &e), e);
            if (getenv("SQ_VERBOSE"))
                printf("P=%d n=%2d L2 %.3e H1 %.3e\n", P, sizes[i], l2[i], h1[i]);
            sem_field_free(&u);
            sem_poisson_free(&S);
            sem_tri_mesh_free(&m);
        }
        char what[32];
        snprintf(what, sizeof what, "P=%d", P);
        const double r2 = log2(l2[1] / l2[2]), r1 = log2(h1[1] / h1[2]);
        if (getenv("SQ_VERBOSE")) printf("P=%d rates L2 %.3f H1 %.3f\n", P, r2, r1);
        fail += sq_check_abs(what, "L2 rate", r2, P + 1.0, 0.3);
        fail += sq_check_abs(what, "H1 rate", r1, (double)P, 0.3);
    }
    return fail ? 1 : 0;
}
