#include "triangulate.h"

#include "face_info.h"
#include "sq_segment.h"
#include "tri_curve.h"
#include "tri_geom.h"
#include "tri_lagrange.h"

#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#define MAX_ROUNDS 16 /* boundary re-discretizations before giving up */
#define MIN_SCALED_JAC 0.05 /* below this a curved element is split further */
/* Halvings of crossing chords before giving up: 40 take a chord down to
 * 1e-12 of its length, past any gap double precision can resolve. */
#define MAX_UNTANGLE 40

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

/* Append s to edge e's list; bdisc_sort orders the lists before use. */
static sq_status bdisc_insert(bdisc *b, int e, double s, sq_error *err)
{
    if (b->n[e] == b->cap[e]) {
        int cap = 2 * b->cap[e] + 8;
        double *p = realloc(b->s[e], sizeof(double) * (size_t)cap);
        if (!p) return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
        b->s[e] = p;
        b->cap[e] = cap;
    }
    b->s[e][b->n[e]++] = s;
    return SQ_OK;
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* Sort every edge's arc lengths and drop repeats (a split can land on a
 * point already there): a round inserts many splits, so sorting once beats
 * keeping the lists sorted insert by insert, quadratic on thin faces. */
static void bdisc_sort(bdisc *b)
{
    for (int e = 0; e < b->nedges; e++) {
        if (b->n[e] < 2) continue;
        qsort(b->s[e], (size_t)b->n[e], sizeof(double), cmp_double);
        int m = 1;
        for (int k = 1; k < b->n[e]; k++)
            if (b->s[e][k] != b->s[e][m - 1]) b->s[e][m++] = b->s[e][k];
        b->n[e] = m;
    }
}

/* Index of arc length s of edge e in the sorted lists (-1 if absent). */
static int bdisc_index(const bdisc *b, int e, double s)
{
    int first = 0;
    for (int k = 0; k < e; k++) first += b->n[k];
    const double *hit = bsearch(&s, b->s[e], (size_t)b->n[e], sizeof(double), cmp_double);
    return hit ? first + (int)(hit - b->s[e]) : -1;
}

typedef struct {
    double x;
    int i;
} sorted_x;

typedef struct {
    const sq_tri_options *opt;
    double size;
    sorted_x *byx; /* extra points sorted by x (size_ctx_init) */
    double hmin;   /* smallest size at an extra point */
} size_ctx;

/* Size at xy due to extra point i: its own size growing with the distance. */
static double extra_h(const sq_tri_options *opt, double h0, double growth, int i,
                      const double xy[2])
{
    double d = hypot(xy[0] - opt->extra_xy[2 * i], xy[1] - opt->extra_xy[2 * i + 1]);
    return (opt->extra_sizes ? opt->extra_sizes[i] : h0) + growth * d;
}

double sq_tri_graded_size(const sq_tri_options *opt, double size, const double xy[2])
{
    const double h0 = opt->extra_size > 0.0 ? opt->extra_size : size / 8.0;
    const double growth = opt->extra_growth > 0.0 ? opt->extra_growth : 0.5;
    double h = opt->user_size ? fmin(size, opt->user_size(xy, opt->user_ctx)) : size;
    for (int i = 0; i < opt->nextra; i++) {
        double hi = extra_h(opt, h0, growth, i, xy);
        if (hi < h) h = hi;
    }
    return h;
}

static int cmp_by_x(const void *a, const void *b)
{
    const sorted_x *p = a, *q = b;
    if (p->x != q->x) return (p->x > q->x) - (p->x < q->x);
    return (p->i > q->i) - (p->i < q->i);
}

static void size_ctx_free(size_ctx *c)
{
    free(c->byx);
}

/* The extra points sorted by x, so that graded_size looks only at those
 * within reach: with hundreds of corners (a 500-gon) the sum over all of
 * them at every CGAL query was the triangulation's whole cost. */
static sq_status size_ctx_init(size_ctx *c, const sq_tri_options *opt, double size, sq_error *err)
{
    *c = (size_ctx){opt, size, NULL, HUGE_VAL};
    int n = opt->nextra;
    c->byx = malloc(sizeof(sorted_x) * ((size_t)n + 1));
    if (!c->byx) return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    const double h0 = opt->extra_size > 0.0 ? opt->extra_size : size / 8.0;
    for (int i = 0; i < n; i++) {
        c->byx[i] = (sorted_x){opt->extra_xy[2 * i], i};
        double hi = opt->extra_sizes ? opt->extra_sizes[i] : h0;
        if (hi < c->hmin) c->hmin = hi;
    }
    if (n > 1) qsort(c->byx, (size_t)n, sizeof(sorted_x), cmp_by_x);
    return SQ_OK;
}

