/* Singular points very close to the boundary (issue 14, the T106 cascade's
 * class): a 2 x 1 box with a slot 0.8 long and 2r = 0.004 wide, turned by
 * 20°, as a hole.  Around each rounded end the boundary turns by 180° within
 * r, and the guiding field has two valence-5 zeros there, about r/2 from
 * the boundary: 4 points, the Gauss-Bonnet minimum of the face (4 corners of
 * one quad, χ = 0).  They lie within 1e-3 of the face's size of the
 * boundary, where they used to be flagged "on the boundary" and dropped
 * (Poincaré-Hopf broken, no valid layout); lines running on either side of
 * the slot met across it.  Now: the 4 points read, a valid layout of 12
 * quad patches with exactly them, no separatrix inside the slot.  The face
 * is written by Gmsh's OpenCASCADE kernel (/usr/bin/python3). */
#include "layout_pipeline.h"
#include "test_util.h"

#include <gsl/gsl_errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <unistd.h>

#define R 0.002      /* the slot's end radius */
#define HALF 0.4     /* its half length */
#define TURN_DEG 20.0

static int write_face(const char *path)
{
    char cmd[2048];
    snprintf(cmd, sizeof cmd,
             "/usr/bin/python3 -c \"import gmsh, math; gmsh.initialize(); "
             "gmsh.option.setNumber('General.Terminal', 0); o = gmsh.model.occ; "
             "b = o.addRectangle(-1, -0.5, 0, 2, 1); "
             "s = o.addRectangle(%.17g, %.17g, 0, %.17g, %.17g, roundedRadius=%.17g); "
             "o.rotate([(2, s)], 0, 0, 0, 0, 0, 1, math.radians(%.17g)); "
             "o.cut([(2, b)], [(2, s)]); o.synchronize(); gmsh.write('%s'); "
             "gmsh.finalize()\" > /dev/null",
             -HALF, -R, 2 * HALF, 2 * R, 0.999 * R, TURN_DEG, path);
    return system(cmd);
}

/* Distance from p to the slot's axis (the segment between the centres of
 * its rounded ends): r on the slot's boundary, less inside. */
static double axis_distance(const double p[2])
{
    double c = cos(TURN_DEG * M_PI / 180.0), s = sin(TURN_DEG * M_PI / 180.0);
    double u = c * p[0] + s * p[1], v = -s * p[0] + c * p[1];
    double du = fmax(fabs(u) - (HALF - R), 0.0);
    return hypot(du, v);
}

int main(void)
{
    gsl_set_error_handler_off();
    char dir[] = "/tmp/t517-XXXXXX", path[64];
    if (!mkdtemp(dir)) {
        printf("t517: no temporary directory\n");
        return 1;
    }
    snprintf(path, sizeof path, "%s/slot.step", dir);
    if (write_face(path) != 0) {
        printf("t517: gmsh could not write %s\n", path);
        return 1;
    }
    sq_error err;
    cad_model *m = NULL;
    cad_face *f = NULL;
    SQ_TEST_OK(cad_model_read(path, &m, &err), err);
    SQ_TEST_OK(cad_face_create(m, 0, &f, &err), err);
    sq_layout_options opt;
    sq_layout_options_default(&opt);
    sq_layout_result r;
    sq_status st = sq_layout_run(f, &opt, &r, &err);
    int fails = 0;
    if (st != SQ_OK) {
        printf("slot: sq_layout_run: %s\n", err.msg);
        fails++;
    }
    const sq_field_analysis *a = &r.analysis;
    const double diag = hypot(a->info.bbox[2] - a->info.bbox[0], a->info.bbox[3] - a->info.bbox[1]);
    fails += sq_check_int("slot", "Poincare-Hopf lhs", a->ph_lhs, a->ph_rhs);
    int near = 0;
    for (int k = 0; k < a->npoints; k++) {
        const sq_critical_point *p = &a->points[k];
        fails += sq_check_int("slot", "critical point valence", p->valence, 5);
        fails += sq_check_int("slot", "critical point on the boundary", p->near_boundary, 0);
        near += p->dist_boundary < 1e-3 * diag; /* the class the test is about */
    }
    fails += sq_check_int("slot", "critical points", a->npoints, 4);
    fails += sq_check_int("slot", "of them within 1e-3 of the face's size", near, 4);
    if (st == SQ_OK) {
        fails += sq_check_int("slot", "layout singular points", r.nsing, 4);
        fails += sq_check_int("slot", "Gauss-Bonnet minimum", r.report.gauss_bonnet_min, 4);
        fails += sq_check_int("slot", "patches", r.layout.npatches, 12);
        fails += sq_check_int("slot", "quad patches", r.layout.stats.quad_patches, 12);
        sq_layout_defects d;
        fails += sq_check_int("slot", "defects", sq_layout_check(&r.layout, &d), 0);
        sq_layout_defects_free(&d);
        /* no separatrix point inside the slot: at least r from its axis, up
         * to the field triangulation's curved boundary (order 8 on arcs of
         * 30°: relative chord error far below the 1e-3 allowed) */
        double closest = HUGE_VAL;
        for (int s = 0; s < r.layout.seps.n; s++)
            for (int j = 0; j < r.layout.seps.s[s].npts; j++)
                closest = fmin(closest, axis_distance(&r.layout.seps.s[s].xy[2 * j]));
        if (closest < R * (1.0 - 1e-3)) {
            printf("slot: a separatrix runs inside the slot (%g from its axis, r = %g)\n",
                   closest, R);
            fails++;
        }
    }
    sq_layout_result_free(&r);
    cad_face_free(&f);
    cad_model_free(&m);
    remove(path);
    rmdir(dir);
    return fails != 0;
}
