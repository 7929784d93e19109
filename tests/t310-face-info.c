/* Corners, interior angles, loops, chi and area (Green's theorem on the exact
 * curves) of every example face and of the optional real CAD files, against
 * examples/README.md and the real files' own README (tests/README.md).
 * Tolerances (no BLAS): the area is GSL's QAG to 1e-13 relative of each
 * edge's integral (src/face/face_info.c), exact curves in closed form: 1e-12 for
 * the examples, 1e-6 where the expected value has 7 digits (the real files,
 * naca0012); corner positions are the files' points, to the 1e-9 arc-length
 * slack of cad_face (1e-6 where the README rounds them). */
#include "face_info.h"
#include "test_util.h"

#include <gsl/gsl_errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct {
    double x, y, angle; /* angle 0: any (only the position is checked) */
} corner;

typedef struct {
    const char *file;
    int real;       /* in $SEMQUAD_REAL_GEOMETRIES rather than SQ_EXAMPLES */
    int face;       /* -1: default face */
    const char *unit;
    double area, area_rtol;
    int nloops, ncorners;
    double angle_tol; /* degrees */
    int nexp;
    corner exp[10];
    int nangles; /* if > 0: the sorted corner angles, for files whose corner
                    positions the README does not give */
    double angles[10];
} face_case;

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

static const double PI = 3.14159265358979323846;

static int check_case(const face_case *c)
{
    char path[4096];
    if (!sq_test_path(path, sizeof path, c->real, c->file)) return 77;
    cad_model *m = NULL;
    cad_face *f = NULL;
    sq_error err;
    sq_face_info info;
    int fails = 0;
    SQ_TEST_OK(cad_model_read(path, &m, &err), err);
    int idx = c->face >= 0 ? c->face : cad_model_default_face(m, &(const char *){NULL});
    SQ_TEST_OK(cad_face_create(m, idx, &f, &err), err);
    SQ_TEST_OK(sq_face_info_compute(f, &info, &err), err);
    fails += sq_check_str(c->file, "unit", cad_model_unit(m), c->unit);
    fails += sq_check_rel(c->file, "area", info.area, c->area, c->area_rtol);
    fails += sq_check_int(c->file, "loops", info.nloops, c->nloops);
    fails += sq_check_int(c->file, "chi", info.chi, 2 - c->nloops);
    fails += sq_check_int(c->file, "corners", info.ncorners, c->ncorners);
    double scale = fmax(info.bbox[2] - info.bbox[0], info.bbox[3] - info.bbox[1]);
    for (int k = 0; k < c->nexp; k++) {
        const corner *e = &c->exp[k];
        int found = -1;
        for (int v = 0; v < info.nvertices; v++)
            if (hypot(info.vertices[v].x - e->x, info.vertices[v].y - e->y) < 1e-6 * scale) found = v;
        if (found < 0) {
            printf("%s: no vertex at (%g, %g)\n", c->file, e->x, e->y);
            fails++;
            continue;
        }
        char what[64];
        snprintf(what, sizeof what, "angle at (%g, %g)", e->x, e->y);
        if (e->angle > 0)
            fails += sq_check_abs(c->file, what, info.vertices[found].angle_deg, e->angle, c->angle_tol);
        else
            fails += sq_check_int(c->file, "smooth junction", info.vertices[found].smooth, 1);
    }
    if (c->nangles && info.ncorners == c->nangles) {
        double got[10];
        int n = 0;
        for (int v = 0; v < info.nvertices; v++)
            if (!info.vertices[v].smooth) got[n++] = info.vertices[v].angle_deg;
        qsort(got, (size_t)n, sizeof *got, cmp_double);
        for (int k = 0; k < n; k++)
            fails += sq_check_abs(c->file, "sorted corner angle", got[k], c->angles[k], c->angle_tol);
    }
    sq_face_info_free(&info);
    cad_face_free(&f);
    cad_model_free(&m);
    return fails ? 1 : 0;
}

/* Interior angle at vertex b of the counter-clockwise polygon.step
 * (74.48, 123.69, 78.11, 123.21, 140.51 degrees as the README rounds them). */
static double poly_angle(int a, int b, int c)
{
    static const double P[5][2] = {{0, 0}, {3, 0}, {4, 1.5}, {1.5, 2.5}, {0.5, 1.8}};
    double ux = P[c][0] - P[b][0], uy = P[c][1] - P[b][1];
    double wx = P[a][0] - P[b][0], wy = P[a][1] - P[b][1];
    double ang = atan2(ux * wy - uy * wx, ux * wx + uy * wy) * 180.0 / PI;
    return ang < 0 ? ang + 360.0 : ang;
}

