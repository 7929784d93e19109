#include "quad_mesher.h"

#include "gauss.h"
#include "quad_relax.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define MAX_SEGMENTS 1000000
/* a relaxed mesh is kept at once when its curved quads are at least this
 * far from folding (smallest scaled Jacobian over their nodes) */
#define SJ_ACCEPT 0.2 /* per edge: quantization that runs away is a bug */

void sq_mesher_options_default(sq_mesher_options *opt)
{
    memset(opt, 0, sizeof *opt);
    opt->order = 4;
    opt->nodes = SQ_NODES_GLL;
    opt->bl_ratio = 1.2;
    opt->max_quads = SQ_MAX_QUADS;
}

sq_status sq_mesher_check_size(double area, double size, double max_quads, sq_error *err)
{
    double quads = fabs(area) / (size * size);
    if (!(quads <= max_quads))
        return SQ_FAIL(err, SQ_ERR_USAGE,
                       "--size %g gives about %.3g quads, more than --max-quads %.3g: a size of "
                       "%.3g or more fits",
                       size, quads, max_quads, sqrt(fabs(area) / max_quads));
    return SQ_OK;
}

static int is_quad(const sq_layout_patch *p) { return p->ncorners == 4 && p->ncycles == 1; }

/* Segments on side k of patch p. */
static long side_count(const sq_layout_patch *p, int k, const int *n)
{
    long c = 0;
    for (int h = p->side_start[k]; h < p->side_start[k + 1]; h++) c += n[p->half[h].edge];
    return c;
}

/* Quads of a quantization: the product of each patch's two side counts. */
static double quantized_quads(const sq_layout *L, const int *n)
{
    double quads = 0.0;
    for (int q = 0; q < L->npatches; q++)
        quads += (double)side_count(&L->patches[q], 0, n) * (double)side_count(&L->patches[q], 1, n);
    return quads;
}

/* Boundary layers (Marcon 2019 §3.4): an edge leaving a boundary-layer
 * curve is graded from that end, first segment bl_first, growing by
 * bl_ratio over bl_layers segments, then uniform.  grade[e]: bit 1 graded
 * from n0, bit 2 from n1. */
static int on_bl_curve(const sq_layout *L, const sq_face_info *info, const sq_mesher_options *o,
                       int node)
{
    const sq_layout_node *v = &L->nodes[node];
    for (int b = 0; b < o->nbl; b++) {
        if (v->kind == SQ_LNODE_FOOT && v->id == o->bl_edges[b]) return 1;
        if (v->kind == SQ_LNODE_CORNER && (info->vertices[v->id].edge_in == o->bl_edges[b] ||
                                           info->vertices[v->id].edge_out == o->bl_edges[b]))
            return 1;
    }
    return 0;
}

static int is_bl_edge(const sq_layout *L, const sq_mesher_options *o, int e)
{
    for (int b = 0; b < o->nbl; b++)
        if (L->edges[e].cad_edge == o->bl_edges[b]) return 1;
    return 0;
}

static void bl_grading(const sq_layout *L, const sq_face_info *info, const sq_mesher_options *o,
                       int *grade)
{
    for (int e = 0; e < L->nedges; e++) {
        grade[e] = 0;
        if (o->nbl == 0 || is_bl_edge(L, o, e)) continue;
        grade[e] = on_bl_curve(L, info, o, L->edges[e].n0) | 2 * on_bl_curve(L, info, o, L->edges[e].n1);
    }
}

/* Thickness of nb geometric layers. */
static double bl_thickness(const sq_mesher_options *o, int nb)
{
    return o->bl_ratio == 1.0 ? o->bl_first * nb
                              : o->bl_first * (pow(o->bl_ratio, nb) - 1.0) / (o->bl_ratio - 1.0);
}

/* Segments an edge of length len needs: its layers, then the rest at size. */
static int edge_segments(double len, double size, int grade, const sq_mesher_options *o)
{
    int ends = (grade & 1) + ((grade & 2) >> 1), nb = 0;
    double rest = len;
    while (ends && nb < o->bl_layers && rest - ends * o->bl_first * pow(o->bl_ratio, nb) > 0.0) {
        rest -= ends * o->bl_first * pow(o->bl_ratio, nb);
        nb++;
    }
    long v = lround(rest / size);
    return (int)fmin((double)(ends * nb + (v < 1 ? 1 : v)), MAX_SEGMENTS);
}

/* Arc-length fractions f[0..n] of an edge with n segments. */
static void edge_fractions(double len, int n, int grade, const sq_mesher_options *o, double *f)
{
    int ends = (grade & 1) + ((grade & 2) >> 1), nb = 0;
    while (ends && nb < o->bl_layers && ends * (nb + 1) < n &&
           ends * bl_thickness(o, nb + 1) < len)
        nb++;
    double T = bl_thickness(o, nb) / len; /* one end's layers, as a fraction */
    int mid = n - ends * nb;
    for (int k = 0; k <= n; k++) f[k] = (double)k / n;
    if (!nb) return;
    int lo = grade & 1 ? nb : 0, hi = grade & 2 ? n - nb : n;
    double a = grade & 1 ? T : 0.0, b = grade & 2 ? 1.0 - T : 1.0;
    for (int k = 0; k <= n; k++) {
        if (k <= lo && (grade & 1)) f[k] = bl_thickness(o, k) / len;
        else if (k >= hi && (grade & 2)) f[k] = 1.0 - bl_thickness(o, n - k) / len;
        else f[k] = a + (b - a) * (double)(k - lo) / mid;
    }
}

/* Edge measure in units of the field's size: m[e] = the integral of
 * ds / e^H along edge e (its length when the field carries no size), and
 * its cumulative values at SIZE_SAMPLES + 1 equal arc-length fractions.
 * Boundary-layer edges keep their length: their grading is absolute. */
