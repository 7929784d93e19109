/* Separatrices from face vertices taking n >= 2 quads (Marcon 2019 §3.3,
 * Algorithm 1 at boundary vertices): n - 1 rays into the face, between the
 * outgoing and the incoming edge.  lshape's 270-degree corner (1, 1) takes
 * 3 quads: 2 rays continuing its edges, to (0, 1) and (1, 0).  polygon's
 * 140.5-degree corner (0.5, 1.8) takes 2 quads but, within
 * SQ_LAYOUT_BEND_TOL_DEG of 180 degrees, is a bend of a patch side: no ray
 * (the one ray it had ran along an edge on curved faces, stress corpus
 * 0035), and polygon has no singular point: no separatrix at all. */
#include "t50x_trace.h"

static double mod2pi(double a)
{
    return a - 2.0 * M_PI * floor(a / (2.0 * M_PI));
}

/* rays starting at vertex k: count, and each inside the wedge */
static int check_corner(const char *ctx, const t5_case *c, const sq_separatrix_set *set, int k,
                        int want)
{
    int fails = 0, n = 0;
    sq_error err;
    const sq_vertex *v = &c->a.info.vertices[k];
    double t[2];
    SQ_TEST_OK(cad_face_edge_eval(c->face, v->edge_out, 0.0, NULL, t, NULL, &err), err);
    double beta = atan2(t[1], t[0]);
    for (int q = 0; q < set->n; q++) {
        const sq_separatrix *s = &set->s[q];
        if (s->start.kind != SQ_END_CORNER || s->start.id != k) continue;
        n++;
        double rel = mod2pi(s->start_angle - beta) * 180.0 / M_PI;
        fails += sq_check_int(ctx, "ray inside the face's wedge", rel > 1.0 && rel < v->angle_deg - 1.0, 1);
        fails += sq_check_abs(ctx, "ray starts at the vertex", hypot(s->xy[0] - v->x, s->xy[1] - v->y), 0.0, 0.0);
    }
    fails += sq_check_int(ctx, "rays from the corner", n, want);
    return fails;
}

static int find_vertex(const t5_case *c, double x, double y)
{
    for (int k = 0; k < c->a.info.nvertices; k++)
        if (hypot(c->a.info.vertices[k].x - x, c->a.info.vertices[k].y - y) < 1e-9) return k;
    return -1;
}

int main(void)
{
    gsl_set_error_handler_off();
    int fails = 0;
    sq_error err;
    sq_trace_options opt;
    sq_trace_options_default(&opt);
    sq_separatrix_set set;
    t5_case c;

    t5_open(&c, "lshape.step", 8);
    int k = find_vertex(&c, 1, 1);
    fails += sq_check_int("lshape", "corner (1,1) found", k >= 0, 1);
    if (k < 0) return 1;
    fails += sq_check_int("lshape", "quads at (1,1)", c.quads[k], 3);
    fails += sq_check_int("lshape", "singular points", c.a.npoints, 0);
    SQ_TEST_OK(sq_trace_separatrices(&c.cf, c.face, &c.a.info, c.quads, c.a.npoints, c.sing, &opt, &set, &err), err);
    fails += sq_check_int("lshape", "separatrices", set.n, 2);
    fails += check_corner("lshape", &c, &set, k, 2);
    fails += t5_check_ends("lshape", &c, &set, 8.0);
    for (int q = 0; q < set.n; q++) {
        const sq_separatrix *s = &set.s[q];
        const double *p = &s->xy[2 * (s->npts - 1)];
        /* the rays continue the edges: along y = 1 to x = 0, x = 1 to y = 0 */
        double a = mod2pi(s->start_angle) * 180.0 / M_PI;
        int left = fabs(a - 180.0) < 45.0;
        fails += sq_check_abs("lshape", "start angle (deg)", a, left ? 180.0 : 270.0, 1e-6);
        fails += sq_check_abs("lshape", "end x", p[0], left ? 0.0 : 1.0, 1e-6);
        fails += sq_check_abs("lshape", "end y", p[1], left ? 1.0 : 0.0, 1e-6);
    }
    sq_separatrix_set_free(&set);
    t5_close(&c);

    t5_open(&c, "polygon.step", 8);
    k = find_vertex(&c, 0.5, 1.8);
    fails += sq_check_int("polygon", "corner (0.5,1.8) found", k >= 0, 1);
    if (k < 0) return 1;
    fails += sq_check_int("polygon", "quads at (0.5,1.8)", c.quads[k], 2);
    SQ_TEST_OK(sq_trace_separatrices(&c.cf, c.face, &c.a.info, c.quads, c.a.npoints, c.sing, &opt, &set, &err), err);
    fails += check_corner("polygon", &c, &set, k, 0);
    fails += sq_check_int("polygon", "separatrices", set.n, 0);
    sq_separatrix_set_free(&set);
    t5_close(&c);
    return fails != 0;
}
