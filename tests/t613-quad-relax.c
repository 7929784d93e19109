/* Winslow relaxation with sliding boundary vertices (quad_relax.h): on the
 * unit square, a 6 x 4 grid whose interior vertices are shaken and whose
 * boundary vertices are moved along their edges relaxes back to the uniform
 * grid — the energy's minimizer there (conformal map of the square onto
 * itself followed by the stretch to 6 x 4 cells) — to 1e-6 (where the
 * relaxation stops: its steps are below 1e-6 of the extent), with the
 * boundary vertices still on their edges. */
#include "cad.h"
#include "quad_relax.h"
#include "test_util.h"

#define NU 6
#define NV 4
#define ID(i, j) ((j) * (NU + 1) + (i))

int main(void)
{
    char path[4096];
    sq_test_path(path, sizeof path, 0, "square.step");
    cad_model *model = NULL;
    cad_face *f = NULL;
    sq_error err;
    SQ_TEST_OK(cad_model_read(path, &model, &err), err);
    SQ_TEST_OK(cad_face_create(model, 0, &f, &err), err);
    int nv = (NU + 1) * (NV + 1), nq = NU * NV, fails = 0;
    double xy[2 * (NU + 1) * (NV + 1)];
    int quad[4 * NU * NV], tag[4 * NU * NV], fixed[(NU + 1) * (NV + 1)];
    for (int j = 0; j <= NV; j++)
        for (int i = 0; i <= NU; i++) {
            double x = (double)i / NU, y = (double)j / NV;
            int bx = i == 0 || i == NU, by = j == 0 || j == NV;
            /* a deterministic shake: inside in both directions, on the
             * boundary along it (corners stay) */
            double dx = 0.3 / NU * sin(3.0 * i + 5.0 * j), dy = 0.3 / NV * cos(7.0 * i + 2.0 * j);
            xy[2 * ID(i, j)] = x + (bx ? 0.0 : dx);
            xy[2 * ID(i, j) + 1] = y + (by ? 0.0 : dy);
            fixed[ID(i, j)] = bx && by;
        }
    for (int j = 0; j < NV; j++)
        for (int i = 0; i < NU; i++) {
            int q = j * NU + i, c[4] = {ID(i, j), ID(i + 1, j), ID(i + 1, j + 1), ID(i, j + 1)};
            for (int k = 0; k < 4; k++) {
                quad[4 * q + k] = c[k];
                tag[4 * q + k] = -1;
                int on = (k == 0 && j == 0) || (k == 1 && i == NU - 1) || (k == 2 && j == NV - 1) ||
                         (k == 3 && i == 0);
                if (!on) continue;
                /* the CAD edge under the side's (unshaken) midpoint */
                int a = c[k], b = c[(k + 1) % 4];
                double mid[2] = {0.5 * ((a % (NU + 1)) + (b % (NU + 1))) / NU,
                                 0.5 * ((a / (NU + 1)) + (b / (NU + 1))) / NV};
                for (int e = 0; e < cad_face_num_edges(f); e++) {
                    double d;
                    SQ_TEST_OK(cad_face_edge_project(f, e, mid, NULL, NULL, &d, &err), err);
                    if (d < 1e-9) tag[4 * q + k] = e;
                }
                fails += sq_check_int("t613", "side on a CAD edge", tag[4 * q + k] >= 0, 1);
            }
        }
    sq_relax_mesh m = {nv, nq, xy, quad, tag, fixed};
    SQ_TEST_OK(sq_quad_relax(f, &m, &err), err);
    double worst = 0.0;
    for (int j = 0; j <= NV; j++)
        for (int i = 0; i <= NU; i++)
            worst = fmax(worst, hypot(xy[2 * ID(i, j)] - (double)i / NU,
                                      xy[2 * ID(i, j) + 1] - (double)j / NV));
    fails += sq_check_abs("t613", "largest distance to the uniform grid", worst, 0.0, 1e-6);
    cad_face_free(&f);
    cad_model_free(&model);
    return fails != 0;
}
