#include "triangulate.h"

#include "face_info.h"
#include "tri_curve.h"
#include "tri_geom.h"
#include "tri_lagrange.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define MAX_ROUNDS 16 /* boundary re-discretizations before giving up */
#define MIN_SCALED_JAC 0.05 /* below this a curved element is split further */

/* Sorted arc lengths of the discretization points of every CAD edge (each
 * list starts with 0; the edge's end is the next edge's start). */
typedef struct {
    int nedges;
    int *n, *cap;
    double **s;
} bdisc;

static void bdisc_free(bdisc *b)
{
    for (int e = 0; e < b->nedges && b->s; e++) free(b->s[e]);
    free(b->s);
    free(b->n);
    free(b->cap);
    memset(b, 0, sizeof *b);
}

static sq_status bdisc_insert(bdisc *b, int e, double s, sq_error *err)
{
    int i = b->n[e];
    if (i == b->cap[e]) {
        int cap = 2 * b->cap[e] + 8;
        double *p = realloc(b->s[e], sizeof(double) * (size_t)cap);
        if (!p) return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
        b->s[e] = p;
        b->cap[e] = cap;
    }
    while (i > 0 && b->s[e][i - 1] > s) {
        b->s[e][i] = b->s[e][i - 1];
        i--;
    }
    b->s[e][i] = s;
    b->n[e]++;
    return SQ_OK;
}

typedef struct {
    const sq_tri_options *opt;
    double size;
} size_ctx;

double sq_tri_graded_size(const sq_tri_options *opt, double size, const double xy[2])
{
    const double h0 = opt->extra_size > 0.0 ? opt->extra_size : size / 8.0;
    const double growth = opt->extra_growth > 0.0 ? opt->extra_growth : 0.5;
    double h = size;
    for (int i = 0; i < opt->nextra; i++) {
        double d = hypot(xy[0] - opt->extra_xy[2 * i], xy[1] - opt->extra_xy[2 * i + 1]);
        double hi = (opt->extra_sizes ? opt->extra_sizes[i] : h0) + growth * d;
        if (hi < h) h = hi;
    }
    return h;
}

static double graded_size(const double xy[2], void *p)
{
    const size_ctx *c = p;
    return sq_tri_graded_size(c->opt, c->size, xy);
}

/* Step 1 of the design: equidistribute rho(s) = 1/size(x(s)) + |k(s)|/max_turn,
 * size(x) graded towards the extra points. */
static sq_status bdisc_initial(const cad_face *face, const size_ctx *sc, double max_turn, bdisc *b,
                               sq_error *err)
{
    enum { NS = 2048 };
    int ne = cad_face_num_edges(face);
    b->nedges = ne;
    b->n = calloc((size_t)ne, sizeof(int));
    b->cap = calloc((size_t)ne, sizeof(int));
    b->s = calloc((size_t)ne, sizeof(double *));
    if (!b->n || !b->cap || !b->s) return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    int *nseg = calloc((size_t)ne, sizeof(int));
    double *cum = malloc(sizeof(double) * (NS + 1));
    sq_status st = SQ_OK;
    if (!nseg || !cum) {
        st = SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
        goto done;
    }
    for (int l = 0; l < cad_face_num_loops(face) && st == SQ_OK; l++) {
        int first = cad_face_loop_first_edge(face, l), n = cad_face_loop_num_edges(face, l);
        int total = 0, longest = first;
        for (int e = first; e < first + n && st == SQ_OK; e++) {
            double L = cad_face_edge_length(face, e), rho_prev = 0.0;
            if (L > cad_face_edge_length(face, longest)) longest = e;
            cum[0] = 0.0;
            for (int k = 0; k <= NS && st == SQ_OK; k++) {
                double kappa = 0.0, x[2];
                st = cad_face_edge_eval(face, e, L * k / NS, x, NULL, &kappa, err);
                double rho = 1.0 / graded_size(x, (void *)sc) + fabs(kappa) / max_turn;
                if (k > 0) cum[k] = cum[k - 1] + 0.5 * (rho + rho_prev) * L / NS;
                rho_prev = rho;
            }
            nseg[e] = (int)ceil(cum[NS] - 1e-9);
            if (nseg[e] < 1) nseg[e] = 1;
            total += nseg[e];
            if (st != SQ_OK) break;
            /* invert the cumulative density at equal steps */
            if ((st = bdisc_insert(b, e, 0.0, err)) != SQ_OK) break;
            int k = 0;
            for (int j = 1; j < nseg[e] && st == SQ_OK; j++) {
                double target = cum[NS] * j / nseg[e];
                while (k < NS - 1 && cum[k + 1] < target) k++;
                double f = (target - cum[k]) / (cum[k + 1] - cum[k]);
                st = bdisc_insert(b, e, L * (k + f) / NS, err);
            }
        }
        /* A loop needs three segments to bound anything. */
        for (int j = total; j < 3 && st == SQ_OK; j++) {
            double L = cad_face_edge_length(face, longest);
            int m = b->n[longest];
            st = bdisc_insert(b, longest, 0.5 * (b->s[longest][m - 1] + L), err);
        }
    }
done:
    free(nseg);
    free(cum);
    return st;
}

