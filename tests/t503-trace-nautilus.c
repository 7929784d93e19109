/* The nautilus (Marcon 2019 §4, Figs. 11, 16-17): low-order fields trace a
 * spiral ending in a limit cycle here; with the P = 8 guiding field every
 * separatrix ends (boundary, corner or singular point) well within the
 * length bound, with normal merging and with aggressive merging (5 steps,
 * §3.3.1). */
#include "t50x_trace.h"

int main(void)
{
    gsl_set_error_handler_off();
    int fails = 0;
    sq_error err;
    t5_case c;
    t5_open(&c, "nautilus.step", 8);
    fails += sq_check_int("nautilus", "singular points", c.a.npoints, 4);
    double perim = 0.0;
    for (int e = 0; e < cad_face_num_edges(c.face); e++) perim += cad_face_edge_length(c.face, e);
    double md[2] = {1.0, 5.0};
    for (int i = 0; i < 2; i++) {
        char ctx[64];
        snprintf(ctx, sizeof ctx, "nautilus merge distance %g", md[i]);
        sq_trace_options opt;
        sq_trace_options_default(&opt);
        opt.merge_distance = md[i];
        sq_separatrix_set set;
        sq_trace_stats st;
        SQ_TEST_OK(sq_trace_separatrices_stats(&c.cf, c.face, &c.a.info, c.quads, c.a.npoints,
                                               c.sing, &opt, &set, &st, &err),
                   err);
        /* 4 valence-3 points and the 270-degree corner's 2 */
        fails += sq_check_int(ctx, "separatrices traced", st.traced, 14);
        fails += sq_check_int(ctx, "separatrices after merging", set.n, st.traced - st.merges);
        fails += sq_check_int(ctx, "at least one merge", st.merges >= 1, 1);
        /* no spiral: every line ends, none longer than the perimeter */
        fails += t5_check_ends(ctx, &c, &set, perim);
        sq_separatrix_set_free(&set);
    }
    t5_close(&c);
    return fails != 0;
}
