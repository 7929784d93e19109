/* A degenerate zero of the guiding field split into elementary points
 * (degenerate_split.h): on the unit disc (u, v) ≈ z^4, one zero of index 4
 * at the centre.  The critical-point stage finds it (index 4, centred to
 * 1e-10, coefficient c = 1 to 1e-6); the default layout splits it into four
 * valence-3 points at half the distance to the boundary, symmetric under
 * rotations by 90° to 1e-9, traces the H/θ field of that pattern and gets
 * 5 quad patches, each split point a corner of 3 of them; the quad mesh of
 * that layout has no inverted quad; at P = 4, where the discretization
 * error splits the zero into four close roots, the same.  Synthetic zeros of index 2 and -2 on
 * the square split into two valence-3 / valence-5 points at half the
 * distance to the boundary, on rays that are directions of the cross of
 * the expansion there ((arg c + m φ)/4 = φ mod π/2); index 3 on the first
 * ray only (no placement of three points 120° apart does better). */
#include "degenerate_split.h"
#include "layout_pipeline.h"
#include "quad_mesher.h"
#include "test_util.h"

#include <complex.h>
#include <gsl/gsl_errno.h>

/* One synthetic zero of index m with expansion coefficient c at (0.5, 0.4)
 * of the unit square, split. */
static int synthetic(const cad_face *square, int m, double complex c)
{
    sq_critical_point p = {.x = 0.5, .y = 0.4, .index = m, .valence = 4 - m,
                           .dist_boundary = 0.4, .coef = {creal(c), cimag(c)}};
    sq_field_analysis a = {.npoints = 1, .points = &p};
    sq_singularity *s = NULL;
    int n = 0, nd = 0, fails = 0;
    sq_error err;
    char ctx[64];
    snprintf(ctx, sizeof ctx, "index %d, c = %g%+gi", m, creal(c), cimag(c));
    SQ_TEST_OK(sq_elementary_points(square, &a, &s, &n, &nd, &err), err);
    fails += sq_check_int(ctx, "zeros split", nd, 1);
    fails += sq_check_int(ctx, "points", n, abs(m));
    for (int k = 0; k < n; k++) {
        double dx = s[k].x - p.x, dy = s[k].y - p.y, phi = atan2(dy, dx);
        fails += sq_check_int(ctx, "valence", s[k].valence, m > 0 ? 3 : 5);
        /* closed forms of the given p and c (cos, sin, carg, cpow of numbers
         * <= 1): a few tens of U, here and for the angle below */
        fails += sq_check_abs(ctx, "radius", hypot(dx, dy), SQ_SPLIT_FRACTION * 0.4, 1e-12);
        double complex w = c * cpow(dx + I * dy, m > 0 ? m : 0) * cpow(dx - I * dy, m < 0 ? -m : 0);
        double off = 0.25 * carg(w) - phi; /* cross direction against the ray */
        /* every ray when (4 - m)/|m| is an integer, else the first */
        if (k == 0 || (4 - m) % abs(m) == 0)
            fails += sq_check_abs(ctx, "cross along the ray (mod pi/2)",
                                  off - M_PI_2 * round(off / M_PI_2), 0.0, 1e-12);
    }
    free(s);
    return fails;
}