#define SIZE_SAMPLES 32
static sq_status size_measure(const sq_layout *L, const cad_face *face, const sq_face_info *info,
                              const sq_mesher_options *o, const int *grade, double *m, double *cum, sq_error *err)
{
    for (int e = 0; e < L->nedges; e++) {
        double *c = &cum[(size_t)e * (SIZE_SAMPLES + 1)], prev = 0.0;
        int elem = -1;
        for (int k = 0; k <= SIZE_SAMPLES; k++) {
            double x[2], r = 1.0;
            if (o->field && o->field->size && !grade[e]) {
                SQ_TRY(sq_layout_edge_point(L, face, e, (double)k / SIZE_SAMPLES, x, err));
                double sz = o->field->size(o->field->ctx, x, &elem);
                /* e^H vanishes at a valence-3 point and blows up at a
                 * valence-5 one: bounded to a factor 4 either way */
                r = sz > 0.0 ? 1.0 / fmin(fmax(sz, 0.25), 4.0) : 1.0;
            }
            c[k] = k == 0 ? 0.0 : c[k - 1] + 0.5 * (prev + r) * L->edges[e].length / SIZE_SAMPLES;
            prev = r;
        }
        m[e] = c[SIZE_SAMPLES];
    }
    /* e^H is relative: scaled by c with c^2 the mean of e^{-2H} over the
     * face (sampled on a grid), so that about area / size^2 quads result,
     * as without it */
    if (o->field && o->field->size) {
        double sum = 0.0;
        int cnt = 0, elem = -1;
        for (int j = 0; j < SIZE_SAMPLES; j++)
            for (int i = 0; i < SIZE_SAMPLES; i++) {
                double x[2] = {info->bbox[0] + (i + 0.5) / SIZE_SAMPLES * (info->bbox[2] - info->bbox[0]),
                               info->bbox[1] + (j + 0.5) / SIZE_SAMPLES * (info->bbox[3] - info->bbox[1])};
                double sz = o->field->size(o->field->ctx, x, &elem);
                if (sz <= 0.0) continue; /* outside */
                sz = fmin(fmax(sz, 0.25), 4.0);
                sum += 1.0 / (sz * sz);
                cnt++;
            }
        double c = cnt ? sqrt(sum / cnt) : 1.0;
        for (int e = 0; e < L->nedges; e++)
            if (!grade[e]) {
                m[e] /= c;
                for (int k = 0; k <= SIZE_SAMPLES; k++) cum[(size_t)e * (SIZE_SAMPLES + 1) + k] /= c;
            }
    }
    return SQ_OK;
}

/* Arc-length fraction where the cumulative measure cum reaches fraction u. */
static double measure_fraction(const double *cum, double u)
{
    double target = u * cum[SIZE_SAMPLES];
    int k = 0;
    while (k < SIZE_SAMPLES - 1 && cum[k + 1] < target) k++;
    double d = cum[k + 1] - cum[k];
    return (k + (d > 0.0 ? (target - cum[k]) / d : 0.0)) / SIZE_SAMPLES;
}

/* Design 1: chord quantization. */
static sq_status quantize(const sq_layout *L, const double *len, double size, const int *grade,
                          const sq_mesher_options *o, int *n, sq_error *err)
{
    for (int e = 0; e < L->nedges; e++) n[e] = edge_segments(len[e], size, grade[e], o);
    for (int changed = 1; changed;) {
        changed = 0;
        for (int q = 0; q < L->npatches; q++) {
            const sq_layout_patch *p = &L->patches[q];
            for (int k = 0; k < 2; k++) {
                long a = side_count(p, k, n), c = side_count(p, k + 2, n);
                if (a == c) continue;
                int s = a < c ? k : k + 2, best = -1;
                double ratio = -1.0;
                for (int h = p->side_start[s]; h < p->side_start[s + 1]; h++) {
                    int e = p->half[h].edge;
                    double r = len[e] / n[e];
                    if (r > ratio) {
                        ratio = r;
                        best = e;
                    }
                }
                n[best] += (int)labs(a - c);
                if (n[best] > MAX_SEGMENTS)
                    return SQ_FAIL(err, SQ_ERR_LAYOUT,
                                   "chord quantization does not settle (patch %d): the layout's "
                                   "chords are inconsistent", q);
                changed = 1;
            }
        }
    }
    return SQ_OK;
}

/* Node fractions along one segment: GLL or equispaced, tau[0..Q]. */
static sq_status sub_fractions(int Q, sq_node_kind kind, double *tau, sq_error *err)
{
    if (kind == SQ_NODES_EQUISPACED || Q == 1) {
        for (int i = 0; i <= Q; i++) tau[i] = (double)i / Q;
        return SQ_OK;
    }
    double x[11], w[11];
    SQ_TRY(sem_gauss_lobatto(Q + 1, x, w, err));
    for (int i = 0; i <= Q; i++) tau[i] = 0.5 * (1.0 + x[i]);
    tau[0] = 0.0;
    tau[Q] = 1.0;
    return SQ_OK;
}

typedef struct {
    int *n;        /* segments per edge */
    long *base;    /* first global id of each edge's interior points */
    double **pts;  /* per edge: n*Q+1 points from n0 to n1 */
} edge_nodes;

static void edge_nodes_free(edge_nodes *en, int nedges)
{
    for (int e = 0; en->pts && e < nedges; e++) free(en->pts[e]);
    free(en->pts);
    free(en->n);
    free(en->base);
}

/* Point k of edge e walked in direction `reversed`, and its global id. */
static void edge_point(const sq_layout *L, const edge_nodes *en, int Q, int e, int reversed, int k,
                       double xy[2], long *gid)
{
    int M = en->n[e] * Q + 1, kk = reversed ? M - 1 - k : k;
    xy[0] = en->pts[e][2 * kk];
    xy[1] = en->pts[e][2 * kk + 1];
    if (kk == 0) *gid = L->edges[e].n0;
    else if (kk == M - 1) *gid = L->edges[e].n1;
    else *gid = en->base[e] + kk - 1;
}

/* The points of side k of patch p in walking order: count N (returned),
 * xy[2N], gid[N]; tags[N-1]: CAD edge under each segment (-1 inside). */
static int side_points(const sq_layout *L, const edge_nodes *en, int Q, const sq_layout_patch *p,
                       int k, double *xy, long *gid, int *tags)
{
    int N = 0;
    for (int h = p->side_start[k]; h < p->side_start[k + 1]; h++) {
        int e = p->half[h].edge, M = en->n[e] * Q + 1;
        for (int i = h == p->side_start[k] ? 0 : 1; i < M; i++) {
            edge_point(L, en, Q, e, p->half[h].reversed, i, &xy[2 * N], &gid[N]);
            if (N > 0) tags[N - 1] = L->edges[e].cad_edge;
            N++;
        }
    }
    return N;
}

/* Cumulative chord-length fractions of a point list read with stride. */
static void fractions(const double *xy, int N, double *f)
{
    f[0] = 0.0;
    for (int i = 1; i < N; i++)
        f[i] = f[i - 1] + hypot(xy[2 * i] - xy[2 * i - 2], xy[2 * i + 1] - xy[2 * i - 1]);
    for (int i = 1; i < N; i++) f[i] /= f[N - 1] > 0.0 ? f[N - 1] : 1.0;
}

typedef struct {
    int NU, NV;      /* grid points - 1 along u and v */
    double *xy;      /* 2*(NU+1)*(NV+1), index j*(NU+1)+i */
    long *gid;
    int *tag[4];     /* CAD edge under each boundary segment of side k, in grid order */
} patch_grid;

static void patch_grid_free(patch_grid *g)
{
    free(g->xy);
    free(g->gid);
    for (int k = 0; k < 4; k++) free(g->tag[k]);
    memset(g, 0, sizeof *g);
}

