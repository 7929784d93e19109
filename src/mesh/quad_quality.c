/* semquad — quality of a high-order quad mesh (quad_mesh.h).
 *
 * eta (Jezdimirović 2021, Table 1; docs/conventions.md "Quality") on the
 * straight corner polygon with signed angles w.r.t. the majority orientation,
 * in [0, 2π) (docs/conventions.md), as tests/t611 measures the MSH output
 * independently, so the report agrees with what a reader of the file finds; the curved variant uses
 * the tangents of the element's sides at its corners, from the derivative
 * of its Lagrange map.  Scaled Jacobian: min det J / max |det J| over the
 * whole element, bounded by the Bézier coefficients of det J
 * (jacobian_bezier.h, Johnen 2013), and, for comparison, over the
 * element's (Q+1)^2 nodes only.  Area: Gauss–Legendre with Q+1 points per
 * direction, exact for the polynomial map (det J has degree 2Q-1 in each
 * variable). */
#include "jacobian_bezier.h"
#include "quad_mesh.h"

#include "gauss.h"
#include "sq_parallel.h"
#include "sq_parallel_sort.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Angle at c from a (next corner direction) to b (previous), quadstats.py's
 * convention: atan2(orient * (a x b), a . b) wrapped to [0, 2π). */
static double corner_angle(double ax, double ay, double bx, double by, double orient)
{
    double cr = orient * (ax * by - ay * bx), dt = ax * bx + ay * by;
    double th = atan2(cr, dt);
    if (th < 0) th += 2 * M_PI;
    return th;
}

static double eta_of(const double ang[4])
{
    /* in degrees, as quadstats.py, so the numbers agree to the last bits */
    const double deg = 180.0 / M_PI;
    double worst = 0.0;
    for (int k = 0; k < 4; k++) {
        double d = fabs(ang[k] * deg - 90.0);
        if (d > worst) worst = d;
    }
    return 1.0 - worst / 90.0;
}

double sq_quad_corner_eta(const double *const c[4])
{
    double ang[4];
    for (int k = 0; k < 4; k++) {
        const double *p = c[k], *a = c[(k + 1) % 4], *b = c[(k + 3) % 4];
        ang[k] = corner_angle(a[0] - p[0], a[1] - p[1], b[0] - p[0], b[1] - p[1], 1.0);
    }
    return eta_of(ang);
}

/* quads per range: a range's Bézier work arrays are set up once */
#define QUALITY_GRAIN 64

static const int CORNER[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};

/* The corner vertex of quad q at corner k. */
static int corner_vertex(const sq_quad_mesh *m, int q, int k)
{
    int Q = m->order;
    return m->conn[(size_t)q * (Q + 1) * (Q + 1) + sq_quad_node(Q, CORNER[k][0] * Q, CORNER[k][1] * Q)];
}

static const double *corner_xy(const sq_quad_mesh *m, int q, int k)
{
    return &m->xy[2 * (size_t)corner_vertex(m, q, k)];
}

static double signed_area(const sq_quad_mesh *m, int q)
{
    double a = 0.0;
    for (int k = 0; k < 4; k++) {
        const double *p = corner_xy(m, q, k), *r = corner_xy(m, q, (k + 1) % 4);
        a += p[0] * r[1] - r[0] * p[1];
    }
    return 0.5 * a;
}

typedef struct {
    const sq_quad_mesh *m;
    signed char *sign; /* per quad: the sign of its corner polygon's area */
} sign_pass;

static sq_status area_signs(void *ctx, long begin, long end, sq_error *err)
{
    (void)err;
    const sign_pass *p = ctx;
    for (long q = begin; q < end; q++) {
        double a = signed_area(p->m, (int)q);
        p->sign[q] = (signed char)((a > 0) - (a < 0));
    }
    return SQ_OK;
}

/* *orient: the majority orientation of the corner polygons (quadstats.py),
 * the signs found on the threads and counted here. */
