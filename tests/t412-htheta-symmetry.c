/* Symmetric patterns give symmetric fields: the equilateral triangle with
 * its natural pattern (one valence-3 point at the centroid, from the
 * guiding field) under rotations by 120°, and the unit disc with four
 * valence-3 points on the axes under rotations by 90°: H is invariant and
 * θ turns with the rotation, modulo π/2.
 * Tolerances: CGAL's triangulations are symmetric only up to the vertices'
 * round-off (the triangle) or not at all (the disc), so the fields are
 * symmetric to the H/θ solve's discretisation error at order 8 (1e-8 on
 * the triangle, 1e-11 on the disc measured, any kernel): 1e-6, the points'
 * own accuracy (t401).  The triangle's centroid is a simple zero on a
 * mesh symmetric to round-off: off by the field's round-off over its
 * gradient, kappa (3n+1) U (t201) with kappa ~ 1e4, n ~ 1e3 (3e-9; 3e-11
 * measured): 1e-8.  The jump is a sum of θ differences around the point,
 * each with the same solve's round-off times |θ| <= 2 pi: 1e-8. */
#include "htheta_field.h"
#include "test_face.h"

#include <gsl/gsl_errno.h>

static double wrap4(double d) { return d - M_PI_2 * round(d / M_PI_2); }

/* worst |H(Rp) − H(p)| and |θ(Rp) − θ(p) − angle| (mod π/2) over points
 * p = c + ρ(cos φ, sin φ) */
static void symmetry(const sq_htheta *ht, const double c[2], double angle, double rmax,
                     double *eh, double *et)
{
    *eh = *et = 0.0;
    int e1 = -1, e2 = -1;
    for (int i = 1; i <= 8; i++)
        for (int k = 0; k < 24; k++) {
            const double rho = rmax * i / 8.0, phi = 2.0 * M_PI * k / 24.0 + 0.1;
            const double p[2] = {c[0] + rho * cos(phi), c[1] + rho * sin(phi)};
            const double q[2] = {c[0] + rho * cos(phi + angle), c[1] + rho * sin(phi + angle)};
            double h1, h2, t1, t2;
            if (sq_htheta_eval(ht, p, &e1, &h1, NULL, &t1, NULL) ||
                sq_htheta_eval(ht, q, &e2, &h2, NULL, &t2, NULL))
                continue;
            *eh = fmax(*eh, fabs(h2 - h1));
            *et = fmax(*et, fabs(wrap4(t2 - t1 - angle)));
        }
}

int main(void)
{
    gsl_set_error_handler_off();
    sq_error err;
    cad_model *m = NULL;
    cad_face *f = NULL;
    int fails = 0;
    double eh, et;

    /* triangle, natural pattern */
    sq_test_open_face("triangle.step", &m, &f);
    sq_pattern p;
    sq_test_natural_pattern(f, &p);
    const double c[2] = {0.5, sqrt(3.0) / 6.0};
    fails += sq_check_int("triangle", "natural points", p.npoints, 1);
    if (p.npoints == 1) {
        fails += sq_check_int("triangle", "valence", p.points[0].valence, 3);
        fails += sq_check_abs("triangle", "distance to the centroid",
                              hypot(p.points[0].x - c[0], p.points[0].y - c[1]), 0.0, 1e-8);
        fails += sq_check_int("triangle", "origin", p.points[0].origin, SQ_ORIGIN_CRITICAL);
        /* exactly at the centroid for the symmetry check */
        p.points[0].x = c[0];
        p.points[0].y = c[1];
    }
    sq_htheta_options o;
    sq_htheta_options_default(&o);
    sq_htheta ht;
    SQ_TEST_OK(sq_htheta_compute(f, &p, &o, &ht, &err), err);
    symmetry(&ht, c, 2.0 * M_PI / 3.0, 0.25, &eh, &et);
    fails += sq_check_abs("triangle", "H(R p) - H(p), R = 120 deg", eh, 0.0, 1e-6);
    fails += sq_check_abs("triangle", "theta(R p) - theta(p) - 120 deg mod 90", et, 0.0, 1e-6);
    fails += sq_check_abs("triangle", "jump at the centroid", ht.points[0].jump, M_PI_2, 1e-8);
    fails += sq_check_int("triangle", "aligned", ht.loops[0].aligned, 1);
    sq_htheta_free(&ht);
    sq_pattern_free(&p);
    cad_face_free(&f);
    cad_model_free(&m);

    /* disc, four valence-3 points */
    sq_test_open_face("disc.step", &m, &f);
    SQ_TEST_OK(sq_pattern_parse("0.5 0 3\n0 0.5 3\n-0.5 0 3\n0 -0.5 3\n", "disc", &p, &err), err);
    SQ_TEST_OK(sq_htheta_compute(f, &p, &o, &ht, &err), err);
    const double o0[2] = {0.0, 0.0};
    symmetry(&ht, o0, M_PI_2, 0.9, &eh, &et);
    fails += sq_check_abs("disc", "H(R p) - H(p), R = 90 deg", eh, 0.0, 1e-6);
    fails += sq_check_abs("disc", "theta(R p) - theta(p) mod 90", et, 0.0, 1e-6);
    /* not symmetric under the 45° rotation: the points matter */
    symmetry(&ht, o0, M_PI_4, 0.9, &eh, &et);
    if (!(eh > 0.1)) {
        printf("disc: H looks 8-fold symmetric (%g)\n", eh);
        fails++;
    }
    sq_htheta_free(&ht);
    sq_pattern_free(&p);
    cad_face_free(&f);
    cad_model_free(&m);
    return fails != 0;
}
