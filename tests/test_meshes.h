/* semquad tests — small meshes built without cad/ (static inline, shared by
 * the t2xx solver tests), and error norms of a field against an exact
 * solution.
 *
 *  - tm_square(n, Pg): structured n x n mesh of the unit square, each cell
 *    cut along its lower-left/upper-right diagonal; geometry nodes of order
 *    Pg placed affinely; boundary tags bottom 0, right 1, top 2, left 3.
 *  - tm_disc(R, n, Pg): disc of radius R from five blocks, an inner square
 *    [-a,a]^2 (a = R/2) and four blocks between its sides and the circle,
 *    each block n x n cells.  Every geometry node is placed by the block's
 *    map: x = (1-eta) * (point on the square side) + eta * R (cos t, sin t),
 *    t linear in xi over a quarter of the circle, so boundary nodes lie
 *    exactly on the circle (at the angles of the edge's GLL nodes) and the
 *    map is smooth inside each block.  Boundary tag 0.  The centre is a
 *    vertex when n is even.  tm_disc_a(R, a, n, Pg) chooses a.  The blend
 *    distorts the outer triangles (scaled Jacobian about 0.26 at n = 1,
 *    0.32 at n = 2): with n = 1 the interpolation error of e^x sin y at
 *    P = 12 is only 8e-8, with n = 2 it is 2e-11.
 * Both are counter-clockwise with neighbours built. */
#ifndef SQ_TEST_MESHES_H
#define SQ_TEST_MESHES_H

#include "gauss.h"
#include "tri_geom.h"
#include "tri_lagrange.h"
#include "tri_mesh.h"
#include "tri_nodes.h"
#include "tri_quad.h"

#include <math.h>
#include <stdlib.h>

#ifndef TM_PI
#define TM_PI 3.14159265358979323846
#endif

/* A parametric block (xi, eta) in [0,1]^2 -> (x, y). */
typedef void (*tm_block_map)(double xi, double eta, const void *ctx, double out[2]);

/* Geometry nodes of triangle t whose corners have block parameters
 * p0, p1, p2 (counter-clockwise): node (r,s) at parameter
 * p0 + r (p1 - p0) + s (p2 - p0), mapped by F. */
static inline void tm_fill_nodes(sem_tri_mesh *m, int t, const double *rs, const double p0[2],
                                 const double p1[2], const double p2[2], tm_block_map F,
                                 const void *ctx)
{
    double *g = m->gxy + 2 * (size_t)m->nodes_per_tri * t;
    for (int k = 0; k < m->nodes_per_tri; ++k) {
        const double r = rs[2 * k], s = rs[2 * k + 1];
        const double xi = p0[0] + r * (p1[0] - p0[0]) + s * (p2[0] - p0[0]);
        const double eta = p0[1] + r * (p1[1] - p0[1]) + s * (p2[1] - p0[1]);
        F(xi, eta, ctx, g + 2 * k);
    }
}

static inline void tm_square_map(double xi, double eta, const void *ctx, double out[2])
{
    (void)ctx;
    out[0] = xi;
    out[1] = eta;
}

/* Set btag of every boundary edge (neigh == -1) from its midpoint. */
static inline void tm_tag_square(sem_tri_mesh *m)
{
    for (int t = 0; t < m->ntris; ++t)
        for (int k = 0; k < 3; ++k) {
            if (m->neigh[3 * t + k] >= 0) continue;
            const double *a = m->vxy + 2 * m->tri[3 * t + k];
            const double *b = m->vxy + 2 * m->tri[3 * t + (k + 1) % 3];
            const double x = 0.5 * (a[0] + b[0]), y = 0.5 * (a[1] + b[1]);
            int tag = 0;
            /* side midpoints: a few U off the side, others >= 1/n away */
            if (fabs(y) < 1e-12) tag = 0;
            else if (fabs(x - 1.0) < 1e-12) tag = 1;
            else if (fabs(y - 1.0) < 1e-12) tag = 2;
            else tag = 3;
            m->btag[3 * t + k] = tag;
        }
}

/* n x n unit square, geometry order Pg (straight).  NULL on failure. */
static inline sem_tri_mesh *tm_square(int n, int Pg)
{
    sem_tri_mesh *m = NULL;
    if (sem_tri_mesh_create(Pg, (n + 1) * (n + 1), 2 * n * n, &m, NULL) != SQ_OK) return NULL;
    double *rs = malloc(sizeof(double) * 2 * (size_t)m->nodes_per_tri);
    if (!rs || sem_tri_nodes(Pg, rs, NULL) != SQ_OK) {
        free(rs);
        sem_tri_mesh_free(&m);
        return NULL;
    }
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) {
            m->vxy[2 * (j * (n + 1) + i)] = (double)i / n;
            m->vxy[2 * (j * (n + 1) + i) + 1] = (double)j / n;
        }
    int t = 0;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const int v00 = j * (n + 1) + i, v10 = v00 + 1, v01 = v00 + n + 1, v11 = v01 + 1;
            const double p00[2] = {(double)i / n, (double)j / n};
            const double p10[2] = {(double)(i + 1) / n, (double)j / n};
            const double p01[2] = {(double)i / n, (double)(j + 1) / n};
            const double p11[2] = {(double)(i + 1) / n, (double)(j + 1) / n};
            m->tri[3 * t] = v00, m->tri[3 * t + 1] = v10, m->tri[3 * t + 2] = v11;
            tm_fill_nodes(m, t++, rs, p00, p10, p11, tm_square_map, NULL);
            m->tri[3 * t] = v00, m->tri[3 * t + 1] = v11, m->tri[3 * t + 2] = v01;
            tm_fill_nodes(m, t++, rs, p00, p11, p01, tm_square_map, NULL);
        }
    free(rs);
    if (sem_tri_mesh_build_neighbours(m, NULL) != SQ_OK) {
        sem_tri_mesh_free(&m);
        return NULL;
    }
    tm_tag_square(m);
    return m;
}