static sq_status orientation(const sq_quad_mesh *m, int threads, double *orient, sq_error *err)
{
    sign_pass p = {m, malloc((size_t)m->nquads + 1)};
    if (!p.sign) return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    sq_status st = sq_parallel_for(threads, m->nquads, QUALITY_GRAIN, area_signs, &p, err);
    long balance = 0;
    for (int q = 0; q < m->nquads; q++) balance += p.sign[q];
    *orient = balance >= 0 ? 1.0 : -1.0;
    free(p.sign);
    return st;
}

static void straight_angles(const sq_quad_mesh *m, int q, double orient, double ang[4])
{
    for (int k = 0; k < 4; k++) {
        const double *c = corner_xy(m, q, k), *a = corner_xy(m, q, (k + 1) % 4),
                     *b = corner_xy(m, q, (k + 3) % 4);
        ang[k] = corner_angle(a[0] - c[0], a[1] - c[1], b[0] - c[0], b[1] - c[1], orient);
    }
}

/* Derivative matrix D[a*(Q+1)+i] = l_i'(t_a) of the element's own nodes. */
static void diff_matrix(const sq_quad_basis *b, double *D)
{
    int Q = b->order;
    double l[11];
    for (int a = 0; a <= Q; a++) sq_quad_basis_eval(b, b->t[a], l, &D[a * (Q + 1)]);
}

/* x_u, x_v (d = {x_u, x_v, y_u, y_v}) at node (a, b) of quad q. */
static void node_deriv(const sq_quad_mesh *m, const double *D, int q, int a, int b, double d[4])
{
    int Q = m->order;
    const int *c = &m->conn[(size_t)q * (Q + 1) * (Q + 1)];
    d[0] = d[1] = d[2] = d[3] = 0.0;
    for (int i = 0; i <= Q; i++) {
        const double *p = &m->xy[2 * (size_t)c[sq_quad_node(Q, i, b)]];
        const double *r = &m->xy[2 * (size_t)c[sq_quad_node(Q, a, i)]];
        double du = D[a * (Q + 1) + i], dv = D[b * (Q + 1) + i];
        d[0] += du * p[0];
        d[2] += du * p[1];
        d[1] += dv * r[0];
        d[3] += dv * r[1];
    }
}

static void curved_angles(const sq_quad_mesh *m, const double *D, int q, double orient,
                          double ang[4])
{
    int Q = m->order;
    for (int k = 0; k < 4; k++) {
        double d[4];
        node_deriv(m, D, q, CORNER[k][0] * Q, CORNER[k][1] * Q, d);
        double xu[2] = {d[0], d[2]}, xv[2] = {d[1], d[3]}, a[2], b[2];
        /* tangent towards the next corner (a) and the previous one (b) */
        switch (k) {
        case 0: a[0] = xu[0], a[1] = xu[1], b[0] = xv[0], b[1] = xv[1]; break;
        case 1: a[0] = xv[0], a[1] = xv[1], b[0] = -xu[0], b[1] = -xu[1]; break;
        case 2: a[0] = -xu[0], a[1] = -xu[1], b[0] = -xv[0], b[1] = -xv[1]; break;
        default: a[0] = -xv[0], a[1] = -xv[1], b[0] = xu[0], b[1] = xu[1]; break;
        }
        ang[k] = corner_angle(a[0], a[1], b[0], b[1], orient);
    }
}

sq_status sq_quad_mesh_eta_curved(const sq_quad_mesh *m, double *eta_curved, sq_error *err)
{
    sq_quad_basis b;
    SQ_TRY(sq_quad_basis_init(&b, m->order, m->nodes, err));
    double D[121], orient;
    SQ_TRY(orientation(m, 1, &orient, err));
    diff_matrix(&b, D);
    for (int q = 0; q < m->nquads; q++) {
        double ang[4];
        curved_angles(m, D, q, orient, ang);
        eta_curved[q] = eta_of(ang);
    }
    return SQ_OK;
}

/* The scaled Jacobian of quad q by the Bézier bounds of its det J (the
 * per-quad value, *valid if they prove det J > 0) and by det J at its nodes
 * (*at_nodes). */