/* sq_tri_graded_size, the same minimum (exactly: a minimum does not depend
 * on the order), over the points whose x is close enough to matter. */
static double graded_size(const double xy[2], void *p)
{
    const size_ctx *c = p;
    const sq_tri_options *opt = c->opt;
    const double h0 = opt->extra_size > 0.0 ? opt->extra_size : c->size / 8.0;
    const double growth = opt->extra_growth > 0.0 ? opt->extra_growth : 0.5;
    int n = opt->nextra, lo = 0, hi = n;
    while (lo < hi) { /* first point with x >= xy[0] */
        int mid = (lo + hi) / 2;
        if (c->byx[mid].x < xy[0]) lo = mid + 1;
        else hi = mid;
    }
    double h = c->size;
    if (opt->user_size) h = fmin(h, opt->user_size(xy, opt->user_ctx));
    for (int j = lo; j < n && c->hmin + growth * (c->byx[j].x - xy[0]) < h; j++) {
        double hj = extra_h(opt, h0, growth, c->byx[j].i, xy);
        if (hj < h) h = hj;
    }
    for (int j = lo - 1; j >= 0 && c->hmin + growth * (xy[0] - c->byx[j].x) < h; j--) {
        double hj = extra_h(opt, h0, growth, c->byx[j].i, xy);
        if (hj < h) h = hj;
    }
    return h;
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
    int npts = 0; /* over all loops */
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
            int budget = sc->opt->max_vertices;
            if (st == SQ_OK && budget > 0 && !(npts + cum[NS] <= budget)) {
                st = SQ_FAIL(err, SQ_ERR_GEOMETRY,
                             "the boundary alone needs more than %d points at the size %g (the "
                             "size is far below the face's size)",
                             budget, sc->size);
                break;
            }
            nseg[e] = (int)ceil(cum[NS] - 1e-9);
            if (nseg[e] < 1) nseg[e] = 1;
            total += nseg[e];
            npts += nseg[e];
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

/* The edges whose points opt->edge_points prescribes take exactly those. */
static sq_status bdisc_prescribed(const sq_edge_points *ep, bdisc *b, sq_error *err)
{
    for (int e = 0; e < b->nedges; e++) {
        if (ep[e].n <= 0) continue;
        b->n[e] = 0;
        for (int k = 0; k < ep[e].n; k++) SQ_TRY(bdisc_insert(b, e, ep[e].s[k], err));
    }
    return SQ_OK;
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

/* Where two loops (or two parts of one) come closer than a chord's
 * sagitta, the chords cross although the curves do not (a near-tangent
 * hole): both chords are halved, on their curves, until no two cross, so
 * that the polygon is simple for the CDT.  Only the crossing chords are
 * split, so the work stays near the close approach; a face whose curves
 * do cross (or touch) is refused after MAX_UNTANGLE halvings. */
static sq_status untangle(const cad_face *face, const sq_tri_options *opt, bpoly *p, bdisc *b,
                          sq_error *err)
{
    sq_status st = SQ_OK;
    for (int round = 0; st == SQ_OK; round++) {
        int *seg = malloc(sizeof(int) * 2 * (size_t)p->np), *pairs = NULL, npairs = 0;
        if (!seg) return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
        for (int i = 0; i < p->np; i++) {
            seg[2 * i] = i;
            seg[2 * i + 1] = p->next[i];
        }
        st = cad_segments_crossing(p->np, p->xy, p->np, seg, 0, &pairs, &npairs, err);
        free(seg);
        if (st == SQ_OK && npairs > 0 &&
            (round == MAX_UNTANGLE || (opt->max_vertices > 0 && p->np > opt->max_vertices))) {
            const double *q = &p->xy[2 * pairs[0]];
            st = SQ_FAIL(err, SQ_ERR_GEOMETRY,
                         "the face's boundary curves cross or touch near (%.6g, %.6g): their "
                         "chords still cross after %d halvings",
                         q[0], q[1], round);
        }
        for (int k = 0; k < 2 * npairs && st == SQ_OK; k++) {
            int i = pairs[k];
            st = bdisc_insert(b, p->edge[i], 0.5 * (p->s[i] + seg_end_s(face, p, i)), err);
        }
        free(pairs);
        if (st != SQ_OK || npairs == 0) return st;
        bpoly_free(p);
        bdisc_sort(b);
        st = bpoly_build(face, b, p, err);
    }
    return st;
}

static int point_in_polygon(const bpoly *p, int start, const double q[2])
{
    int inside = 0, i = start;
    do {
        int j = p->next[i];
        inside ^= sq_segment_crosses_ray(q, &p->xy[2 * i], &p->xy[2 * j]);
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

int sq_tri_order_for(int p) { return p < SQ_TRI_MAX_ORDER ? p : SQ_TRI_MAX_ORDER; }

void sq_tri_options_default(sq_tri_options *opt)
{
    memset(opt, 0, sizeof *opt);
    opt->order = 4;
    opt->size = 0.0;
    opt->min_angle_deg = 20.0;
    opt->max_turn_deg = 30.0;
    opt->max_vertices = SQ_TRI_MAX_VERTICES;
}

void sq_triangulation_free(sq_triangulation *tri)
{
    if (!tri) return;
    sem_tri_mesh_free(&tri->mesh);
    free(tri->bs);
    free(tri->jac);
    memset(tri, 0, sizeof *tri);
}

/* The refinement's splits of boundary segments go into b at their arc
 * lengths.  When every split point is close to its CAD edge (a line's, to
 * rounding; a curve's, within a small part of the segment) they are
 * adopted, moved onto the curve: p becomes the polygon of b and o's
 * vertices are renumbered into it, so no second CDT is needed (redoing it
 * cascaded near graded corners: 16 rounds were not enough).  *nsplit counts
 * the splits farther off: then the CDT is redone with their points on the
 * curve. */
static sq_status take_splits(const cad_face *face, bpoly *p, bdisc *b, cad_cdt_output *o,
                             int *nsplit, sq_error *err)
{
    double *vs = malloc(sizeof(double) * ((size_t)o->nverts + 1));
    if (!vs) return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    int nadopt = 0;
    sq_status st = SQ_OK;
    *nsplit = 0;
    for (int v = 0; v < o->nverts && st == SQ_OK; v++) {
        int i = o->on_segment[v];
        if (i < 0) continue;
        const double *a = &p->xy[2 * i], *c = &p->xy[2 * p->next[i]], *q = &o->xy[2 * v];
        double len = hypot(c[0] - a[0], c[1] - a[1]);
        double f = hypot(q[0] - a[0], q[1] - a[1]) / len, X[2];
        double s0 = p->s[i], s1 = seg_end_s(face, p, i);
        vs[v] = s0 + f * (s1 - s0);
        st = bdisc_insert(b, p->edge[i], vs[v], err);
        if (st == SQ_OK) st = cad_face_edge_eval(face, p->edge[i], vs[v], X, NULL, NULL, err);
        /* 1e-2 of the segment (a curve's sagitta on short segments; lines
         * are within round-off; an edge runs continuously into the corners
         * it shares, cad_face_edge_eval): moving the point onto the curve
         * turns its triangles' angles by less than a degree where they are
         * above the 20-degree bound, and build_mesh's Jacobian check stays
         * the judge (it splits what came out poor); a few roundings of the
         * coordinates */
        double tol = 1e-2 * len + 16.0 * DBL_EPSILON * (fabs(q[0]) + fabs(q[1]));
        if (hypot(X[0] - q[0], X[1] - q[1]) > tol) (*nsplit)++;
        nadopt++;
    }
    if (st != SQ_OK || *nsplit > 0 || nadopt == 0) {
        free(vs);
        return st;
    }
    bpoly q = {0};
    bdisc_sort(b);
    st = bpoly_build(face, b, &q, err);
    for (int v = 0; v < o->nverts && st == SQ_OK; v++) {
        int i = o->on_segment[v], src = o->source[v];
        int k = i >= 0       ? bdisc_index(b, p->edge[i], vs[v])
                : src < 0    ? -1
                : src < p->np ? bdisc_index(b, p->edge[src], p->s[src])
                             : q.np + src - p->np; /* an extra point */
        if (i < 0 && src < 0) continue;
        if (k < 0)
            st = SQ_FAIL(err, SQ_ERR_INTERNAL, "boundary point %d lost in the discretization", v);
        else if (k < q.np) {
            o->xy[2 * v] = q.xy[2 * k];
            o->xy[2 * v + 1] = q.xy[2 * k + 1];
        }
        o->source[v] = k;
        o->on_segment[v] = -1;
    }
    free(vs);
    bpoly_free(p);
    *p = q;
    return st;
}

/* One CDT of the current polygon p.  On return *nsplit counts boundary
 * segments the refinement split off their curves (take_splits). */
static sq_status cdt_round(const cad_face *face, const sq_tri_options *opt, size_ctx *sc,
                           bpoly *p, bdisc *b, cad_cdt_output *out, int *nsplit,
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
                        .size = opt->nextra || opt->user_size ? graded_size : NULL,
                        .size_ctx = sc,
                        .max_vertices = opt->max_vertices,
                        .keep_segments = opt->keep_segments};
    if ((st = cad_cdt_mesh(&in, out, err)) != SQ_OK) goto done;
    st = take_splits(face, p, b, out, nsplit, err);
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
 * exactly the polygon's points, its elements measured by sampler (order P).
 * *nbad counts elements whose scaled Jacobian is below MIN_SCALED_JAC;
 * their boundary segments got midpoints in b. */
static sq_status build_mesh(const cad_face *face, const sq_tri_options *opt,
                            const sem_tri_geom_sampler *sampler, const bpoly *p,
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
                /* the CDT's domain is bounded by other lines than the
                 * polygon's: its loops touch or overlap there */
                const double *q = &m->vxy[2 * m->tri[3 * e + k]];
                st = SQ_FAIL(err, SQ_ERR_GEOMETRY,
                             "the face's loops touch or overlap near (%.6g, %.6g): the "
                             "triangulation's boundary there is no boundary segment",
                             q[0], q[1]);
                goto done;
            }
            m->btag[3 * e + k] = p->edge[i];
            out->bs[6 * e + 2 * k] = p->s[i];
            out->bs[6 * e + 2 * k + 1] = seg_end_s(face, p, i);
        }
    }
    if ((st = sq_tri_curve(face, m, out->bs, sampler, jac, &out->area, err)) != SQ_OK) goto done;
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

double sq_tri_size(const sq_tri_options *opt, double area)
{
    return opt->size > 0.0 ? opt->size : sqrt(fabs(area)) / 3.0;
}

sq_status sq_triangulate(const cad_face *face, const sq_tri_options *opt, sq_triangulation *out,
                         sq_error *err)
{
    memset(out, 0, sizeof *out);
    if (opt->order < 1 || opt->order > SQ_TRI_MAX_ORDER)
        return SQ_FAIL(err, SQ_ERR_USAGE, "order %d out of range 1..12", opt->order);
    if (!(opt->min_angle_deg >= 0.0) || opt->min_angle_deg > 30.0)
        return SQ_FAIL(err, SQ_ERR_USAGE, "minimum angle %g out of range [0, 30] degrees",
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
    size_ctx sc = {0};
    bdisc b = {0};
    bpoly p = {0};
    cad_cdt_output o = {0};
    /* the det J samples of order opt->order, tabulated once for every round */
    sem_tri_lagrange *lag = NULL;
    sem_tri_geom_sampler *sampler = NULL;
    sq_status st = sem_tri_lagrange_create(opt->order, &lag, err);
    if (st == SQ_OK) st = sem_tri_geom_sampler_create(lag, &sampler, err);
    if (st == SQ_OK) st = size_ctx_init(&sc, opt, size, err);
    if (st == SQ_OK) st = bdisc_initial(face, &sc, opt->max_turn_deg * M_PI / 180.0, &b, err);
    if (st == SQ_OK && opt->edge_points) st = bdisc_prescribed(opt->edge_points, &b, err);
    int round = 0, done = 0;
    for (; st == SQ_OK && !done && round < MAX_ROUNDS; round++) {
        int nsplit = 0, nbad = 0;
        bpoly_free(&p);
        cad_cdt_output_free(&o);
        sq_triangulation_free(out);
        bdisc_sort(&b);
        if ((st = bpoly_build(face, &b, &p, err)) != SQ_OK) break;
        if ((st = untangle(face, opt, &p, &b, err)) != SQ_OK) break;
        if ((st = cdt_round(face, opt, &sc, &p, &b, &o, &nsplit, err)) != SQ_OK) break;
        if (nsplit) continue;
        if ((st = build_mesh(face, opt, sampler, &p, &o, &b, out, &nbad, err)) != SQ_OK) break;
        done = nbad == 0;
    }
    if (st == SQ_OK && !done)
        st = SQ_FAIL(err, SQ_ERR_GEOMETRY,
                     "no valid curved triangulation after %d refinements of the boundary "
                     "(smallest scaled Jacobian %.3g); try a smaller --size",
                     MAX_ROUNDS, out->mesh ? out->min_scaled_jacobian : 0.0);
    if (st == SQ_OK) out->size = size;
    if (st != SQ_OK) sq_triangulation_free(out);
    sem_tri_geom_sampler_free(&sampler);
    sem_tri_lagrange_free(&lag);
    bpoly_free(&p);
    cad_cdt_output_free(&o);
    bdisc_free(&b);
    size_ctx_free(&sc);
    return st;
}
