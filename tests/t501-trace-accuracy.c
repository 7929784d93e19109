/* Tracing accuracy (Marcon 2019 §3.3, AB4): on fields whose field lines are
 * known exactly, the traced lines stay on them.
 *  - synthetic cross fields on the annulus: concentric circles and
 *    straight lines (only the sq_cross_field interface is used);
 *  - the real guiding field of the annulus at P = 10, whose field lines are
 *    exactly circles and rays (issue 5: within 1e-8 of the exact curve),
 *    at step_rel = 0.025.
 * The straight line and the ray end exactly on the CAD circles. */
#include "field_analysis.h"
#include "trace.h"
#include "test_util.h"

#include <gsl/gsl_errno.h>

typedef struct {
    int kind; /* 0: circles, 1: lines at angle a */
    double a;
} synth;

static int synth_dir(void *ctx, const double x[2], int *elem, double *theta)
{
    const synth *s = ctx;
    double r = hypot(x[0], x[1]);
    if (r < 0.4 || r > 1.0) return 1;
    *elem = 0;
    *theta = s->kind == 0 ? atan2(x[1], x[0]) + M_PI / 2 : s->a;
    return 0;
}

static double synth_size(void *ctx, int elem)
{
    (void)ctx, (void)elem;
    return 0.1;
}

/* largest |r - r0| along a line */
static double radius_dev(const sq_separatrix *s, double r0)
{
    double d = 0.0;
    for (int i = 0; i < s->npts; i++) d = fmax(d, fabs(hypot(s->xy[2 * i], s->xy[2 * i + 1]) - r0));
    return d;
}

/* largest distance from the line through p in direction a */
static double line_dev(const sq_separatrix *s, const double p[2], double a)
{
    double d = 0.0;
    for (int i = 0; i < s->npts; i++)
        d = fmax(d, fabs(-(s->xy[2 * i] - p[0]) * sin(a) + (s->xy[2 * i + 1] - p[1]) * cos(a)));
    return d;
}

/* distance of the end from CAD edge end.id, and the end's arc length check */
static int check_end_on_cad(const char *ctx, const cad_face *f, const sq_separatrix *s)
{
    int fails = sq_check_int(ctx, "end kind (boundary)", s->end.kind, SQ_END_BOUNDARY);
    if (s->end.kind != SQ_END_BOUNDARY) return fails;
    sq_error err;
    const double *p = &s->xy[2 * (s->npts - 1)];
    double d, sp, q[2];
    SQ_TEST_OK(cad_face_edge_project(f, s->end.id, p, &sp, NULL, &d, &err), err);
    SQ_TEST_OK(cad_face_edge_eval(f, s->end.id, s->end.s, q, NULL, NULL, &err), err);
    /* the end is snapped to the edge's point at s (src/trace_ab4.c): both
     * sides are curve evaluations, a few U of coordinates <= 1 */
    fails += sq_check_abs(ctx, "distance of the end from its CAD edge", d, 0.0, 1e-12);
    fails += sq_check_abs(ctx, "end = edge(s)", hypot(q[0] - p[0], q[1] - p[1]), 0.0, 1e-12);
    return fails;
}

