/* Marcon 2019 Fig. 12: the half disc's layout from two valence-3 points and
 * five hand-made separatrices (one joining the two points): 4 quad
 * patches, each valence-3 point a corner of 3 patches, the two 90° corners
 * of one patch each, areas summing to π/2. */
#include "layout.h"
#include "t51x_layout.h"
#include "test_util.h"

#include <gsl/gsl_errno.h>

int main(void)
{
    gsl_set_error_handler_off();
    char path[4096];
    sq_test_path(path, sizeof path, 0, "half_disc.step");
    cad_model *m = NULL;
    cad_face *f = NULL;
    sq_error err;
    sq_face_info info;
    SQ_TEST_OK(cad_model_read(path, &m, &err), err);
    SQ_TEST_OK(cad_face_create(m, 0, &f, &err), err);
    SQ_TEST_OK(sq_face_info_compute(f, &info, &err), err);
    int fails = sq_check_int("half disc", "vertices", info.nvertices, 2);
    int quads[2] = {1, 1};
    sq_singularity sing[2] = {{-0.4, 0.35, 3, SQ_ORIGIN_IMPOSED}, {0.4, 0.35, 3, SQ_ORIGIN_IMPOSED}};
    sq_separatrix s[5];
    sq_sep_end S0 = {SQ_END_SINGULAR, 0, 0}, S1 = {SQ_END_SINGULAR, 1, 0};
    for (int k = 0; k < 2; k++) {
        double a[2] = {sing[k].x, sing[k].y}, down[2] = {a[0], 0.0};
        sq_sep_end fe = nearest_foot(f, down, down);
        straight(&s[2 * k], a, down, 15, k ? S1 : S0, fe);
        /* towards the arc at 135° (left point) or 45° (right point) */
        double c = k ? cos(M_PI / 4) : cos(3 * M_PI / 4), sn = sin(M_PI / 4);
        double b = a[0] * c + a[1] * sn, t = -b + sqrt(b * b - (a[0] * a[0] + a[1] * a[1] - 1));
        double arc[2] = {a[0] + t * c, a[1] + t * sn};
        fe = nearest_foot(f, arc, arc);
        straight(&s[2 * k + 1], a, arc, 15, k ? S1 : S0, fe);
    }
    double a0[2] = {sing[0].x, sing[0].y}, a1[2] = {sing[1].x, sing[1].y};
    straight(&s[4], a0, a1, 21, S0, S1);
    s[4].merged = 1;
    sq_separatrix_set set = {5, 5, s};
    sq_layout L;
    SQ_TEST_OK(sq_layout_build(f, &info, quads, 2, sing, &set, NULL, NULL, &L, &err), err);
    fails += sq_check_int("half disc", "separatrices", L.stats.separatrices, 5);
    fails += sq_check_int("half disc", "patches", L.npatches, 4);
    fails += sq_check_int("half disc", "quad patches", L.stats.quad_patches, 4);
    double sum = 0.0;
    int ncorner[64] = {0};
    for (int p = 0; p < L.npatches; p++) {
        sum += L.patches[p].area;
        fails += sq_check_int("half disc", "corners", L.patches[p].ncorners, 4);
        for (int k = 0; k < L.patches[p].ncorners; k++) ncorner[L.patches[p].corners[k]]++;
    }
    /* patch areas by cad_split's adaptive Green rule: 1e-9 (t320) */
    fails += sq_check_abs("half disc", "area sum", sum, M_PI / 2, 1e-9);
    for (int v = 0; v < L.nnodes; v++) {
        const sq_layout_node *n = &L.nodes[v];
        int want = n->kind == SQ_LNODE_SINGULAR ? 3 : n->kind == SQ_LNODE_CORNER ? 1 : 2;
        fails += sq_check_int("half disc", "corner of patches", ncorner[v], want);
    }
    /* the bottom-middle patch: a rectangle 0.8 x 0.35 */
    int found = 0;
    for (int p = 0; p < L.npatches; p++)
        /* straight sides: exact to a few tens of U (t320) */
        if (fabs(L.patches[p].area - 0.8 * 0.35) < 1e-12) found++;
    fails += sq_check_int("half disc", "0.8 x 0.35 patches", found, 1);
    sq_layout_defects d;
    fails += sq_check_int("half disc", "defects", sq_layout_check(&L, &d), 0);
    sq_layout_defects_free(&d);
    sq_layout_free(&L);
    for (int k = 0; k < 5; k++) free(s[k].xy);
    sq_face_info_free(&info);
    cad_face_free(&f);
    cad_model_free(&m);
    return fails != 0;
}
