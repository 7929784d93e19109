/* Guiding field on every example: the singular points, their valences and
 * positions, the corner valences and the Poincaré–Hopf sum, as issue 4 and
 * the geometries' README state them.
 * Tolerances: the faces' symmetries put the points exactly on axes and
 * centroids, but the triangulations are not symmetric, so a point is off by
 * the field's discretisation error at the order used, not by round-off:
 * 1e-6 of the shape at P = 10 (t402 bounds the change from P to P + 2 by
 * that), 1e-5 where the point sits in a region of coarse elements (the
 * triangle's centroid, the holes' mirror), 1e-4 at order 4.  The BLAS
 * kernel moves them by round-off only (1e-10, a thousandth of that).
 * Corners are matched to the files' points (a few U) within 1e-9. */
#include "field_analysis.h"
#include "test_util.h"

#include <gsl/gsl_errno.h>

static int run(const char *file, sq_field_analysis *a, int order)
{
    char path[4096];
    cad_model *m = NULL;
    cad_face *f = NULL;
    sq_error err;
    sq_test_path(path, sizeof path, 0, file);
    SQ_TEST_OK(cad_model_read(path, &m, &err), err);
    SQ_TEST_OK(cad_face_create(m, 0, &f, &err), err);
    sq_field_options opt;
    sq_field_options_default(&opt);
    opt.order = order;
    opt.tri.order = order;
    SQ_TEST_OK(sq_field_analyse(f, &opt, a, &err), err);
    cad_face_free(&f);
    cad_model_free(&m);
    return 0;
}

/* count of interior points of valence v */
static int count_valence(const sq_field_analysis *a, int v)
{
    int n = 0;
    for (int k = 0; k < a->npoints; k++)
        n += a->points[k].valence == v;
    return n;
}

static int corner_valence_at(const sq_field_analysis *a, double x, double y)
{
    for (int k = 0; k < a->info.nvertices; k++)
        if (hypot(a->info.vertices[k].x - x, a->info.vertices[k].y - y) < 1e-9)
            return a->corners[k].valence;
    return -99;
}

/* is there a point at the mirror image (about x = x0) of each point? */
static double mirror_error(const sq_field_analysis *a, double x0)
{
    double worst = 0.0;
    for (int k = 0; k < a->npoints; k++) {
        double best = HUGE_VAL;
        for (int q = 0; q < a->npoints; q++)
            best = fmin(best, hypot(2 * x0 - a->points[k].x - a->points[q].x,
                                    a->points[k].y - a->points[q].y));
        worst = fmax(worst, best);
    }
    return worst;
}

static int common(const char *file, const sq_field_analysis *a, int npts, int valence,
                  const char *method)
{
    int fails = 0;
    fails += sq_check_int(file, "singular points", a->npoints, npts);
    fails += sq_check_int(file, "singular points of the expected valence",
                          count_valence(a, valence), npts);
    fails += sq_check_int(file, "Poincare-Hopf lhs = 4 chi", a->ph_lhs, a->ph_rhs);
    fails += sq_check_str(file, "method", a->field.method == SEM_CG ? "cg" : "dg", method);
    for (int k = 0; k < a->npoints; k++)
        fails += sq_check_int(file, "near boundary", a->points[k].near_boundary, 0);
    return fails;
}

