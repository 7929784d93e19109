/* sq_trace_continue (layout repairs): a separatrix cut short and continued
 * along the field ends where the full one did; a line continued into
 * another separatrix ends on it (SQ_END_SEPARATRIX, on its polyline). */
#include "t50x_trace.h"

int main(void)
{
    gsl_set_error_handler_off();
    int fails = 0;
    sq_error err;
    t5_case c;
    t5_open(&c, "half_disc.step", 8);
    sq_trace_options opt;
    sq_trace_options_default(&opt);
    sq_separatrix_set set;
    SQ_TEST_OK(sq_trace_separatrices(&c.cf, c.face, &c.a.info, c.quads, c.a.npoints, c.sing, &opt, &set, &err), err);
    for (int k = 0; k < set.n; k++) {
        sq_separatrix *s = &set.s[k];
        if (s->merged || s->end.kind != SQ_END_BOUNDARY) continue;
        double end[2] = {s->xy[2 * s->npts - 2], s->xy[2 * s->npts - 1]};
        sq_sep_end e0 = s->end;
        s->npts = s->npts / 2 + 1;
        s->end.kind = SQ_END_OPEN;
        SQ_TEST_OK(sq_trace_continue(&c.cf, c.face, &c.a.info, c.a.npoints, c.sing, &opt, &set, k, &err), err);
        const double *p = &s->xy[2 * s->npts - 2];
        fails += sq_check_int("continue", "end kind", s->end.kind, e0.kind);
        fails += sq_check_int("continue", "end edge", s->end.id, e0.id);
        /* the same AB4 path from a point of it: the steps differ, so the
         * ends differ by AB4's error, below its 1e-9 tolerance per unit
         * length (src/trace_ab4.c) over lengths <= 2 */
        fails += sq_check_abs("continue", "end moved by", hypot(p[0] - end[0], p[1] - end[1]), 0.0, 1e-8);
    }
    sq_separatrix_set_free(&set);
    /* obstacle: a segment y = 0.25 across the face; a line going up the
     * symmetry axis x = 0 (the field is axis-aligned there) ends on it */
    sq_separatrix o = {0}, l = {0};
    o.npts = 2;
    o.xy = malloc(4 * sizeof *o.xy);
    o.xy[0] = -0.9, o.xy[1] = 0.25, o.xy[2] = 0.9, o.xy[3] = 0.25;
    l.npts = 2;
    l.xy = malloc(4 * sizeof *l.xy);
    l.xy[0] = 0.0, l.xy[1] = 0.02, l.xy[2] = 0.0, l.xy[3] = 0.05;
    l.start_angle = M_PI / 2;
    SQ_TEST_OK(sq_separatrix_set_append(&set, &o, &err), err);
    SQ_TEST_OK(sq_separatrix_set_append(&set, &l, &err), err);
    SQ_TEST_OK(sq_trace_continue(&c.cf, c.face, &c.a.info, c.a.npoints, c.sing, &opt, &set, 1, &err), err);
    const sq_separatrix *s1 = &set.s[1];
    const double *p = &s1->xy[2 * s1->npts - 2];
    fails += sq_check_int("continue to an obstacle", "end kind", s1->end.kind, SQ_END_SEPARATRIX);
    fails += sq_check_int("continue to an obstacle", "end id", s1->end.id, 0);
    /* y: the intersection with the horizontal segment y = 0.25, a few U;
     * x and s: the field's axis alignment to its discretisation error */
    fails += sq_check_abs("continue to an obstacle", "end y", p[1], 0.25, 1e-15);
    fails += sq_check_abs("continue to an obstacle", "end x", p[0], 0.0, 1e-6);
    fails += sq_check_abs("continue to an obstacle", "arc length along the obstacle", s1->end.s, 0.9, 1e-6);
    sq_separatrix_set_free(&set);
    t5_close(&c);
    return fails != 0;
}