static sq_status quad_jacobian(const sq_quad_mesh *m, const double *D, sq_jac_bezier *jb, int q,
                               double *ratio, double *at_nodes, int *valid, int *capped,
                               sq_error *err)
{
    int Q = m->order;
    double jmin = HUGE_VAL, jmax = 0.0;
    for (int j = 0; j <= Q; j++)
        for (int i = 0; i <= Q; i++) {
            double d[4];
            node_deriv(m, D, q, i, j, d);
            double dj = d[0] * d[3] - d[1] * d[2];
            jmin = fmin(jmin, dj);
            jmax = fmax(jmax, fabs(dj));
        }
    *at_nodes = jmax > 0.0 ? jmin / jmax : -1.0;
    sq_jac_bounds bd;
    SQ_TRY(sq_jac_bezier_bounds(jb, m->xy, &m->conn[(size_t)q * (Q + 1) * (Q + 1)], &bd, err));
    *ratio = sq_jac_ratio(&bd);
    *valid = sq_jac_valid(&bd);
    *capped += bd.capped;
    return SQ_OK;
}

static int cmp_u64(const void *a, const void *b)
{
    unsigned long long x = *(const unsigned long long *)a, y = *(const unsigned long long *)b;
    return x < y ? -1 : x > y;
}

/* What one quad's pass finds (the per-quad results the summary reduces in
 * quad order, so it does not depend on the threads). */
typedef struct {
    double eta_curved, sj_nodes, area;
    double ang[4]; /* straight corner angles, for the vertices' angle sums */
    int corner[4]; /* the corner vertices */
    int capped;
    char valid;
} quad_result;

typedef struct {
    const sq_quad_mesh *m;
    const double *D, *gw;
    const double (*gl)[11], (*gdl)[11];
    double orient;
    int ng;
    double *eta, *sjac;
    quad_result *res;
    unsigned long long *keys; /* 4 per quad: its sides' vertex pairs */
    int threads;
} quality_pass;

/* Area of quad q by Gauss quadrature of det J. */
static double quad_area(const quality_pass *p, int q)
{
    const sq_quad_mesh *m = p->m;
    int Q = m->order;
    const int *c = &m->conn[(size_t)q * (Q + 1) * (Q + 1)];
    double area = 0.0;
    for (int pv = 0; pv < p->ng; pv++)
        for (int pu = 0; pu < p->ng; pu++) {
            double d[4] = {0, 0, 0, 0};
            for (int j = 0; j <= Q; j++)
                for (int i = 0; i <= Q; i++) {
                    const double *x = &m->xy[2 * (size_t)c[sq_quad_node(Q, i, j)]];
                    double fu = p->gdl[pu][i] * p->gl[pv][j], fv = p->gl[pu][i] * p->gdl[pv][j];
                    d[0] += fu * x[0];
                    d[1] += fv * x[0];
                    d[2] += fu * x[1];
                    d[3] += fv * x[1];
                }
            area += p->gw[pu] * p->gw[pv] * (d[0] * d[3] - d[1] * d[2]);
        }
    return area;
}

/* Quad q's sides as vertex pairs, least vertex in the high bits. */
static void side_keys(const sq_quad_mesh *m, int q, unsigned long long key[4])
{
    for (int k = 0; k < 4; k++) {
        int v = corner_vertex(m, q, k), w = corner_vertex(m, q, (k + 1) % 4);
        unsigned long long lo = (unsigned)(v < w ? v : w), hi = (unsigned)(v < w ? w : v);
        key[k] = lo << 32 | hi;
    }
}

