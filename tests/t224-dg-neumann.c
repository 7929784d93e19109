/* t224: Neumann data, pure Neumann problems and point sources with DG.
 *  - mixed: unit square, u = e^x sin y, Dirichlet on bottom/left, Neumann
 *    ∂u/∂n on right/top: converges spectrally in P;
 *  - pure Neumann on the square (u = e^x sin y, f = 0, g = ∂u/∂n): the
 *    zero-mean solution converges to u - mean(u), mean = (e-1)(1-cos 1);
 *  - pure Neumann on the curved disc with a source, u = Re (x+iy)^5 + x^2,
 *    f = -2: Re z^5 has zero mean on the disc (quarter-turn symmetry), the
 *    mean of x^2 is computed by quadrature;
 *  - incompatible pure-Neumann data is refused with SQ_ERR_USAGE naming
 *    the imbalance;
 *  - a point source -Δu = c δ(x - x0), c = -1, with Dirichlet data
 *    (1/2π) log|x - x0| on the disc: the solution matches (1/2π) log r away
 *    from the source, better as P grows (algebraically: the singularity
 *    pollutes the whole mesh). */
#include "field.h"
#include "field_error.h"
#include "locate.h"
#include "poisson.h"
#include "sem_roundoff.h"
#include "test_meshes.h"
#include "test_util.h"

static void u_exp(const double x[2], void *ctx, double *u, double g[2])
{
    const double shift = ctx ? *(const double *)ctx : 0.0;
    const double ex = exp(x[0]);
    *u = ex * sin(x[1]) - shift;
    g[0] = ex * sin(x[1]);
    g[1] = ex * cos(x[1]);
}

static double bval_exp(const double x[2], const double n[2], int tag, void *ctx)
{
    const int mixed = *(const int *)ctx;
    double u, g[2];
    u_exp(x, NULL, &u, g);
    if (!mixed || tag == 1 || tag == 2) return g[0] * n[0] + g[1] * n[1];
    return u;
}

static sem_bc_kind kind_mixed(int tag, void *ctx)
{
    (void)ctx;
    return tag == 1 || tag == 2 ? SEM_BC_NEUMANN : SEM_BC_DIRICHLET;
}
static sem_bc_kind kind_neumann(int tag, void *ctx)
{
    (void)tag;
    (void)ctx;
    return SEM_BC_NEUMANN;
}

/* Re z^5 + x^2 - shift */
static void u_poly(const double x[2], void *ctx, double *u, double g[2])
{
    const double shift = ctx ? *(const double *)ctx : 0.0;
    const double a = x[0], b = x[1];
    *u = a * a * a * a * a - 10 * a * a * a * b * b + 5 * a * b * b * b * b + a * a - shift;
    g[0] = 5 * a * a * a * a - 30 * a * a * b * b + 5 * b * b * b * b + 2 * a;
    g[1] = -20 * a * a * a * b + 20 * a * b * b * b;
}
static double f_poly(const double x[2], void *ctx)
{
    (void)x;
    (void)ctx;
    return -2.0;
}
static double g_poly(const double x[2], const double n[2], int tag, void *ctx)
{
    (void)tag;
    (void)ctx;
    double u, g[2];
    u_poly(x, NULL, &u, g);
    return g[0] * n[0] + g[1] * n[1];
}

static const double X0[2] = {0.1, 0.05};
static void u_log(const double x[2], void *ctx, double *u, double g[2])
{
    (void)ctx;
    const double dx = x[0] - X0[0], dy = x[1] - X0[1], r2 = dx * dx + dy * dy;
    *u = log(r2) / (4.0 * TM_PI);
    g[0] = dx / (2.0 * TM_PI * r2);
    g[1] = dy / (2.0 * TM_PI * r2);
}
static double g_log(const double x[2], const double n[2], int tag, void *ctx)
{
    (void)n;
    (void)tag;
    double u, g[2];
    u_log(x, ctx, &u, g);
    return u;
}
static double g_one(const double x[2], const double n[2], int tag, void *ctx)
{
    (void)x;
    (void)n;
    (void)tag;
    (void)ctx;
    return 1.0;
}

static double solve_err(const sem_tri_mesh *m, int P, sem_bc_kind_fn kind,
                        const sem_poisson_data *d, sem_exact_fn ex, void *ex_ctx, double rmin)
{
    sq_error e;
    sem_poisson *S = NULL;
    sem_field *u = NULL;
    SQ_TEST_OK(sem_poisson_create(m, P, SEM_DG, kind, NULL, &S, &e), e);
    SQ_TEST_OK(sem_field_create(m, P, 1, &u, &e), e);
    SQ_TEST_OK(sem_poisson_solve(S, d, u, &e), e);
    double l2;
    if (rmin > 0) {
        if (tm_errors_region(u, (tm_exact_fn)ex, ex_ctx, X0, rmin, &l2, NULL)) exit(1);
    } else {
        SQ_TEST_OK(sem_field_error(u, 0, ex, ex_ctx, 0, &l2, NULL, &e), e);
    }
    sem_field_free(&u);
    sem_poisson_free(&S);
    return l2;
}