typedef struct {
    double R, a;
    int side; /* -1: inner square; 0..3: block outside side (E, N, W, S) */
} tm_disc_block;

static inline void tm_disc_map(double xi, double eta, const void *ctx, double out[2])
{
    const tm_disc_block *b = ctx;
    if (b->side < 0) { /* inner square [-a,a]^2 */
        out[0] = -b->a + 2.0 * b->a * xi;
        out[1] = -b->a + 2.0 * b->a * eta;
        return;
    }
    /* Block of side k: the east block rotated by k*pi/2.  East: inner side
     * x = a from y = a down to -a, arc from pi/4 down to -pi/4, so that
     * (xi, eta) -> (x, y) keeps the counter-clockwise orientation. */
    const double t = 0.25 * TM_PI - 0.5 * TM_PI * xi;
    const double ix = b->a, iy = b->a - 2.0 * b->a * xi;
    const double ex = (1.0 - eta) * ix + eta * b->R * cos(t);
    const double ey = (1.0 - eta) * iy + eta * b->R * sin(t);
    /* exact quarter turns, so that shared block edges coincide */
    switch (b->side) {
    case 0: out[0] = ex, out[1] = ey; break;
    case 1: out[0] = -ey, out[1] = ex; break;
    case 2: out[0] = -ex, out[1] = -ey; break;
    default: out[0] = ey, out[1] = -ex; break;
    }
}

/* Vertex index of (x,y) in m->vxy[0..*nv), appending it if new (the same
 * vertex from two blocks differs by a few U; distinct ones by >= 1e-2). */
static inline int tm_vertex(sem_tri_mesh *m, int *nv, const double p[2])
{
    for (int v = 0; v < *nv; ++v)
        if (fabs(m->vxy[2 * v] - p[0]) < 1e-10 && fabs(m->vxy[2 * v + 1] - p[1]) < 1e-10) return v;
    m->vxy[2 * *nv] = p[0];
    m->vxy[2 * *nv + 1] = p[1];
    return (*nv)++;
}

/* Disc of radius R, 5 blocks of n x n cells, geometry order Pg, inner
 * square [-a,a]^2 (0 < a < R/sqrt 2). */
static inline sem_tri_mesh *tm_disc_a(double R, double a, int n, int Pg)
{
    sem_tri_mesh *m = NULL;
    const int ntri = 5 * 2 * n * n;
    if (sem_tri_mesh_create(Pg, 5 * (n + 1) * (n + 1), ntri, &m, NULL) != SQ_OK) return NULL;
    double *rs = malloc(sizeof(double) * 2 * (size_t)m->nodes_per_tri);
    if (!rs || sem_tri_nodes(Pg, rs, NULL) != SQ_OK) {
        free(rs);
        sem_tri_mesh_free(&m);
        return NULL;
    }
    int nv = 0, t = 0;
    for (int side = -1; side < 4; ++side) {
        const tm_disc_block blk = {R, a, side};
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                const double p00[2] = {(double)i / n, (double)j / n};
                const double p10[2] = {(double)(i + 1) / n, (double)j / n};
                const double p01[2] = {(double)i / n, (double)(j + 1) / n};
                const double p11[2] = {(double)(i + 1) / n, (double)(j + 1) / n};
                double x[2];
                tm_disc_map(p00[0], p00[1], &blk, x);
                const int v00 = tm_vertex(m, &nv, x);
                tm_disc_map(p10[0], p10[1], &blk, x);
                const int v10 = tm_vertex(m, &nv, x);
                tm_disc_map(p01[0], p01[1], &blk, x);
                const int v01 = tm_vertex(m, &nv, x);
                tm_disc_map(p11[0], p11[1], &blk, x);
                const int v11 = tm_vertex(m, &nv, x);
                /* alternate the diagonal so that no triangle has two
                 * boundary edges at the block corners */
                if ((i + j) % 2 == 0) {
                    m->tri[3 * t] = v00, m->tri[3 * t + 1] = v10, m->tri[3 * t + 2] = v11;
                    tm_fill_nodes(m, t++, rs, p00, p10, p11, tm_disc_map, &blk);
                    m->tri[3 * t] = v00, m->tri[3 * t + 1] = v11, m->tri[3 * t + 2] = v01;
                    tm_fill_nodes(m, t++, rs, p00, p11, p01, tm_disc_map, &blk);
                } else {
                    m->tri[3 * t] = v00, m->tri[3 * t + 1] = v10, m->tri[3 * t + 2] = v01;
                    tm_fill_nodes(m, t++, rs, p00, p10, p01, tm_disc_map, &blk);
                    m->tri[3 * t] = v10, m->tri[3 * t + 1] = v11, m->tri[3 * t + 2] = v01;
                    tm_fill_nodes(m, t++, rs, p10, p11, p01, tm_disc_map, &blk);
                }
            }
    }
    free(rs);
    m->nverts = nv;
    if (sem_tri_mesh_build_neighbours(m, NULL) != SQ_OK) {
        sem_tri_mesh_free(&m);
        return NULL;
    }
    for (int k = 0; k < 3 * ntri; ++k)
        if (m->neigh[k] < 0) m->btag[k] = 0;
    return m;
}

