/* Quality of high-order quads on meshes with known answers: squares (eta 1,
 * tau 100 %, scaled Jacobian 1), a parallelogram of angle 60 deg (eta 2/3),
 * an annulus sector (straight eta 1 - dtheta/pi, curved eta 1, area 3π/4
 * exactly by quadrature at Q = 8), a quarter disc with one valence-3
 * vertex; resampling GLL <-> equispaced.
 * Tolerances (no BLAS: 1D Lagrange bases in closed form, src/mesh/quad_quality.c;
 * Q <= 10, coordinates <= 2): straight-sided eta from corner angles by a
 * few atan2/acos, a few U of angles <= pi over 90 deg: 1e-13 (1e-12 for
 * the annulus, whose corner coordinates are cos/sin); the curved measures
 * and scaled Jacobians differentiate the nodes with D (sums of Q + 1 terms
 * of sum |l'| <= Q^2 times |x| <= 2): 2 Q^2 (Q + 1) U |x| <= 5e-12, 1e-11
 * (1e-10 for eta curved mean: a mean of those over ~1e2 points); areas by
 * Gauss sums over n^2 (Q+1)^2 points: a few 1e-14; the annulus's curved
 * corner eta and Q = 8 area are discretisation errors of the arcs (the
 * boundary nodes lie on the circles to 2 U: 1e-15); resampling twice
 * through Lagrange bases of Lebesgue constants <= 30: 1e-12.  The scaled
 * Jacobian by Bézier bounds of an affine quad (det J constant) is 1 up to
 * the round-off of det J's Bernstein coefficients, bounded by
 * sq_jac_bezier_coefficients for each quad (r): min/max of coefficients
 * within r of J is at least (J - r)/(J + r) >= 1 - 2 r/J; that bound grows
 * with the Lagrange-to-Bernstein map (1e-11 at Q = 4, 5e-6 at Q = 10
 * equispaced); the deviations found are 1e-4 of it or less (2e-14 at
 * Q = 4, 1e-10 at Q = 10 equispaced). */
#include "jacobian_bezier.h"
#include "t6xx-quad-meshes.h"

/* 2 r/J over the quads of an affine mesh: the tolerance of a scaled
 * Jacobian of 1 by Bézier bounds (above). */
static double bezier_tol(const sq_quad_mesh *m)
{
    sq_jac_bezier *jb = NULL;
    sq_error err;
    SQ_TEST_OK(sq_jac_bezier_create(m->order, m->nodes, &jb, &err), err);
    int N = 2 * m->order;
    double c[400], tol = 0.0;
    for (int q = 0; q < m->nquads; q++) {
        double r =
            sq_jac_bezier_coefficients(jb, m->xy, &m->conn[q * (m->order + 1) * (m->order + 1)], c);
        double jmin = c[0];
        for (int k = 1; k < N * N; k++)
            jmin = fmin(jmin, c[k]);
        tol = fmax(tol, 2.0 * r / jmin);
    }
    sq_jac_bezier_free(&jb);
    return tol;
}

static const char *kind_name(sq_node_kind k) { return k == SQ_NODES_GLL ? "gll" : "equi"; }

static int check_square(int n, int Q, sq_node_kind kind)
{
    char ctx[64];
    snprintf(ctx, sizeof ctx, "square n=%d Q=%d %s", n, Q, kind_name(kind));
    sq_quad_mesh *m = t6_square(n, Q, kind);
    sq_quad_quality q;
    sq_error err;
    double *eta = malloc(sizeof(double) * m->nquads), *sj = malloc(sizeof(double) * m->nquads);
    SQ_TEST_OK(sq_quad_mesh_quality(m, eta, sj, 1, &q, &err), err);
    int f = 0;
    f += sq_check_abs(ctx, "eta mean", q.eta_mean, 1.0, 1e-13);
    f += sq_check_abs(ctx, "eta min", q.eta_min, 1.0, 1e-13);
    f += sq_check_abs(ctx, "tau %", q.tau_percent, 100.0, 0.0);
    f += sq_check_abs(ctx, "eta curved min", q.eta_curved_min, 1.0, 1e-11);
    double tb = bezier_tol(m);
    f += sq_check_abs(ctx, "min scaled Jacobian", q.min_scaled_jacobian, 1.0, tb);
    f += sq_check_abs(ctx, "min scaled Jacobian (nodes)", q.min_scaled_jacobian_nodes, 1.0, 1e-11);
    f += sq_check_abs(ctx, "area", q.area, 1.0, 1e-12);
    f += sq_check_int(ctx, "irregular interior", q.irregular_interior, 0);
    f += sq_check_int(ctx, "irregular boundary", q.irregular_boundary, 0);
    f += sq_check_int(ctx, "vertices", q.vertices, (n + 1) * (n + 1));
    f += sq_check_int(ctx, "boundary vertices", q.boundary_vertices, 4 * n);
    f += sq_check_int(ctx, "nodes", m->nnodes, (n * Q + 1) * (n * Q + 1));
    f += sq_check_int(ctx, "boundary sides", m->nbnd, 4 * n);
    f += sq_check_int(ctx, "inverted", q.inverted, 0);
    for (int e = 0; e < m->nquads; e++) {
        f += sq_check_abs(ctx, "eta[e]", eta[e], 1.0, 1e-13);
        f += sq_check_abs(ctx, "sjac[e]", sj[e], 1.0, tb);
    }
    free(eta), free(sj);
    sq_quad_mesh_free(&m);
    return f;
}

