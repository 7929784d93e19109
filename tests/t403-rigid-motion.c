/* Robustness: rotating, scaling and translating an example in its plane
 * moves its singular points the same way (same count, valences, positions
 * mapped to 1e-6 of the shape's size), and tilting the plane in 3D keeps
 * the pattern's intrinsic shape (distances between the points).  The
 * moved face gets its own triangulation (CGAL is not invariant under the
 * motion), so positions differ by the discretisation error, 1e-6 of the
 * size at the order used (t402), not by round-off. */
#include "field_analysis.h"
#include "test_util.h"

#include <gsl/gsl_errno.h>

static void analyse(const char *file, const double axis[3], double angle, double scale,
                    const double t[3], sq_field_analysis *a)
{
    char path[4096];
    cad_model *m = NULL;
    cad_face *f = NULL;
    sq_error err;
    sq_test_path(path, sizeof path, 0, file);
    SQ_TEST_OK(cad_model_read(path, &m, &err), err);
    SQ_TEST_OK(cad_model_transform(m, axis, angle, scale, t, &err), err);
    SQ_TEST_OK(cad_face_create(m, 0, &f, &err), err);
    sq_field_options opt;
    sq_field_options_default(&opt);
    SQ_TEST_OK(sq_field_analyse(f, &opt, a, &err), err);
    cad_face_free(&f);
    cad_model_free(&m);
}

/* largest distance from a mapped point of a to the nearest point of b */
static double mapped_distance(const sq_field_analysis *a, const sq_field_analysis *b, double angle,
                              double scale, const double t[3])
{
    double worst = 0.0, c = cos(angle), s = sin(angle);
    for (int k = 0; k < a->npoints; k++) {
        double x = scale * (c * a->points[k].x - s * a->points[k].y) + t[0];
        double y = scale * (s * a->points[k].x + c * a->points[k].y) + t[1];
        double best = HUGE_VAL;
        for (int q = 0; q < b->npoints; q++) {
            if (b->points[q].valence != a->points[k].valence) continue;
            best = fmin(best, hypot(x - b->points[q].x, y - b->points[q].y));
        }
        worst = fmax(worst, best);
    }
    return worst;
}

/* sorted pairwise distances, scaled */
static double pair_mismatch(const sq_field_analysis *a, const sq_field_analysis *b, double scale)
{
    double worst = 0.0;
    for (int i = 0; i < a->npoints; i++)
        for (int j = i + 1; j < a->npoints; j++) {
            double d = scale * hypot(a->points[i].x - a->points[j].x, a->points[i].y - a->points[j].y);
            double best = HUGE_VAL;
            for (int p = 0; p < b->npoints; p++)
                for (int q = p + 1; q < b->npoints; q++)
                    best = fmin(best, fabs(d - hypot(b->points[p].x - b->points[q].x,
                                                     b->points[p].y - b->points[q].y)));
            worst = fmax(worst, best);
        }
    return worst;
}

int main(void)
{
    gsl_set_error_handler_off();
    const double z[3] = {0, 0, 1}, zero[3] = {0, 0, 0};
    const char *files[] = {"half_disc.step", "nautilus.step", "square_hole.step"};
    const double size[] = {2.0, 2.0, 1.0};
    /* fixed pseudo-random motions (reproducible) */
    const double angles[] = {0.7, -2.1, 3.0};
    const double scales[] = {3.5, 0.02, 250.0};
    const double shifts[3][3] = {{10.0, -4.0, 0.0}, {-0.3, 0.8, 0.0}, {1e3, 2e3, 0.0}};
    int fails = 0;
    for (int i = 0; i < 3; i++) {
        sq_field_analysis ref, moved, tilted;
        analyse(files[i], z, 0.0, 1.0, zero, &ref);
        analyse(files[i], z, angles[i], scales[i], shifts[i], &moved);
        fails += sq_check_int(files[i], "points after the motion", moved.npoints, ref.npoints);
        fails += sq_check_abs(files[i], "mapped point distance / size",
                              mapped_distance(&ref, &moved, angles[i], scales[i], shifts[i]) /
                                  (scales[i] * size[i]), 0.0, 1e-6);
        fails += sq_check_int(files[i], "Poincare-Hopf after the motion", moved.ph_lhs, moved.ph_rhs);
        /* a plane tilted in 3D: only intrinsic quantities compare */
        const double axis[3] = {0.3, 0.9, 0.1};
        analyse(files[i], axis, 1.1, 2.0, shifts[i], &tilted);
        fails += sq_check_int(files[i], "points in the tilted plane", tilted.npoints, ref.npoints);
        fails += sq_check_abs(files[i], "pairwise distances in the tilted plane / size",
                              pair_mismatch(&ref, &tilted, 2.0) / (2.0 * size[i]), 0.0, 1e-6);
        sq_field_analysis_free(&ref);
        sq_field_analysis_free(&moved);
        sq_field_analysis_free(&tilted);
    }
    return fails ? 1 : 0;
}
