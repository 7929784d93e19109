/* θ is H's harmonic conjugate, solved with H's factor (theta_field.h): on
 * the annulus 0.4 < ρ < 1 (examples/annulus.step) without singular points
 * the exact fields are H = ln ρ − mean and θ = φ + π/2 (the tangent angle
 * of the outer circle at the anchor), ∇θ = n × ∇H = (−y, x)/ρ².  θ_r has
 * the period 2π round the hole, carried by the hole's arg term, and the
 * remainder θ_r' = φ − arg(x − p) (p the term's centre, within the
 * lattice's 1e-3 of the hole's centre) is single-valued and smooth.
 *
 * Tolerances: ∇θ_h is the L² projection of n × ∇H_h − ∇(arg term) onto the
 * gradients of H's space, plus the arg term's exact gradient, so
 * ‖∇θ_h − ∇θ‖ ≤ ‖∇H_h − ∇H‖ + ‖(I − Π)∇θ_r'‖: H's own discretization
 * error plus the approximation error of the remainder, |p|/ρ ≈ 2e-3 of
 * ln ρ's variation and no less smooth; the norms are RMS over a lattice
 * of about 2400 points in the face (standing for the L² norms): bound
 * 2 ‖∇H_h − ∇H‖ + 1e-12.  The period is the arg term's, the flux of H's
 * data through the hole (∮ κ = 2π on the order-8 geometry: 1e-10).
 * Cauchy–Riemann residual |∇θ_h − n × ∇H_h| ≤ both errors pointwise: its
 * RMS under the sum of the two RMS errors.  One factorization in all.
 *
 * On square_hole.step with its natural pattern (four valence-5 points and
 * a hole) the jumps of θ across the cut are the arg terms' (θ_r' is
 * continuous): −π/2 around each point to round-off — θ on either side of
 * a cut edge is evaluated at its midpoint as placed by two elements' maps,
 * equal to 1e-16, where the spoke grading puts the midpoints about 1e-4
 * from the point and θ_s changes by 1/(4r) ≈ 3e3 per unit length: 1e-12
 * per edge, bound 1e-10 — and around the hole its period from H's data,
 * which Gauss–Bonnet makes the expected −(∮ κ_g + Σ s_i) = 2π to the
 * data's quadrature (1e-10). */
#include "htheta_field.h"
#include "test_face.h"

#include <gsl/gsl_errno.h>

static int square_hole(void)
{
    cad_model *m = NULL;
    cad_face *f = NULL;
    sq_pattern p;
    sq_htheta ht;
    sq_test_natural_htheta("square_hole.step", &m, &f, &p, &ht);
    int fails = sq_check_int("square_hole", "points", ht.npoints, 4);
    for (int j = 0; j < ht.npoints; j++)
        fails += sq_check_abs("square_hole", "jump around a valence-5 point", ht.points[j].jump,
                              -M_PI_2, 1e-10);
    fails += sq_check_abs("square_hole", "jump around the hole", ht.loops[1].jump,
                          ht.loops[1].expected_jump, 1e-10);
    fails += sq_check_abs("square_hole", "expected jump", ht.loops[1].expected_jump, 2.0 * M_PI,
                          1e-10);
    sq_htheta_free(&ht);
    sq_pattern_free(&p);
    cad_face_free(&f);
    cad_model_free(&m);
    return fails;
}

int main(void)
{
    gsl_set_error_handler_off();
    sq_error err;
    cad_model *m = NULL;
    cad_face *f = NULL;
    sq_test_open_face("annulus.step", &m, &f);
    sq_pattern p;
    memset(&p, 0, sizeof p);
    sq_htheta_options o;
    sq_htheta_options_default(&o);
    sq_htheta ht;
    SQ_TEST_OK(sq_htheta_compute(f, &p, &o, &ht, &err), err);
    int fails = sq_check_int("annulus", "factorizations", ht.work.factorizations, 1);
    fails += sq_check_int("annulus", "loops", ht.nloops, 2);
    fails += sq_check_abs("annulus", "jump around the hole", ht.loops[1].jump, 2.0 * M_PI, 1e-10);
    /* mean of ln ρ over the annulus: (ρ² ln ρ − ρ²/2)/(1 − a²) from a to 1, a = 0.4 */
    const double a = 0.4;
    const double mean = (-0.5 - (a * a * log(a) - 0.5 * a * a)) / (1.0 - a * a);
    double eh = 0.0, et = 0.0, ecr = 0.0, ev = 0.0, dth = 0.0;
    int n = 0, elem = -1;
    for (int i = 0; i < 60; i++)
        for (int j = 0; j < 60; j++) {
            const double x[2] = {-1.0 + (i + 0.5) / 30.0, -1.0 + (j + 0.5) / 30.0};
            const double r2 = x[0] * x[0] + x[1] * x[1];
            if (r2 <= a * a || r2 >= 1.0) continue;
            double H, gH[2], th, gt[2];
            if (sq_htheta_eval(&ht, x, &elem, &H, gH, &th, gt)) continue;
            n++;
            const double dx = gH[0] - x[0] / r2, dy = gH[1] - x[1] / r2;
            eh += dx * dx + dy * dy;
            const double tx = gt[0] + x[1] / r2, ty = gt[1] - x[0] / r2;
            et += tx * tx + ty * ty;
            const double cx = gt[0] + gH[1], cy = gt[1] - gH[0];
            ecr += cx * cx + cy * cy;
            ev = fmax(ev, fabs(H - (0.5 * log(r2) - mean)));
            const double d = th - (atan2(x[1], x[0]) + M_PI_2);
            dth = fmax(dth, fabs(d - 2.0 * M_PI * round(d / (2.0 * M_PI))));
        }
    eh = sqrt(eh / n), et = sqrt(et / n), ecr = sqrt(ecr / n);
    printf("annulus: %d points, RMS |grad H err| %.3g, |grad theta err| %.3g, CR residual %.3g, "
           "max |H err| %.3g, max |theta err| %.3g\n",
           n, eh, et, ecr, ev, dth);
    fails += sq_check_int("annulus", "lattice points in the face", n > 1500, 1);
    fails += sq_check_abs("annulus", "RMS grad theta error", et, 0.0, 2.0 * eh + 1e-12);
    fails += sq_check_abs("annulus", "RMS Cauchy-Riemann residual", ecr, 0.0, et + eh + 1e-12);
    /* θ's value: its gradient's error integrated over the annulus' radius
     * from the anchor, ~ RMS error x diameter, 10x for the pointwise max */
    fails += sq_check_abs("annulus", "max theta error", dth, 0.0, 20.0 * (2.0 * eh + 1e-12));
    sq_htheta_free(&ht);
    cad_face_free(&f);
    cad_model_free(&m);
    fails += square_hole();
    if (fails) printf("t711: %d failure(s)\n", fails);
    return fails ? 1 : 0;
}
