/* semquad — the size field h(x) (size_field.h): a minimum of linear
 * distance–threshold contributions, as Gmsh's Distance + Threshold fields
 * with a gradation bound, and of the CAD curves' curvature sizes. */
#include "size_field.h"

#include <float.h>
#include <math.h>
#include <stdlib.h>

/* Polyline segments per CAD edge: the chord error of a circle of radius R
 * is R (1 - cos(pi / N)) ~ 5e-5 R at N = 256 — far below any cell. */
#define EDGE_SAMPLES 256

typedef struct {
    sq_size_source s;
    double slope; /* growth of the size per unit distance: min(ratio, g) - 1 */
    double *poly; /* SQ_SIZE_EDGE: EDGE_SAMPLES + 1 points */
} source;

/* A curved CAD edge's curvature sizes: polyline points and the size
 * 1 / (N |kappa|) at each (HUGE_VAL where the edge is straight). */
typedef struct {
    double *poly, *h;
} curved_edge;

/* A wall (a boundary-layer CAD edge): its polyline; the size normal to
 * it is wall_size() of the distance. */
typedef struct {
    double *poly;
} wall;

struct sq_size_field {
    const sq_size_field *base; /* a walls field: the isotropic part is base's (NULL: far) */
    int nwalls;
    wall *walls;
    double wall_b, wall_a, wall_t, wall_g; /* b + a d up to d = t, then growing by g - 1 */
    int n;
    source *src;
    int ncurved;
    curved_edge *curved;
    double slope; /* growth away from the curves: g - 1 */
};

sq_status sq_size_sources_check(const sq_size_source *src, int n, double gradation, sq_error *err)
{
    if (!(gradation > 1.0 && isfinite(gradation)))
        return SQ_FAIL(err, SQ_ERR_USAGE, "size gradation %g: expects a number > 1", gradation);
    for (int i = 0; i < n; i++) {
        const sq_size_source *s = &src[i];
        if (!(s->h > 0.0 && isfinite(s->h)))
            return SQ_FAIL(err, SQ_ERR_USAGE, "size source %d: size %g, expects > 0", i + 1, s->h);
        if (s->ratio != 0.0 && !(s->ratio >= 1.0 && isfinite(s->ratio)))
            return SQ_FAIL(err, SQ_ERR_USAGE, "size source %d: growth ratio %g, expects >= 1",
                           i + 1, s->ratio);
        if (!isfinite(s->x[0]) || !isfinite(s->x[1]) || !isfinite(s->x1[0]) || !isfinite(s->x1[1]))
            return SQ_FAIL(err, SQ_ERR_USAGE, "size source %d: coordinates not finite", i + 1);
        switch (s->kind) {
        case SQ_SIZE_EDGE:
            if (s->edge < 0)
                return SQ_FAIL(err, SQ_ERR_USAGE, "size source %d: edge %d, expects >= 0", i + 1,
                               s->edge);
            break;
        case SQ_SIZE_POINT:
            if (!(s->r >= 0.0 && isfinite(s->r)))
                return SQ_FAIL(err, SQ_ERR_USAGE, "size source %d: radius %g, expects >= 0",
                               i + 1, s->r);
            break;
        case SQ_SIZE_BOX:
            if (!(s->x1[0] > s->x[0] && s->x1[1] > s->x[1]))
                return SQ_FAIL(err, SQ_ERR_USAGE,
                               "size source %d: box (%g,%g)-(%g,%g) is empty (expects x0 < x1, "
                               "y0 < y1)", i + 1, s->x[0], s->x[1], s->x1[0], s->x1[1]);
            break;
        default:
            return SQ_FAIL(err, SQ_ERR_USAGE, "size source %d: unknown kind %d", i + 1,
                           (int)s->kind);
        }
    }
    return SQ_OK;
}

