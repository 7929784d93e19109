/* t220: the SIPG discretization (sem/poisson_dg.c) is consistent: on a
 * straight mesh it reproduces any polynomial of degree <= P to round-off,
 * with Dirichlet data imposed weakly (Nitsche) on every side, or mixed
 * with Neumann data on two sides; the same on geometry of order 3 whose
 * nodes are placed affinely (the curved code path), and on a square whose
 * interior nodes are moved (a genuinely curved interior map, straight
 * boundary).
 * Tolerances: u lies in the space, so only the solve's round-off is left,
 * as for CG (t203): sq_solve_roundoff (sem_roundoff.h) in L2, 2 P^2 n
 * times that in H1 (inverse inequality). */
#include "field.h"
#include "poisson.h"
#include "sem_roundoff.h"
#include "test_meshes.h"
#include "test_util.h"

typedef struct {
    int P;
    double a, b, c;
    int mixed; /* tags 1 and 2 carry Neumann data */
} poly;

/* u = (a + b x + c y)^P + x^2 y (P >= 3) or x y (P = 2) */
static void exact(const double x[2], void *ctx, double *u, double g[2])
{
    const poly *p = ctx;
    const double l = p->a + p->b * x[0] + p->c * x[1];
    const double lp = pow(l, p->P), dl = p->P * pow(l, p->P - 1);
    double v = lp, gx = dl * p->b, gy = dl * p->c;
    if (p->P >= 3) {
        v += x[0] * x[0] * x[1];
        gx += 2 * x[0] * x[1];
        gy += x[0] * x[0];
    } else if (p->P == 2) {
        v += x[0] * x[1];
        gx += x[1];
        gy += x[0];
    }
    *u = v;
    g[0] = gx;
    g[1] = gy;
}

static double src(const double x[2], void *ctx)
{
    const poly *p = ctx;
    const double l = p->a + p->b * x[0] + p->c * x[1];
    double f = p->P >= 2 ? -p->P * (p->P - 1) * pow(l, p->P - 2) * (p->b * p->b + p->c * p->c) : 0.0;
    if (p->P >= 3) f -= 2 * x[1];
    return f;
}

static double bval(const double x[2], const double n[2], int tag, void *ctx)
{
    double u, g[2];
    exact(x, ctx, &u, g);
    if (((const poly *)ctx)->mixed && (tag == 1 || tag == 2)) return g[0] * n[0] + g[1] * n[1]; /* Neumann sides */
    return u;
}

static sem_bc_kind mixed(int tag, void *ctx)
{
    (void)ctx;
    return tag == 1 || tag == 2 ? SEM_BC_NEUMANN : SEM_BC_DIRICHLET;
}

static int run(const char *ctxname, sem_tri_mesh *m, int n, int P, int use_mixed)
{
    /* max |u| on the unit square: (|a| + |b| + |c|)^P + 1 */
    const double tol = sq_solve_roundoff(P, n, 1.0 + pow(1.8, P));
    sq_error err;
    poly p = {P, 0.4, 0.8, -0.6, use_mixed};
    sem_poisson *S = NULL;
    sem_field *u = NULL;
    SQ_TEST_OK(sem_poisson_create(m, P, SEM_DG, use_mixed ? mixed : NULL, NULL, &S, &err), err);
    SQ_TEST_OK(sem_field_create(m, P, 1, &u, &err), err);
    const sem_poisson_data d = {src, &p, bval, &p, 0, NULL};
    SQ_TEST_OK(sem_poisson_solve(S, &d, u, &err), err);
    double l2, h1;
    int fail = 0;
    if (tm_errors(u, exact, &p, &l2, &h1)) return 1;
    char what[128];
    snprintf(what, sizeof what, "%s P=%d %s", ctxname, P, use_mixed ? "mixed" : "Dirichlet");
    fail += sq_check_int(what, "ndofs", sem_poisson_ndofs(S), (long)m->ntris * (P + 1) * (P + 2) / 2);
    fail += sq_check_abs(what, "L2 error", l2, 0.0, tol);
    fail += sq_check_abs(what, "H1 error", h1, 0.0, 2.0 * P * P * n * tol);
    sem_field_free(&u);
    sem_poisson_free(&S);
    return fail;
}

/* Move the interior geometry nodes of a straight square mesh by a smooth
 * displacement that vanishes on the boundary of the square: the elements
 * become curved, the domain does not. */
static void bend(sem_tri_mesh *m)
{
    for (size_t k = 0; k < (size_t)m->nodes_per_tri * m->ntris; ++k) {
        double *x = m->gxy + 2 * k;
        const double bump = 0.03 * sin(TM_PI * x[0]) * sin(TM_PI * x[1]);
        x[0] += bump;
        x[1] += 0.5 * bump;
    }
}

int main(void)
{
    int fail = 0;
    sem_tri_mesh *m = tm_square(3, 1);
    sem_tri_mesh *m3 = tm_square(2, 3);
    if (!m || !m3) return 1;
    for (int P = 1; P <= 8; ++P) {
        fail += run("straight mesh", m, 3, P, 0);
        fail += run("straight mesh", m, 3, P, 1);
        fail += run("order-3 geometry", m3, 2, P, 0);
    }
    /* curved interior map: polynomials are no longer in the (mapped) space
     * exactly, but the quadratic (P >= 2 reproduces it only on affine
     * elements), so check the linear function at P = 1..4 */
    bend(m3);
    for (int P = 1; P <= 4; ++P) {
        sq_error err;
        poly p = {1, 0.4, 0.8, -0.6, 0};
        sem_poisson *S = NULL;
        sem_field *u = NULL;
        SQ_TEST_OK(sem_poisson_create(m3, P, SEM_DG, NULL, NULL, &S, &err), err);
        SQ_TEST_OK(sem_field_create(m3, P, 1, &u, &err), err);
        const sem_poisson_data d = {src, &p, bval, &p, 0, NULL};
        SQ_TEST_OK(sem_poisson_solve(S, &d, u, &err), err);
        double l2, h1;
        if (tm_errors(u, exact, &p, &l2, &h1)) return 1;
        /* a linear function is not a polynomial of (r,s) on a curved element:
         * the error is the approximation error, small and falling with P
         * (CPU-independent: round-off is far below) */
        fail += sq_check_abs("bent elements, linear u", "L2 error", l2, 0.0, P == 1 ? 1e-2 : 2e-3);
        sem_field_free(&u);
        sem_poisson_free(&S);
    }
    sem_tri_mesh_free(&m);
    sem_tri_mesh_free(&m3);
    return fail ? 1 : 0;
}
