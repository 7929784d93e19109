/* Square, no singular point: H constant, θ equal to the boundary angle
 * (0 mod π/2) everywhere, parametrization gradients of unit length.
 * These hold in floating point as well: the H data and the angles' offsets
 * from the edges' multiples of pi/2 are zero, so every solve sums zeros
 * (0 under every OpenBLAS kernel).  1e-10 leaves room for data carrying a
 * few U (edge angles through atan2) amplified by the solves' condition
 * numbers, 1e5 at most on these ~1e3-unknown systems: 1e5 * few U. */
#include "htheta_field.h"
#include "test_face.h"

#include <gsl/gsl_errno.h>

int main(void)
{
    gsl_set_error_handler_off();
    sq_error err;
    cad_model *m = NULL;
    cad_face *f = NULL;
    sq_test_open_face("square.step", &m, &f);
    sq_pattern p;
    SQ_TEST_OK(sq_pattern_parse("# nothing\n", "empty", &p, &err), err);
    sq_htheta_options o;
    sq_htheta_options_default(&o);
    sq_htheta ht;
    SQ_TEST_OK(sq_htheta_compute(f, &p, &o, &ht, &err), err);
    int fails = 0, elem = -1;
    double hmin = HUGE_VAL, hmax = -HUGE_VAL, tworst = 0.0, gworst = 0.0;
    for (int i = 0; i <= 20; i++)
        for (int j = 0; j <= 20; j++) {
            const double x[2] = {0.001 + 0.998 * i / 20.0, 0.001 + 0.998 * j / 20.0};
            double H, th, gu[2], gv[2];
            if (sq_htheta_eval(&ht, x, &elem, &H, NULL, &th, NULL)) {
                printf("(%g, %g) not found\n", x[0], x[1]);
                return 1;
            }
            hmin = fmin(hmin, H);
            hmax = fmax(hmax, H);
            tworst = fmax(tworst, fabs(th - M_PI_2 * round(th / M_PI_2)));
            sq_htheta_param_gradients(&ht, x, &elem, gu, gv, NULL);
            gworst = fmax(gworst, fabs(hypot(gu[0], gu[1]) - 1.0));
        }
    fails += sq_check_abs("square", "H variation", hmax - hmin, 0.0, 1e-10);
    fails += sq_check_abs("square", "H (zero mean)", hmax, 0.0, 1e-10);
    fails += sq_check_abs("square", "theta mod pi/2", tworst, 0.0, 1e-10);
    fails += sq_check_abs("square", "|grad U| - 1", gworst, 0.0, 1e-10);
    fails += sq_check_int("square", "branch cut edges", ht.theta.cut.nedges, 0);
    fails += sq_check_int("square", "aligned", ht.loops[0].aligned, 1);
    sq_cross_field cf = sq_htheta_cross_field(&ht);
    double th, xc[2] = {0.3, 0.6};
    elem = -1;
    fails += sq_check_int("square", "cross field inside", cf.direction(cf.ctx, xc, &elem, &th), 0);
    fails += sq_check_abs("square", "cross field size e^H", cf.size(cf.ctx, xc, &elem), 1.0, 1e-10);
    sq_htheta_free(&ht);
    sq_pattern_free(&p);
    cad_face_free(&f);
    cad_model_free(&m);
    return fails != 0;
}