int main(void)
{
    gsl_set_error_handler_off();
    int fails = 0;
    char path[4096];
    sq_error err;
    cad_model *m = NULL;
    cad_face *f = NULL;
    sq_test_path(path, sizeof path, 0, "annulus.step");
    SQ_TEST_OK(cad_model_read(path, &m, &err), err);
    SQ_TEST_OK(cad_face_create(m, 0, &f, &err), err);
    sq_face_info info;
    SQ_TEST_OK(sq_face_info_compute(f, &info, &err), err);
    sq_trace_options opt;
    sq_trace_options_default(&opt);

    /* synthetic circles: one turn at r = 0.7 (ends open at the length bound) */
    synth sc = {0, 0.0};
    sq_cross_field cf = {&sc, synth_dir, synth_size, NULL};
    sq_separatrix s;
    double p0[2] = {0.7, 0.0};
    opt.max_length = 2 * M_PI * 0.7;
    SQ_TEST_OK(sq_trace_streamline(&cf, f, &info, 0, NULL, &opt, p0, M_PI / 2, &s, NULL, &err), err);
    fails += sq_check_int("synthetic circle", "end kind (open: length bound)", s.end.kind, SQ_END_OPEN);
    fails += sq_check_abs("synthetic circle", "max |r - 0.7|", radius_dev(&s, 0.7), 0.0, 1e-8);
    free(s.xy);

    /* synthetic straight lines at 0.3 rad: a chord to the outer circle */
    synth sl = {1, 0.3};
    cf.ctx = &sl;
    opt.max_length = 0.0;
    double p1[2] = {0.5, -0.3};
    SQ_TEST_OK(sq_trace_streamline(&cf, f, &info, 0, NULL, &opt, p1, 0.3, &s, NULL, &err), err);
    /* a constant direction: AB4 has no truncation error, the ~1e2 steps add
     * a few U each of |x| <= 1 */
    fails += sq_check_abs("synthetic line", "max distance from the line", line_dev(&s, p1, 0.3), 0.0, 1e-12);
    fails += check_end_on_cad("synthetic line", f, &s);
    fails += sq_check_abs("synthetic line", "end radius", hypot(s.xy[2 * s.npts - 2], s.xy[2 * s.npts - 1]), 1.0, 1e-12);
    free(s.xy);

    /* the real guiding field at P = 10: circles and rays */
    sq_field_options fo;
    sq_field_options_default(&fo);
    fo.order = 10;
    fo.tri.order = 10;
    /* elements of about a third of the gap, so that the field itself is
     * accurate to ~1e-9 in angle at P = 10 */
    fo.tri.size = 0.2;
    sq_field_analysis a;
    SQ_TEST_OK(sq_field_analyse(f, &fo, &a, &err), err);
    fails += sq_check_int("annulus P=10", "singular points", a.npoints, 0);
    sq_cross_field gf = sq_guiding_cross_field(&a.field);
    /* AB4's truncation error on a circle of radius R is ~ L (h/R)^4 / 3:
     * at half the default step it is below 1e-9 */
    opt.step_rel = 0.025;
    double radii[5] = {0.5, 0.6, 0.7, 0.8, 0.95}, tolr[5] = {1e-8, 1e-8, 1e-8, 1e-8, 1e-8};
    for (int k = 0; k < 5; k++) {
        char ctx[64];
        snprintf(ctx, sizeof ctx, "annulus P=10 circle r=%.2f", radii[k]);
        double q[2] = {radii[k] * cos(0.3), radii[k] * sin(0.3)};
        opt.max_length = 2 * M_PI * radii[k];
        SQ_TEST_OK(sq_trace_streamline(&gf, f, &a.info, 0, NULL, &opt, q, 0.3 + M_PI / 2, &s, NULL, &err), err);
        fails += sq_check_int(ctx, "end kind (open after one turn)", s.end.kind, SQ_END_OPEN);
        fails += sq_check_abs(ctx, "max |r - r0|", radius_dev(&s, radii[k]), 0.0, tolr[k]);
        free(s.xy);
    }
    opt.max_length = 0.0;
    double q[2] = {0.5 * cos(1.0), 0.5 * sin(1.0)};
    SQ_TEST_OK(sq_trace_streamline(&gf, f, &a.info, 0, NULL, &opt, q, 1.0, &s, NULL, &err), err);
    fails += sq_check_abs("annulus P=10 ray", "max distance from the ray", line_dev(&s, q, 1.0), 0.0, 1e-8);
    fails += check_end_on_cad("annulus P=10 ray", f, &s);
    const double *e = &s.xy[2 * s.npts - 2];
    /* radius: snapped onto the circle (a few U); angle: the field's 1e-9
     * and AB4's 1e-9 over the ray */
    fails += sq_check_abs("annulus P=10 ray", "end radius", hypot(e[0], e[1]), 1.0, 1e-12);
    fails += sq_check_abs("annulus P=10 ray", "end angle", atan2(e[1], e[0]), 1.0, 1e-8);
    free(s.xy);
    /* and inwards, to the hole */
    SQ_TEST_OK(sq_trace_streamline(&gf, f, &a.info, 0, NULL, &opt, q, 1.0 + M_PI, &s, NULL, &err), err);
    fails += check_end_on_cad("annulus P=10 ray in", f, &s);
    e = &s.xy[2 * s.npts - 2];
    fails += sq_check_abs("annulus P=10 ray in", "end radius", hypot(e[0], e[1]), 0.4, 1e-12);
    fails += sq_check_abs("annulus P=10 ray in", "end angle", atan2(e[1], e[0]), 1.0, 1e-8);
    free(s.xy);

    sq_field_analysis_free(&a);
    sq_face_info_free(&info);
    cad_face_free(&f);
    cad_model_free(&m);
    return fails != 0;
}
