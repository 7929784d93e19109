/* The relaxation's target-matrix energy with the user's sizes
 * (quad_relax.h), on the unit square (square.step), an 8 x 4 grid:
 * 1. A tensor-product grid graded along x (x_i = (r^i - 1) / (r^8 - 1),
 *    r = 1.3; y uniform) is where every corner's target term is at its
 *    minimum (a right angle, the start's aspect ratio and area: the size
 *    h = 1 everywhere exceeds every side, so no target is scaled down):
 *    the relaxation leaves it, to 1e-12 (the Newton step of a zero
 *    gradient is zero; the compass search finds no eta to raise in a grid
 *    of right angles).  Without sizes, Winslow's energy takes the same
 *    grid to the uniform one, its minimizer (t613), to 1e-8: the grading
 *    a graded mesh loses without targets.
 * 2. A size h = 0.05 within 0.05 of the centre (growing by 1.3 outside;
 *    far size 1) on the uniform grid: the targets of the quads near the
 *    centre are scaled down, so the four quads around the centre vertex
 *    shrink (measured: to 0.46 of their area; asserted: below 0.9, and
 *    every quad convex). */
#include "cad.h"
#include "quad_relax.h"
#include "size_field.h"
#include "test_face.h"

#define NU 8
#define NV 4
#define NVX ((NU + 1) * (NV + 1))
#define ID(i, j) ((j) * (NU + 1) + (i))

/* The grid's quads and the CAD edges under their boundary sides. */
static int grid_topology(const cad_face *f, int *quad, int *tag, int *fixed)
{
    sq_error err;
    int fails = 0;
    for (int j = 0; j <= NV; j++)
        for (int i = 0; i <= NU; i++)
            fixed[ID(i, j)] = (i == 0 || i == NU) && (j == 0 || j == NV);
    for (int j = 0; j < NV; j++)
        for (int i = 0; i < NU; i++) {
            int q = j * NU + i, c[4] = {ID(i, j), ID(i + 1, j), ID(i + 1, j + 1), ID(i, j + 1)};
            double mid[4][2] = {{(i + 0.5) / NU, 0.0}, {1.0, (j + 0.5) / NV}, {(i + 0.5) / NU, 1.0},
                                {0.0, (j + 0.5) / NV}};
            for (int k = 0; k < 4; k++) {
                quad[4 * q + k] = c[k];
                tag[4 * q + k] = -1;
                int on = (k == 0 && j == 0) || (k == 1 && i == NU - 1) || (k == 2 && j == NV - 1) ||
                         (k == 3 && i == 0);
                for (int e = 0; on && e < cad_face_num_edges(f); e++) {
                    double d;
                    SQ_TEST_OK(cad_face_edge_project(f, e, mid[k], NULL, NULL, &d, &err), err);
                    if (d < 1e-9) tag[4 * q + k] = e;
                }
                if (on) fails += sq_check_int("t627", "side on a CAD edge", tag[4 * q + k] >= 0, 1);
            }
        }
    return fails;
}

static double quad_area(const double *xy, const int *c)
{
    double a = 0.0;
    for (int k = 0; k < 4; k++) {
        const double *p = &xy[2 * c[k]], *q = &xy[2 * c[(k + 1) % 4]];
        a += 0.5 * (p[0] * q[1] - q[0] * p[1]);
    }
    return a;
}

static int all_convex(const double *xy, const int *quad, int nq)
{
    for (int q = 0; q < nq; q++)
        for (int k = 0; k < 4; k++) {
            const double *p = &xy[2 * quad[4 * q + k]], *a = &xy[2 * quad[4 * q + (k + 1) % 4]],
                         *b = &xy[2 * quad[4 * q + (k + 3) % 4]];
            if (!((a[0] - p[0]) * (b[1] - p[1]) - (a[1] - p[1]) * (b[0] - p[0]) > 0.0)) return 0;
        }
    return 1;
}

int main(void)
{
    cad_model *model = NULL;
    cad_face *f = NULL;
    sq_error err;
    sq_test_open_face("square.step", &model, &f);
    int quad[4 * NU * NV], tag[4 * NU * NV], fixed[NVX], fails = grid_topology(f, quad, tag, fixed);
    double graded[2 * NVX], xy[2 * NVX];
    const double r = 1.3;
    for (int j = 0; j <= NV; j++)
        for (int i = 0; i <= NU; i++) {
            graded[2 * ID(i, j)] = (pow(r, i) - 1.0) / (pow(r, NU) - 1.0);
            graded[2 * ID(i, j) + 1] = (double)j / NV;
        }

    /* 1. the graded grid: a fixed point of the targets, not of Winslow */
    sq_size_source whole = {.kind = SQ_SIZE_POINT, .x = {0.5, 0.5}, .r = 0.0, .h = 1.0};
    sq_size_field *sizes = NULL;
    SQ_TEST_OK(sq_size_field_create(f, &whole, 1, 1.3, 0.0, &sizes, &err), err);
    memcpy(xy, graded, sizeof xy);
    sq_relax_mesh m = {NVX, NU * NV, xy, quad, tag, fixed};
    m.sizes = sizes;
    m.far = 1.0;
    SQ_TEST_OK(sq_quad_relax(f, &m, NULL, &err), err);
    double moved = 0.0;
    for (int i = 0; i < NVX; i++)
        moved = fmax(moved, hypot(xy[2 * i] - graded[2 * i], xy[2 * i + 1] - graded[2 * i + 1]));
    fails += sq_check_abs("t627 targets", "graded grid moved by", moved, 0.0, 1e-12);
    sq_size_field_free(&sizes);

    memcpy(xy, graded, sizeof xy);
    m.sizes = NULL;
    SQ_TEST_OK(sq_quad_relax(f, &m, NULL, &err), err);
    double off = 0.0;
    for (int j = 0; j <= NV; j++)
        for (int i = 0; i <= NU; i++)
            off = fmax(off, hypot(xy[2 * ID(i, j)] - (double)i / NU, xy[2 * ID(i, j) + 1] - (double)j / NV));
    /* the relaxation's stopping rule, as in t613: within 1e-8 */
    fails += sq_check_abs("t627 Winslow", "graded grid to the uniform one", off, 0.0, 1e-8);

    /* 2. a refinement at the centre, on the uniform grid */
    sq_size_source centre = {.kind = SQ_SIZE_POINT, .x = {0.5, 0.5}, .r = 0.05, .h = 0.05};
    SQ_TEST_OK(sq_size_field_create(f, &centre, 1, 1.3, 0.0, &sizes, &err), err);
    for (int j = 0; j <= NV; j++)
        for (int i = 0; i <= NU; i++) {
            xy[2 * ID(i, j)] = (double)i / NU;
            xy[2 * ID(i, j) + 1] = (double)j / NV;
        }
    m.sizes = sizes;
    SQ_TEST_OK(sq_quad_relax(f, &m, NULL, &err), err);
    double around = 0.0;
    for (int q = 0; q < NU * NV; q++)
        for (int k = 0; k < 4; k++)
            if (quad[4 * q + k] == ID(NU / 2, NV / 2)) around += quad_area(xy, &quad[4 * q]);
    double ratio = around / (4.0 / (NU * NV));
    printf("t627 refine: the quads around the centre at %.3f of their area\n", ratio);
    fails += sq_check_int("t627 refine", "quads around the centre shrink below 0.9", ratio < 0.9, 1);
    fails += sq_check_int("t627 refine", "every quad convex", all_convex(xy, quad, NU * NV), 1);
    sq_size_field_free(&sizes);
    cad_face_free(&f);
    cad_model_free(&model);
    return fails != 0;
}
