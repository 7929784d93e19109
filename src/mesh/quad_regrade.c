/* semquad — boundary layers exact on every grid line (docs/sizes.md, "A
 * boundary layer that blends in"): the transfinite map grades only the
 * layout edges leaving a wall by the walls' metric; the columns between
 * them take its scaling (the patch's width over the spoke's length), so
 * their first cells were squeezed.  Here every grid line leaving a wall is
 * followed straight on through regular vertices, across patches, to where
 * it ends (the boundary, an irregular vertex) and its nodes redistributed
 * along it: one-dimensional equidistribution of the metric, the layers'
 * cells exact and the rest scaled so that the line keeps its count. */
#include "quad_mesher_private.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Midpoint samples of the metric per segment of a line: the layers' size
 * b + a d varies by at most the ratio over a cell, so the rule's error on
 * a cell's measure is below (ln r)^2 / (24 SUB^2), 3e-5 at r = 1.3. */
#define SUB 16
/* The scaling beyond the layers is clamped to [1/MAX_SCALE, MAX_SCALE]: a
 * line whose count is far from its measure is spread evenly instead. */
#define MAX_SCALE 8.0

/* Adjacency of the vertex mesh: the quads around each vertex (CSR),
 * whether it lies on the boundary, on a wall. */
typedef struct {
    int *start, *around;
    char *bnd, *wall;
} adjacency;

static void adjacency_free(adjacency *a)
{
    free(a->start), free(a->around), free(a->bnd), free(a->wall);
}

static sq_status adjacency_make(const qm_vmesh *v, const sq_mesher_options *o, adjacency *a,
                                sq_error *err)
{
    a->start = calloc((size_t)v->nv + 2, sizeof(int));
    a->around = malloc(sizeof(int) * (4 * (size_t)v->nq + 1));
    a->bnd = calloc((size_t)v->nv + 1, 1);
    a->wall = calloc((size_t)v->nv + 1, 1);
    if (!a->start || !a->around || !a->bnd || !a->wall)
        return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    for (int q = 0; q < v->nq; q++)
        for (int k = 0; k < 4; k++) {
            a->start[v->quad[4 * q + k] + 2]++;
            int t = v->side_tag[4 * q + k], w = 0;
            if (t < 0) continue;
            for (int b = 0; b < o->nbl; b++) w |= o->bl_edges[b] == t;
            for (int e = 0; e < 2; e++) {
                int i = v->quad[4 * q + (k + e) % 4];
                a->bnd[i] = 1;
                a->wall[i] |= (char)w;
            }
        }
    for (int i = 0; i < v->nv; i++) a->start[i + 2] += a->start[i + 1];
    for (int q = 0; q < v->nq; q++)
        for (int k = 0; k < 4; k++) a->around[a->start[v->quad[4 * q + k] + 1]++] = q;
    return SQ_OK;
}

static int quad_has(const qm_vmesh *v, int q, int i)
{
    const int *c = &v->quad[4 * q];
    return c[0] == i || c[1] == i || c[2] == i || c[3] == i;
}

/* The grid line through prev and cur continued past cur: at a regular
 * interior vertex (4 quads) the neighbour sharing no quad with prev; -1
 * elsewhere. */
static int straight_on(const qm_vmesh *v, const adjacency *a, int prev, int cur)
{
    if (a->bnd[cur] || a->start[cur + 1] - a->start[cur] != 4) return -1;
    for (int t = a->start[cur]; t < a->start[cur + 1]; t++) {
        const int *c = &v->quad[4 * a->around[t]];
        int k = 0;
        while (c[k] != cur) k++;
        for (int s = 1; s <= 3; s += 2) {
            int n = c[(k + s) % 4], touches = 0;
            for (int u = a->start[cur]; u < a->start[cur + 1]; u++)
                touches |= quad_has(v, a->around[u], n) && quad_has(v, a->around[u], prev);
            if (n != prev && !touches) return n;
        }
    }
    return -1;
}

/* The vertex a line leaves wall vertex w by: at a regular boundary
 * vertex (2 quads) the corner both quads share besides w; -1 elsewhere. */