int main(void)
{
    gsl_set_error_handler_off();
    char path[4096];
    sq_test_path(path, sizeof path, 0, "disc.step");
    cad_model *model = NULL;
    cad_face *f = NULL;
    sq_error err;
    SQ_TEST_OK(cad_model_read(path, &model, &err), err);
    SQ_TEST_OK(cad_face_create(model, 0, &f, &err), err);
    sq_layout_options lo;
    sq_layout_options_default(&lo);
    sq_layout_result r;
    SQ_TEST_OK(sq_layout_run(f, &lo, &r, &err), err);
    int fails = 0;
    const sq_field_analysis *a = &r.analysis;
    fails += sq_check_int("disc", "critical points", a->npoints, 1);
    if (a->npoints == 1) {
        const sq_critical_point *p = &a->points[0];
        fails += sq_check_int("disc", "index of the centre", p->index, 4);
        /* the centre is the circle-mode fit's (src/field/critical_points.c,
         * fit_degenerate: Vieta, stable under round-off), iterated to 1e-12
         * rho, on a mesh symmetric to round-off: the field's round-off over
         * |c| rho^3 (kappa (3n+1) U, t412): 1e-10; c itself is the fit's
         * mode, to the field's discretisation error: 1e-6 */
        fails += sq_check_abs("disc", "centre x", p->x, 0.0, 1e-10);
        fails += sq_check_abs("disc", "centre y", p->y, 0.0, 1e-10);
        fails += sq_check_abs("disc", "Re c", p->coef[0], 1.0, 1e-6);
        fails += sq_check_abs("disc", "Im c", p->coef[1], 0.0, 1e-6);
    }
    fails += sq_check_int("disc", "Poincare-Hopf lhs", a->ph_lhs, a->ph_rhs);
    fails += sq_check_int("disc", "degenerate points split", r.ndegenerate, 1);
    fails += sq_check_str("disc", "field traced", r.field.kind, "H-theta");
    fails += sq_check_int("disc", "singular points", r.nsing, 4);
    for (int k = 0; k < r.nsing; k++) {
        const sq_singularity *s = &r.sing[k];
        fails += sq_check_int("disc", "valence", s->valence, 3);
        fails += sq_check_int("disc", "origin", s->origin, SQ_ORIGIN_SPLIT);
        /* the split's radius from the centre (1e-10) and the distance to the
         * circle (cad_face's 1e-9 projection slack); the points turn with
         * the fitted phase of c (6e-10 rad between BLAS kernels), which the
         * rotation check does not see */
        fails += sq_check_abs("disc", "radius", hypot(s->x, s->y), SQ_SPLIT_FRACTION, 1e-9);
        /* its image under the rotation by 90 degrees is another split point */
        double best = HUGE_VAL;
        for (int j = 0; j < r.nsing; j++)
            best = fmin(best, hypot(r.sing[j].x + s->y, r.sing[j].y - s->x));
        fails += sq_check_abs("disc", "rotated point's distance to the pattern", best, 0.0, 1e-9);
    }
    sq_layout_defects d;
    fails += sq_check_int("disc", "layout defects", sq_layout_check(&r.layout, &d), 0);
    sq_layout_defects_free(&d);
    fails += sq_check_int("disc", "patches", r.layout.stats.patches, 5);
    fails += sq_check_int("disc", "quad patches", r.layout.stats.quad_patches, 5);
    double sum = 0.0;
    for (int p = 0; p < r.layout.npatches; p++)
        sum += r.layout.patches[p].area;
    /* patch areas by cad_split's adaptive Green rule: 1e-9 (t320) */
    fails += sq_check_rel("disc", "area sum", sum, M_PI, 1e-9);

    sq_mesher_options mo;
    sq_mesher_options_default(&mo);
    sq_quad_mesh *m = NULL;
    SQ_TEST_OK(sq_mesh_layout(f, r.info, &r.layout, &mo, &m, &err), err);
    sq_quad_quality q;
    SQ_TEST_OK(sq_quad_mesh_quality(m, NULL, NULL, 1, &q, &err), err);
    fails += sq_check_int("disc mesh", "irregular interior vertices", q.irregular_interior, 4);
    fails += sq_check_int("disc mesh", "inverted quads", q.inverted, 0);
    if (!(q.min_scaled_jacobian > 0.0)) {
        printf("disc mesh: min scaled Jacobian %g <= 0\n", q.min_scaled_jacobian);
        fails++;
    }
    sq_quad_mesh_free(&m);
    sq_layout_result_free(&r);
    cad_face_free(&f);
    cad_model_free(&model);

    /* P = 4: the discretization error splits the zero into four roots
     * 0.01 apart, one cluster, split again at the layout's scale */
    sq_test_path(path, sizeof path, 0, "disc.step");
    SQ_TEST_OK(cad_model_read(path, &model, &err), err);
    SQ_TEST_OK(cad_face_create(model, 0, &f, &err), err);
    lo.field.order = lo.field.tri.order = 4;
    SQ_TEST_OK(sq_layout_run(f, &lo, &r, &err), err);
    fails += sq_check_int("disc P=4", "critical points", r.analysis.npoints, 1);
    fails += sq_check_int("disc P=4", "split points", r.nsing, 4);
    fails += sq_check_int("disc P=4", "quad patches", r.layout.stats.quad_patches, 5);
    fails += sq_check_int("disc P=4", "patches", r.layout.stats.patches, 5);
    for (int k = 0; k < r.nsing; k++)
        fails += sq_check_abs("disc P=4", "radius", hypot(r.sing[k].x, r.sing[k].y), 0.5, 1e-3);
    sq_layout_result_free(&r);
    cad_face_free(&f);
    cad_model_free(&model);

    sq_test_path(path, sizeof path, 0, "square.step");
    SQ_TEST_OK(cad_model_read(path, &model, &err), err);
    SQ_TEST_OK(cad_face_create(model, 0, &f, &err), err);
    fails += synthetic(f, 2, 1.0);
    fails += synthetic(f, 2, I);
    fails += synthetic(f, -2, 1.0);
    fails += synthetic(f, -2, cexp(0.7 * I));
    fails += synthetic(f, 3, cexp(-1.1 * I));
    cad_face_free(&f);
    cad_model_free(&model);
    return fails ? 1 : 0;
}
