/* semquad tests t6xx — synthetic high-order quad meshes built with
 * sq_quad_mesh_elevate: a unit square, a parallelogram, an annulus sector
 * (nodes exactly on the circles) and a three-patch rounded quarter disc
 * (one interior valence-3 vertex, curved outer sides). */
#ifndef T6XX_QUAD_MESHES_H
#define T6XX_QUAD_MESHES_H

#include "quad_mesh.h"
#include "test_util.h"

#include <math.h>
#include <stdlib.h>

/* Tag of a boundary side from its midpoint in the parameter domain. */
typedef int (*t6_tag_fn)(const double mid[2]);

/* Coarse mesh of npatch parameter quads (corners ccw) each split n x n,
 * vertices merged when closer than 1e-12, boundary sides tagged by tag(). */
static inline sq_quad_mesh *t6_build(int npatch, const double (*pc)[4][2], int n, t6_tag_fn tag,
                              int ntags, int Q, sq_node_kind kind, sq_quad_warp_fn warp,
                              void *ctx)
{
    int maxv = npatch * (n + 1) * (n + 1), nq = npatch * n * n, nv = 0;
    double *v = malloc(sizeof(double) * 2 * (size_t)maxv);
    int *quads = malloc(sizeof(int) * 4 * (size_t)nq), *tags = malloc(sizeof(int) * 4 * (size_t)nq);
    int *id = malloc(sizeof(int) * (size_t)(n + 1) * (n + 1));
    for (int p = 0; p < npatch; p++) {
        const double(*c)[2] = pc[p];
        for (int j = 0; j <= n; j++)
            for (int i = 0; i <= n; i++) {
                double u = (double)i / n, w = (double)j / n, x[2];
                for (int d = 0; d < 2; d++)
                    x[d] = (1 - u) * (1 - w) * c[0][d] + u * (1 - w) * c[1][d] + u * w * c[2][d] +
                           (1 - u) * w * c[3][d];
                int k = 0;
                /* the same point from two blocks: a few roundings of
                 * coordinates <= 2 (a few U) against spacings >= 1e-2 */
                while (k < nv && fabs(v[2 * k] - x[0]) + fabs(v[2 * k + 1] - x[1]) > 1e-12) k++;
                if (k == nv) v[2 * nv] = x[0], v[2 * nv + 1] = x[1], nv++;
                id[j * (n + 1) + i] = k;
            }
        for (int j = 0; j < n; j++)
            for (int i = 0; i < n; i++) {
                int q = p * n * n + j * n + i, *qq = &quads[4 * q];
                qq[0] = id[j * (n + 1) + i];
                qq[1] = id[j * (n + 1) + i + 1];
                qq[2] = id[(j + 1) * (n + 1) + i + 1];
                qq[3] = id[(j + 1) * (n + 1) + i];
            }
    }
    for (int q = 0; q < nq; q++)
        for (int k = 0; k < 4; k++) {
            const double *a = &v[2 * quads[4 * q + k]], *b = &v[2 * quads[4 * q + (k + 1) % 4]];
            double mid[2] = {0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1])};
            tags[4 * q + k] = tag(mid); /* used only on boundary sides */
        }
    sq_quad_mesh *m = NULL;
    sq_error err;
    SQ_TEST_OK(sq_quad_mesh_elevate(nv, v, nq, quads, tags, ntags, Q, kind, warp, ctx, &m, &err),
               err);
    for (int p = 0; p < npatch; p++)
        for (int q = p * n * n; q < (p + 1) * n * n; q++) m->patch[q] = p;
    free(v), free(quads), free(tags), free(id);
    return m;
}

/* Unit square sides: 0 bottom, 1 right, 2 top, 3 left (midpoints of sides
 * are a few U off the sides, interior ones >= 1e-2 away). */
static inline int t6_square_tag(const double m[2])
{
    if (m[1] < 1e-12) return 0;
    if (m[0] > 1 - 1e-12) return 1;
    if (m[1] > 1 - 1e-12) return 2;
    return 3;
}

static const double t6_unit[1][4][2] = {{{0, 0}, {1, 0}, {1, 1}, {0, 1}}};

static inline sq_quad_mesh *t6_square(int n, int Q, sq_node_kind kind)
{
    return t6_build(1, t6_unit, n, t6_square_tag, 4, Q, kind, NULL, NULL);
}

/* Parallelogram with angle alpha at the origin: (u, v) -> (u + v cos a, v sin a). */
static inline void t6_shear(void *ctx, const double in[2], double out[2])
{
    double a = *(const double *)ctx;
    out[0] = in[0] + in[1] * cos(a);
    out[1] = in[1] * sin(a);
}

static inline sq_quad_mesh *t6_parallelogram(int n, double *alpha, int Q, sq_node_kind kind)
{
    return t6_build(1, t6_unit, n, t6_square_tag, 4, Q, kind, t6_shear, alpha);
}

/* Annulus sector r in [1, 2] (u), theta in [0, pi/2] (v): counter-clockwise. */
static inline void t6_polar(void *ctx, const double in[2], double out[2])
{
    (void)ctx;
    double r = 1.0 + in[0], t = 0.5 * M_PI * in[1];
    out[0] = r * cos(t);
    out[1] = r * sin(t);
}

static inline sq_quad_mesh *t6_annulus(int nr_nt, int Q, sq_node_kind kind)
{
    return t6_build(1, t6_unit, nr_nt, t6_square_tag, 4, Q, kind, t6_polar, NULL);
}

/* A rounded quarter disc from three patches of the unit square mapped by
 * the elliptical square-to-disc map (x sqrt(1 - y^2/2), y sqrt(1 - x^2/2))
 * applied to 0.9 (x, y) and scaled back: smooth with a positive Jacobian,
 * curved outer sides, one interior vertex of valence 3 where the patches
 * meet.  Tags: 0 (y = 0), 1 (the outer curve), 2 (x = 0). */
static inline void t6_disc_map(void *ctx, const double in[2], double out[2])
{
    (void)ctx;
    double x = 0.9 * in[0], y = 0.9 * in[1];
    out[0] = x * sqrt(1 - 0.5 * y * y) / 0.9;
    out[1] = y * sqrt(1 - 0.5 * x * x) / 0.9;
}

static inline int t6_disc_tag(const double m[2])
{
    if (m[1] < 1e-12) return 0;
    if (m[0] < 1e-12) return 2;
    return 1;
}

static const double t6_disc_patches[3][4][2] = {
    {{0, 0}, {0.5, 0}, {0.5, 0.5}, {0, 0.5}},
    {{0.5, 0}, {1, 0}, {1, 1}, {0.5, 0.5}},
    {{0.5, 0.5}, {1, 1}, {0, 1}, {0, 0.5}}};

static inline sq_quad_mesh *t6_quarter_disc(int n, int Q, sq_node_kind kind)
{
    return t6_build(3, t6_disc_patches, n, t6_disc_tag, 3, Q, kind, t6_disc_map, NULL);
}

#endif
