/* t203: the CG Poisson solver reproduces polynomials of degree <= P to
 * round-off (see Tolerances; straight meshes: the 2-triangle unit square and a 3 x 3
 * structured square), P = 1..10, with
 *  - Dirichlet data on every side,
 *  - Dirichlet on bottom/right, Neumann (du/dn) on top/left,
 *  - pure Neumann: the solution is u minus its mean, and has zero mean;
 * incompatible pure Neumann data is refused with SQ_ERR_USAGE; the count of
 * degrees of freedom is V + E(P-1) + T(P-1)(P-2)/2. */
#include "poisson.h"
#include "sem_roundoff.h"
#include "test_meshes.h"
#include "test_util.h"

#define DEG 10

/* Tolerances.  u lies in the discrete space, so only round-off is left:
 * sq_solve_roundoff (sem_roundoff.h) with |u| <= sum |c| on the unit
 * square (3e-9 at P = 10, n = 3; measured 7e-14 with every OpenBLAS
 * kernel), and 2 P^2 n times that in H1 (inverse inequality). */
typedef struct {
    double c[DEG + 1][DEG + 1]; /* u = sum c[i][j] x^i y^j */
    int P;
    double shift; /* subtracted from u */
} poly;

static double l2_tol(const poly *p, int n)
{
    double s = 0.0;
    for (int i = 0; i <= p->P; ++i)
        for (int j = 0; i + j <= p->P; ++j) s += fabs(p->c[i][j]);
    return sq_solve_roundoff(p->P, n, s);
}

static double ipow(double x, int k)
{
    double r = 1.0;
    for (int i = 0; i < k; ++i) r *= x;
    return r;
}

static void poly_eval(const poly *p, const double x[2], double *u, double g[2], double *lap)
{
    double v = 0, gx = 0, gy = 0, l = 0;
    for (int i = 0; i <= p->P; ++i)
        for (int j = 0; i + j <= p->P; ++j) {
            const double c = p->c[i][j];
            v += c * ipow(x[0], i) * ipow(x[1], j);
            if (i > 0) gx += c * i * ipow(x[0], i - 1) * ipow(x[1], j);
            if (j > 0) gy += c * j * ipow(x[0], i) * ipow(x[1], j - 1);
            if (i > 1) l += c * i * (i - 1) * ipow(x[0], i - 2) * ipow(x[1], j);
            if (j > 1) l += c * j * (j - 1) * ipow(x[0], i) * ipow(x[1], j - 2);
        }
    if (u) *u = v - p->shift;
    if (g) g[0] = gx, g[1] = gy;
    if (lap) *lap = l;
}

static void exact(const double x[2], void *ctx, double *u, double g[2]) { poly_eval(ctx, x, u, g, NULL); }

static double src(const double x[2], void *ctx)
{
    double l;
    poly_eval(ctx, x, NULL, NULL, &l);
    return -l;
}

static sem_bc_kind kind_dir(int tag, void *ctx) { (void)tag, (void)ctx; return SEM_BC_DIRICHLET; }
static sem_bc_kind kind_mixed(int tag, void *ctx)
{
    (void)ctx;
    return tag <= 1 ? SEM_BC_DIRICHLET : SEM_BC_NEUMANN;
}
static sem_bc_kind kind_neu(int tag, void *ctx) { (void)tag, (void)ctx; return SEM_BC_NEUMANN; }

typedef struct {
    poly p;
    int mode; /* 0 Dirichlet, 1 Neumann, 2 mixed */
} ctx_t;

/* The value on Dirichlet tags, the outward flux on Neumann tags. */
static double bnd(const double x[2], const double n[2], int tag, void *ctx)
{
    const ctx_t *c = ctx;
    double u, g[2];
    poly_eval(&c->p, x, &u, g, NULL);
    if (c->mode == 0 || (c->mode == 2 && tag <= 1)) return u;
    return g[0] * n[0] + g[1] * n[1];
}

static int run(sem_tri_mesh *m, int n, int P, int mode, const poly *pin, double *mean_out)
{
    char where[128];
    snprintf(where, sizeof where, "t203 n=%d P=%d %s", n, P,
             mode == 0 ? "dirichlet" : mode == 1 ? "pure-neumann" : "mixed");
    ctx_t c = {*pin, mode};
    sq_error err = {0};
    sem_poisson *s = NULL;
    sem_field *u = NULL;
    sem_bc_kind_fn kf = mode == 0 ? kind_dir : mode == 1 ? kind_neu : kind_mixed;
    SQ_TEST_OK(sem_poisson_create(m, P, SEM_CG, kf, NULL, &s, &err), err);
    SQ_TEST_OK(sem_field_create(m, P, 1, &u, &err), err);
    int fails = 0;
    const long V = (long)(n + 1) * (n + 1), E = 3L * n * n + 2L * n, T = 2L * n * n;
    fails += sq_check_int(where, "ndofs", sem_poisson_ndofs(s),
                          V + E * (P - 1) + T * (P - 1) * (P - 2) / 2);
    sem_poisson_data d = {src, &c.p, bnd, &c, 0, NULL};
    SQ_TEST_OK(sem_poisson_solve(s, &d, u, &err), err);
    if (mode == 1) {
        fails += sq_check_abs(where, "mean", tm_mean(u), 0.0, l2_tol(pin, n)); /* |mean| <= L2 */
        c.p.shift = *mean_out; /* exact solution: u minus its mean */
    }
    double l2, h1;
    tm_errors(u, exact, &c.p, &l2, &h1);
    if (getenv("T203_VERBOSE")) printf("%s L2 %.3g H1 %.3g\n", where, l2, h1);
    fails += sq_check_abs(where, "L2 error", l2, 0.0, l2_tol(pin, n));
    fails += sq_check_abs(where, "H1 error", h1, 0.0, 2.0 * P * P * n * l2_tol(pin, n));
    if (mode == 0) *mean_out = tm_mean(u);
    sem_field_free(&u);
    sem_poisson_free(&s);
    return fails;
}

int main(void)
{
    int fails = 0;
    srand(203);
    for (int n = 1; n <= 3; n += 2) {
        sem_tri_mesh *m = tm_square(n, 1);
        if (!m) return printf("t203: mesh\n"), 1;
        for (int P = 1; P <= DEG; ++P) {
            poly p = {{{0}}, P, 0.0};
            for (int i = 0; i <= P; ++i)
                for (int j = 0; i + j <= P; ++j) p.c[i][j] = 2.0 * rand() / RAND_MAX - 1.0;
            double mean = 0.0;
            fails += run(m, n, P, 0, &p, &mean); /* also gives the exact mean */
            fails += run(m, n, P, 2, &p, &mean);
            fails += run(m, n, P, 1, &p, &mean);
        }
        /* incompatible pure Neumann data: f = 1, g = 0 */
        sem_poisson *s = NULL;
        sem_field *u = NULL;
        sq_error err = {0};
        SQ_TEST_OK(sem_poisson_create(m, 3, SEM_CG, kind_neu, NULL, &s, &err), err);
        SQ_TEST_OK(sem_field_create(m, 3, 1, &u, &err), err);
        poly one = {{{0}}, 2, 0.0};
        one.c[2][0] = -0.5; /* -Δu = 1 */
        sem_poisson_data d = {src, &one, NULL, NULL, 0, NULL};
        fails += sq_check_int("t203 incompatible", "status", sem_poisson_solve(s, &d, u, &err),
                              SQ_ERR_USAGE);
        sem_field_free(&u);
        sem_poisson_free(&s);
        sem_tri_mesh_free(&m);
    }
    return fails ? 1 : 0;
}