/* Quads [begin, end): eta, curved eta, Jacobian bounds, area. */
static sq_status quality_range(void *ctx, long begin, long end, sq_error *err)
{
    const quality_pass *p = ctx;
    sq_jac_bezier *jb = NULL;
    SQ_TRY(sq_jac_bezier_create(p->m->order, p->m->nodes, &jb, err));
    sq_status st = SQ_OK;
    for (long q = begin; q < end && st == SQ_OK; q++) {
        quad_result *r = &p->res[q];
        straight_angles(p->m, (int)q, p->orient, r->ang);
        p->eta[q] = eta_of(r->ang);
        for (int k = 0; k < 4; k++) r->corner[k] = corner_vertex(p->m, (int)q, k);
        side_keys(p->m, (int)q, &p->keys[4 * q]);
        double ang[4];
        curved_angles(p->m, p->D, (int)q, p->orient, ang);
        r->eta_curved = eta_of(ang);
        int valid = 0;
        r->capped = 0;
        p->sjac[q] = r->sj_nodes = -1.0;
        st = quad_jacobian(p->m, p->D, jb, (int)q, &p->sjac[q], &r->sj_nodes, &valid, &r->capped,
                           err);
        r->valid = (char)valid;
        r->area = quad_area(p, (int)q);
    }
    sq_jac_bezier_free(&jb);
    return st;
}

typedef struct {
    const quality_pass *p;
    int *valence;
    double *angsum;
} corner_pass;

/* vertices per range: each range reads every quad's corners */
#define CORNER_GRAIN 4096

/* Valences and angle sums of vertices [begin, end): every quad's corners
 * read, those of the range added in quad order (so each sum is the same
 * for every thread count). */
static sq_status corner_sums(void *ctx, long begin, long end, sq_error *err)
{
    (void)err;
    const corner_pass *c = ctx;
    for (int q = 0; q < c->p->m->nquads; q++)
        for (int k = 0; k < 4; k++) {
            int v = c->p->res[q].corner[k];
            if (v < begin || v >= end) continue;
            c->valence[v]++;
            c->angsum[v] += c->p->res[q].ang[k];
        }
    return SQ_OK;
}

/* Valences and angle sums of the corner vertices (in quad order), the
 * boundary's by the edges used once (quadstats.py): the vertex counts of
 * qq.  keys[4 nquads] are sorted here. */
static sq_status vertex_topology(const quality_pass *p, unsigned long long *keys,
                                 sq_quad_quality *qq, sq_error *err)
{
    const sq_quad_mesh *m = p->m;
    int nq = m->nquads, nv = 0; /* corner vertices are < nv */
    for (int q = 0; q < nq; q++)
        for (int k = 0; k < 4; k++)
            if (p->res[q].corner[k] >= nv) nv = p->res[q].corner[k] + 1;
    corner_pass c = {p, calloc((size_t)nv + 1, sizeof *c.valence),
                     calloc((size_t)nv + 1, sizeof *c.angsum)};
    int *valence = c.valence;
    double *angsum = c.angsum;
    char *bnd = calloc((size_t)nv + 1, 1);
    if (!valence || !angsum || !bnd) {
        free(valence), free(angsum), free(bnd);
        return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    }
    sq_status st = sq_parallel_for(p->threads, nv, CORNER_GRAIN, corner_sums, &c, err);
    size_t ne = 4 * (size_t)nq;
    if (st == SQ_OK) st = sq_parallel_sort(p->threads, keys, ne, sizeof *keys, cmp_u64, err);
    if (st != SQ_OK) {
        free(valence), free(angsum), free(bnd);
        return st;
    }
    for (size_t i = 0; i < ne;) {
        size_t k = i;
        while (k < ne && keys[k] == keys[i]) k++;
        if (k - i == 1) {
            bnd[keys[i] >> 32] = 1;
            bnd[keys[i] & 0xffffffffULL] = 1;
        }
        i = k;
    }
    for (int v = 0; v < nv; v++) {
        if (!valence[v]) continue;
        qq->vertices++;
        if (!bnd[v]) {
            qq->irregular_interior += valence[v] != 4;
            continue;
        }
        qq->boundary_vertices++;
        /* expected valence from the mesh's interior angle, round half up */
        int expect = (int)floor(angsum[v] * (180.0 / M_PI) / 90.0 + 0.5);
        if (expect < 1) expect = 1;
        qq->irregular_boundary += valence[v] != expect;
    }
    free(valence), free(angsum), free(bnd);
    return SQ_OK;
}