sq_status sq_size_curvature_check(double per_radian, sq_error *err)
{
    if (!(per_radian >= 0.0 && isfinite(per_radian)))
        return SQ_FAIL(err, SQ_ERR_USAGE,
                       "curvature_elements %g: expects a number >= 0 (elements per radian)",
                       per_radian);
    return SQ_OK;
}

static sq_status sample_edge(const cad_face *face, int edge, double **poly, sq_error *err)
{
    double len = cad_face_edge_length(face, edge);
    *poly = malloc(sizeof(double) * 2 * (EDGE_SAMPLES + 1));
    if (!*poly) return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    for (int k = 0; k <= EDGE_SAMPLES; k++)
        SQ_TRY(cad_face_edge_eval(face, edge, len * k / EDGE_SAMPLES, &(*poly)[2 * k], NULL, NULL,
                                  err));
    return SQ_OK;
}

/* Edge `edge`'s curvature sizes 1 / (N |kappa|) at its polyline's points
 * into c; c->poly stays NULL when the edge is straight throughout. */
static sq_status curvature_sizes(const cad_face *face, int edge, double per_radian,
                                 curved_edge *c, sq_error *err)
{
    double len = cad_face_edge_length(face, edge);
    double *poly = malloc(sizeof(double) * 2 * (EDGE_SAMPLES + 1));
    double *h = malloc(sizeof(double) * (EDGE_SAMPLES + 1));
    if (!poly || !h) {
        free(poly), free(h);
        return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    }
    int curved = 0;
    for (int k = 0; k <= EDGE_SAMPLES; k++) {
        double kappa;
        sq_status st = cad_face_edge_eval(face, edge, len * k / EDGE_SAMPLES, &poly[2 * k], NULL,
                                          &kappa, err);
        if (st != SQ_OK) {
            free(poly), free(h);
            return st;
        }
        /* a radius beyond 1e12 lengths of the edge is a straight line's
         * round-off */
        int bent = fabs(kappa) * len > 1e-12;
        h[k] = bent ? 1.0 / (per_radian * fabs(kappa)) : HUGE_VAL;
        curved |= bent;
    }
    if (!curved) {
        free(poly), free(h);
        return SQ_OK;
    }
    c->poly = poly, c->h = h;
    return SQ_OK;
}

/* The curvature sizes of every curved edge of face into f. */
static sq_status curvature_field(const cad_face *face, double per_radian, sq_size_field *f,
                                 sq_error *err)
{
    int ne = cad_face_num_edges(face);
    if (!(f->curved = calloc((size_t)ne + 1, sizeof *f->curved)))
        return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    for (int e = 0; e < ne; e++) {
        SQ_TRY(curvature_sizes(face, e, per_radian, &f->curved[f->ncurved], err));
        if (f->curved[f->ncurved].poly) f->ncurved++;
    }
    return SQ_OK;
}

sq_status sq_size_field_create(const cad_face *face, const sq_size_source *src, int n,
                               double gradation, double per_radian, sq_size_field **out,
                               sq_error *err)
{
    *out = NULL;
    SQ_TRY(sq_size_sources_check(src, n, gradation, err));
    SQ_TRY(sq_size_curvature_check(per_radian, err));
    for (int i = 0; i < n; i++)
        if (src[i].kind == SQ_SIZE_EDGE && src[i].edge >= cad_face_num_edges(face))
            return SQ_FAIL(err, SQ_ERR_USAGE, "size source %d: edge %d, the face has edges 0..%d",
                           i + 1, src[i].edge, cad_face_num_edges(face) - 1);
    sq_size_field *f = calloc(1, sizeof *f);
    if (!f || !(f->src = calloc((size_t)n + 1, sizeof *f->src))) {
        free(f);
        return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    }
    f->n = n;
    f->slope = gradation - 1.0;
    sq_status st = per_radian > 0.0 ? curvature_field(face, per_radian, f, err) : SQ_OK;
    for (int i = 0; i < n && st == SQ_OK; i++) {
        source *s = &f->src[i];
        s->s = src[i];
        double ratio = src[i].ratio > 0.0 ? src[i].ratio : gradation;
        s->slope = fmin(ratio, gradation) - 1.0;
        if (src[i].kind == SQ_SIZE_EDGE) st = sample_edge(face, src[i].edge, &s->poly, err);
    }
    if (st != SQ_OK) sq_size_field_free(&f);
    *out = f;
    return st;
}

