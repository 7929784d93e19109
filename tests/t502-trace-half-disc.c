/* Separatrices of the half disc at P = 8 (Marcon 2019 Fig. 8, §3.3): two
 * valence-3 points, 6 separatrices traced, the two running towards each
 * other meet and merge, 5 remain; every end exactly on its CAD curve or at
 * a singular point; the start angles are fixed points of Algorithm 1, the
 * merged separatrix keeps both, and the picture is mirror-symmetric. */
#include "t50x_trace.h"

#define HALF_PI 1.57079632679489661923

static double mod2pi(double a)
{
    return a - 2.0 * M_PI * floor(a / (2.0 * M_PI));
}

int main(void)
{
    gsl_set_error_handler_off();
    int fails = 0;
    sq_error err;
    t5_case c;
    t5_open(&c, "half_disc.step", 8);
    const char *ctx = "half_disc P=8";
    fails += sq_check_int(ctx, "singular points", c.a.npoints, 2);
    sq_trace_options opt;
    sq_trace_options_default(&opt);
    sq_separatrix_set set;
    sq_trace_stats st;
    SQ_TEST_OK(sq_trace_separatrices_stats(&c.cf, c.face, &c.a.info, c.quads, c.a.npoints, c.sing,
                                           &opt, &set, &st, &err),
               err);
    fails += sq_check_int(ctx, "separatrices traced", st.traced, 6);
    fails += sq_check_int(ctx, "pairs merged", st.merges, 1);
    fails += sq_check_int(ctx, "separatrices after merging", set.n, 5);
    double perim = 2.0 + M_PI;
    fails += t5_check_ends(ctx, &c, &set, 4.0 * perim);

    /* start angles at each singular point, the merged one's end included */
    double ang[2][3];
    int na[2] = {0, 0}, nmerged = 0;
    for (int k = 0; k < set.n; k++) {
        const sq_separatrix *s = &set.s[k];
        fails += sq_check_int(ctx, "start kind (singular)", s->start.kind, SQ_END_SINGULAR);
        int j = s->start.id;
        if (na[j] < 3) ang[j][na[j]] = mod2pi(s->start_angle);
        na[j]++;
        /* the first segment leaves along the start angle */
        double d = atan2(s->xy[3] - s->xy[1], s->xy[2] - s->xy[0]) - s->start_angle;
        d = fabs(d - 2 * M_PI * nearbyint(d / (2 * M_PI)));
        fails += sq_check_abs(ctx, "first segment direction - start angle", d, 0.0, 1e-3);
        if (s->merged) {
            nmerged++;
            fails += sq_check_int(ctx, "merged: end kind (singular)", s->end.kind, SQ_END_SINGULAR);
            fails += sq_check_int(ctx, "merged: ends at the other point", s->end.id, 1 - j);
            int o = s->end.id;
            if (na[o] < 3) ang[o][na[o]] = mod2pi(s->end_angle - M_PI);
            na[o]++;
            /* and arrives along the other point's start angle */
            int n = s->npts;
            double e = atan2(s->xy[2 * n - 1] - s->xy[2 * n - 3], s->xy[2 * n - 2] - s->xy[2 * n - 4]) - s->end_angle;
            e = fabs(e - 2 * M_PI * nearbyint(e / (2 * M_PI)));
            fails += sq_check_abs(ctx, "merged: last segment direction - end angle", e, 0.0, 1e-3);
        }
    }
    fails += sq_check_int(ctx, "merged separatrices", nmerged, 1);
    fails += sq_check_int(ctx, "directions at point 0", na[0], 3);
    fails += sq_check_int(ctx, "directions at point 1", na[1], 3);
    if (na[0] != 3 || na[1] != 3) return 1;
    for (int j = 0; j < 2; j++) {
        /* each is a fixed point of Algorithm 1 at the radius the tracer used */
        double p0[2] = {c.sing[j].x, c.sing[j].y}, th;
        int elem = -1;
        c.cf.direction(c.cf.ctx, p0, &elem, &th);
        double rad = opt.step_rel * c.cf.element_size(c.cf.ctx, elem);
        for (int q = 0; q < 3; q++) {
            double p1[2] = {p0[0] + rad * cos(ang[j][q]), p0[1] + rad * sin(ang[j][q])};
            int e2 = elem;
            SQ_TEST_OK(c.cf.direction(c.cf.ctx, p1, &e2, &th) ? SQ_ERR_INTERNAL : SQ_OK, err);
            double m = th - ang[j][q];
            m -= HALF_PI * nearbyint(m / HALF_PI);
            fails += sq_check_abs(ctx, "Algorithm 1 residual of a start angle", m, 0.0, 1e-8);
        }
        /* 3 directions, sorted: gaps near 120 degrees (the field is not
         * conformal at the points: 110-127 degrees, not exactly 120) */
        for (int a = 0; a < 3; a++)
            for (int b = a + 1; b < 3; b++)
                if (ang[j][b] < ang[j][a]) {
                    double t = ang[j][a];
                    ang[j][a] = ang[j][b];
                    ang[j][b] = t;
                }
        for (int q = 0; q < 3; q++) {
            double gap = q < 2 ? ang[j][q + 1] - ang[j][q] : ang[j][0] + 2 * M_PI - ang[j][2];
            fails += sq_check_abs(ctx, "gap between start directions (deg)", gap * 180 / M_PI, 120.0, 15.0);
        }
    }
    /* mirror symmetry about x = 0: the point at x < 0 has the angles
     * π - those at x > 0 (to the field's symmetry, 1e-6 in the points'
     * positions, over Algorithm 1's radius) */
    int r = c.sing[0].x > 0 ? 0 : 1, l = 1 - r;
    for (int q = 0; q < 3; q++) {
        double best = HUGE_VAL;
        for (int t = 0; t < 3; t++) {
            double d = mod2pi(M_PI - ang[r][q] - ang[l][t]);
            best = fmin(best, fmin(d, 2 * M_PI - d));
        }
        fails += sq_check_abs(ctx, "mirror symmetry of start angles (rad)", best, 0.0, 1e-3);
    }
    /* the separatrix towards the arc ends on the bisector: radial by symmetry */
    for (int k = 0; k < set.n; k++) {
        const sq_separatrix *s = &set.s[k];
        const double *p = &s->xy[2 * (s->npts - 1)];
        if (s->end.kind == SQ_END_BOUNDARY && p[1] > 0.5)
            fails += sq_check_abs(ctx, "arc end |x| - |y|", fabs(p[0]) - fabs(p[1]), 0.0, 1e-5);
    }
    sq_separatrix_set_free(&set);
    t5_close(&c);
    return fails != 0;
}
