/* Holonomy (Jezdimirović 2021 §5.2.3) on square_hole.step: the natural
 * pattern (four valence-5 points on the diagonals) is tangent to the hole;
 * the same points turned by 20° about the centre are not, and the check
 * names loop 1.  The jump of θ around the hole is its turning (2π here)
 * plus a multiple of π/2, as Gauss–Bonnet makes it. */
#include "htheta_field.h"
#include "test_face.h"

#include <gsl/gsl_errno.h>

int main(void)
{
    gsl_set_error_handler_off();
    char path[4096];
    sq_error err;
    cad_model *m = NULL;
    cad_face *f = NULL;
    sq_test_open_face("square_hole.step", &m, &f);
    int fails = 0;
    sq_htheta_options o;
    sq_htheta_options_default(&o);
    sq_htheta ht;
    sq_pattern p;

    /* natural */
    sq_test_natural_pattern(f, &p);
    fails += sq_check_int("natural", "points", p.npoints, 4);
    SQ_TEST_OK(sq_htheta_compute(f, &p, &o, &ht, &err), err);
    fails += sq_check_int("natural", "loops", ht.nloops, 2);
    fails += sq_check_int("natural", "hole aligned", ht.loops[1].aligned, 1);
    fails += sq_check_abs("natural", "hole misalignment (deg)", ht.loops[1].misalignment * 180 / M_PI,
                          0.0, 1e-3);
    /* misalignment: the natural field follows the hole to its
     * discretisation error (1e-3 deg); the jump sums θ differences around
     * the hole, the solve's round-off kappa (3n+1) U |θ| (t412) over the
     * hole's ~1e2 edges: 1e-7; the turning is the curvature integral by
     * GSL's QAG to 1e-13 relative: 1e-9 */
    fails += sq_check_abs("natural", "jump around the hole", ht.loops[1].jump, 2.0 * M_PI, 1e-7);
    fails += sq_check_abs("natural", "hole turning", ht.loops[1].turning, 2.0 * M_PI, 1e-9);
    fails += sq_check_int("natural", "alignment gate", sq_htheta_check_alignment(&ht, 0, &err), SQ_OK);
    sq_htheta_free(&ht);
    sq_pattern_free(&p);

    /* turned by 20° */
    sq_test_path(path, sizeof path, 0, "square_hole_twisted.txt");
    SQ_TEST_OK(sq_pattern_read(path, &p, &err), err);
    SQ_TEST_OK(sq_htheta_compute(f, &p, &o, &ht, &err), err);
    fails += sq_check_int("twisted", "outer aligned", ht.loops[0].aligned, 1);
    fails += sq_check_int("twisted", "hole aligned", ht.loops[1].aligned, 0);
    fails += sq_check_abs("twisted", "hole misalignment (deg)", ht.loops[1].misalignment * 180 / M_PI,
                          -19.14, 0.05);
    /* the misalignment is the same all along the hole (a rigid turn) */
    fails += sq_check_abs("twisted", "spread along the hole (deg)", ht.loops[1].spread * 180 / M_PI,
                          0.0, 1e-3);
    fails += sq_check_abs("twisted", "(jump - turning)/(pi/2)",
                          (ht.loops[1].jump - ht.loops[1].turning) / M_PI_2, 0.0, 1e-7);
    sq_error_clear(&err);
    fails += sq_check_int("twisted", "alignment gate", sq_htheta_check_alignment(&ht, 0, &err),
                          SQ_ERR_PATTERN);
    if (!strstr(err.msg, "boundary loop 1") || !strstr(err.msg, "-19.1")) {
        printf("twisted: message '%s' does not name loop 1 and the angle\n", err.msg);
        fails++;
    }
    fails += sq_check_int("twisted", "gate with --allow-misaligned",
                          sq_htheta_check_alignment(&ht, 1, &err), SQ_OK);
    sq_htheta_free(&ht);
    sq_pattern_free(&p);
    cad_face_free(&f);
    cad_model_free(&m);
    return fails != 0;
}