static int check_parallelogram(int Q, sq_node_kind kind)
{
    char ctx[64];
    snprintf(ctx, sizeof ctx, "parallelogram Q=%d %s", Q, kind_name(kind));
    double alpha = M_PI / 3;
    sq_quad_mesh *m = t6_parallelogram(4, &alpha, Q, kind);
    sq_quad_quality q;
    sq_error err;
    SQ_TEST_OK(sq_quad_mesh_quality(m, NULL, NULL, 1, &q, &err), err);
    int f = 0;
    /* angles 60 and 120 deg: eta = 1 - 30/90 */
    f += sq_check_abs(ctx, "eta mean", q.eta_mean, 2.0 / 3.0, 1e-13);
    f += sq_check_abs(ctx, "eta min", q.eta_min, 2.0 / 3.0, 1e-13);
    f += sq_check_abs(ctx, "eta curved mean", q.eta_curved_mean, 2.0 / 3.0, 1e-10);
    f += sq_check_abs(ctx, "tau %", q.tau_percent, 0.0, 0.0);
    f += sq_check_abs(ctx, "min scaled Jacobian (affine)", q.min_scaled_jacobian, 1.0,
                      bezier_tol(m));
    f += sq_check_abs(ctx, "min scaled Jacobian (affine, nodes)", q.min_scaled_jacobian_nodes, 1.0,
                      1e-11);
    f += sq_check_abs(ctx, "area", q.area, sin(alpha), 1e-12);
    f += sq_check_int(ctx, "irregular boundary", q.irregular_boundary, 0);
    sq_quad_mesh_free(&m);
    return f;
}

static int check_annulus(int n, int Q, sq_node_kind kind)
{
    char ctx[64];
    snprintf(ctx, sizeof ctx, "annulus n=%d Q=%d %s", n, Q, kind_name(kind));
    sq_quad_mesh *m = t6_annulus(n, Q, kind);
    sq_quad_quality q;
    sq_error err;
    SQ_TEST_OK(sq_quad_mesh_quality(m, NULL, NULL, 1, &q, &err), err);
    int f = 0;
    /* corner polygon of a polar cell: isosceles trapezoid with angles
     * 90 deg +- dtheta/2, dtheta = (pi/2)/n */
    double eta_s = 1.0 - 0.5 / n;
    f += sq_check_abs(ctx, "eta mean", q.eta_mean, eta_s, 1e-12);
    f += sq_check_abs(ctx, "eta min", q.eta_min, eta_s, 1e-12);
    f += sq_check_abs(ctx, "tau %", q.tau_percent, eta_s > 0.9 ? 100.0 : 0.0, 0.0);
    if (!(q.min_scaled_jacobian > 0.0)) {
        printf("%s: min scaled Jacobian %g <= 0\n", ctx, q.min_scaled_jacobian);
        f++;
    }
    /* the sides' tangents at the corners are radial and circumferential */
    double tol_c = Q >= 8 ? 1e-6 : Q >= 4 ? 1e-2 : 0.1;
    f += sq_check_abs(ctx, "eta curved min", q.eta_curved_min, 1.0, tol_c);
    if (Q == 8) f += sq_check_rel(ctx, "area (Q = 8)", q.area, 0.75 * M_PI, 1e-10);
    /* boundary nodes exactly on the circles r = 1 and r = 2 */
    for (int s = 0; s < m->nbnd; s++) {
        int side = m->bnd_side[s];
        if (side != 1 && side != 3) continue;
        for (int k = 0; k <= Q; k++) {
            int i = side == 1 ? Q : 0, g = m->conn[(size_t)m->bnd_quad[s] * (Q + 1) * (Q + 1) +
                                                     sq_quad_node(Q, i, k)];
            f += sq_check_abs(ctx, "node radius", hypot(m->xy[2 * g], m->xy[2 * g + 1]),
                              side == 1 ? 2.0 : 1.0, 1e-15);
        }
    }
    sq_quad_mesh_free(&m);
    return f;
}

