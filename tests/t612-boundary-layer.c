/* Boundary layers (--bl, Marcon 2019 §3.4) on naca0012 around the airfoil
 * (CAD edge 4): every Jacobian positive at Q = 4, the first cells near
 * --bl-first (the bound below).  Heights are measured from the quads on the
 * airfoil: the distance to the airfoil of their far corners.  The
 * continuity of the layers with the core and their growth: t643. */
#include "layout_pipeline.h"
#include "quad_mesher.h"
#include "test_util.h"

#include <gsl/gsl_errno.h>

static int cmp(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

int main(void)
{
    gsl_set_error_handler_off();
    char path[4096];
    sq_test_path(path, sizeof path, 0, "naca0012.step");
    cad_model *model = NULL;
    cad_face *f = NULL;
    sq_error err;
    SQ_TEST_OK(cad_model_read(path, &model, &err), err);
    SQ_TEST_OK(cad_face_create(model, 0, &f, &err), err);
    sq_layout_options lo;
    sq_layout_options_default(&lo);
    sq_layout_result r;
    SQ_TEST_OK(sq_layout_run(f, &lo, &r, &err), err);
    const int airfoil = 4;
    const double d = 0.002, ratio = 1.2;
    sq_mesher_options mo;
    sq_mesher_options_default(&mo);
    mo.order = 4;
    mo.size = 0.1;
    mo.nbl = 1;
    mo.bl_edges = &airfoil;
    mo.bl_first = d;
    mo.bl_ratio = ratio;
    mo.bl_layers = 10;
    sq_quad_mesh *m = NULL;
    SQ_TEST_OK(sq_mesh_layout(f, r.info, &r.layout, &mo, &m, &err), err);
    sq_quad_quality q;
    SQ_TEST_OK(sq_quad_mesh_quality(m, NULL, NULL, 1, &q, &err), err);
    int fails = 0;
    fails += sq_check_int("naca0012 bl", "inverted quads", q.inverted, 0);
    if (!(q.min_scaled_jacobian > 0.0)) {
        printf("naca0012 bl: min scaled Jacobian %g\n", q.min_scaled_jacobian);
        fails++;
    }
    /* first-layer heights: the far corners of the quads on the airfoil */
    int Q = m->order, npe = (Q + 1) * (Q + 1), n = 0;
    double *h = malloc(sizeof(double) * 2 * (size_t)m->nbnd + 1);
    const int corner[4] = {sq_quad_node(Q, 0, 0), sq_quad_node(Q, Q, 0), sq_quad_node(Q, Q, Q),
                           sq_quad_node(Q, 0, Q)};
    for (int b = 0; b < m->nbnd; b++) {
        if (m->bnd_tag[b] != airfoil) continue;
        int qd = m->bnd_quad[b], k = m->bnd_side[b];
        for (int c = 2; c <= 3; c++) {
            const double *x = &m->xy[2 * m->conn[qd * npe + corner[(k + c) % 4]]];
            double dist;
            SQ_TEST_OK(cad_face_edge_project(f, airfoil, x, NULL, NULL, &dist, &err), err);
            h[n++] = dist;
        }
    }
    qsort(h, (size_t)n, sizeof *h, cmp);
    /* The layers are the walls' sizes (docs/sizes.md): every grid line
     * leaving the airfoil is re-graded along itself by the metric
     * (quad_regrade.c), before and after the relaxation, so its first
     * cell is d to the midpoint rule's error (below 1e-4) and the
     * straight segments' distance to the curved profile (the normal
     * metric gives the height d also along a line leaving obliquely):
     * within [0.95 d, 1.05 d], but at the trailing-edge corner (the fan
     * of 4 sides there: its two quads' far corners sit on lines that do
     * not leave the wall, heights near d / 2).  Measured 0.988 d ..
     * 1.011 d, the corner's two 0.54 d (was 0.53 d .. 2.94 d: the
     * transfinite map's columns). */
    int within = 0;
    for (int k = 0; k < n; k++) within += h[k] >= 0.95 * d && h[k] <= 1.05 * d;
    if (getenv("SQ_VERBOSE"))
        for (int k = 0; k < n; k++) printf("%.3f%c", h[k] / d, k == n - 1 ? '\n' : ' ');
    if (!(within >= n - 2)) {
        printf("naca0012 bl: %d of %d first cells within [%g, %g]\n", within, n, 0.95 * d, 1.05 * d);
        fails++;
    }
    free(h);
    sq_quad_mesh_free(&m);
    sq_layout_result_free(&r);
    cad_face_free(&f);
    cad_model_free(&model);
    return fails ? 1 : 0;
}