/* The polygon of a discretization: points, their (edge, s), and loop ranges. */
typedef struct {
    int np;
    double *xy;
    int *edge;
    double *s;
    int *next; /* next point along its loop */
} bpoly;

static void bpoly_free(bpoly *p)
{
    free(p->xy);
    free(p->edge);
    free(p->s);
    free(p->next);
    memset(p, 0, sizeof *p);
}

static sq_status bpoly_build(const cad_face *face, const bdisc *b, bpoly *p, sq_error *err)
{
    int np = 0;
    for (int e = 0; e < b->nedges; e++) np += b->n[e];
    p->np = np;
    p->xy = malloc(sizeof(double) * 2 * (size_t)np);
    p->edge = malloc(sizeof(int) * (size_t)np);
    p->s = malloc(sizeof(double) * (size_t)np);
    p->next = malloc(sizeof(int) * (size_t)np);
    if (!p->xy || !p->edge || !p->s || !p->next) return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    int i = 0;
    for (int l = 0; l < cad_face_num_loops(face); l++) {
        int first = cad_face_loop_first_edge(face, l), n = cad_face_loop_num_edges(face, l);
        int start = i;
        for (int e = first; e < first + n; e++)
            for (int k = 0; k < b->n[e]; k++, i++) {
                p->edge[i] = e;
                p->s[i] = b->s[e][k];
                p->next[i] = i + 1;
                SQ_TRY(cad_face_edge_eval(face, e, p->s[i], &p->xy[2 * i], NULL, NULL, err));
            }
        p->next[i - 1] = start;
    }
    return SQ_OK;
}

/* Arc length at which the segment from point i ends on point i's edge. */
static double seg_end_s(const cad_face *face, const bpoly *p, int i)
{
    int j = p->next[i];
    return p->edge[j] == p->edge[i] && p->s[j] > p->s[i] ? p->s[j]
                                                          : cad_face_edge_length(face, p->edge[i]);
}

static int point_in_polygon(const bpoly *p, int start, const double q[2])
{
    int inside = 0, i = start;
    do {
        int j = p->next[i];
        const double *a = &p->xy[2 * i], *c = &p->xy[2 * j];
        if ((a[1] > q[1]) != (c[1] > q[1]) &&
            q[0] < a[0] + (q[1] - a[1]) * (c[0] - a[0]) / (c[1] - a[1]))
            inside = !inside;
        i = j;
    } while (i != start);
    return inside;
}

/* A seed strictly inside the hole whose polygon contains point `start`: the
 * hole lies to the right of travel, so step right from a segment midpoint. */
