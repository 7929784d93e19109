/* Bounds of det J by Bézier coefficients (src/mesh/jacobian_bezier.c,
 * Johnen 2013) on single order-4 quads of the unit square with one
 * interior node moved by δ along x: x = u + δ l_i(u) l_j(v), y = v, so
 * det J = 1 + δ l_i'(u) l_j(v).  At the nodes l_j(t_b) is 0 or 1, so det J
 * there is 1 + δ l_i'(t_a); between them |l_i' l_j| grows past its node
 * values (GLL, i = j = 1: min l_1'(t_a) = -2.82 at the nodes, -3.97 over
 * the square; equispaced, i = 1, j = 2: -5.33 and -9.00).  Hence
 *   - GLL δ = 0.30, equispaced δ = 0.15: det J > 0 at every node (>= 0.15,
 *     0.20) but < 0 between them (-0.19, -0.35): the node sampling says
 *     valid, the bounds must prove it invalid (a value <= 0 found);
 *   - GLL δ = 0.20 (min 0.21) and a polar annulus element: proven valid.
 * Each bound is checked against det J sampled densely from the Lagrange
 * map (independent of the Bernstein path) on a G x G grid: the lower bound
 * is below every sample, and the least sample is within the refinement's
 * own tolerance (SQ_JAC_TOL of max |det J|, or twice the round-off bound r)
 * plus the grid's error of the lower bound.  The grid error: the least
 * sample lies at most 1/(2G) in each direction from the minimiser along
 * which det J is stationary (interior: its gradient vanishes; on a side:
 * the grid covers the side, its tangential derivative vanishes; a corner
 * is sampled), so it exceeds the minimum by at most
 * (|J_uu| + 2|J_uv| + |J_vv|)/2 (1/(2G))^2, the second derivatives bounded
 * by the coefficients' differences (n(n-1) max|Δ²c|, n^2 max|ΔuΔv c|,
 * n = 2Q-1: Bernstein derivative rule).  Samples of det J err by round-off
 * of sums of (Q+1)^2 terms |l_i'||l_j||x| (Markov: sum |l'| <= Q^2 Λ,
 * Λ <= 2 the Lebesgue constant at Q = 4): 4 (Q+1)^2 Q^2 Λ^2 U max|x| max|∇x|
 * per sample, added to the comparisons. */
#include "jacobian_bezier.h"
#include "t6xx-quad-meshes.h"

#include <float.h>

#define G 400

static sq_quad_mesh *moved_square(int Q, sq_node_kind kind, int i, int j, double delta)
{
    const double v[] = {0, 0, 1, 0, 1, 1, 0, 1};
    const int quad[] = {0, 1, 2, 3};
    sq_quad_mesh *m = NULL;
    sq_error err;
    SQ_TEST_OK(sq_quad_mesh_elevate(4, v, 1, quad, NULL, 1, Q, kind, NULL, NULL, &m, &err), err);
    m->xy[2 * m->conn[sq_quad_node(Q, i, j)]] += delta;
    return m;
}

/* Bound of (|J_uu| + 2|J_uv| + |J_vv|)/2 from the coefficients c (N x N). */
static double second_derivative_bound(const double *c, int N)
{
    int n = N - 1;
    double uu = 0.0, uv = 0.0, vv = 0.0;
    for (int l = 0; l < N; l++)
        for (int k = 0; k < N; k++) {
            const double *p = &c[l * N + k];
            if (k + 2 < N) uu = fmax(uu, fabs(p[2] - 2 * p[1] + p[0]));
            if (l + 2 < N) vv = fmax(vv, fabs(p[2 * N] - 2 * p[N] + p[0]));
            if (k + 1 < N && l + 1 < N) uv = fmax(uv, fabs(p[N + 1] - p[N] - p[1] + p[0]));
        }
    return 0.5 * (n * (n - 1.0) * (uu + vv) + 2.0 * n * n * uv);
}

/* Checks of quad 0 of m: the bounds against the dense samples; *valid set
 * to sq_jac_valid, *found_negative to whether a value <= 0 was found. */