/* Design 3: discrete transfinite interpolation of the four sides. */
static sq_status fill_patch(const sq_layout *L, const edge_nodes *en, int Q, int q, long *next_id,
                            patch_grid *g, sq_error *err)
{
    const sq_layout_patch *p = &L->patches[q];
    int NU = (int)side_count(p, 0, en->n) * Q, NV = (int)side_count(p, 1, en->n) * Q;
    int maxN = (NU > NV ? NU : NV) + 1;
    size_t np = (size_t)(NU + 1) * (NV + 1);
    g->NU = NU;
    g->NV = NV;
    g->xy = malloc(sizeof(double) * 2 * np);
    g->gid = malloc(sizeof(long) * np);
    double *sxy = malloc(sizeof(double) * 2 * 4 * (size_t)maxN);
    long *sid = malloc(sizeof(long) * 4 * (size_t)maxN);
    double *f = malloc(sizeof(double) * 4 * (size_t)maxN);
    int ok = g->xy && g->gid && sxy && sid && f;
    for (int k = 0; k < 4 && ok; k++) ok = (g->tag[k] = malloc(sizeof(int) * (size_t)maxN)) != NULL;
    if (!ok) {
        free(sxy);
        free(sid);
        free(f);
        return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    }
    double *S[4];
    long *I[4];
    int *T[4];
    for (int k = 0; k < 4; k++) {
        S[k] = sxy + 2 * (size_t)k * maxN;
        I[k] = sid + (size_t)k * maxN;
        T[k] = g->tag[k];
        side_points(L, en, Q, p, k, S[k], I[k], T[k]);
    }
#define G(i, j) ((size_t)(j) * (NU + 1) + (i))
    /* boundary of the grid: bottom left->right, right bottom->top, top and
     * left walked backwards (the patch's cycle runs counter-clockwise) */
    for (int i = 0; i <= NU; i++) {
        memcpy(&g->xy[2 * G(i, 0)], &S[0][2 * i], 2 * sizeof(double));
        g->gid[G(i, 0)] = I[0][i];
        memcpy(&g->xy[2 * G(i, NV)], &S[2][2 * (NU - i)], 2 * sizeof(double));
        g->gid[G(i, NV)] = I[2][NU - i];
    }
    for (int j = 0; j <= NV; j++) {
        memcpy(&g->xy[2 * G(NU, j)], &S[1][2 * j], 2 * sizeof(double));
        g->gid[G(NU, j)] = I[1][j];
        memcpy(&g->xy[2 * G(0, j)], &S[3][2 * (NV - j)], 2 * sizeof(double));
        g->gid[G(0, j)] = I[3][NV - j];
    }
    /* blending parameters from the sides' arc-length fractions */
    double *fb = f, *ft = f + maxN, *fl = f + 2 * maxN, *fr = f + 3 * maxN;
    double *tmp = malloc(sizeof(double) * 2 * (size_t)maxN);
    if (!tmp) {
        free(sxy);
        free(sid);
        free(f);
        return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    }
    for (int i = 0; i <= NU; i++) memcpy(&tmp[2 * i], &g->xy[2 * G(i, 0)], 2 * sizeof(double));
    fractions(tmp, NU + 1, fb);
    for (int i = 0; i <= NU; i++) memcpy(&tmp[2 * i], &g->xy[2 * G(i, NV)], 2 * sizeof(double));
    fractions(tmp, NU + 1, ft);
    for (int j = 0; j <= NV; j++) memcpy(&tmp[2 * j], &g->xy[2 * G(0, j)], 2 * sizeof(double));
    fractions(tmp, NV + 1, fl);
    for (int j = 0; j <= NV; j++) memcpy(&tmp[2 * j], &g->xy[2 * G(NU, j)], 2 * sizeof(double));
    fractions(tmp, NV + 1, fr);
    free(tmp);
    const double *P00 = &g->xy[2 * G(0, 0)], *P10 = &g->xy[2 * G(NU, 0)],
                 *P11 = &g->xy[2 * G(NU, NV)], *P01 = &g->xy[2 * G(0, NV)];
    for (int j = 1; j < NV; j++)
        for (int i = 1; i < NU; i++) {
            /* (xi, eta): where the lines joining matching side fractions meet */
            double du = ft[i] - fb[i], dv = fr[j] - fl[j];
            double xi = (fb[i] + du * fl[j]) / (1.0 - du * dv), eta = fl[j] + dv * xi;
            const double *B = &g->xy[2 * G(i, 0)], *T = &g->xy[2 * G(i, NV)];
            const double *Lf = &g->xy[2 * G(0, j)], *R = &g->xy[2 * G(NU, j)];
            for (int c = 0; c < 2; c++)
                g->xy[2 * G(i, j) + c] =
                    (1 - eta) * B[c] + eta * T[c] + (1 - xi) * Lf[c] + xi * R[c] -
                    ((1 - xi) * (1 - eta) * P00[c] + xi * (1 - eta) * P10[c] + xi * eta * P11[c] +
                     (1 - xi) * eta * P01[c]);
            g->gid[G(i, j)] = (*next_id)++;
        }
#undef G
    free(sxy);
    free(sid);
    free(f);
    return SQ_OK;
}

/* Vertex-level mesh: patch grids of corner vertices glued along edges. */
typedef struct {
    int nv, nq;
    double *xy;     /* 2*nv */
    int *foot;      /* nv: 1 where a separatrix ends on the boundary */
    int *quad;      /* 4*nq corner vertices, counter-clockwise */
    int *patch;     /* nq */
    int *side_tag;  /* 4*nq: CAD edge under side k, or -1 */
} vmesh;

static void vmesh_free(vmesh *v)
{
    free(v->xy);
    free(v->foot);
    free(v->quad);
    free(v->patch);
    free(v->side_tag);
    memset(v, 0, sizeof *v);
}

static double quad_area2(const double *a, const double *b, const double *c)
{
    return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
}

/* Every corner triangle of quad q has positive area. */
static int quad_valid(const vmesh *v, int q)
{
    const int *c = &v->quad[4 * q];
    for (int k = 0; k < 4; k++)
        if (!(quad_area2(&v->xy[2 * c[k]], &v->xy[2 * c[(k + 1) % 4]], &v->xy[2 * c[(k + 3) % 4]]) >
              0.0))
            return 0;
    return 1;
}

/* Is xy a corner of the face (a non-smooth vertex, even one inside a
 * single closed edge, such as a trailing edge)? */
static int at_face_corner(const sq_face_info *info, const double xy[2])
{
    double scale = hypot(info->bbox[2] - info->bbox[0], info->bbox[3] - info->bbox[1]);
    for (int c = 0; c < info->nvertices; c++)
        if (!info->vertices[c].smooth &&
            hypot(info->vertices[c].x - xy[0], info->vertices[c].y - xy[1]) < 1e-9 * scale)
            return 1;
    return 0;
}

/* Slide boundary vertex i towards the middle of its two boundary
 * neighbours, staying on the CAD curve: keeps the spacing even where a
 * patch side is made of several layout edges (e.g. across the seam vertex
 * of a closed curve).  Returns the distance moved. */