int main(void)
{
    gsl_set_error_handler_off();
    const double s3 = sqrt(3.0);
    const face_case cases[] = {
        {"half_disc.step", 0, -1, "mm", PI / 2, 1e-12, 1, 2, 1e-9, 2, {{1, 0, 90}, {-1, 0, 90}}},
        {"quarter_circle.step", 0, -1, "mm", PI / 4, 1e-12, 1, 3, 1e-9, 3,
         {{0, 0, 90}, {1, 0, 90}, {0, 1, 90}}},
        {"square.step", 0, -1, "mm", 1.0, 1e-12, 1, 4, 1e-9, 4,
         {{0, 0, 90}, {1, 0, 90}, {1, 1, 90}, {0, 1, 90}}},
        {"triangle.step", 0, -1, "mm", s3 / 4, 1e-12, 1, 3, 1e-6, 3,
         {{0, 0, 60}, {1, 0, 60}, {0.5, s3 / 2, 60}}},
        {"square_hole.step", 0, -1, "mm", 1 - PI / 16, 1e-12, 2, 4, 1e-9, 4,
         {{0, 0, 90}, {1, 0, 90}, {1, 1, 90}, {0, 1, 90}}},
        {"two_holes.step", 0, -1, "mm", 8 - PI / 2, 1e-12, 1, 6, 1e-9, 6,
         {{1, 0, 90}, {3, 0, 90}, {4, 1, 90}, {4, 2, 90}, {0, 2, 90}, {0, 1, 90}}},
        {"nautilus.step", 0, -1, "mm", 5 * PI / 8, 1e-12, 1, 2, 1e-9, 3,
         {{-1, 0, 90}, {0, 0, 270}, {1, 0, 0}}},
        {"polygon.step", 0, -1, "mm", 6.85, 1e-12, 1, 5, 1e-9, 5,
         {{0, 0, poly_angle(4, 0, 1)}, {3, 0, poly_angle(0, 1, 2)}, {4, 1.5, poly_angle(1, 2, 3)},
          {1.5, 2.5, poly_angle(2, 3, 4)}, {0.5, 1.8, poly_angle(3, 4, 0)}}},
        {"naca0012.step", 0, -1, "mm", 20 - 0.081706, 1e-6, 2, 5, 0.1, 5,
         {{-2, -2, 90}, {3, -2, 90}, {3, 2, 90}, {-2, 2, 90}, {1, 0, 343.5}}},
        {"annulus.step", 0, -1, "mm", 0.84 * PI, 1e-12, 2, 0, 0, 0, {{0}}},
        {"lshape.step", 0, -1, "mm", 3.0, 1e-12, 1, 6, 1e-9, 6,
         {{0, 0, 90}, {2, 0, 90}, {2, 1, 90}, {1, 1, 270}, {1, 2, 90}, {0, 2, 90}}},
        /* real files, read in place */
        {"real_t106_cascade.step", 1, -1, "m", 2.894541, 1e-6, 2, 10, 0.01, 0, {{0}}, 10,
         {53.75, 90, 90, 115.24, 115.24, 126.25, 143.75, 216.25, 244.76, 244.76}},
        {"real_aerofoil_box.step", 1, -1, "m", 2.989443, 1e-6, 2, 6, 0.01, 4,
         {{-0.5, -0.75, 90}, {1.5, -0.75, 90}, {1.5, 0.75, 90}, {-0.5, 0.75, 90}}, 6,
         {90, 90, 90, 90, 192.47, 341.24}},
        {"real_circle_square.step", 1, 1, "mm", 6158.884, 1e-6, 2, 4, 1e-6, 4,
         {{-50.14393, -50.00122, 90}, {49.99620, -50.00122, 90}, {49.99620, 49.93208, 90},
          {-50.14393, 49.93208, 90}}, 0, {0}},
    };
    int fails = 0, real_missing = 0;
    for (size_t i = 0; i < sizeof cases / sizeof *cases; i++) {
        if (cases[i].real && real_missing) continue; /* one line says they are absent */
        int r = check_case(&cases[i]);
        if (r == 77) real_missing = 1;
        else fails += r;
    }
    return fails ? 1 : 0;
}
