/* Positions of the singular points converge with the order: on half_disc
 * and nautilus the points found at orders P and P+2 differ by less than
 * 1e-6 at P = 10, and the difference falls as P grows.  The bound is the
 * discretisation error at P = 10 (1e-7 .. 1e-6 of the shape, exponential
 * in P): round-off moves a simple zero by the field's error over its
 * gradient, 1e-12 here, and any kernel's by less than 1e-9. */
#include "field_analysis.h"
#include "test_util.h"

#include <gsl/gsl_errno.h>

static void analyse(const char *file, int P, sq_field_analysis *a)
{
    char path[4096];
    cad_model *m = NULL;
    cad_face *f = NULL;
    sq_error err;
    sq_test_path(path, sizeof path, 0, file);
    SQ_TEST_OK(cad_model_read(path, &m, &err), err);
    SQ_TEST_OK(cad_face_create(m, 0, &f, &err), err);
    sq_field_options opt;
    sq_field_options_default(&opt);
    opt.order = P;
    opt.tri.order = P < 12 ? P : 12;
    SQ_TEST_OK(sq_field_analyse(f, &opt, a, &err), err);
    cad_face_free(&f);
    cad_model_free(&m);
}

/* largest distance from a point of a to the nearest point of b */
static double set_distance(const sq_field_analysis *a, const sq_field_analysis *b)
{
    double worst = 0.0;
    for (int k = 0; k < a->npoints; k++) {
        double best = HUGE_VAL;
        for (int q = 0; q < b->npoints; q++)
            best = fmin(best, hypot(a->points[k].x - b->points[q].x, a->points[k].y - b->points[q].y));
        worst = fmax(worst, best);
    }
    return worst;
}

static int study(const char *file, int npts)
{
    const int orders[] = {4, 6, 8, 10, 12};
    sq_field_analysis a[5];
    int fails = 0;
    for (int i = 0; i < 5; i++) {
        analyse(file, orders[i], &a[i]);
        fails += sq_check_int(file, "singular points", a[i].npoints, npts);
    }
    double prev = HUGE_VAL;
    for (int i = 0; i + 1 < 5 && !fails; i++) {
        double d = set_distance(&a[i], &a[i + 1]);
        if (getenv("SQ_VERBOSE")) printf("%s P=%d vs P=%d: %.3e\n", file, orders[i], orders[i + 1], d);
        if (!(d < prev)) {
            printf("%s: difference P=%d vs %d is %.3e, not below the previous %.3e\n", file,
                   orders[i], orders[i + 1], d, prev);
            fails++;
        }
        prev = d;
        if (orders[i] == 10) fails += sq_check_abs(file, "P=10 vs P=12 position difference", d, 0.0, 1e-6);
    }
    for (int i = 0; i < 5; i++) sq_field_analysis_free(&a[i]);
    return fails;
}

int main(void)
{
    gsl_set_error_handler_off();
    return study("half_disc.step", 2) + study("nautilus.step", 4) ? 1 : 0;
}
