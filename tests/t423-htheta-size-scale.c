/* The H/θ field's sizes are scaled to the face (htheta_field.h,
 * sq_htheta_cross_field): the mean of size^-2 over the face is 1, so that
 * about area / size^2 quads result.  On the disc (examples/disc.step, its
 * natural pattern: four valence-3 points) H is far from constant: the
 * bounded e^H spans more than a factor 4 between the points and the
 * boundary, so a wrong scale is a large error.
 *
 * The mean is measured independently of the field's own rule: a polar
 * product rule (Gauss–Legendre in r with weight r, uniform in angle) at
 * two resolutions.  The bound leaves kinks in the integrand, so neither
 * rule converges fast: the field's rule of degree 3 is 0.2 % from the
 * converged value on this face (rules of degree 12 and 20 agree to 1e-4),
 * and the polar rule's own error is estimated by the difference of its
 * two resolutions.  Hence |mean - 1| <= 3e-3 + 2 |difference|. */
#include "test_face.h"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>

/* The mean of size^-2 over the unit disc by the polar rule of nr x nt
 * points; *outside counts points where the field has no size. */
static double polar_mean(const sq_cross_field *cf, int nr, int nt, int *outside)
{
    gsl_integration_glfixed_table *t = gsl_integration_glfixed_table_alloc((size_t)nr);
    double sum = 0.0, area = 0.0;
    int elem = -1;
    for (int i = 0; i < nr; i++) {
        double r, w;
        gsl_integration_glfixed_point(0.0, 1.0, (size_t)i, &r, &w, t);
        for (int j = 0; j < nt; j++) {
            const double a = 2.0 * M_PI * (j + 0.5) / nt;
            const double x[2] = {r * cos(a), r * sin(a)};
            const double s = cf->size(cf->ctx, x, &elem);
            if (!(s > 0.0)) {
                (*outside)++;
                continue;
            }
            sum += w * r / (s * s);
            area += w * r;
        }
    }
    gsl_integration_glfixed_table_free(t);
    return sum / area;
}

int main(void)
{
    gsl_set_error_handler_off();
    cad_model *m = NULL;
    cad_face *f = NULL;
    sq_pattern p;
    sq_htheta ht;
    sq_test_natural_htheta("disc.step", &m, &f, &p, &ht);
    sq_cross_field cf = sq_htheta_cross_field(&ht);
    int fails = sq_check_int("disc", "points", ht.npoints, 4), outside = 0;
    /* the sizes vary: the scale matters (bounded e^H from 1/4 up) */
    double lo = HUGE_VAL, hi = 0.0;
    for (int k = 0; k <= 10; k++) {
        const double x[2] = {0.1 * k * cos(0.3), 0.1 * k * sin(0.3) - (k == 10 ? 1e-3 : 0.0)};
        int elem = -1;
        const double s = cf.size(cf.ctx, x, &elem);
        lo = fmin(lo, s);
        hi = fmax(hi, s);
    }
    printf("disc: sizes along a radius from %.4f to %.4f\n", lo, hi);
    fails += sq_check_int("disc", "sizes along a radius vary by over 1.5", hi / lo > 1.5, 1);
    const double m1 = polar_mean(&cf, 48, 192, &outside);
    const double m2 = polar_mean(&cf, 96, 384, &outside);
    const double tol = 3e-3 + 2.0 * fabs(m2 - m1);
    fails += sq_check_int("disc", "polar points outside the field", outside, 0);
    fails += sq_check_abs("disc", "mean of size^-2 over the face", m2, 1.0, tol);
    printf("disc: scale %.6f, mean of size^-2 %.6f (coarser rule %.6f), tolerance %.2e\n",
           ht.size_scale, m2, m1, tol);
    sq_htheta_free(&ht);
    sq_pattern_free(&p);
    cad_face_free(&f);
    cad_model_free(&m);
    return fails != 0;
}