static int check_disc(int n, int Q, sq_node_kind kind)
{
    char ctx[64];
    snprintf(ctx, sizeof ctx, "quarter disc n=%d Q=%d %s", n, Q, kind_name(kind));
    sq_quad_mesh *m = t6_quarter_disc(n, Q, kind);
    sq_quad_quality q;
    sq_error err;
    SQ_TEST_OK(sq_quad_mesh_quality(m, NULL, NULL, 1, &q, &err), err);
    int f = 0;
    f += sq_check_int(ctx, "quads", m->nquads, 3 * n * n);
    f += sq_check_int(ctx, "irregular interior", q.irregular_interior, 1);
    f += sq_check_int(ctx, "irregular boundary", q.irregular_boundary, 0);
    f += sq_check_int(ctx, "inverted", q.inverted, 0);
    f += sq_check_int(ctx, "vertices", q.vertices, 3 * (n + 1) * (n + 1) - 3 * (n + 1) + 1);
    /* V - E + F = 1 */
    if (!(q.min_scaled_jacobian > 0.0 && q.eta_min > 0.0 && q.eta_mean > 0.5)) {
        printf("%s: sjac %g eta min %g mean %g\n", ctx, q.min_scaled_jacobian, q.eta_min,
               q.eta_mean);
        f++;
    }
    sq_quad_mesh_free(&m);
    return f;
}

/* GLL -> equispaced -> GLL gives the nodes back. */
static int check_resample(int Q)
{
    char ctx[64];
    snprintf(ctx, sizeof ctx, "resample Q=%d", Q);
    sq_quad_mesh *m = t6_annulus(3, Q, SQ_NODES_GLL), *e = NULL, *g = NULL, *d = NULL;
    sq_error err;
    SQ_TEST_OK(sq_quad_mesh_resample(m, SQ_NODES_EQUISPACED, &e, &err), err);
    SQ_TEST_OK(sq_quad_mesh_resample(e, SQ_NODES_GLL, &g, &err), err);
    d = t6_annulus(3, Q, SQ_NODES_EQUISPACED);
    int f = sq_check_int(ctx, "kind", e->nodes, SQ_NODES_EQUISPACED);
    double back = 0.0, interp = 0.0;
    for (int v = 0; v < m->nnodes; v++) {
        back = fmax(back, hypot(g->xy[2 * v] - m->xy[2 * v], g->xy[2 * v + 1] - m->xy[2 * v + 1]));
        interp = fmax(interp, hypot(e->xy[2 * v] - d->xy[2 * v], e->xy[2 * v + 1] - d->xy[2 * v + 1]));
    }
    f += sq_check_abs(ctx, "round trip", back, 0.0, 1e-12);
    /* equispaced nodes of the GLL interpolant are close to the exact ones */
    f += sq_check_abs(ctx, "interpolant vs exact", interp, 0.0, Q >= 6 ? 1e-6 : 0.05);
    sq_quad_mesh_free(&m), sq_quad_mesh_free(&e), sq_quad_mesh_free(&g), sq_quad_mesh_free(&d);
    return f;
}

int main(void)
{
    int f = 0;
    for (int Q = 1; Q <= 10; Q++)
        for (int k = 0; k < 2; k++) {
            sq_node_kind kind = k ? SQ_NODES_EQUISPACED : SQ_NODES_GLL;
            f += check_square(3, Q, kind);
            f += check_parallelogram(Q, kind);
            f += check_annulus(6, Q, kind);
            f += check_disc(2, Q, kind);
            f += check_resample(Q);
        }
    /* bad arguments */
    sq_quad_mesh *m = NULL;
    sq_error err;
    f += sq_check_int("create", "order 11", sq_quad_mesh_create(11, SQ_NODES_GLL, 1, 1, 0, &m, &err),
                      SQ_ERR_USAGE);
    f += m != NULL;
    return f ? 1 : 0;
}
