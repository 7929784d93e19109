/* The n-quad split of patches with n != 3, 4 corners (the last repair of
 * sq_layout_build): a regular pentagon and an irregular one, each face vertex taking one quad and no separatrix, so
 * the whole face is one 5-corner patch.  Without a field no extra
 * separatrix can be traced, so the patch is split around a centre into
 * five quads: a valence-5 node joined to the five side midpoints (feet on
 * the boundary).  The faces are written by Gmsh's OpenCASCADE kernel
 * (/usr/bin/python3). */
#include "layout.h"
#include "test_util.h"

#include <gsl/gsl_errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static int write_polygon(const char *path, const double *xy, int n)
{
    char cmd[4096];
    int len = snprintf(cmd, sizeof cmd,
                       "/usr/bin/python3 -c \"import gmsh; gmsh.initialize(); "
                       "gmsh.option.setNumber('General.Terminal', 0); p = [");
    for (int k = 0; k < n; k++)
        len += snprintf(cmd + len, sizeof cmd - (size_t)len, "gmsh.model.occ.addPoint(%.17g, %.17g, 0), ",
                        xy[2 * k], xy[2 * k + 1]);
    snprintf(cmd + len, sizeof cmd - (size_t)len,
             "]; l = [gmsh.model.occ.addLine(p[i], p[(i + 1) %% %d]) for i in range(%d)]; "
             "gmsh.model.occ.addPlaneSurface([gmsh.model.occ.addCurveLoop(l)]); "
             "gmsh.model.occ.synchronize(); gmsh.write('%s'); gmsh.finalize()\"",
             n, n, path);
    strncat(cmd, " > /dev/null", sizeof cmd - strlen(cmd) - 1);
    return system(cmd);
}

/* Build the layout of the polygon (one quad per vertex, no separatrix) and
 * check the split: 5 quad patches of a valid layout, one inserted node of
 * valence 5 at `cen`, patch areas summing to the face's. */
static int check_polygon(const char *name, const char *dir, const double *xy, int n,
                         const double cen[2], double tol)
{
    char path[4096];
    snprintf(path, sizeof path, "%s/%s.step", dir, name);
    if (write_polygon(path, xy, n) != 0) {
        printf("%s: gmsh could not write %s\n", name, path);
        return 1;
    }
    sq_error err;
    cad_model *m = NULL;
    cad_face *f = NULL;
    sq_face_info info;
    SQ_TEST_OK(cad_model_read(path, &m, &err), err);
    SQ_TEST_OK(cad_face_create(m, 0, &f, &err), err);
    SQ_TEST_OK(sq_face_info_compute(f, &info, &err), err);
    int fails = sq_check_int(name, "face vertices", info.nvertices, n);
    int quads[16];
    for (int k = 0; k < info.nvertices && k < 16; k++) quads[k] = 1;
    sq_separatrix_set none = {0, 0, NULL};
    sq_layout L;
    sq_status st = sq_layout_build(f, &info, quads, 0, NULL, &none, NULL, NULL, &L, &err);
    if (st != SQ_OK) {
        printf("%s: sq_layout_build: %s\n", name, err.msg);
        fails++;
    } else {
        fails += sq_check_int(name, "polygons split", L.stats.polygons_split, 1);
        fails += sq_check_int(name, "patches", L.npatches, n);
        fails += sq_check_int(name, "quad patches", L.stats.quad_patches, n);
        fails += sq_check_int(name, "separatrices", L.stats.separatrices, n);
        sq_layout_defects d;
        fails += sq_check_int(name, "defects", sq_layout_check(&L, &d), 0);
        sq_layout_defects_free(&d);
        fails += sq_check_int(name, "inserted nodes", L.nsing, 1);
        if (L.nsing == 1) {
            fails += sq_check_int(name, "node valence", L.sing[0].valence, n);
            fails += sq_check_int(name, "node role", L.role[0], SQ_LROLE_MIDPOINT);
            fails += sq_check_abs(name, "node x", L.sing[0].x, cen[0], tol);
            fails += sq_check_abs(name, "node y", L.sing[0].y, cen[1], tol);
        }
        /* areas exact (Green's theorem on straight sides and straight
         * spokes): round-off of sums of O(1) terms */
        double sum = 0.0;
        for (int p = 0; p < L.npatches; p++) sum += L.patches[p].area;
        fails += sq_check_rel(name, "area sum", sum, info.area, 1e-12);
        sq_layout_free(&L);
    }
    sq_face_info_free(&info);
    cad_face_free(&f);
    cad_model_free(&m);
    remove(path);
    return fails;
}

int main(void)
{
    gsl_set_error_handler_off();
    char dir[] = "/tmp/t516-XXXXXX";
    if (!mkdtemp(dir)) {
        printf("t516: no temporary directory\n");
        return 1;
    }
    int fails = 0;
    /* regular pentagon of circumradius 1: its centroid, the origin, sees
     * every side midpoint; the five quads are congruent (area / 5 each) */
    double pent[10];
    for (int k = 0; k < 5; k++) {
        pent[2 * k] = cos(M_PI / 2 + 2 * M_PI * k / 5);
        pent[2 * k + 1] = sin(M_PI / 2 + 2 * M_PI * k / 5);
    }
    const double origin[2] = {0.0, 0.0};
    /* the centroid by Green's theorem on the straight sides: round-off */
    fails += check_polygon("pentagon", dir, pent, 5, origin, 1e-12);
    /* a house, (0,0), (2,0), (2,1.5), (1,2.5), (0,1.5): irregular (corners of
     * 90° and 135°, sides of 1.41 to 2); the node at its area centroid,
     * (1, y) with y by the shoelace formula (x = 1 by symmetry) */
    double house[10] = {0, 0, 2, 0, 2, 1.5, 1, 2.5, 0, 1.5};
    double a2 = 0.0, my = 0.0; /* twice the area, 6 × the y moment */
    for (int k = 0; k < 5; k++) {
        const double *p = &house[2 * k], *q = &house[2 * ((k + 1) % 5)];
        double c = p[0] * q[1] - q[0] * p[1];
        a2 += c;
        my += (p[1] + q[1]) * c;
    }
    const double hcen[2] = {1.0, my / (3.0 * a2)};
    fails += check_polygon("house", dir, house, 5, hcen, 1e-12);
    rmdir(dir);
    return fails != 0;
}