/* The same with a = R/2. */
static inline sem_tri_mesh *tm_disc(double R, int n, int Pg) { return tm_disc_a(R, 0.5 * R, n, Pg); }

/* Exact solution: value and gradient at x. */
typedef void (*tm_exact_fn)(const double x[2], void *ctx, double *u, double grad[2]);

/* Errors of a one-component field against an exact solution over the
 * (discrete) domain: L2 norm, H1 seminorm (may be NULL), optionally
 * restricted to points with |x - c| >= rmin (rmin <= 0: everywhere).
 * Quadrature of degree 2 P + 2 Pg + 4.  Returns 0 on success. */
#include "field.h"
static inline int tm_errors_region(const sem_field *u, tm_exact_fn exact, void *ctx,
                                   const double c[2], double rmin, double *l2, double *h1)
{
    const sem_tri_mesh *m = u->mesh;
    sem_tri_quad *q = NULL;
    sem_tri_lagrange *L = NULL;
    *l2 = NAN;
    if (h1) *h1 = NAN;
    if (sem_tri_quad_create(2 * u->P + 2 * m->order + 4, &q, NULL) != SQ_OK) return 1;
    if (sem_tri_lagrange_create(m->order, &L, NULL) != SQ_OK) {
        sem_tri_quad_free(&q);
        return 1;
    }
    double e0 = 0.0, e1 = 0.0;
    for (int t = 0; t < m->ntris; ++t) {
        const double *g = m->gxy + 2 * (size_t)m->nodes_per_tri * t;
        for (int k = 0; k < q->npts; ++k) {
            double x[2], J[4], v, dr, ds, ue, ge[2];
            const double r = q->rs[2 * k], s = q->rs[2 * k + 1];
            const double det = sem_tri_geom_map(L, g, r, s, x, J);
            if (rmin > 0.0 && hypot(x[0] - c[0], x[1] - c[1]) < rmin) continue;
            sem_field_eval_ref(u, t, r, s, &v, &dr, &ds);
            exact(x, ctx, &ue, ge);
            /* grad_x = J^{-T} (d/dr, d/ds) */
            const double gx = (J[3] * dr - J[2] * ds) / det;
            const double gy = (-J[1] * dr + J[0] * ds) / det;
            const double w = q->w[k] * fabs(det);
            e0 += w * (v - ue) * (v - ue);
            e1 += w * ((gx - ge[0]) * (gx - ge[0]) + (gy - ge[1]) * (gy - ge[1]));
        }
    }
    sem_tri_quad_free(&q);
    sem_tri_lagrange_free(&L);
    *l2 = sqrt(e0);
    if (h1) *h1 = sqrt(e1);
    return 0;
}

static inline int tm_errors(const sem_field *u, tm_exact_fn exact, void *ctx, double *l2,
                            double *h1)
{
    const double c[2] = {0.0, 0.0};
    return tm_errors_region(u, exact, ctx, c, 0.0, l2, h1);
}

/* Mean of a one-component field over the domain. */
static inline double tm_mean(const sem_field *u)
{
    const sem_tri_mesh *m = u->mesh;
    sem_tri_quad *q = NULL;
    sem_tri_lagrange *L = NULL;
    if (sem_tri_quad_create(u->P + 2 * m->order, &q, NULL) != SQ_OK) return NAN;
    if (sem_tri_lagrange_create(m->order, &L, NULL) != SQ_OK) {
        sem_tri_quad_free(&q);
        return NAN;
    }
    double iu = 0.0, area = 0.0;
    for (int t = 0; t < m->ntris; ++t) {
        const double *g = m->gxy + 2 * (size_t)m->nodes_per_tri * t;
        for (int k = 0; k < q->npts; ++k) {
            double v;
            const double w =
                q->w[k] * fabs(sem_tri_geom_map(L, g, q->rs[2 * k], q->rs[2 * k + 1], NULL, NULL));
            sem_field_eval_ref(u, t, q->rs[2 * k], q->rs[2 * k + 1], &v, NULL, NULL);
            iu += w * v;
            area += w;
        }
    }
    sem_tri_quad_free(&q);
    sem_tri_lagrange_free(&L);
    return iu / area;
}

#endif