static int check_bounds(const char *ctx, const sq_quad_mesh *m, int *valid, int *found_negative)
{
    int Q = m->order, N = 2 * Q, f = 0;
    sq_error err;
    sq_jac_bezier *jb = NULL;
    SQ_TEST_OK(sq_jac_bezier_create(Q, m->nodes, &jb, &err), err);
    sq_jac_bounds b;
    SQ_TEST_OK(sq_jac_bezier_bounds(jb, m->xy, m->conn, &b, &err), err);
    double c[400];
    sq_jac_bezier_coefficients(jb, m->xy, m->conn, c);
    double grid = second_derivative_bound(c, N) * 0.25 / ((double)G * G);
    sq_quad_basis basis;
    SQ_TEST_OK(sq_quad_basis_init(&basis, Q, m->nodes, &err), err);
    double smin = HUGE_VAL, smax = -HUGE_VAL, xmax = 0.0, dmax = 0.0;
    for (int v = 0; v <= G; v++)
        for (int u = 0; u <= G; u++) {
            double x[2], d[4];
            sq_quad_mesh_map(m, &basis, 0, (double)u / G, (double)v / G, x, d);
            double J = d[0] * d[3] - d[1] * d[2];
            smin = fmin(smin, J), smax = fmax(smax, J);
            xmax = fmax(xmax, fmax(fabs(x[0]), fabs(x[1])));
            for (int k = 0; k < 4; k++)
                dmax = fmax(dmax, fabs(d[k]));
        }
    const double U = 0.5 * DBL_EPSILON, lambda = 2.0;
    double eval = 4.0 * (Q + 1) * (Q + 1) * Q * Q * lambda * lambda * U * xmax * dmax;
    double S = fmax(fabs(b.min_up), fabs(b.max_lo));
    double sharp = fmax(SQ_JAC_TOL * S, 2.0 * b.roundoff);
    if (!(b.min_lo <= smin + b.roundoff + eval)) {
        printf("%s: lower bound %.17g above the least sample %.17g\n", ctx, b.min_lo, smin);
        f++;
    }
    if (!(b.max_up >= smax - b.roundoff - eval)) {
        printf("%s: upper bound %.17g below the largest sample %.17g\n", ctx, b.max_up, smax);
        f++;
    }
    f += sq_check_abs(ctx, "least sample - lower bound", smin - b.min_lo, 0.0,
                      sharp + grid + b.roundoff + eval);
    f += sq_check_abs(ctx, "upper bound - largest sample", b.max_up - smax, 0.0,
                      sharp + grid + b.roundoff + eval);
    f += sq_check_int(ctx, "capped", b.capped, 0);
    *valid = sq_jac_valid(&b);
    *found_negative = b.min_up <= 0.0;
    sq_jac_bezier_free(&jb);
    return f;
}

/* Node sampling says valid, the bounds prove invalid. */
static int check_invalid(const char *ctx, sq_node_kind kind, int i, int j, double delta)
{
    sq_quad_mesh *m = moved_square(4, kind, i, j, delta);
    sq_quad_quality q;
    sq_error err;
    SQ_TEST_OK(sq_quad_mesh_quality(m, NULL, NULL, 1, &q, &err), err);
    int valid, negative, f = check_bounds(ctx, m, &valid, &negative);
    if (!(q.min_scaled_jacobian_nodes > 0.0)) {
        printf("%s: det J at the nodes %g: the quad was meant valid there\n", ctx,
               q.min_scaled_jacobian_nodes);
        f++;
    }
    f += sq_check_int(ctx, "proven valid", valid, 0);
    f += sq_check_int(ctx, "value <= 0 found", negative, 1);
    f += sq_check_int(ctx, "inverted (quality)", q.inverted, 1);
    if (!(q.min_scaled_jacobian < 0.0)) {
        printf("%s: scaled Jacobian by the bounds %g, expected < 0\n", ctx, q.min_scaled_jacobian);
        f++;
    }
    sq_quad_mesh_free(&m);
    return f;
}

static int check_valid(const char *ctx, sq_quad_mesh *m)
{
    sq_quad_quality q;
    sq_error err;
    SQ_TEST_OK(sq_quad_mesh_quality(m, NULL, NULL, 1, &q, &err), err);
    int f = 0, valid = 1, negative = 0;
    /* every quad, the first one against the dense samples */
    sq_quad_mesh one = *m;
    one.nquads = 1;
    f += check_bounds(ctx, &one, &valid, &negative);
    f += sq_check_int(ctx, "proven valid", valid, 1);
    f += sq_check_int(ctx, "inverted (quality)", q.inverted, 0);
    sq_quad_mesh_free(&m);
    return f;
}

int main(void)
{
    int f = 0;
    f += check_invalid("GLL, node (1,1) moved 0.30", SQ_NODES_GLL, 1, 1, 0.30);
    f += check_invalid("equispaced, node (1,2) moved 0.15", SQ_NODES_EQUISPACED, 1, 2, 0.15);
    f += check_valid("GLL, node (1,1) moved 0.20", moved_square(4, SQ_NODES_GLL, 1, 1, 0.20));
    for (int Q = 2; Q <= 10; Q += 4)
        f += check_valid("annulus", t6_annulus(2, Q, SQ_NODES_GLL));
    return f ? 1 : 0;
}