/* The summary from the per-quad results, in quad order. */
static void reduce(const quality_pass *p, sq_quad_quality *qq)
{
    int nq = p->m->nquads;
    double eta_sum = 0.0, etac_sum = 0.0, eta_min = HUGE_VAL, etac_min = HUGE_VAL;
    double sj_min = HUGE_VAL, sjn_min = HUGE_VAL, area = 0.0;
    int n_tau = 0, n_tauc = 0, inverted = 0;
    for (int q = 0; q < nq; q++) {
        const quad_result *r = &p->res[q];
        double e = p->eta[q], ec = r->eta_curved, s = p->sjac[q];
        eta_sum += e;
        etac_sum += ec;
        eta_min = fmin(eta_min, e);
        etac_min = fmin(etac_min, ec);
        n_tau += e > 0.9;
        n_tauc += ec > 0.9;
        if (s < sj_min) sj_min = s, qq->worst_quad = q;
        sjn_min = fmin(sjn_min, r->sj_nodes);
        inverted += !r->valid;
        qq->jacobian_capped += r->capped;
        area += r->area;
    }
    qq->eta_mean = eta_sum / nq;
    qq->eta_min = eta_min;
    qq->tau_percent = 100.0 * n_tau / nq;
    qq->eta_curved_mean = etac_sum / nq;
    qq->eta_curved_min = etac_min;
    qq->tau_curved_percent = 100.0 * n_tauc / nq;
    qq->min_scaled_jacobian = sj_min;
    qq->min_scaled_jacobian_nodes = sjn_min;
    qq->area = area;
    qq->inverted = inverted;
}

sq_status sq_quad_mesh_quality(const sq_quad_mesh *m, double *eta, double *sjac, int threads,
                               sq_quad_quality *qq, sq_error *err)
{
    memset(qq, 0, sizeof *qq);
    int Q = m->order, nq = m->nquads;
    if (nq == 0) return SQ_FAIL(err, SQ_ERR_USAGE, "quality of an empty mesh");
    sq_quad_basis b;
    SQ_TRY(sq_quad_basis_init(&b, Q, m->nodes, err));
    double D[121];
    diff_matrix(&b, D);
    /* Gauss–Legendre on [0,1] for the area */
    int ng = Q + 1;
    double gx[12], gw[12], gl[12][11], gdl[12][11];
    SQ_TRY(sem_gauss_jacobi(ng, 0.0, 0.0, gx, gw, err));
    for (int p = 0; p < ng; p++) {
        gx[p] = 0.5 * (gx[p] + 1.0);
        gw[p] *= 0.5;
        sq_quad_basis_eval(&b, gx[p], gl[p], gdl[p]);
    }
    double orient;
    SQ_TRY(orientation(m, threads, &orient, err));
    quality_pass p = {.m = m, .D = D, .gw = gw, .gl = (const double(*)[11])gl,
                      .gdl = (const double(*)[11])gdl, .orient = orient, .ng = ng,
                      .eta = eta ? eta : malloc((size_t)nq * sizeof *eta),
                      .sjac = sjac ? sjac : malloc((size_t)nq * sizeof *sjac),
                      .res = malloc((size_t)nq * sizeof *p.res),
                      .keys = malloc(4 * (size_t)nq * sizeof *p.keys), .threads = threads};
    sq_status st = p.eta && p.sjac && p.res && p.keys
                       ? SQ_OK : SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    if (st == SQ_OK) st = sq_parallel_for(threads, nq, QUALITY_GRAIN, quality_range, &p, err);
    if (st == SQ_OK) {
        reduce(&p, qq);
        st = vertex_topology(&p, p.keys, qq, err);
    }
    if (st == SQ_OK) sq_quad_mesh_map(m, &b, qq->worst_quad, 0.5, 0.5, qq->worst_xy, NULL);
    if (!eta) free(p.eta);
    if (!sjac) free(p.sjac);
    free(p.res);
    free(p.keys);
    return st;
}