static double slide(const cad_face *face, vmesh *v, int i, const int nb[2], const int tg[2],
                    const int *adjq, int q0, int q1)
{
    double mid[2] = {0.5 * (v->xy[2 * nb[0]] + v->xy[2 * nb[1]]),
                     0.5 * (v->xy[2 * nb[0] + 1] + v->xy[2 * nb[1] + 1])};
    double best[2] = {mid[0], mid[1]}, bestd = HUGE_VAL;
    for (int k = 0; k < 2; k++) {
        double foot[2], d;
        if (cad_face_edge_project(face, tg[k], mid, NULL, foot, &d, NULL) != SQ_OK) return 0.0;
        if (d < bestd) {
            bestd = d;
            best[0] = foot[0];
            best[1] = foot[1];
        }
    }
    double old[2] = {v->xy[2 * i], v->xy[2 * i + 1]};
    v->xy[2 * i] = best[0];
    v->xy[2 * i + 1] = best[1];
    for (int t = q0; t < q1; t++)
        if (!quad_valid(v, adjq[t])) {
            v->xy[2 * i] = old[0];
            v->xy[2 * i + 1] = old[1];
            return 0.0;
        }
    return hypot(best[0] - old[0], best[1] - old[1]);
}

/* Laplacian smoothing of the free vertices (inside the face, valence 4),
 * a move kept only if every quad around the vertex stays convex at its
 * corners: untangles what the patches' transfinite interpolation folded,
 * so that the relaxation (relax below) starts from a valid mesh. */
static sq_status smooth(const cad_face *face, const sq_face_info *info, vmesh *v, const int *keep,
                        sq_error *err)
{
    int *deg = calloc((size_t)v->nv, sizeof(int)), *fixed = calloc((size_t)v->nv, sizeof(int));
    /* boundary neighbours and the CAD edges of the two boundary sides */
    int *bn = malloc(sizeof(int) * 2 * (size_t)v->nv), *bt = malloc(sizeof(int) * 2 * (size_t)v->nv);
    int *nbn = calloc((size_t)v->nv, sizeof(int));
    if (!bn || !bt || !nbn) {
        free(deg);
        free(fixed);
        free(bn);
        free(bt);
        free(nbn);
        return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    }
    int *start = calloc((size_t)v->nv + 1, sizeof(int)), *adjq = malloc(sizeof(int) * 4 * (size_t)v->nq);
    sq_status st = deg && fixed && start && adjq ? SQ_OK : SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    if (st == SQ_OK) {
        for (int q = 0; q < v->nq; q++)
            for (int k = 0; k < 4; k++) {
                deg[v->quad[4 * q + k]]++;
                if (v->side_tag[4 * q + k] >= 0) {
                    int a = v->quad[4 * q + k], b = v->quad[4 * q + (k + 1) % 4];
                    fixed[a] = fixed[b] = 1;
                    if (nbn[a] < 2) bn[2 * a + nbn[a]] = b, bt[2 * a + nbn[a]++] = v->side_tag[4 * q + k];
                    if (nbn[b] < 2) bn[2 * b + nbn[b]] = a, bt[2 * b + nbn[b]++] = v->side_tag[4 * q + k];
                }
            }
        /* boundary vertices that may slide: two quads, two boundary
         * neighbours on the same CAD edge, not a separatrix's foot, not in a
         * boundary layer, not at a corner of the face */
        for (int i = 0; i < v->nv; i++) {
            /* both sides on one CAD edge: an element side must never span
             * two curves (its high-order nodes follow one) */
            if (nbn[i] != 2 || deg[i] != 2 || v->foot[i] || (keep && keep[i]) ||
                bt[2 * i] != bt[2 * i + 1]) {
                nbn[i] = 0;
                continue;
            }
            if (at_face_corner(info, &v->xy[2 * i])) nbn[i] = 0;
        }
        for (int i = 0; i < v->nv; i++) {
            if (deg[i] != 4) fixed[i] = 1; /* singular points stay where the field put them */
            if (keep && keep[i]) fixed[i] = 1;
            start[i + 1] = start[i] + deg[i];
        }
        int *fill = calloc((size_t)v->nv, sizeof(int));
        if (!fill) st = SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
        for (int q = 0; q < v->nq && fill; q++)
            for (int k = 0; k < 4; k++) {
                int a = v->quad[4 * q + k];
                adjq[start[a] + fill[a]++] = q;
            }
        free(fill);
    }
    for (int it = 0; it < 200 && st == SQ_OK; it++) {
        double moved = 0.0;
        for (int i = 0; i < v->nv; i++) {
            if (fixed[i]) continue;
            /* average of the edge neighbours: in each quad, the two corners
             * adjacent to i (each counted twice over its two quads) */
            double sx = 0.0, sy = 0.0;
            for (int t = start[i]; t < start[i + 1]; t++) {
                const int *c = &v->quad[4 * adjq[t]];
                int k = 0;
                while (c[k] != i) k++;
                sx += v->xy[2 * c[(k + 1) % 4]] + v->xy[2 * c[(k + 3) % 4]];
                sy += v->xy[2 * c[(k + 1) % 4] + 1] + v->xy[2 * c[(k + 3) % 4] + 1];
            }
            double n = 2.0 * (start[i + 1] - start[i]), old[2] = {v->xy[2 * i], v->xy[2 * i + 1]};
            v->xy[2 * i] = sx / n;
            v->xy[2 * i + 1] = sy / n;
            int ok = 1;
            for (int t = start[i]; t < start[i + 1] && ok; t++) ok = quad_valid(v, adjq[t]);
            if (!ok) {
                v->xy[2 * i] = old[0];
                v->xy[2 * i + 1] = old[1];
            } else {
                moved = fmax(moved, hypot(v->xy[2 * i] - old[0], v->xy[2 * i + 1] - old[1]));
            }
        }
        for (int i = 0; i < v->nv; i++)
            if (nbn[i] == 2) moved = fmax(moved, slide(face, v, i, &bn[2 * i], &bt[2 * i], adjq, start[i], start[i + 1]));
        if (moved < 1e-12) break;
    }
    free(bn);
    free(bt);
    free(nbn);
    free(deg);
    free(fixed);
    free(start);
    free(adjq);
    return st;
}

/* Design 3b: the whole vertex mesh relaxed towards an orthogonal map
 * (quad_relax.h); what stays: singular points (interior vertices of valence
 * other than 4), the face's corners and the boundary layers.  With the
 * singular points free the relaxation gives up once it folds a curved
 * boundary quad (*folded): the attempt with them held follows. */
static sq_status relax(const cad_face *face, const sq_face_info *info, vmesh *v, const int *keep,
                       int move_singular, sq_relax_work **work, int *folded, sq_error *err)
{
    int *deg = calloc((size_t)v->nv + 1, sizeof(int)), *bnd = calloc((size_t)v->nv + 1, sizeof(int));
    int *fixed = calloc((size_t)v->nv + 1, sizeof(int));
    if (!deg || !bnd || !fixed) {
        free(deg);
        free(bnd);
        free(fixed);
        return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    }
    for (int q = 0; q < v->nq; q++)
        for (int k = 0; k < 4; k++) {
            deg[v->quad[4 * q + k]]++;
            if (v->side_tag[4 * q + k] >= 0)
                bnd[v->quad[4 * q + k]] = bnd[v->quad[4 * q + (k + 1) % 4]] = 1;
        }
    for (int i = 0; i < v->nv; i++)
        fixed[i] = (keep && keep[i]) || (!bnd[i] && deg[i] != 4 && !move_singular) ||
                   (bnd[i] && at_face_corner(info, &v->xy[2 * i]));
    sq_relax_mesh rm = {v->nv, v->nq, v->xy, v->quad, v->side_tag, fixed, move_singular, 0};
    sq_status st = sq_quad_relax(face, &rm, work, err);
    *folded = rm.folded;
    free(deg);
    free(bnd);
    free(fixed);
    return st;
}

