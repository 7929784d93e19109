/* The per-patch parametrization gradients ∇U = e^{−H}(cos θ, sin θ),
 * ∇V = e^{−H}(−sin θ, cos θ) (Jezdimirović 2021 eqs. 18–20) are curl-free
 * away from the singular points: the analytic curl from ∇H and ∇θ, and a
 * centred finite-difference circulation around small squares.  Checked on
 * the square with four valence-5 and four valence-3 points and on the
 * half disc with its natural pattern.  The curl is 0 for the exact fields:
 * what is left is the order-8 discretisation error of ∇H and ∇θ (1e-4 of
 * |∇U| / diameter away from the points), the differences' truncation
 * h^2 |∇^3 U| / 6 = 1e-8 relative and round-off |U| U / h (1e-12): 1e-4. */
#include "htheta_field.h"
#include "test_face.h"

#include <gsl/gsl_errno.h>

static int check(const char *file, const char *pattern)
{
    char path[4096];
    sq_error err;
    cad_model *m = NULL;
    cad_face *f = NULL;
    sq_test_path(path, sizeof path, 0, file);
    SQ_TEST_OK(cad_model_read(path, &m, &err), err);
    SQ_TEST_OK(cad_face_create(m, 0, &f, &err), err);
    sq_pattern p;
    if (pattern) {
        sq_test_path(path, sizeof path, 0, pattern);
        SQ_TEST_OK(sq_pattern_read(path, &p, &err), err);
    } else {
        sq_test_natural_pattern(f, &p);
    }
    sq_htheta_options o;
    sq_htheta_options_default(&o);
    sq_htheta ht;
    SQ_TEST_OK(sq_htheta_compute(f, &p, &o, &ht, &err), err);
    const double *bb = ht.info.bbox, diag = hypot(bb[2] - bb[0], bb[3] - bb[1]);
    double worst = 0.0, worst_fd = 0.0;
    int elem = -1, n = 0;
    for (int i = 1; i < 30; i++)
        for (int j = 1; j < 30; j++) {
            const double x[2] = {bb[0] + (bb[2] - bb[0]) * i / 30.0, bb[1] + (bb[3] - bb[1]) * j / 30.0};
            double dmin = HUGE_VAL, db;
            for (int k = 0; k < ht.npoints; k++)
                dmin = fmin(dmin, hypot(x[0] - ht.points[k].x, x[1] - ht.points[k].y));
            SQ_TEST_OK(sq_face_boundary_distance(f, x, &db, &err), err);
            if (dmin < 0.05 * diag || db < 0.02 * diag) continue;
            double gu[2], gv[2], curl[2];
            if (sq_htheta_param_gradients(&ht, x, &elem, gu, gv, curl)) continue;
            const double scale = hypot(gu[0], gu[1]) / diag;
            worst = fmax(worst, fmax(fabs(curl[0]), fabs(curl[1])) / scale);
            /* circulation of ∇U around a square of side 2h over its area,
             * with θ taken on the branch nearest the centre's (mod π/2 the
             * cross is what is known; a branch jump is a multiple of π/2) */
            const double h = 1e-4 * diag;
            double g[4][2], th0 = atan2(gu[1], gu[0]);
            const double off[4][2] = {{h, 0}, {0, h}, {-h, 0}, {0, -h}};
            int e2 = elem, bad = 0;
            for (int q = 0; q < 4; q++) {
                const double y[2] = {x[0] + off[q][0], x[1] + off[q][1]};
                double a[2], b[2];
                bad |= sq_htheta_param_gradients(&ht, y, &e2, a, b, NULL);
                const double th = atan2(a[1], a[0]), r = hypot(a[0], a[1]);
                const double t = th + M_PI_2 * round((th0 - th) / M_PI_2);
                g[q][0] = r * cos(t), g[q][1] = r * sin(t);
            }
            if (bad) continue;
            const double cfd = (g[0][1] - g[2][1]) / (2 * h) - (g[1][0] - g[3][0]) / (2 * h);
            worst_fd = fmax(worst_fd, fabs(cfd) / scale);
            n++;
        }
    int fails = 0;
    if (n < 200) {
        printf("%s: only %d sample points\n", file, n);
        fails++;
    }
    /* relative to |∇U| / diameter */
    fails += sq_check_abs(file, "curl of grad U (analytic)", worst, 0.0, 1e-4);
    fails += sq_check_abs(file, "curl of grad U (finite differences)", worst_fd, 0.0, 1e-4);
    sq_htheta_free(&ht);
    sq_pattern_free(&p);
    cad_face_free(&f);
    cad_model_free(&m);
    return fails;
}

int main(void)
{
    gsl_set_error_handler_off();
    int fails = check("square.step", "square_v5.txt");
    fails += check("half_disc.step", NULL);
    return fails != 0;
}