static sq_status hole_seed(const bpoly *p, int start, double seed[2], sq_error *err)
{
    for (double eps = 1e-2; eps > 1e-8; eps *= 0.1) {
        int i = start;
        do {
            int j = p->next[i];
            const double *a = &p->xy[2 * i], *c = &p->xy[2 * j];
            double tx = c[0] - a[0], ty = c[1] - a[1];
            seed[0] = 0.5 * (a[0] + c[0]) + eps * ty;
            seed[1] = 0.5 * (a[1] + c[1]) - eps * tx;
            if (point_in_polygon(p, start, seed)) return SQ_OK;
            i = j;
        } while (i != start);
    }
    return SQ_FAIL(err, SQ_ERR_GEOMETRY, "cannot find a point inside a hole of the face");
}

void sq_tri_options_default(sq_tri_options *opt)
{
    memset(opt, 0, sizeof *opt);
    opt->order = 4;
    opt->size = 0.0;
    opt->min_angle_deg = 20.0;
    opt->max_turn_deg = 30.0;
}

void sq_triangulation_free(sq_triangulation *tri)
{
    if (!tri) return;
    sem_tri_mesh_free(&tri->mesh);
    free(tri->bs);
    free(tri->jac);
    memset(tri, 0, sizeof *tri);
}

/* One CDT of the current polygon.  On return *nsplit counts boundary
 * segments the refinement split; their split points were added to b. */
static sq_status cdt_round(const cad_face *face, const sq_tri_options *opt, size_ctx *sc,
                           const bpoly *p, bdisc *b, cad_cdt_output *out, int *nsplit,
                           sq_error *err)
{
    int np = p->np, nl = cad_face_num_loops(face);
    int npts = np + opt->nextra;
    double *xy = malloc(sizeof(double) * 2 * (size_t)npts);
    int *seg = malloc(sizeof(int) * 2 * (size_t)np);
    double *holes = malloc(sizeof(double) * 2 * (size_t)(nl > 1 ? nl - 1 : 1));
    sq_status st = SQ_OK;
    if (!xy || !seg || !holes) {
        st = SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
        goto done;
    }
    memcpy(xy, p->xy, sizeof(double) * 2 * (size_t)np);
    if (opt->nextra) memcpy(xy + 2 * np, opt->extra_xy, sizeof(double) * 2 * (size_t)opt->nextra);
    for (int i = 0; i < np; i++) {
        seg[2 * i] = i;
        seg[2 * i + 1] = p->next[i];
    }
    /* loop l starts at the first point of its first edge */
    int nh = 0;
    for (int l = 1; l < nl && st == SQ_OK; l++) {
        int e0 = cad_face_loop_first_edge(face, l), start = 0;
        for (int e = 0; e < e0; e++) start += b->n[e];
        st = hole_seed(p, start, &holes[2 * nh++], err);
    }
    if (st != SQ_OK) goto done;
    cad_cdt_input in = {.npoints = npts,
                        .xy = xy,
                        .nsegments = np,
                        .seg = seg,
                        .nholes = nh,
                        .holes = holes,
                        .min_angle_deg = opt->min_angle_deg,
                        .max_size = sc->size,
                        .size = opt->nextra ? graded_size : NULL,
                        .size_ctx = sc};
    if ((st = cad_cdt_mesh(&in, out, err)) != SQ_OK) goto done;
    *nsplit = 0;
    for (int v = 0; v < out->nverts && st == SQ_OK; v++) {
        int i = out->on_segment[v];
        if (i < 0) continue;
        const double *a = &p->xy[2 * i], *c = &p->xy[2 * p->next[i]], *q = &out->xy[2 * v];
        double len = hypot(c[0] - a[0], c[1] - a[1]);
        double f = hypot(q[0] - a[0], q[1] - a[1]) / len;
        double s0 = p->s[i], s1 = seg_end_s(face, p, i);
        st = bdisc_insert(b, p->edge[i], s0 + f * (s1 - s0), err);
        (*nsplit)++;
    }
done:
    free(xy);
    free(seg);
    free(holes);
    return st;
}

