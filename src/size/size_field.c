/* semquad — the size field h(x) (size_field.h): a minimum of linear
 * distance–threshold contributions, as Gmsh's Distance + Threshold fields
 * with a gradation bound. */
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

struct sq_size_field {
    int n;
    source *src;
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

sq_status sq_size_field_create(const cad_face *face, const sq_size_source *src, int n,
                               double gradation, sq_size_field **out, sq_error *err)
{
    *out = NULL;
    SQ_TRY(sq_size_sources_check(src, n, gradation, err));
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
    sq_status st = SQ_OK;
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
    free((*f)->src);
    free(*f);
    *f = NULL;
}

/* Distance from x to the polyline p[EDGE_SAMPLES + 1]. */
static double polyline_distance(const double *p, const double x[2])
{
    double best = DBL_MAX;
    for (int k = 0; k < EDGE_SAMPLES; k++) {
        double ax = p[2 * k], ay = p[2 * k + 1], dx = p[2 * k + 2] - ax, dy = p[2 * k + 3] - ay;
        double l2 = dx * dx + dy * dy;
        double t = l2 > 0.0 ? ((x[0] - ax) * dx + (x[1] - ay) * dy) / l2 : 0.0;
        t = fmin(fmax(t, 0.0), 1.0);
        best = fmin(best, hypot(x[0] - ax - t * dx, x[1] - ay - t * dy));
    }
    return best;
}

/* Distance from x to source s's region (0 inside it). */
static double source_distance(const source *s, const double x[2])
{
    switch (s->s.kind) {
    case SQ_SIZE_EDGE: return polyline_distance(s->poly, x);
    case SQ_SIZE_POINT: return fmax(hypot(x[0] - s->s.x[0], x[1] - s->s.x[1]) - s->s.r, 0.0);
    default: {
        double dx = fmax(fmax(s->s.x[0] - x[0], x[0] - s->s.x1[0]), 0.0);
        double dy = fmax(fmax(s->s.x[1] - x[1], x[1] - s->s.x1[1]), 0.0);
        return hypot(dx, dy);
    }
    }
}

double sq_size_field_eval(const sq_size_field *f, const double x[2], double far)
{
    double h = far;
    for (int i = 0; i < f->n; i++) {
        const source *s = &f->src[i];
        h = fmin(h, s->s.h + s->slope * source_distance(s, x));
    }
    return h;
}