/* Glue the patch grids into the vertex mesh. */
static sq_status build_vmesh(const sq_layout *L, patch_grid *grids, long nids, vmesh *v,
                             sq_error *err)
{
    long *map = malloc(sizeof(long) * (size_t)(nids + 1));
    double *gxy = malloc(sizeof(double) * 2 * (size_t)(nids + 1));
    int nq = 0;
    for (int q = 0; q < L->npatches; q++) nq += grids[q].NU * grids[q].NV;
    v->quad = malloc(sizeof(int) * 4 * (size_t)(nq + 1));
    v->patch = malloc(sizeof(int) * (size_t)(nq + 1));
    v->side_tag = malloc(sizeof(int) * 4 * (size_t)(nq + 1));
    if (!map || !gxy || !v->quad || !v->patch || !v->side_tag) {
        free(map);
        free(gxy);
        return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    }
    for (long i = 0; i < nids; i++) map[i] = -1;
    for (int q = 0; q < L->npatches; q++) {
        const patch_grid *g = &grids[q];
        for (size_t k = 0; k < (size_t)(g->NU + 1) * (g->NV + 1); k++) {
            map[g->gid[k]] = 0;
            gxy[2 * g->gid[k]] = g->xy[2 * k];
            gxy[2 * g->gid[k] + 1] = g->xy[2 * k + 1];
        }
    }
    int nv = 0;
    for (long i = 0; i < nids; i++)
        if (map[i] == 0) map[i] = nv++;
    v->nv = nv;
    v->xy = malloc(sizeof(double) * 2 * (size_t)(nv + 1));
    v->foot = calloc((size_t)nv + 1, sizeof(int));
    if (!v->xy || !v->foot) {
        free(map);
        free(gxy);
        return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    }
    for (long i = 0; i < nids; i++)
        if (map[i] >= 0) {
            v->xy[2 * map[i]] = gxy[2 * i];
            v->xy[2 * map[i] + 1] = gxy[2 * i + 1];
            /* the layout's nodes come first in the id space */
            if (i < L->nnodes) v->foot[map[i]] = L->nodes[i].kind == SQ_LNODE_FOOT;
        }
    int qq = 0;
    for (int q = 0; q < L->npatches; q++) {
        const patch_grid *g = &grids[q];
        for (int b = 0; b < g->NV; b++)
            for (int a = 0; a < g->NU; a++, qq++) {
                int *c = &v->quad[4 * qq];
#define GID(i, j) (int)map[g->gid[(size_t)(j) * (g->NU + 1) + (i)]]
                c[0] = GID(a, b);
                c[1] = GID(a + 1, b);
                c[2] = GID(a + 1, b + 1);
                c[3] = GID(a, b + 1);
#undef GID
                int *t = &v->side_tag[4 * qq];
                t[0] = b == 0 ? g->tag[0][a] : -1;
                t[1] = a == g->NU - 1 ? g->tag[1][b] : -1;
                t[2] = b == g->NV - 1 ? g->tag[2][g->NU - 1 - a] : -1;
                t[3] = a == 0 ? g->tag[3][g->NV - 1 - b] : -1;
                v->patch[qq] = q;
            }
    }
    v->nq = qq;
    free(map);
    free(gxy);
    return SQ_OK;
}

/* Arc length of vertex x on CAD edge c, continued across the closing point
 * of a closed edge towards s_ref. */
static sq_status arc_on_edge(const cad_face *face, int c, const double x[2], double *s,
                             sq_error *err)
{
    SQ_TRY(cad_face_edge_project(face, c, x, s, NULL, NULL, err));
    return SQ_OK;
}

/* The other quad on side (a, b) of quad q, or -1; *k its local side. */
static int across(const vmesh *v, const int *vstart, const int *vquads, int q, int a, int b, int *k)
{
    for (int t = vstart[a]; t < vstart[a + 1]; t++) {
        int p = vquads[t];
        if (p == q) continue;
        for (int l = 0; l < 4; l++)
            if (v->quad[4 * p + l] == b && v->quad[4 * p + (l + 1) % 4] == a) {
                *k = l;
                return p;
            }
    }
    return -1;
}

/* Boundary layers, exactly: from every vertex of a wall (a boundary-layer
 * CAD edge), march outwards through the quads' columns and put the vertex
 * of layer j at bl_thickness(j) along the wall's normal — the graded edges
 * only approximate that between them.  The march stops where the graded
 * mesh had no more layers (a vertex further than 1.25 times the asked
 * thickness). */
static sq_status bl_march(const cad_face *face, const sq_mesher_options *o, vmesh *v, sq_error *err)
{
    int *vstart = calloc((size_t)v->nv + 1, sizeof(int)), *vquads = malloc(sizeof(int) * 4 * (size_t)v->nq);
    int *fill = calloc((size_t)v->nv + 1, sizeof(int));
    double *orig = malloc(sizeof(double) * 2 * (size_t)v->nv + 1);
    sq_status st = vstart && vquads && fill && orig ? SQ_OK : SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    if (st == SQ_OK) {
        memcpy(orig, v->xy, sizeof(double) * 2 * (size_t)v->nv);
        for (int t = 0; t < 4 * v->nq; t++) vstart[v->quad[t] + 1]++;
        for (int i = 0; i < v->nv; i++) vstart[i + 1] += vstart[i];
        for (int q = 0; q < v->nq; q++)
            for (int l = 0; l < 4; l++) {
                int a = v->quad[4 * q + l];
                vquads[vstart[a] + fill[a]++] = q;
            }
    }
    double limit = 1.25 * bl_thickness(o, o->bl_layers);
    for (int q0 = 0; q0 < v->nq && st == SQ_OK; q0++)
        for (int k0 = 0; k0 < 4 && st == SQ_OK; k0++) {
            int tag = v->side_tag[4 * q0 + k0], is = 0;
            for (int b = 0; b < o->nbl; b++) is |= tag == o->bl_edges[b];
            if (!is) continue;
            for (int end = 0; end < 2 && st == SQ_OK; end++) {
                /* the column from wall vertex w: through q0, then across */
                int q = q0, k = k0, w = v->quad[4 * q0 + (k0 + end) % 4];
                double s, X[2], tg[2];
                st = cad_face_edge_project(face, tag, &v->xy[2 * w], &s, NULL, NULL, err);
                if (st == SQ_OK) st = cad_face_edge_eval(face, tag, s, X, tg, NULL, err);
                for (int j = 1; j <= o->bl_layers && q >= 0 && st == SQ_OK; j++) {
                    /* in quad q with wall-side k, the vertex above the column */
                    int up = v->quad[4 * q + (end ? (k + 2) % 4 : (k + 3) % 4)];
                    double dist, dx = orig[2 * up] - X[0], dy = orig[2 * up + 1] - X[1];
                    st = cad_face_edge_project(face, tag, &orig[2 * up], NULL, NULL, &dist, err);
                    if (st != SQ_OK || dist > limit) break;
                    /* a column that leaves the wall obliquely (a fan at a
                     * corner of the wall) keeps its graded vertices */
                    if (-dx * tg[1] + dy * tg[0] < 0.5 * hypot(dx, dy)) break;
                    double h = bl_thickness(o, j);
                    /* the face is on the left of the wall's direction */
                    v->xy[2 * up] = X[0] - h * tg[1];
                    v->xy[2 * up + 1] = X[1] + h * tg[0];
                    /* next quad outwards: across the side opposite the wall side */
                    int a = v->quad[4 * q + (k + 2) % 4], b = v->quad[4 * q + (k + 3) % 4], kk;
                    q = across(v, vstart, vquads, q, a, b, &kk);
                    k = q >= 0 ? kk : k;
                }
            }
        }
    free(vstart);
    free(vquads);
    free(fill);
    free(orig);
    return st;
}

