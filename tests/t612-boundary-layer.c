/* Boundary layers (--bl, Marcon 2019 §3.4) on naca0012 around the airfoil
 * (CAD edge 4): every Jacobian positive at Q = 4, the first cell as high as
 * --bl-first and the layers growing by --bl-ratio.  Heights are measured
 * from the quads on the airfoil: the distance to the airfoil of the
 * vertices one and two layers out. */
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
    /* first cells within 1 % of --bl-first: all but those of the fan at
     * the trailing-edge corner, whose columns leave the wall obliquely */
    int within = 0;
    for (int k = 0; k < n; k++) within += fabs(h[k] - d) <= 0.01 * d;
    if (getenv("SQ_VERBOSE"))
        printf("%d of %d first cells within 1 %%, heights %g .. %g\n", within, n, h[0], h[n - 1]);
    if (!(within >= 0.9 * n)) {
        printf("naca0012 bl: %d of %d first cells within 1 %% of %g\n", within, n, d);
        fails++;
    }
    fails += sq_check_rel("naca0012 bl", "median first-cell height", h[n / 2], d, 0.01);
    /* growth: as many vertices at the second layer's height d (1 + r) and
     * at the third's d (1 + r + r^2) as at the first's */
    int at[3] = {0, 0, 0};
    const double level[3] = {d, d * (1 + ratio), d * (1 + ratio + ratio * ratio)};
    for (int i = 0; i < m->nnodes; i++) {
        double dist;
        SQ_TEST_OK(cad_face_edge_project(f, airfoil, &m->xy[2 * i], NULL, NULL, &dist, &err), err);
        for (int l = 0; l < 3; l++) at[l] += fabs(dist - level[l]) <= 0.01 * level[l];
    }
    if (getenv("SQ_VERBOSE")) printf("vertices at layers 1..3: %d %d %d\n", at[0], at[1], at[2]);
    if (!(at[1] >= 0.9 * at[0] && at[2] >= 0.9 * at[0] && at[0] > 0)) {
        printf("naca0012 bl: vertices at layer heights %d, %d, %d: the growth ratio %g is not kept\n",
               at[0], at[1], at[2], ratio);
        fails++;
    }
    free(h);
    sq_quad_mesh_free(&m);
    sq_layout_result_free(&r);
    cad_face_free(&f);
    cad_model_free(&model);
    return fails ? 1 : 0;
}
