/* Layout graph on the unit square with its two midlines given as four
 * separatrices meeting at a valence-4 node: 4 quad patches of area 1/4,
 * the node a corner of 4 patches, each side made of one edge. */
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
    sq_singularity c = {0.5, 0.5, 4, SQ_ORIGIN_IMPOSED};
    double ctr[2] = {0.5, 0.5}, mids[4][2] = {{0.5, 0}, {1, 0.5}, {0.5, 1}, {0, 0.5}};
    sq_separatrix s[4];
    for (int k = 0; k < 4; k++)
        straight(&s[k], ctr, mids[k], 11, (sq_sep_end){SQ_END_SINGULAR, 0, 0}, nearest_foot(f, mids[k], NULL));
    sq_separatrix_set set = {4, 4, s};
    sq_layout L;
    SQ_TEST_OK(sq_layout_graph(f, &info, quads, 1, &c, &set, &L, &err), err);
    int fails = 0;
    fails += sq_check_int("square", "patches", L.npatches, 4);
    fails += sq_check_int("square", "edges", L.nedges, 12);
    fails += sq_check_int("square", "nodes", L.nnodes, 9);
    for (int p = 0; p < L.npatches; p++) {
        const sq_layout_patch *P = &L.patches[p];
        fails += sq_check_int("square", "corners", P->ncorners, 4);
        fails += sq_check_int("square", "cycles", P->ncycles, 1);
        /* straight sides: cad_split's Green rule exact to a few tens of U
         * (t320); corner angles from segments' directions, a few U, but
         * the lines are traced (AB4 1e-9) */
        fails += sq_check_abs("square", "area", P->area, 0.25, 1e-12);
        for (int k = 0; k < 4; k++) {
            fails += sq_check_int("square", "side edges", P->side_start[k + 1] - P->side_start[k], 1);
            fails += sq_check_abs("square", "corner angle", P->corner_angle[k], M_PI / 2, 1e-9);
        }
        /* sides chain from corner to corner */
        for (int k = 0; k < 4; k++) {
            const sq_layout_half *h = &P->half[P->side_start[k]];
            const sq_layout_edge *E = &L.edges[h->edge];
            int from = h->reversed ? E->n1 : E->n0;
            fails += sq_check_int("square", "side start node", from, P->corners[k]);
        }
    }
    sq_layout_defects d;
    fails += sq_check_int("square", "defects", sq_layout_check(&L, &d), 0);
    for (int k = 0; k < d.n; k++) printf("  %s\n", d.d[k].msg);
    sq_layout_defects_free(&d);
    sq_layout_free(&L);
    /* the same through sq_layout_build: nothing to repair */
    SQ_TEST_OK(sq_layout_build(f, &info, quads, 1, &c, &set, NULL, NULL, &L, &err), err);
    fails += sq_check_int("square build", "quad patches", L.stats.quad_patches, 4);
    fails += sq_check_int("square build", "separatrices", L.stats.separatrices, 4);
    sq_layout_free(&L);
    for (int k = 0; k < 4; k++) free(s[k].xy);
    sq_face_info_free(&info);
    cad_face_free(&f);
    cad_model_free(&m);
    return fails != 0;
}