/* Design 4: the order-Q quads.  Element sides on the boundary follow the
 * CAD curve between their vertices' arc lengths; other sides are straight;
 * element interiors by transfinite interpolation of their four sides. */
/* A side inside a boundary layer that runs along its wall is curved like
 * the wall: its nodes at arc length and distance interpolated between its
 * vertices', offset from the wall along the inward normal, so thin layer
 * elements follow a curved wall instead of being cut by it.  Returns 1 and
 * fills c, s0, s1, d0, d1 for such a side. */
static int layer_side(const cad_face *face, const sq_mesher_options *o, double thick,
                      const double A[2], const double B[2], int *c, double *s0, double *s1,
                      double *d0, double *d1)
{
    for (int b = 0; b < o->nbl; b++) {
        int e = o->bl_edges[b];
        if (cad_face_edge_project(face, e, A, s0, NULL, d0, NULL) != SQ_OK ||
            cad_face_edge_project(face, e, B, s1, NULL, d1, NULL) != SQ_OK)
            return 0;
        if (*d0 > thick || *d1 > thick) continue;
        double Lc = cad_face_edge_length(face, e);
        if (fabs(*s1 - *s0) > 0.5 * Lc) { /* a closed edge: the shorter way round */
            if (*s1 > *s0) *s0 += Lc;
            else *s1 += Lc;
        }
        /* along the wall, not across it */
        if (fabs(*s1 - *s0) <= fabs(*d1 - *d0)) return 0;
        *c = e;
        return 1;
    }
    return 0;
}