/* Smallest angle of the straight triangle (degrees). */
static double tri_min_angle(const double *a, const double *b, const double *c)
{
    const double *p[3] = {a, b, c};
    double m = 180.0;
    for (int k = 0; k < 3; k++) {
        const double *o = p[k], *u = p[(k + 1) % 3], *w = p[(k + 2) % 3];
        double ux = u[0] - o[0], uy = u[1] - o[1], wx = w[0] - o[0], wy = w[1] - o[1];
        double ang = atan2(fabs(ux * wy - uy * wx), ux * wx + uy * wy) * 180.0 / M_PI;
        if (ang < m) m = ang;
    }
    return m;
}

/* Build the order-P mesh from the final CDT, whose boundary vertices are
 * exactly the polygon's points.  *nbad counts elements whose scaled Jacobian
 * is below MIN_SCALED_JAC; their boundary segments got midpoints in b. */
static sq_status build_mesh(const cad_face *face, const sq_tri_options *opt, const bpoly *p,
                            const cad_cdt_output *o, bdisc *b, sq_triangulation *out, int *nbad,
                            sq_error *err)
{
    int *map = malloc(sizeof(int) * (size_t)o->nverts);
    sq_status st = SQ_OK;
    if (!map) return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    /* keep only vertices used by triangles (extra points outside the face
     * would be left isolated) */
    for (int v = 0; v < o->nverts; v++) map[v] = -1;
    int nv = 0;
    for (int t = 0; t < 3 * o->ntris; t++)
        if (map[o->tri[t]] < 0) map[o->tri[t]] = nv++;
    double *jac;
    if ((st = sem_tri_mesh_create(opt->order, nv, o->ntris, &out->mesh, err)) != SQ_OK) goto done;
    sem_tri_mesh *m = out->mesh;
    out->bs = calloc(6 * (size_t)o->ntris, sizeof(double));
    jac = out->jac = malloc(sizeof(double) * (size_t)o->ntris);
    if (!out->bs || !jac) {
        st = SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
        goto done;
    }
    for (int v = 0; v < o->nverts; v++)
        if (map[v] >= 0) {
            m->vxy[2 * map[v]] = o->xy[2 * v];
            m->vxy[2 * map[v] + 1] = o->xy[2 * v + 1];
        }
    for (int t = 0; t < 3 * o->ntris; t++) m->tri[t] = map[o->tri[t]];
    if ((st = sem_tri_mesh_build_neighbours(m, err)) != SQ_OK) goto done;
    out->min_angle_deg = 180.0;
    for (int e = 0; e < m->ntris; e++) {
        double a = tri_min_angle(&m->vxy[2 * m->tri[3 * e]], &m->vxy[2 * m->tri[3 * e + 1]],
                                 &m->vxy[2 * m->tri[3 * e + 2]]);
        if (a < out->min_angle_deg) out->min_angle_deg = a;
        for (int k = 0; k < 3; k++) {
            if (m->neigh[3 * e + k] >= 0) continue;
            int va = o->tri[3 * e + k], vb = o->tri[3 * e + (k + 1) % 3];
            int i = o->source[va];
            if (i < 0 || i >= p->np || p->next[i] != o->source[vb]) {
                st = SQ_FAIL(err, SQ_ERR_INTERNAL,
                             "boundary edge of triangle %d is not a boundary segment", e);
                goto done;
            }
            m->btag[3 * e + k] = p->edge[i];
            out->bs[6 * e + 2 * k] = p->s[i];
            out->bs[6 * e + 2 * k + 1] = seg_end_s(face, p, i);
        }
    }
    if ((st = sq_tri_curve(face, m, out->bs, jac, err)) != SQ_OK) goto done;
    *nbad = 0;
    out->min_scaled_jacobian = HUGE_VAL;
    for (int e = 0; e < m->ntris && st == SQ_OK; e++) {
        if (jac[e] < out->min_scaled_jacobian) out->min_scaled_jacobian = jac[e];
        if (jac[e] >= MIN_SCALED_JAC) continue;
        (*nbad)++;
        for (int k = 0; k < 3 && st == SQ_OK; k++)
            if (m->btag[3 * e + k] >= 0)
                st = bdisc_insert(b, m->btag[3 * e + k],
                                  0.5 * (out->bs[6 * e + 2 * k] + out->bs[6 * e + 2 * k + 1]), err);
    }
done:
    free(map);
    return st;
}