void sq_size_field_free(sq_size_field **f)
{
    if (!f || !*f) return;
    for (int i = 0; i < (*f)->n; i++) free((*f)->src[i].poly);
    for (int i = 0; i < (*f)->nwalls; i++) free((*f)->walls[i].poly);
    free((*f)->walls);
    for (int i = 0; i < (*f)->ncurved; i++) free((*f)->curved[i].poly), free((*f)->curved[i].h);
    free((*f)->src);
    free((*f)->curved);
    free(*f);
    *f = NULL;
}

/* Distance from x to the polyline p[EDGE_SAMPLES + 1]; its nearest
 * segment's unit normal into nrm (NULL: not wanted). */
static double polyline_nearest(const double *p, const double x[2], double nrm[2])
{
    double best = DBL_MAX;
    for (int k = 0; k < EDGE_SAMPLES; k++) {
        double ax = p[2 * k], ay = p[2 * k + 1], dx = p[2 * k + 2] - ax, dy = p[2 * k + 3] - ay;
        double l2 = dx * dx + dy * dy;
        double t = l2 > 0.0 ? ((x[0] - ax) * dx + (x[1] - ay) * dy) / l2 : 0.0;
        t = fmin(fmax(t, 0.0), 1.0);
        double d = hypot(x[0] - ax - t * dx, x[1] - ay - t * dy);
        if (d < best && nrm && l2 > 0.0) {
            /* the direction from the foot where x is off the segment's
             * line, else the segment's normal */
            double ex = x[0] - ax - t * dx, ey = x[1] - ay - t * dy, el = hypot(ex, ey);
            double sl = sqrt(l2);
            nrm[0] = el > 1e-9 * sl ? ex / el : -dy / sl;
            nrm[1] = el > 1e-9 * sl ? ey / el : dx / sl;
        }
        best = fmin(best, d);
    }
    return best;
}

/* Distance from x to source s's region (0 inside it). */
static double source_distance(const source *s, const double x[2])
{
    switch (s->s.kind) {
    case SQ_SIZE_EDGE: return polyline_nearest(s->poly, x, NULL);
    case SQ_SIZE_POINT: return fmax(hypot(x[0] - s->s.x[0], x[1] - s->s.x[1]) - s->s.r, 0.0);
    default: {
        double dx = fmax(fmax(s->s.x[0] - x[0], x[0] - s->s.x1[0]), 0.0);
        double dy = fmax(fmax(s->s.x[1] - x[1], x[1] - s->s.x1[1]), 0.0);
        return hypot(dx, dy);
    }
    }
}

/* The least of h_k + slope |x - p_k| over the curve c, h linear along its
 * segments where both ends have one. */
static double curvature_eval(const curved_edge *c, double slope, const double x[2])
{
    double best = HUGE_VAL;
    for (int k = 0; k < EDGE_SAMPLES; k++) {
        const double *a = &c->poly[2 * k];
        double ha = c->h[k], hb = c->h[k + 1];
        if (ha == HUGE_VAL && hb == HUGE_VAL) continue;
        if (ha == HUGE_VAL || hb == HUGE_VAL) { /* the curved end alone */
            const double *p = ha == HUGE_VAL ? a + 2 : a;
            best = fmin(best, fmin(ha, hb) + slope * hypot(x[0] - p[0], x[1] - p[1]));
            continue;
        }
        double dx = a[2] - a[0], dy = a[3] - a[1], l2 = dx * dx + dy * dy;
        double t = l2 > 0.0 ? ((x[0] - a[0]) * dx + (x[1] - a[1]) * dy) / l2 : 0.0;
        t = fmin(fmax(t, 0.0), 1.0);
        double d = hypot(x[0] - a[0] - t * dx, x[1] - a[1] - t * dy);
        best = fmin(best, ha + t * (hb - ha) + slope * d);
    }
    return best;
}