static int leaving(const qm_vmesh *v, const adjacency *a, int w)
{
    if (a->start[w + 1] - a->start[w] != 2) return -1;
    const int *c = &v->quad[4 * a->around[a->start[w]]];
    int q1 = a->around[a->start[w] + 1];
    for (int k = 0; k < 4; k++)
        if (c[k] != w && quad_has(v, q1, c[k]) && !a->bnd[c[k]]) return c[k];
    return -1;
}

/* The line's measure: m[j * SUB + s] the integral of 1 / h(x, t) from its
 * start to the s-th sub-interval's start of segment j (line[0..n]). */
static void line_measure(const qm_vmesh *v, const sq_mesher_options *o, double far,
                         const int *line, int n, double *m)
{
    m[0] = 0.0;
    for (int j = 0; j < n; j++) {
        const double *p = &v->xy[2 * line[j]], *q = &v->xy[2 * line[j + 1]];
        double t[2] = {q[0] - p[0], q[1] - p[1]}, len = hypot(t[0], t[1]);
        for (int s = 0; s < SUB; s++) {
            double u = (s + 0.5) / SUB, x[2] = {p[0] + u * t[0], p[1] + u * t[1]};
            m[j * SUB + s + 1] =
                m[j * SUB + s] + len / SUB / sq_size_field_eval_dir(o->sizes, x, t, far);
        }
    }
}

/* The weight chi of the scaling at measure M: 0 over the first a cells
 * (the layers), rising linearly to 1 at the end b; with a wall at the
 * end too, b is where its layers begin and chi a tent between a and
 * b. */
static double ramp(double M, double a, double b, int end_wall)
{
    if (b <= a) return 0.0;
    double up = (M - a) / (end_wall ? 0.5 * (b - a) : b - a);
    double down = end_wall ? (b - M) / (0.5 * (b - a)) : 1.0;
    return fmax(0.0, fmin(1.0, fmin(up, down)));
}

/* The nodes of line[0..n] (its ends kept) moved along the line so that
 * node k sits where the measure, scaled by 1 + (lambda - 1) chi beyond
 * the layers, reaches k: lambda such that the line's n cells hold its
 * scaled measure, so its first cells (the layers) are the metric's own
 * (read with the far size far).  out[2 k]
 * receives node k's position. */
static void regrade_line(const qm_vmesh *v, const sq_mesher_options *o, double far,
                         const int *line, int n, int end_wall, double *m, double *w, double *out)
{
    line_measure(v, o, far, line, n, m);
    int ns = n * SUB;
    double total = m[ns], chi_m = 0.0, a = o->bl_layers;
    double b = end_wall ? total - o->bl_layers : total;
    for (int s = 0; s < ns; s++)
        chi_m += (m[s + 1] - m[s]) * ramp(0.5 * (m[s] + m[s + 1]), a, b, end_wall);
    double lambda = chi_m > 0.0 ? 1.0 + (n - total) / chi_m : 1.0;
    lambda = fmin(fmax(lambda, 1.0 / MAX_SCALE), MAX_SCALE);
    w[0] = 0.0;
    for (int s = 0; s < ns; s++) {
        double chi = ramp(0.5 * (m[s] + m[s + 1]), a, b, end_wall);
        w[s + 1] = w[s] + (m[s + 1] - m[s]) * (1.0 + (lambda - 1.0) * chi);
    }
    /* node k where w reaches k w[ns] / n, linear inside a sub-interval */
    int s = 0;
    for (int k = 1; k < n; k++) {
        double target = w[ns] * k / n;
        while (s < ns - 1 && w[s + 1] < target) s++;
        double d = w[s + 1] - w[s], f = d > 0.0 ? (target - w[s]) / d : 0.0;
        double u = (s % SUB + f) / SUB;
        const double *p = &v->xy[2 * line[s / SUB]], *q = &v->xy[2 * line[s / SUB + 1]];
        out[2 * k] = p[0] + u * (q[0] - p[0]);
        out[2 * k + 1] = p[1] + u * (q[1] - p[1]);
    }
}

/* Follow the line leaving wall vertex w: line[0] = w, then straight on
 * through vertices no earlier line took (claimed), to its last vertex
 * (the boundary, an irregular or claimed vertex); its segment count. */