static sq_status mesh_area(const sem_tri_mesh *m, double *area, sq_error *err)
{
    sem_tri_lagrange *lag = NULL;
    sem_tri_geom_sampler *S = NULL;
    SQ_TRY(sem_tri_lagrange_create(m->order, &lag, err));
    sq_status st = sem_tri_geom_sampler_create(lag, &S, err);
    double a = 0.0;
    for (int e = 0; e < m->ntris && st == SQ_OK; e++)
        a += sem_tri_geom_sampler_area(S, &m->gxy[2 * (size_t)m->nodes_per_tri * (size_t)e]);
    *area = a;
    sem_tri_geom_sampler_free(&S);
    sem_tri_lagrange_free(&lag);
    return st;
}

double sq_tri_size(const sq_tri_options *opt, double area)
{
    return opt->size > 0.0 ? opt->size : sqrt(fabs(area)) / 3.0;
}

sq_status sq_triangulate(const cad_face *face, const sq_tri_options *opt, sq_triangulation *out,
                         sq_error *err)
{
    memset(out, 0, sizeof *out);
    if (opt->order < 1 || opt->order > 12)
        return SQ_FAIL(err, SQ_ERR_USAGE, "order %d out of range 1..12", opt->order);
    if (opt->min_angle_deg <= 0.0 || opt->min_angle_deg > 30.0)
        return SQ_FAIL(err, SQ_ERR_USAGE, "minimum angle %g out of range (0, 30] degrees",
                       opt->min_angle_deg);
    if (opt->max_turn_deg <= 0.0 || opt->max_turn_deg > 90.0)
        return SQ_FAIL(err, SQ_ERR_USAGE, "boundary turning %g out of range (0, 90] degrees",
                       opt->max_turn_deg);
    double size = opt->size;
    if (!(size > 0.0)) {
        sq_face_info info;
        SQ_TRY(sq_face_info_compute(face, &info, err));
        size = sq_tri_size(opt, info.area);
        sq_face_info_free(&info);
    }
    size_ctx sc = {opt, size};
    bdisc b = {0};
    bpoly p = {0};
    cad_cdt_output o = {0};
    sq_status st = bdisc_initial(face, &sc, opt->max_turn_deg * M_PI / 180.0, &b, err);
    int round = 0, done = 0;
    for (; st == SQ_OK && !done && round < MAX_ROUNDS; round++) {
        int nsplit = 0, nbad = 0;
        bpoly_free(&p);
        cad_cdt_output_free(&o);
        sq_triangulation_free(out);
        if ((st = bpoly_build(face, &b, &p, err)) != SQ_OK) break;
        if ((st = cdt_round(face, opt, &sc, &p, &b, &o, &nsplit, err)) != SQ_OK) break;
        if (nsplit) continue;
        if ((st = build_mesh(face, opt, &p, &o, &b, out, &nbad, err)) != SQ_OK) break;
        done = nbad == 0;
    }
    if (st == SQ_OK && !done)
        st = SQ_FAIL(err, SQ_ERR_GEOMETRY,
                     "no valid curved triangulation after %d refinements of the boundary "
                     "(smallest scaled Jacobian %.3g); try a smaller --size",
                     MAX_ROUNDS, out->mesh ? out->min_scaled_jacobian : 0.0);
    if (st == SQ_OK) {
        out->size = size;
        st = mesh_area(out->mesh, &out->area, err);
    }
    if (st != SQ_OK) sq_triangulation_free(out);
    bpoly_free(&p);
    cad_cdt_output_free(&o);
    bdisc_free(&b);
    return st;
}