double sq_size_field_eval(const sq_size_field *f, const double x[2], double far)
{
    double h = f->base ? sq_size_field_eval(f->base, x, far) : far;
    for (int i = 0; i < f->n; i++) {
        const source *s = &f->src[i];
        h = fmin(h, s->s.h + s->slope * source_distance(s, x));
    }
    for (int i = 0; i < f->ncurved; i++) h = fmin(h, curvature_eval(&f->curved[i], f->slope, x));
    return h;
}

sq_status sq_size_field_walls(const cad_face *face, const sq_size_field *base, const int *edges,
                              int n, double first, double ratio, int layers, double gradation,
                              sq_size_field **out, sq_error *err)
{
    *out = NULL;
    if (!(first > 0.0 && isfinite(first)) || !(ratio >= 1.0 && isfinite(ratio)) || layers < 1 ||
        !(gradation > 1.0 && isfinite(gradation)))
        return SQ_FAIL(err, SQ_ERR_USAGE,
                       "boundary layer: first height %g, ratio %g, %d layers, gradation %g (expects "
                       "> 0, >= 1, >= 1, > 1)", first, ratio, layers, gradation);
    for (int i = 0; i < n; i++)
        if (edges[i] < 0 || edges[i] >= cad_face_num_edges(face))
            return SQ_FAIL(err, SQ_ERR_USAGE, "boundary layer: edge %d, the face has edges 0..%d",
                           edges[i], cad_face_num_edges(face) - 1);
    sq_size_field *f = calloc(1, sizeof *f);
    if (!f || !(f->walls = calloc((size_t)n + 1, sizeof *f->walls))) {
        free(f);
        return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    }
    f->base = base;
    /* h = b + a d, a = ln r: the k-th cell of its equidistribution is
     * (b / a)(e^a - 1) e^{a k} = first r^k when b = first a / (r - 1) */
    f->wall_a = log(ratio);
    f->wall_b = ratio > 1.0 ? first * f->wall_a / (ratio - 1.0) : first;
    /* the layers' thickness first (r^n - 1) / (r - 1), where the integral
     * of 1 / (b + a d) reaches n; beyond, a growth of ln g per unit
     * distance gives cells growing by g */
    f->wall_t = ratio > 1.0 ? first * (pow(ratio, layers) - 1.0) / (ratio - 1.0) : first * layers;
    f->wall_g = log(gradation);
    sq_status st = SQ_OK;
    for (int i = 0; i < n && st == SQ_OK; i++)
        st = sample_edge(face, edges[i], &f->walls[i].poly, err), f->nwalls = i + 1;
    if (st != SQ_OK) sq_size_field_free(&f);
    *out = f;
    return st;
}

double sq_size_field_eval_dir(const sq_size_field *f, const double x[2], const double t[2],
                              double far)
{
    double h = sq_size_field_eval(f, x, far);
    if (!f->nwalls) return h;
    /* the metric (1/hn^2) n n^T + (1/h^2)(I - n n^T) of each wall, hn its
     * normal size (at most h), read along t; the finest wall wins */
    double tl = hypot(t[0], t[1]), inv = 1.0 / h;
    for (int i = 0; i < f->nwalls && tl > 0.0; i++) {
        double nrm[2];
        double d = polyline_nearest(f->walls[i].poly, x, nrm);
        double hn = fmin(h, d <= f->wall_t ? f->wall_b + f->wall_a * d
                                           : f->wall_b + f->wall_a * f->wall_t +
                                                 f->wall_g * (d - f->wall_t));
        double c = (t[0] * nrm[0] + t[1] * nrm[1]) / tl;
        inv = fmax(inv, sqrt(c * c / (hn * hn) + (1.0 - c * c) / (h * h)));
    }
    return 1.0 / inv;
}