static int follow(const qm_vmesh *v, const adjacency *a, const char *claimed, int w, int *line)
{
    int n = 0, up = leaving(v, a, w);
    if (up < 0 || claimed[up]) return 0;
    line[0] = w, line[1] = up, n = 1;
    for (int nx; n < v->nv - 1 && (nx = straight_on(v, a, line[n - 1], line[n])) >= 0; n++) {
        if (claimed[nx]) break;
        int seen = 0;
        for (int j = 0; j <= n && !seen; j++) seen = line[j] == nx;
        if (seen) break;
        line[n + 1] = nx;
    }
    return n;
}

/* The vertex of line[0..n] `extra` vertices past the first one where the
 * size along the line is the isotropic size (the walls' layers and growth
 * left behind), at most n. */
static int core_cut(const qm_vmesh *v, const sq_mesher_options *o, double far, const int *line,
                    int n, int extra)
{
    for (int j = 1; j < n; j++) {
        const double *p = &v->xy[2 * line[j]], *q = &v->xy[2 * line[j + 1]];
        double t[2] = {q[0] - p[0], q[1] - p[1]};
        if (sq_size_field_eval_dir(o->sizes, p, t, far) >= sq_size_field_eval(o->sizes, p, far))
            return j + extra < n ? j + extra : n;
    }
    return n;
}

/* Every quad around the vertices line[1..n-1] convex at its corners. */
static int line_valid(const qm_vmesh *v, const adjacency *a, const int *line, int n)
{
    for (int j = 1; j < n; j++)
        for (int t = a->start[line[j]]; t < a->start[line[j] + 1]; t++)
            if (!qm_quad_valid(v, a->around[t])) return 0;
    return 1;
}

sq_status qm_regrade_walls(const sq_mesher_options *o, double far, int reach, qm_vmesh *v,
                           int **ends, sq_error *err)
{
    if (ends && !(*ends = calloc((size_t)v->nv + 1, sizeof(int))))
        return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    adjacency a = {0};
    sq_status st = adjacency_make(v, o, &a, err);
    int *line = st == SQ_OK ? malloc(sizeof(int) * ((size_t)v->nv + 1)) : NULL;
    char *claimed = st == SQ_OK ? calloc((size_t)v->nv + 1, 1) : NULL;
    double *m = st == SQ_OK ? malloc(sizeof(double) * ((size_t)v->nv * SUB + 1)) : NULL;
    double *w = st == SQ_OK ? malloc(sizeof(double) * ((size_t)v->nv * SUB + 1)) : NULL;
    double *pos = st == SQ_OK ? malloc(sizeof(double) * 2 * ((size_t)v->nv + 1)) : NULL;
    if (st == SQ_OK && (!line || !claimed || !m || !w || !pos))
        st = SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    for (int i = 0; i < v->nv && st == SQ_OK; i++) {
        if (!a.wall[i]) continue;
        int n = follow(v, &a, claimed, i, line);
        if (ends && n > 0 && !a.bnd[line[n]] && straight_on(v, &a, line[n - 1], line[n]) < 0 &&
            !claimed[line[n]])
            (*ends)[line[n]] = 1;
        if (reach > 0 && n > 1) n = core_cut(v, o, far, line, n, reach);
        if (n < 2) continue;
        regrade_line(v, o, far, line, n, a.wall[line[n]], m, w, pos);
        /* kept unless it folds a quad (the transfinite grid then stays) */
        for (int j = 1; j < n; j++) {
            double *x = &v->xy[2 * line[j]], keep[2] = {x[0], x[1]};
            x[0] = pos[2 * j], x[1] = pos[2 * j + 1];
            pos[2 * j] = keep[0], pos[2 * j + 1] = keep[1];
        }
        if (!line_valid(v, &a, line, n))
            for (int j = 1; j < n; j++) memcpy(&v->xy[2 * line[j]], &pos[2 * j], 2 * sizeof(double));
        for (int j = 1; j < n; j++) claimed[line[j]] = 1;
    }
    free(line), free(claimed), free(m), free(w), free(pos);
    adjacency_free(&a);
    return st;
}
