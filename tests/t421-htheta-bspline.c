/* The H field on faces with B-spline edges (tests/cascade_aerofoil.py: the
 * cascade passage's blade and the aerofoil box's NACA 4412, cubic B-splines
 * interpolating 121 points, whose curvature varies within one element of
 * the field's triangulation at the round ends): the curvature data's
 * integral is the exact total turning of every boundary (Gauss–Bonnet), so
 * the pure-Neumann data balance and the H field of a Gauss–Bonnet-minimal
 * pattern is solved, at the default order P = 8 and at P = 4, whose
 * coarser rules resolve κ on fewer element edges.  Pointwise κ missed the
 * turning by up to 1e-3 of the data (NekMesh's T106 at P = 8: "H field of
 * this pattern cannot be solved"; here at P = 4 the aerofoil box the same
 * way, the cascade by 1.2e-5 of its data, both by 1-2e-6 at P = 8).
 * argv: cascade.step aerofoil_box.step.
 *
 * Tolerance of the imbalance (∮ κ + ∮ ∂H_s/∂ν + Σ s_i before its
 * correction, which Gauss–Bonnet makes 0): the spans where the rule does
 * not resolve κ add their exact turning, to round-off; those where it does
 * add at most KAPPA_RESOLVED = 1e-6 of their ∫|κ| (h_field.c), the log
 * terms of points far from the boundary next to nothing: 1e-6 of the data
 * size, below which pointwise κ was not on these faces. */
#include "htheta_field.h"
#include "test_util.h"

#include <gsl/gsl_errno.h>

/* The natural pattern of each face (its guiding field's points, the
 * cascade's close valence-3/valence-5 pair left out): as many points as the
 * corners and χ require, gauss_bonnet_min. */
static const char *patterns[] = {
    "0.931738 -0.383094 5\n0.922501 -0.388221 5\n0.042188 -0.167666 5\n-0.029105 0.016086 5\n",
    "-0.003041 -0.003320 5\n-0.007112 0.006698 5\n"};

int main(int argc, char **argv)
{
    gsl_set_error_handler_off();
    if (argc != 3) {
        fprintf(stderr, "usage: t421-htheta-bspline cascade.step aerofoil_box.step\n");
        return 2;
    }
    int fails = 0;
    for (int c = 0; c < 4; c++) {
        sq_error err;
        cad_model *m = NULL;
        cad_face *f = NULL;
        SQ_TEST_OK(cad_model_read(argv[1 + c % 2], &m, &err), err);
        SQ_TEST_OK(cad_face_create(m, 0, &f, &err), err);
        sq_pattern p;
        SQ_TEST_OK(sq_pattern_parse(patterns[c % 2], argv[1 + c % 2], &p, &err), err);
        sq_htheta_options o;
        sq_htheta_options_default(&o);
        o.order = c < 2 ? 8 : 4;
        sq_htheta ht;
        SQ_TEST_OK(sq_htheta_compute(f, &p, &o, &ht, &err), err);
        char what[64];
        snprintf(what, sizeof what, "P = %d: H data imbalance / data size", o.order);
        fails += sq_check_abs(argv[1 + c % 2], what,
                              ht.h.imbalance / ht.h.data_size, 0.0, 1e-6);
        sq_htheta_free(&ht);
        sq_pattern_free(&p);
        cad_face_free(&f);
        cad_model_free(&m);
    }
    return fails != 0;
}