int main(void)
{
    gsl_set_error_handler_off();
    int fails = 0;
    sq_field_analysis a;

    run("half_disc.step", &a, 8);
    fails += common("half_disc", &a, 2, 3, "cg");
    fails +=
        sq_check_abs("half_disc", "mirror symmetry about x = 0", mirror_error(&a, 0.0), 0.0, 1e-6);
    fails += sq_check_int("half_disc", "corner (1,0)", corner_valence_at(&a, 1, 0), 1);
    sq_field_analysis_free(&a);

    run("quarter_circle.step", &a, 8);
    fails += common("quarter_circle", &a, 1, 3, "cg");
    if (a.npoints == 1)
        fails += sq_check_abs("quarter_circle", "y - x", a.points[0].y - a.points[0].x, 0.0, 1e-6);
    sq_field_analysis_free(&a);

    run("triangle.step", &a, 8);
    fails += common("triangle", &a, 1, 3, "dg");
    if (a.npoints == 1) {
        fails += sq_check_abs("triangle", "x", a.points[0].x, 0.5, 1e-5);
        fails += sq_check_abs("triangle", "y", a.points[0].y, sqrt(3.0) / 6, 1e-5);
    }
    sq_field_analysis_free(&a);

    run("square.step", &a, 6);
    fails += common("square", &a, 0, 3, "cg");
    sq_field_analysis_free(&a);

    run("square_hole.step", &a, 8);
    fails += common("square_hole", &a, 4, 5, "cg");
    for (int k = 0; k < a.npoints; k++) { /* on a diagonal of the square */
        double dx = a.points[k].x - 0.5, dy = a.points[k].y - 0.5;
        fails += sq_check_abs("square_hole", "|dx| - |dy|", fabs(dx) - fabs(dy), 0.0, 1e-5);
    }
    sq_field_analysis_free(&a);

    run("two_holes.step", &a, 8);
    fails += common("two_holes", &a, 2, 5, "cg");
    fails +=
        sq_check_abs("two_holes", "mirror symmetry about x = 2", mirror_error(&a, 2.0), 0.0, 1e-5);
    sq_field_analysis_free(&a);

    run("nautilus.step", &a, 8);
    fails += common("nautilus", &a, 4, 3, "cg");
    fails += sq_check_int("nautilus", "corner (0,0) of 270 deg", corner_valence_at(&a, 0, 0), 3);
    sq_field_analysis_free(&a);

    run("annulus.step", &a, 6);
    fails += common("annulus", &a, 0, 3, "cg");
    sq_field_analysis_free(&a);

    run("lshape.step", &a, 6);
    fails += common("lshape", &a, 0, 3, "cg");
    fails += sq_check_int("lshape", "corner (1,1) of 270 deg", corner_valence_at(&a, 1, 1), 3);
    fails += sq_check_int("lshape", "corner (0,0)", corner_valence_at(&a, 0, 0), 1);
    sq_field_analysis_free(&a);

    run("polygon.step", &a, 8);
    fails += common("polygon", &a, 0, 3, "dg");
    fails += sq_check_int("polygon", "corner of 140.5 deg", corner_valence_at(&a, 0.5, 1.8), 2);
    fails += sq_check_int("polygon", "corner (0,0)", corner_valence_at(&a, 0, 0), 1);
    fails += sq_check_int("polygon", "corner (3,0)", corner_valence_at(&a, 3, 0), 1);
    fails += sq_check_int("polygon", "corner (4,1.5)", corner_valence_at(&a, 4, 1.5), 1);
    fails += sq_check_int("polygon", "corner (1.5,2.5)", corner_valence_at(&a, 1.5, 2.5), 1);
    sq_field_analysis_free(&a);

    /* naca0012: DG (the trailing edge is a 343.5 deg corner); we find two
     * valence-5 points just ahead of the leading edge, and the trailing
     * edge takes 4 quads */
    run("naca0012.step", &a, 8);
    fails += common("naca0012", &a, 2, 5, "dg");
    fails += sq_check_int("naca0012", "trailing edge quads", corner_valence_at(&a, 1, 0), 4);
    fails += sq_check_abs("naca0012", "mirror symmetry about y = 0 (sum of y)",
                          a.npoints == 2 ? a.points[0].y + a.points[1].y : 1.0, 0.0, 1e-4);
    sq_field_analysis_free(&a);

    /* Order 4, the mesh command's default: the same singular points on
     * every example.  The triangle's centre is a vertex of its (symmetric)
     * triangulation, where each DG polynomial around it has its root just
     * across an edge: found by the critical-point search's edge rule. */
    static const struct {
        const char *file, *method;
        int npts, valence;
    } p4[] = {
        {"half_disc", "cg", 2, 3}, {"quarter_circle", "cg", 1, 3}, {"triangle", "dg", 1, 3},
        {"square", "cg", 0, 3},    {"square_hole", "cg", 4, 5},    {"two_holes", "cg", 2, 5},
        {"nautilus", "cg", 4, 3},  {"annulus", "cg", 0, 3},        {"lshape", "cg", 0, 3},
        {"polygon", "dg", 0, 3},   {"naca0012", "dg", 2, 5},       {"obtuse_quad", "dg", 1, 3}};
    for (size_t k = 0; k < sizeof p4 / sizeof *p4; ++k) {
        char file[64], name[80];
        snprintf(file, sizeof file, "%s.step", p4[k].file);
        snprintf(name, sizeof name, "%s P=4", p4[k].file);
        run(file, &a, 4);
        fails += common(name, &a, p4[k].npts, p4[k].valence, p4[k].method);
        if (!strcmp(p4[k].file, "triangle") && a.npoints == 1) {
            fails += sq_check_abs(name, "x", a.points[0].x, 0.5, 1e-5);
            fails += sq_check_abs(name, "y", a.points[0].y, sqrt(3.0) / 6, 1e-5);
        }
        sq_field_analysis_free(&a);
    }
    return fails ? 1 : 0;
}
