/* The all-quad last resort's overlap merge (src/layout/repair_overlap.c) on
 * the unit square: separatrix A the vertical midline, B along A from the
 * bottom to (0.5, 0.6) (other points, 1e-12 off A: no crossing the
 * intersection search sees) then bent to the right side at (1, 0.8).
 * Without the merge the graph has two pieces from (0.5, 0) to (0.5, 0.6)
 * and a patch whose ring runs along both (the left half and the lower
 * right as one patch of 10 corners).  With it, B's part along A
 * goes, B's rest ends on A at a node at (0.5, 0.6), and the layout is 3
 * quads: left 1/2, lower right 0.5 * (0.6 + 0.8) / 2 = 0.35, upper right
 * 0.5 * (0.4 + 0.2) / 2 = 0.15, no split needed. */
#include "layout.h"
#include "t51x_layout.h"
#include "test_util.h"

#include <gsl/gsl_errno.h>

int main(void)
{
    gsl_set_error_handler_off();
    char path[4096];
    sq_test_path(path, sizeof path, 0, "square.step");
    cad_model *m = NULL;
    cad_face *f = NULL;
    sq_error err;
    sq_face_info info;
    SQ_TEST_OK(cad_model_read(path, &m, &err), err);
    SQ_TEST_OK(cad_face_create(m, 0, &f, &err), err);
    SQ_TEST_OK(sq_face_info_compute(f, &info, &err), err);
    int quads[8];
    for (int k = 0; k < info.nvertices; k++) quads[k] = 1;
    const double bot[2] = {0.5, 0}, top[2] = {0.5, 1}, knee[2] = {0.5 + 1e-12, 0.6},
                 right[2] = {1, 0.8};
    sq_separatrix s[2];
    straight(&s[0], bot, top, 11, nearest_foot(f, bot, NULL), nearest_foot(f, top, NULL));
    /* B: 7 points to the knee, 1e-12 off A, then 5 to the right side */
    sq_separatrix leg;
    straight(&s[1], bot, knee, 7, nearest_foot(f, bot, NULL), nearest_foot(f, right, NULL));
    straight(&leg, knee, right, 5, s[1].start, s[1].end);
    double *xy = realloc(s[1].xy, 2 * (size_t)(7 + 4) * sizeof *xy);
    for (int j = 1; j < 5; j++) xy[2 * (6 + j)] = leg.xy[2 * j], xy[2 * (6 + j) + 1] = leg.xy[2 * j + 1];
    for (int j = 1; j < 6; j++) xy[2 * j] += 1e-12;
    s[1].xy = xy;
    s[1].npts = 11;
    free(leg.xy);
    sq_separatrix_set set = {2, 2, s};
    sq_layout L;
    int fails = 0;
    SQ_TEST_OK(sq_layout_graph(f, &info, quads, 0, NULL, &set, &L, &err), err);
    /* before: the two copies of the piece along A part no region, so the
     * left half and the lower right are one patch (0.85) whose ring runs
     * up one copy and down the other */
    fails += sq_check_int("overlap", "patches before the merge", L.npatches, 2);
    SQ_TEST_OK(sq_layout_all_quad(f, &info, &L, &err), err);
    fails += sq_check_int("overlap", "overlaps merged", L.stats.overlaps_merged, 1);
    fails += sq_check_int("overlap", "splits", L.stats.all_quad_splits, 0);
    fails += sq_check_int("overlap", "patches", L.npatches, 3);
    /* the areas of straight-sided patches: Green's rule on the polylines,
     * round-off of a few U, and the 1e-12 offset of B over a height 0.6 */
    double want[3] = {0.15, 0.35, 0.5}, got[3];
    for (int p = 0; p < L.npatches && p < 3; p++) {
        fails += sq_check_int("overlap", "corners", L.patches[p].ncorners, 4);
        fails += sq_check_int("overlap", "cycles", L.patches[p].ncycles, 1);
        got[p] = L.patches[p].area;
    }
    for (int a = 0; a < 3; a++) /* sorted */
        for (int b = a + 1; b < 3; b++)
            if (got[b] < got[a]) {
                double t = got[a];
                got[a] = got[b], got[b] = t;
            }
    for (int p = 0; p < 3 && L.npatches == 3; p++)
        fails += sq_check_abs("overlap", "area", got[p], want[p], 1e-11);
    sq_layout_free(&L);
    for (int k = 0; k < 2; k++) free(s[k].xy);
    sq_face_info_free(&info);
    cad_face_free(&f);
    cad_model_free(&m);
    return fails != 0;
}