static sq_status raise_order(const cad_face *face, const vmesh *v, int Q, sq_node_kind kind,
                             const sq_mesher_options *opt, sq_quad_mesh **out, sq_error *err)
{
    double thick = opt->nbl > 0 ? 1.5 * bl_thickness(opt, opt->bl_layers) : 0.0;
    double tau[11];
    SQ_TRY(sub_fractions(Q, kind, tau, err));
    /* unique sides: key (min, max) vertex, found through a per-vertex list */
    int ns = 0, *side_of = malloc(sizeof(int) * 4 * (size_t)v->nq);
    int *head = malloc(sizeof(int) * (size_t)v->nv), *next = malloc(sizeof(int) * 4 * (size_t)v->nq);
    int *sa = malloc(sizeof(int) * 4 * (size_t)v->nq), *sb = malloc(sizeof(int) * 4 * (size_t)v->nq);
    if (!side_of || !head || !next || !sa || !sb) {
        free(side_of);
        free(head);
        free(next);
        free(sa);
        free(sb);
        return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    }
    for (int i = 0; i < v->nv; i++) head[i] = -1;
    int nbnd = 0;
    for (int q = 0; q < v->nq; q++)
        for (int k = 0; k < 4; k++) {
            int a = v->quad[4 * q + k], b = v->quad[4 * q + (k + 1) % 4];
            int lo = a < b ? a : b, hi = a < b ? b : a, f = head[lo];
            while (f >= 0 && sb[f] != hi) f = next[f];
            if (f < 0) {
                f = ns++;
                sa[f] = lo;
                sb[f] = hi;
                next[f] = head[lo];
                head[lo] = f;
            }
            side_of[4 * q + k] = f;
            nbnd += v->side_tag[4 * q + k] >= 0;
        }
    long nn = (long)v->nv + (long)ns * (Q - 1) + (long)v->nq * (Q - 1) * (Q - 1);
    sq_quad_mesh *m = NULL;
    sq_status st = sq_quad_mesh_create(Q, kind, (int)nn, v->nq, nbnd, &m, err);
    double *sidexy = st == SQ_OK ? malloc(sizeof(double) * 2 * ((size_t)ns * (Q + 1) + 1)) : NULL;
    int *done = st == SQ_OK ? calloc((size_t)ns + 1, sizeof(int)) : NULL;
    if (st == SQ_OK && (!sidexy || !done)) st = SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    if (st == SQ_OK) memcpy(m->xy, v->xy, sizeof(double) * 2 * (size_t)v->nv);
    int b = 0;
    for (int q = 0; q < v->nq && st == SQ_OK; q++) {
        double S[4][11][2]; /* side k nodes in the element's walking direction */
        for (int k = 0; k < 4 && st == SQ_OK; k++) {
            int a = v->quad[4 * q + k], c = v->quad[4 * q + (k + 1) % 4], f = side_of[4 * q + k];
            int tag = v->side_tag[4 * q + k];
            if (!done[f]) { /* nodes from sa[f] to sb[f] */
                const double *A = &v->xy[2 * sa[f]], *B = &v->xy[2 * sb[f]];
                double *P = &sidexy[2 * (size_t)f * (Q + 1)];
                double s0 = 0.0, s1 = 0.0;
                if (tag >= 0) {
                    st = arc_on_edge(face, tag, A, &s0, err);
                    if (st == SQ_OK) st = arc_on_edge(face, tag, B, &s1, err);
                    /* the quad walks its boundary side along the curve's
                     * direction of travel (both keep the face on the left):
                     * arc lengths that decrease that way cross a closed
                     * curve's closing point.  (Not "the shorter way round":
                     * a side may cover half a curve or more, a short edge
                     * taken whole by one quad.) */
                    double Lc = cad_face_edge_length(face, tag);
                    if (a == sa[f] && s1 < s0) s1 += Lc;
                    else if (a != sa[f] && s0 < s1) s0 += Lc;
                }
                int lc = -1;
                double ls0 = 0.0, ls1 = 0.0, ld0 = 0.0, ld1 = 0.0;
                int layer = tag < 0 && opt->nbl > 0 &&
                            layer_side(face, opt, thick, A, B, &lc, &ls0, &ls1, &ld0, &ld1);
                for (int i = 0; i <= Q && st == SQ_OK; i++) {
                    if (layer && i > 0 && i < Q) {
                        double s = ls0 + tau[i] * (ls1 - ls0), d = ld0 + tau[i] * (ld1 - ld0);
                        double Lc = cad_face_edge_length(face, lc), X[2], t[2];
                        if (s > Lc) s -= Lc;
                        st = cad_face_edge_eval(face, lc, s, X, t, NULL, err);
                        /* the face is on the left of the wall's direction */
                        P[2 * i] = X[0] - d * t[1];
                        P[2 * i + 1] = X[1] + d * t[0];
                    } else if (tag >= 0 && i > 0 && i < Q) {
                        double s = s0 + tau[i] * (s1 - s0), Lc = cad_face_edge_length(face, tag);
                        if (s > Lc) s -= Lc;
                        st = cad_face_edge_eval(face, tag, s, &P[2 * i], NULL, NULL, err);
                    } else {
                        P[2 * i] = A[0] + tau[i] * (B[0] - A[0]);
                        P[2 * i + 1] = A[1] + tau[i] * (B[1] - A[1]);
                    }
                }
                if (st == SQ_OK) {
                    P[0] = A[0], P[1] = A[1], P[2 * Q] = B[0], P[2 * Q + 1] = B[1];
                    for (int i = 1; i < Q; i++) {
                        long id = v->nv + (long)f * (Q - 1) + (i - 1);
                        m->xy[2 * id] = P[2 * i];
                        m->xy[2 * id + 1] = P[2 * i + 1];
                    }
                }
                done[f] = 1;
            }
            const double *P = &sidexy[2 * (size_t)f * (Q + 1)];
            int fwd = sa[f] == a;
            (void)c;
            for (int i = 0; i <= Q; i++) {
                int ii = fwd ? i : Q - i;
                S[k][i][0] = P[2 * ii];
                S[k][i][1] = P[2 * ii + 1];
            }
            if (tag >= 0) {
                m->bnd_quad[b] = q;
                m->bnd_side[b] = k;
                m->bnd_tag[b] = tag;
                b++;
            }
        }
        if (st != SQ_OK) break;
        int *cn = &m->conn[(size_t)q * (Q + 1) * (Q + 1)];
        for (int j = 0; j <= Q; j++)
            for (int i = 0; i <= Q; i++) {
                int id;
                if ((i == 0 || i == Q) && (j == 0 || j == Q)) {
                    int corner = j == 0 ? (i == 0 ? 0 : 1) : (i == Q ? 2 : 3);
                    id = v->quad[4 * q + corner];
                } else if (j == 0 || i == Q || j == Q || i == 0) {
                    /* side node: side k at its own index t */
                    int k = j == 0 ? 0 : i == Q ? 1 : j == Q ? 2 : 3;
                    int t = k == 0 ? i : k == 1 ? j : k == 2 ? Q - i : Q - j;
                    int f = side_of[4 * q + k], fwd = sa[f] == v->quad[4 * q + k];
                    id = v->nv + f * (Q - 1) + ((fwd ? t : Q - t) - 1);
                } else {
                    id = v->nv + ns * (Q - 1) + q * (Q - 1) * (Q - 1) + (j - 1) * (Q - 1) + (i - 1);
                    /* transfinite interpolation of the four sides at (tau_i, tau_j) */
                    double u = tau[i], w = tau[j];
                    const double *B0 = S[0][i], *T0 = S[2][Q - i], *L0 = S[3][Q - j], *R0 = S[1][j];
                    const double *c00 = S[0][0], *c10 = S[1][0], *c11 = S[2][0], *c01 = S[3][0];
                    for (int d = 0; d < 2; d++)
                        m->xy[2 * id + d] = (1 - w) * B0[d] + w * T0[d] + (1 - u) * L0[d] +
                                            u * R0[d] -
                                            ((1 - u) * (1 - w) * c00[d] + u * (1 - w) * c10[d] +
                                             u * w * c11[d] + (1 - u) * w * c01[d]);
                }
                cn[sq_quad_node(Q, i, j)] = id;
            }
        m->patch[q] = v->patch[q];
    }
    free(side_of);
    free(head);
    free(next);
    free(sa);
    free(sb);
    free(sidexy);
    free(done);
    if (st != SQ_OK) {
        sq_quad_mesh_free(&m);
        return st;
    }
    int ntags = cad_face_num_edges(face);
    for (int k = 0; k < m->nbnd; k++)
        if (m->bnd_tag[k] + 1 > ntags) ntags = m->bnd_tag[k] + 1;
    m->ntags = ntags;
    *out = m;
    return SQ_OK;
}

/* Design 3 from the glued vertex mesh on: untangling, relaxation, order Q.
 * *out is NULL unless SQ_OK. */
static sq_status finish(const cad_face *face, const sq_face_info *info, vmesh *v,
                        const sq_mesher_options *opt, sq_quad_mesh **out, sq_error *err)
{
    sq_status st = SQ_OK;
    int Q = opt->order;
    /* the boundary layers keep their grading: no smoothing there */
    int *keep = NULL;
    if (st == SQ_OK && opt->nbl > 0) {
        double T = 1.5 * bl_thickness(opt, opt->bl_layers);
        keep = calloc((size_t)v->nv + 1, sizeof(int));
        if (!keep) st = SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
        for (int i = 0; i < v->nv && st == SQ_OK; i++)
            for (int b = 0; b < opt->nbl && st == SQ_OK && !keep[i]; b++) {
                double d;
                st = cad_face_edge_project(face, opt->bl_edges[b], &v->xy[2 * i], NULL, NULL, &d, err);
                keep[i] = d < T;
            }
    }
    /* untangling, where transfinite interpolation folded a quad */
    int folded = 0;
    for (int q = 0; q < v->nq && st == SQ_OK; q++) folded += !quad_valid(v, q);
    if (st == SQ_OK && folded) st = smooth(face, info, v, keep, err);
    /* relaxed with the singular points free to even out their angles, then
     * held where the field put them, then not relaxed at all: the first of
     * these whose curved quads all have a scaled Jacobian of at least
     * SJ_ACCEPT, else the one with the largest smallest scaled Jacobian */
    double *smoothed = st == SQ_OK ? malloc(sizeof(double) * 2 * ((size_t)v->nv + 1)) : NULL;
    if (st == SQ_OK && !smoothed) st = SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    if (st == SQ_OK) memcpy(smoothed, v->xy, sizeof(double) * 2 * (size_t)v->nv);
    double best_sj = -HUGE_VAL;
    sq_relax_work *work = NULL; /* the first relaxation's Hessian, for the second */
    for (int attempt = 0; attempt < 3 && st == SQ_OK; attempt++) {
        sq_quad_mesh *m = NULL;
        memcpy(v->xy, smoothed, sizeof(double) * 2 * (size_t)v->nv);
        int folded = 0;
        if (attempt < 2) st = relax(face, info, v, keep, attempt == 0, &work, &folded, err);
        if (folded) continue;
        if (st == SQ_OK && opt->nbl > 0) st = bl_march(face, opt, v, err);
        if (st == SQ_OK) st = raise_order(face, v, Q, opt->nodes, opt, &m, err);
        sq_quad_quality qq;
        if (st == SQ_OK) st = sq_quad_mesh_quality(m, NULL, NULL, &qq, err);
        if (st == SQ_OK && qq.min_scaled_jacobian > best_sj) {
            best_sj = qq.min_scaled_jacobian;
            sq_quad_mesh_free(out);
            *out = m;
            m = NULL;
        }
        sq_quad_mesh_free(&m);
        if (best_sj >= SJ_ACCEPT) break;
    }
    sq_relax_work_free(&work);
    if (st != SQ_OK) sq_quad_mesh_free(out);
    free(smoothed);
    free(keep);
    return st;
}