int main(void)
{
    int fail = 0;
    const int verbose = getenv("SQ_VERBOSE") != NULL;
    sem_tri_mesh *sq = tm_square(3, 1), *disc = tm_disc(1.0, 3, 4);
    if (!sq || !disc) return 1;

    /* mixed and pure Neumann on the square */
    const double mean_exp = (exp(1.0) - 1.0) * (1.0 - cos(1.0));
    for (int mixed = 1; mixed >= 0; --mixed) {
        const sem_poisson_data d = {NULL, NULL, bval_exp, &mixed, 0, NULL};
        double prev = HUGE_VAL;
        double shift = mixed ? 0.0 : mean_exp;
        for (int P = 2; P <= 10; P += 2) {
            const double l2 = solve_err(sq, P, mixed ? kind_mixed : kind_neumann, &d, u_exp, &shift, 0);
            if (verbose) printf("%s P=%d L2 %.3e\n", mixed ? "mixed" : "pure Neumann", P, l2);
            char what[48];
            snprintf(what, sizeof what, "%s P=%d", mixed ? "mixed" : "pure Neumann", P);
            /* the ratio only while l2 can be 0.05 prev above the solve's
             * round-off (sem_roundoff.h; n = 3, |u| <= e): P = 4, 6 */
            const double rf = sq_solve_roundoff(P, 3, exp(1.0));
            if (prev > rf / 0.05) fail += sq_check_abs(what, "L2 error / at P-2", l2 / prev, 0.0, 0.05);
            prev = l2;
        }
        /* at P = 10 the discretisation error (1e-10 at P = 6, falling 1e3
         * per two orders) is below the round-off (3e-13 measured; worst
         * case sq_solve_roundoff, 3.7e-10) */
        fail += sq_check_abs(mixed ? "mixed" : "pure Neumann", "L2 error at P = 10", prev, 0.0,
                             sq_solve_roundoff(10, 3, exp(1.0)));
    }

    /* pure Neumann with a source on the curved disc; the mean of x^2 over
     * the discrete disc by quadrature (Re z^5 has zero mean there) */
    {
        sq_error e;
        sem_tri_quad *q = NULL;
        sem_tri_lagrange *L = NULL;
        SQ_TEST_OK(sem_tri_quad_create(20, &q, &e), e);
        SQ_TEST_OK(sem_tri_lagrange_create(disc->order, &L, &e), e);
        double ix2 = 0.0, area = 0.0;
        for (int t = 0; t < disc->ntris; ++t)
            for (int k = 0; k < q->npts; ++k) {
                double x[2];
                const double *g = disc->gxy + 2 * (size_t)disc->nodes_per_tri * t;
                const double w = q->w[k] * sem_tri_geom_map(L, g, q->rs[2 * k], q->rs[2 * k + 1], x, NULL);
                ix2 += w * x[0] * x[0];
                area += w;
            }
        sem_tri_quad_free(&q);
        sem_tri_lagrange_free(&L);
        double shift = ix2 / area;
        const sem_poisson_data d = {f_poly, NULL, g_poly, NULL, 0, NULL};
        double prev = HUGE_VAL;
        for (int P = 4; P <= 12; P += 2) {
            const double l2 = solve_err(disc, P, kind_neumann, &d, u_poly, &shift, 0);
            if (verbose) printf("disc pure Neumann P=%d L2 %.3e\n", P, l2);
            char what[48];
            snprintf(what, sizeof what, "disc pure Neumann P=%d", P);
            /* as above: the disc of 5 blocks of 3 x 3 cells has h ~ 1/3,
             * |u| <= 2 */
            const double rf = sq_solve_roundoff(P, 3, 2.0);
            if (prev > rf / 0.1) fail += sq_check_abs(what, "L2 error / at P-2", l2 / prev, 0.0, 0.1);
            prev = l2;
        }
        /* discretisation error (6e-10 at P = 10, 1/100 per two orders) plus
         * the worst-case round-off (6e-10) */
        fail += sq_check_abs("disc pure Neumann", "L2 error at P = 12", prev, 0.0, 1e-9);
    }

    /* incompatible data */
    {
        sq_error e;
        sem_poisson *S = NULL;
        sem_field *u = NULL;
        SQ_TEST_OK(sem_poisson_create(sq, 3, SEM_DG, kind_neumann, NULL, &S, &e), e);
        SQ_TEST_OK(sem_field_create(sq, 3, 1, &u, &e), e);
        const sem_poisson_data d = {NULL, NULL, g_one, NULL, 0, NULL};
        const sq_status st = sem_poisson_solve(S, &d, u, &e);
        fail += sq_check_int("incompatible pure Neumann", "status", st, SQ_ERR_USAGE);
        if (st != SQ_OK && !strstr(e.msg, "= 4")) {
            printf("incompatible pure Neumann: message '%s' does not name the imbalance 4\n", e.msg);
            ++fail;
        }
        sem_field_free(&u);
        sem_poisson_free(&S);
    }

    /* point source c = -1 at X0: u = (1/2π) log |x - X0| */
    {
        sq_error e;
        sem_locator *loc = NULL;
        SQ_TEST_OK(sem_locator_create(disc, &loc, &e), e);
        sem_point_source src = {-1, 0, 0, -1.0};
        if (sem_locator_find(loc, X0, -1, &src.elem, &src.r, &src.s) != 0) {
            printf("point source: X0 not located\n");
            return 1;
        }
        const sem_poisson_data d = {NULL, NULL, g_log, NULL, 1, &src};
        double prev = HUGE_VAL;
        for (int P = 2; P <= 10; P += 2) {
            const double l2 = solve_err(disc, P, NULL, &d, u_log, NULL, 0.3);
            if (verbose) printf("point source P=%d L2 (|x-x0| > 0.3) %.3e\n", P, l2);
            char what[48];
            snprintf(what, sizeof what, "point source P=%d", P);
            if (P > 2) fail += sq_check_abs(what, "L2 error / at P-2", l2 / prev, 0.0, 0.9);
            prev = l2;
        }
        fail += sq_check_abs("point source", "L2 error away from the source at P = 10", prev, 0.0, 1.5e-4);
        sem_locator_free(&loc);
    }
    sem_tri_mesh_free(&sq);
    sem_tri_mesh_free(&disc);
    return fail ? 1 : 0;
}
