/* The coarse curved triangulation: the integral of det J over the curved
 * elements matches the exact area to round-off at P = 8 and converges as P
 * grows; every element's scaled Jacobian is positive; CGAL's angle bound
 * holds; every boundary vertex and high-order boundary node lies on its CAD
 * curve; extra points become vertices with graded refinement around them. */
#include "cad.h"
#include "face_info.h"
#include "test_util.h"
#include "triangulate.h"
#include "gauss.h"
#include "sem_roundoff.h"
#include "tri_nodes.h"

#include <gsl/gsl_errno.h>

static const double PI = 3.14159265358979323846;

static int open_example(const char *file, cad_model **m, cad_face **f)
{
    char path[4096];
    sq_error err;
    sq_test_path(path, sizeof path, 0, file);
    SQ_TEST_OK(cad_model_read(path, m, &err), err);
    SQ_TEST_OK(cad_face_create(*m, 0, f, &err), err);
    return 0;
}

/* Distance of every boundary-edge node of the mesh from its CAD edge. */
static double boundary_node_distance(const cad_face *f, const sem_tri_mesh *m)
{
    int P = m->order;
    int idx[SEM_MAX_ORDER + 1];
    double worst = 0.0;
    sq_error err;
    for (int e = 0; e < m->ntris; e++)
        for (int k = 0; k < 3; k++) {
            if (m->btag[3 * e + k] < 0) continue;
            sem_tri_edge_nodes(P, k, idx);
            for (int i = 0; i <= P; i++) {
                const double *x = &m->gxy[2 * ((size_t)m->nodes_per_tri * e + idx[i])];
                double d;
                SQ_TEST_OK(cad_face_edge_project(f, m->btag[3 * e + k], x, NULL, NULL, &d, &err),
                           err);
                if (d > worst) worst = d;
            }
        }
    return worst;
}

/* Relative round-off of an area sum w det J through the nodal basis of
 * order P: det J's relative error 2 n kappa_1(V) U max sum |dl_k| (the map's
 * derivatives, sem_roundoff.h; a worst case: 1.3e-10 at P = 8, 5.6e-13 at
 * P = 3, where the runs give 1e-15) plus the sum's. */
static double area_roundoff(int P)
{
    sem_tri_lagrange *L = NULL;
    if (sem_tri_lagrange_create(P, &L, NULL) != SQ_OK) return 0.0;
    const double r = 2 * sq_lagrange_roundoff(L) * sq_lagrange_dsum(L);
    sem_tri_lagrange_free(&L);
    return r;
}

static int check_area(const char *file, double exact)
{
    cad_model *m = NULL;
    cad_face *f = NULL;
    sq_error err;
    int fails = 0;
    open_example(file, &m, &f);
    double prev = HUGE_VAL;
    const int orders[] = {1, 2, 4, 8};
    for (int i = 0; i < 4; i++) {
        sq_tri_options opt;
        sq_tri_options_default(&opt);
        opt.order = orders[i];
        sq_triangulation t;
        SQ_TEST_OK(sq_triangulate(f, &opt, &t, &err), err);
        double e = fabs(t.area - exact) / exact;
        char what[64];
        snprintf(what, sizeof what, "P=%d area error decreases", opt.order);
        /* below the round-off it need not decrease */
        if (i > 0 && !(e < prev || e < area_roundoff(opt.order))) {
            printf("%s: %s: %.3g after %.3g\n", file, what, e, prev);
            fails++;
        }
        prev = e;
        /* at P = 8 the arcs' interpolation error is below round-off */
        if (opt.order == 8)
            fails += sq_check_rel(file, "area at P=8", t.area, exact, area_roundoff(8));
        if (!(t.min_scaled_jacobian > 0.0)) {
            printf("%s: P=%d min scaled Jacobian %g <= 0\n", file, opt.order, t.min_scaled_jacobian);
            fails++;
        }
        if (t.min_angle_deg < 20.0 - 1e-9) { /* CGAL's bound, angles by acos: 1e-9 deg */
            printf("%s: min angle %g < 20\n", file, t.min_angle_deg);
            fails++;
        }
        /* nodes are curve points (cad_face_edge_eval, a few U of
         * coordinates <= 4); the distance is the projection's round-off */
        fails += sq_check_abs(file, "boundary node distance to the CAD curve",
                              boundary_node_distance(f, t.mesh), 0.0, 1e-12);
        sq_triangulation_free(&t);
    }
    cad_face_free(&f);
    cad_model_free(&m);
    return fails;
}

/* Extra points are vertices, and elements near them are small. */
static int check_extra_points(void)
{
    cad_model *m = NULL;
    cad_face *f = NULL;
    sq_error err;
    int fails = 0;
    open_example("square.step", &m, &f);
    sq_tri_options opt;
    sq_tri_options_default(&opt);
    const double extra[4] = {0.3, 0.4, 0.7, 0.65};
    opt.order = 3;
    opt.size = 0.25;
    opt.nextra = 2;
    opt.extra_xy = extra;
    opt.extra_size = 0.02;
    sq_triangulation t;
    SQ_TEST_OK(sq_triangulate(f, &opt, &t, &err), err);
    const sem_tri_mesh *mesh = t.mesh;
    for (int p = 0; p < 2; p++) {
        int found = 0;
        for (int v = 0; v < mesh->nverts; v++)
            if (mesh->vxy[2 * v] == extra[2 * p] && mesh->vxy[2 * v + 1] == extra[2 * p + 1]) found = 1;
        fails += sq_check_int("square+extra", "extra point is a vertex", found, 1);
    }
    /* longest edge of the triangles touching the first extra point */
    double hmax = 0.0;
    for (int e = 0; e < mesh->ntris; e++)
        for (int k = 0; k < 3; k++) {
            const double *a = &mesh->vxy[2 * mesh->tri[3 * e + k]];
            if (a[0] != extra[0] || a[1] != extra[1]) continue;
            for (int q = 0; q < 3; q++) {
                const double *b = &mesh->vxy[2 * mesh->tri[3 * e + q]];
                double d = hypot(b[0] - a[0], b[1] - a[1]);
                if (d > hmax) hmax = d;
            }
        }
    if (!(hmax > 0.0 && hmax <= 2 * opt.extra_size)) {
        printf("square+extra: edges at the extra point up to %g, expected <= %g\n", hmax,
               2 * opt.extra_size);
        fails++;
    }
    fails += sq_check_rel("square+extra", "area", t.area, 1.0, area_roundoff(opt.order));
    sq_triangulation_free(&t);
    cad_face_free(&f);
    cad_model_free(&m);
    return fails;
}

int main(void)
{
    gsl_set_error_handler_off();
    int fails = 0;
    fails += check_area("half_disc.step", PI / 2);
    fails += check_area("annulus.step", PI * (1 - 0.16));
    fails += check_area("square_hole.step", 1 - PI / 16);
    fails += check_area("quarter_circle.step", PI / 4);
    fails += check_area("nautilus.step", 5 * PI / 8);
    fails += check_area("two_holes.step", 8 - PI / 2);
    fails += check_extra_points();
    return fails ? 1 : 0;
}