sq_status sq_mesh_linear_quads(const cad_face *face, const sq_face_info *info,
                               const sq_linear_quads *lq, const sq_mesher_options *opt,
                               sq_quad_mesh **out, sq_error *err)
{
    *out = NULL;
    if (opt->order < 1 || opt->order > 10)
        return SQ_FAIL(err, SQ_ERR_USAGE, "quad order %d outside 1..10", opt->order);
    if (opt->nbl > 0)
        return SQ_FAIL(err, SQ_ERR_USAGE, "boundary layers need a quad layout (--bl)");
    vmesh v = {lq->nv, lq->nq, malloc(sizeof(double) * 2 * ((size_t)lq->nv + 1)),
               calloc((size_t)lq->nv + 1, sizeof(int)), malloc(sizeof(int) * 4 * ((size_t)lq->nq + 1)),
               malloc(sizeof(int) * ((size_t)lq->nq + 1)), malloc(sizeof(int) * 4 * ((size_t)lq->nq + 1))};
    sq_status st = v.xy && v.foot && v.quad && v.patch && v.side_tag
                       ? SQ_OK
                       : SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    if (st == SQ_OK) {
        memcpy(v.xy, lq->xy, sizeof(double) * 2 * (size_t)lq->nv);
        memcpy(v.quad, lq->quad, sizeof(int) * 4 * (size_t)lq->nq);
        memcpy(v.patch, lq->block, sizeof(int) * (size_t)lq->nq);
        memcpy(v.side_tag, lq->side_tag, sizeof(int) * 4 * (size_t)lq->nq);
        st = finish(face, info, &v, opt, out, err);
    }
    vmesh_free(&v);
    return st;
}

double sq_mesher_default_size(double area) { return sqrt(fabs(area)) / 8.0; }

sq_status sq_mesh_layout(const cad_face *face, const sq_face_info *info, const sq_layout *L,
                         const sq_mesher_options *opt, sq_quad_mesh **out, sq_error *err)
{
    *out = NULL;
    int Q = opt->order;
    if (Q < 1 || Q > 10) return SQ_FAIL(err, SQ_ERR_USAGE, "quad order %d outside 1..10", Q);
    for (int q = 0; q < L->npatches; q++)
        if (!is_quad(&L->patches[q]))
            return SQ_FAIL(err, SQ_ERR_LAYOUT, "patch %d is not a quad (%d corners)", q,
                           L->patches[q].ncorners);
    double size = opt->size > 0.0 ? opt->size : sq_mesher_default_size(L->face_area);
    edge_nodes en = {0};
    patch_grid *grids = calloc((size_t)L->npatches + 1, sizeof *grids);
    en.n = malloc(sizeof(int) * ((size_t)L->nedges + 1));
    en.base = malloc(sizeof(long) * ((size_t)L->nedges + 1));
    en.pts = calloc((size_t)L->nedges + 1, sizeof(double *));
    sq_status st = grids && en.n && en.base && en.pts ? SQ_OK
                                                      : SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    int *grade = malloc(sizeof(int) * ((size_t)L->nedges + 1));
    if (st == SQ_OK && !grade) st = SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    if (st == SQ_OK) bl_grading(L, info, opt, grade);
    double *elen = malloc(sizeof(double) * ((size_t)L->nedges + 1));
    double *cum = malloc(sizeof(double) * ((size_t)L->nedges * (SIZE_SAMPLES + 1) + 1));
    if (st == SQ_OK && (!elen || !cum)) st = SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    if (st == SQ_OK) st = size_measure(L, face, info, opt, grade, elen, cum, err);
    if (st == SQ_OK) st = quantize(L, elen, size, grade, opt, en.n, err);
    /* the quantization can exceed area / size^2 (one segment at least per
     * chord, sides matched): check its own count before allocating */
    double nquads = st == SQ_OK ? quantized_quads(L, en.n) : 0.0;
    if (st == SQ_OK && opt->max_quads > 0.0 && nquads > opt->max_quads)
        st = SQ_FAIL(err, SQ_ERR_USAGE,
                     "the layout's chords at size %g give %.3g quads, more than --max-quads %.3g; "
                     "try a size of %.3g or more",
                     size, nquads, opt->max_quads, size * sqrt(nquads / opt->max_quads));
    /* Design 2: the vertices of every edge, once, by arc length; ids: the
     * layout's nodes first */
    long next_id = L->nnodes;
    for (int e = 0; e < L->nedges && st == SQ_OK; e++) {
        int n = en.n[e];
        en.pts[e] = malloc(sizeof(double) * 2 * (size_t)(n + 1));
        if (!en.pts[e]) {
            st = SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
            break;
        }
        double *f = malloc(sizeof(double) * (size_t)(n + 1));
        if (!f) {
            st = SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
            break;
        }
        edge_fractions(L->edges[e].length, n, grade[e], opt, f);
        if (!grade[e])
            for (int k = 1; k < n; k++) f[k] = measure_fraction(&cum[(size_t)e * (SIZE_SAMPLES + 1)], f[k]);
        for (int k = 1; k < n && st == SQ_OK; k++)
            st = sq_layout_edge_point(L, face, e, f[k], &en.pts[e][2 * k], err);
        free(f);
        /* the ends are the layout's nodes, exactly */
        en.pts[e][0] = L->nodes[L->edges[e].n0].x;
        en.pts[e][1] = L->nodes[L->edges[e].n0].y;
        en.pts[e][2 * n] = L->nodes[L->edges[e].n1].x;
        en.pts[e][2 * n + 1] = L->nodes[L->edges[e].n1].y;
        en.base[e] = next_id;
        next_id += n - 1;
    }
    for (int q = 0; q < L->npatches && st == SQ_OK; q++)
        st = fill_patch(L, &en, 1, q, &next_id, &grids[q], err);
    vmesh v = {0};
    if (st == SQ_OK) st = build_vmesh(L, grids, next_id, &v, err);
    if (st == SQ_OK) st = finish(face, info, &v, opt, out, err);
    vmesh_free(&v);
    free(grade);
    free(elen);
    free(cum);
    for (int q = 0; grids && q < L->npatches; q++) patch_grid_free(&grids[q]);
    free(grids);
    edge_nodes_free(&en, L->nedges);
    return st;
}
