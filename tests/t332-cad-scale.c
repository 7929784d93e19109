/* Faces from 1e-9 to 1e9 read like the unit face (issue 14): the examples'
 * square with a round hole and the disc, scaled by cad_model_transform
 * (tolerances scale with them), give the same status, loops and corners
 * and an area scaled by s^2; scaling about the origin, the corners move
 * to s times their positions.
 *
 * Tolerances: Green's area integrates the exact curves by adaptive
 * Gauss-Kronrod to 1e-13 relative (face_info.c), scale-free, so the scaled
 * area matches s^2 times the unit area to 1e-12 relative; corner positions
 * are curve end points, exact to a few units of round-off times the face's
 * size (1e-12 relative). */
#include "face_info.h"
#include "test_util.h"

#include <gsl/gsl_errno.h>
#include <math.h>
#include <stdio.h>

static int check_scaled(const char *file, const sq_face_info *ref, double s)
{
    char path[4096];
    if (!sq_test_path(path, sizeof path, 0, file)) return 77;
    cad_model *m = NULL;
    cad_face *f = NULL;
    sq_error err;
    sq_face_info info;
    const double axis[3] = {0, 0, 1}, t[3] = {0, 0, 0};
    char ctx[256];
    int fails = 0;
    snprintf(ctx, sizeof ctx, "%s x %g", file, s);
    SQ_TEST_OK(cad_model_read(path, &m, &err), err);
    SQ_TEST_OK(cad_model_transform(m, axis, 0.0, s, t, &err), err);
    fails += sq_check_int(ctx, "status", (int)cad_model_face_status(m, 0, NULL), CAD_FACE_OK);
    SQ_TEST_OK(cad_face_create(m, 0, &f, &err), err);
    SQ_TEST_OK(sq_face_info_compute(f, &info, &err), err);
    fails += sq_check_rel(ctx, "area", info.area, s * s * ref->area, 1e-12);
    fails += sq_check_int(ctx, "loops", info.nloops, ref->nloops);
    fails += sq_check_int(ctx, "corners", info.ncorners, ref->ncorners);
    fails += sq_check_int(ctx, "vertices", info.nvertices, ref->nvertices);
    for (int v = 0; v < info.nvertices && v < ref->nvertices; v++) {
        const sq_vertex *a = &info.vertices[v], *b = &ref->vertices[v];
        double d = hypot(a->x - s * b->x, a->y - s * b->y);
        if (d > 1e-12 * s * (fabs(b->x) + fabs(b->y) + 1)) {
            fprintf(stderr, "%s: vertex %d at (%g, %g), expected (%g, %g)\n", ctx, v, a->x, a->y,
                    s * b->x, s * b->y);
            fails++;
        }
        fails += sq_check_rel(ctx, "corner angle", a->angle_deg, b->angle_deg, 1e-9);
    }
    sq_face_info_free(&info);
    cad_face_free(&f);
    cad_model_free(&m);
    return fails;
}

static int check_file(const char *file)
{
    char path[4096];
    if (!sq_test_path(path, sizeof path, 0, file)) return 77;
    cad_model *m = NULL;
    cad_face *f = NULL;
    sq_error err;
    sq_face_info ref;
    SQ_TEST_OK(cad_model_read(path, &m, &err), err);
    SQ_TEST_OK(cad_face_create(m, 0, &f, &err), err);
    SQ_TEST_OK(sq_face_info_compute(f, &ref, &err), err);
    int fails = 0;
    const double scales[] = {1e-9, 1e-5, 1e5, 1e9};
    for (int k = 0; k < 4; k++) {
        int r = check_scaled(file, &ref, scales[k]);
        if (r == 77) return r;
        fails += r;
    }
    sq_face_info_free(&ref);
    cad_face_free(&f);
    cad_model_free(&m);
    return fails;
}

int main(void)
{
    gsl_set_error_handler_off();
    cad_catch_signals();
    int fails = 0;
    const char *files[] = {"square_hole.step", "disc.step", "naca0012.step"};
    for (int k = 0; k < 3; k++) {
        int r = check_file(files[k]);
        if (r == 77) return r;
        fails += r;
    }
    if (fails == 0) printf("t332: 3 faces at 4 scales from 1e-9 to 1e9: all checks passed\n");
    return fails ? 1 : 0;
}
