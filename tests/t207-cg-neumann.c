/* t207: Neumann data, u = e^x sin y.
 *  - unit square 2 x 2, Dirichlet on bottom/left (tags 0, 3), Neumann
 *    du/dn on right/top (tags 1, 2): L2 error at P = 4, 8, 12 decreasing,
 *    <= 1e-10 at P = 12;
 *  - curved unit disc (5 blocks of 2 x 2 cells, geometry order 8), pure
 *    Neumann with du/dn on the circle, P = 6, 12: the solution has zero mean
 *    (to the quadrature's round-off) and converges to u minus its mean (<= 1e-9 at P = 12; the
 *    mean taken from the Dirichlet solution at P = 12). */
#include "poisson.h"
#include "sem_roundoff.h"
#include "test_meshes.h"
#include "test_util.h"

#include <float.h>

typedef struct {
    double shift;
} ctx_t;

static void exact(const double x[2], void *ctx, double *u, double g[2])
{
    const double e = exp(x[0]);
    *u = e * sin(x[1]) - (ctx ? ((ctx_t *)ctx)->shift : 0.0);
    g[0] = e * sin(x[1]);
    g[1] = e * cos(x[1]);
}

static sem_bc_kind kind_mixed(int tag, void *ctx)
{
    (void)ctx;
    return tag == 1 || tag == 2 ? SEM_BC_NEUMANN : SEM_BC_DIRICHLET;
}
static sem_bc_kind kind_neu(int tag, void *ctx) { (void)tag, (void)ctx; return SEM_BC_NEUMANN; }

/* u on Dirichlet tags, du/dn on Neumann tags (ctx: the kind function) */
static double bnd(const double x[2], const double n[2], int tag, void *ctx)
{
    double u, g[2];
    exact(x, NULL, &u, g);
    const sem_bc_kind_fn kf = *(sem_bc_kind_fn *)ctx;
    if (kf && kf(tag, NULL) == SEM_BC_NEUMANN) return g[0] * n[0] + g[1] * n[1];
    return u;
}

static sem_field *solve(sem_tri_mesh *m, int P, sem_bc_kind_fn kf)
{
    sq_error err = {0};
    sem_poisson *s = NULL;
    sem_field *u = NULL;
    SQ_TEST_OK(sem_poisson_create(m, P, SEM_CG, kf, NULL, &s, &err), err);
    SQ_TEST_OK(sem_field_create(m, P, 1, &u, &err), err);
    sem_poisson_data d = {NULL, NULL, bnd, &kf, 0, NULL};
    SQ_TEST_OK(sem_poisson_solve(s, &d, u, &err), err);
    sem_poisson_free(&s);
    return u;
}

int main(void)
{
    int fails = 0;
    char where[64];
    sem_tri_mesh *sq = tm_square(2, 1), *disc = tm_disc(1.0, 2, 8);
    if (!sq || !disc) return printf("t207: mesh\n"), 1;
    double prev = HUGE_VAL, l2, h1;
    for (int P = 4; P <= 12; P += 4) {
        sem_field *u = solve(sq, P, kind_mixed);
        tm_errors(u, exact, NULL, &l2, &h1);
        if (getenv("T2XX_VERBOSE")) printf("mixed square P=%d L2=%.3e H1=%.3e\n", P, l2, h1);
        snprintf(where, sizeof where, "t207 mixed square P=%d", P);
        /* the floor: the solve's worst-case round-off (sem_roundoff.h; 2 x 2
         * cells, |u| <= e), which the discretisation error falls below at
         * P = 12 */
        const double floor = sq_solve_roundoff(P, 2, exp(1.0));
        fails += sq_check_abs(where, "L2 error below 1% of the previous order's (or round-off)", l2,
                              0.0, fmax(prev / 100, floor));
        prev = l2;
        sem_field_free(&u);
    }
    /* discretisation error (CPU-independent): 1e-2 per four orders from
     * P = 8's 7e-13, or the round-off floor above */
    fails += sq_check_abs("t207 mixed square P=12", "L2 error", prev, 0.0,
                          fmax(1e-10, sq_solve_roundoff(12, 2, exp(1.0))));

    sem_field *ud = solve(disc, 12, NULL);
    ctx_t c = {tm_mean(ud)};
    sem_field_free(&ud);
    for (int P = 6; P <= 12; P += 6) {
        sem_field *u = solve(disc, P, kind_neu);
        tm_errors(u, exact, &c, &l2, &h1);
        const double mean = tm_mean(u);
        if (getenv("T2XX_VERBOSE"))
            printf("pure Neumann disc P=%d L2=%.3e H1=%.3e mean=%.2e\n", P, l2, h1, mean);
        snprintf(where, sizeof where, "t207 pure Neumann disc P=%d", P);
        /* the mean is a quadrature sum of 40 triangles x (P/2 + 9)^2 points
         * of |u| <= e: 40 (P/2 + 9)^2 U e (3e-12 at P = 12) */
        fails += sq_check_abs(where, "mean", mean, 0.0, 40.0 * (P / 2 + 9) * (P / 2 + 9) * (DBL_EPSILON / 2) * exp(1.0));
        /* discretisation errors (5e-6, 8e-12): the rate of t204 on the same
         * mesh, 10x per two orders, plus the round-off (3.4e-10 at worst) */
        fails += sq_check_abs(where, "L2 error", l2, 0.0, P == 12 ? 1e-9 : 1e-4);
        sem_field_free(&u);
    }
    sem_tri_mesh_free(&sq);
    sem_tri_mesh_free(&disc);
    return fails ? 1 : 0;
}
