/* t304 — optional real CAD files written by others (NekMesh's test inputs,
 * tests/README.md): units kept (metres), areas, edges, holes, default face.
 * Skips (77) with one line if $SEMQUAD_REAL_GEOMETRIES does not name a
 * folder holding them (t305 checks the same on the project's own cascade
 * and aerofoil box).
 * Tolerances: areas and boxes are against values with 6 to 7 significant
 * digits (the files' READMEs), so 1e-5 of m^2 and 1e-9 of a box side given
 * exactly; frames are OCC's unit axes, exact up to a few U (1e-15); the
 * curvature of a circle OCC evaluates in closed form (a few U relative of
 * 1/35: 1e-12); the disc's area by green() with the code's arc-length
 * tolerances (t302), relative 3e-12 of 3.8e3 mm^2: 1e-8; loops close
 * within the code's 1e-9 L arc-length slack (check_closed). */
#include "cad.h"
#include "t30x_cad.h"
#include "test_util.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static cad_model *read_model(const char *dir, const char *file)
{
    char path[4096];
    snprintf(path, sizeof path, "%s/%s", dir, file);
    sq_error err;
    cad_model *m = NULL;
    if (cad_model_read(path, &m, &err) != SQ_OK) {
        fprintf(stderr, "%s: %s\n", path, err.msg);
        ++failures;
    }
    return m;
}

int main(void)
{
    char probe[4096];
    if (!sq_test_path(probe, sizeof probe, 1, "real_t106_cascade.step")) return 77;
    const char *dir = getenv("SEMQUAD_REAL_GEOMETRIES");
    sq_error err;
    cad_face *f = NULL;

    /* T106 cascade: metres, 10 straight edges, a B-spline blade as the hole. */
    cad_model *m = read_model(dir, "real_t106_cascade.step");
    if (m) {
        CHECK(!strcmp(cad_model_unit(m), "m"), "t106: unit %s, expected m", cad_model_unit(m));
        CHECK(cad_model_num_faces(m) == 1, "t106: %d faces", cad_model_num_faces(m));
        CHECK(cad_face_create(m, 0, &f, &err) == SQ_OK, "t106: %s", err.msg);
    }
    if (f) {
        CHECK(cad_face_num_loops(f) == 2, "t106: %d loops, expected 2", cad_face_num_loops(f));
        CHECK(cad_face_loop_num_edges(f, 0) == 10, "t106: %d outer edges, expected 10",
              cad_face_loop_num_edges(f, 0));
        for (int k = 0; k < cad_face_loop_num_edges(f, 0); ++k)
            CHECK(cad_face_edge_type(f, k) == CAD_EDGE_LINE, "t106: outer edge %d is a %s", k,
                  cad_edge_type_name(cad_face_edge_type(f, k)));
        for (int k = 0; k < cad_face_loop_num_edges(f, 1); ++k) {
            int e = cad_face_loop_first_edge(f, 1) + k;
            CHECK(cad_face_edge_type(f, e) == CAD_EDGE_BSPLINE, "t106: hole edge %d is a %s", e,
                  cad_edge_type_name(cad_face_edge_type(f, e)));
        }
        double o[3], x[3], y[3];
        cad_face_frame(f, o, x, y);
        NEAR("t106 frame: x axis", x[0], 1.0, 1e-15);
        NEAR("t106 frame: y axis", y[1], 1.0, 1e-15);
        NEAR("t106 area (m^2)", green(f, -1, 2000), 2.894541, 1e-5);
        CHECK(green(f, 1, 2000) < 0, "t106: the hole must be clockwise");
        NEAR("t106 chord (m)", loop_diameter(f, 1), 1.0, 0.01);
        check_closed("t106", f, 1e-9);
        cad_face_free(&f);
    }
    cad_model_free(&m);

    /* Aerofoil box: metres, rectangle with a two-B-spline hole. */
    m = read_model(dir, "real_aerofoil_box.step");
    if (m) {
        CHECK(!strcmp(cad_model_unit(m), "m"), "aerofoil: unit %s, expected m", cad_model_unit(m));
        CHECK(cad_face_create(m, 0, &f, &err) == SQ_OK, "aerofoil: %s", err.msg);
    }
    if (f) {
        CHECK(cad_face_num_loops(f) == 2 && cad_face_loop_num_edges(f, 0) == 4 &&
                  cad_face_loop_num_edges(f, 1) == 2,
              "aerofoil: loops %d, edges %d + %d, expected 2 loops 4 + 2", cad_face_num_loops(f),
              cad_face_loop_num_edges(f, 0), cad_face_loop_num_edges(f, 1));
        NEAR("aerofoil area (m^2)", green(f, -1, 2000), 2.989443, 1e-5);
        check_box("aerofoil", f, 4, (const double[4]){-0.5, -0.75, 1.5, 0.75}, 1e-9);
        NEAR("aerofoil chord (m)", loop_diameter(f, 1), 0.3124, 0.002);
        check_closed("aerofoil", f, 1e-9);
        cad_face_free(&f);
    }
    cad_model_free(&m);

    /* Circle and square (FreeCAD, mm): two planar faces; face 1 is the square. */
    m = read_model(dir, "real_circle_square.step");
    if (m) {
        const char *note = NULL;
        CHECK(!strcmp(cad_model_unit(m), "mm"), "circle_square: unit %s", cad_model_unit(m));
        CHECK(cad_model_num_faces(m) == 2, "circle_square: %d faces, expected 2", cad_model_num_faces(m));
        CHECK(!strcmp(cad_model_face_surface(m, 0), "plane") && !strcmp(cad_model_face_surface(m, 1), "plane"),
              "circle_square: both faces should be planes");
        CHECK(cad_model_default_face(m, &note) == 0 && note && note[0],
              "circle_square: two planar faces: default 0 with a note");
        CHECK(cad_face_create(m, 0, &f, &err) == SQ_OK, "circle_square face 0: %s", err.msg);
        if (f) {
            CHECK(cad_face_num_loops(f) == 1, "circle_square face 0: %d loops", cad_face_num_loops(f));
            NEAR("circle_square disc area (mm^2)", green(f, -1, 64), M_PI * 35 * 35, 1e-8);
            cad_face_free(&f);
        }
        CHECK(cad_face_create(m, 1, &f, &err) == SQ_OK, "circle_square face 1: %s", err.msg);
    }
    if (f) {
        CHECK(cad_face_num_loops(f) == 2 && cad_face_loop_num_edges(f, 0) == 4,
              "circle_square face 1: %d loops, %d outer edges", cad_face_num_loops(f),
              cad_face_loop_num_edges(f, 0));
        for (int e = cad_face_loop_first_edge(f, 1); e < cad_face_num_edges(f); ++e) {
            double k;
            CHECK(cad_face_edge_type(f, e) == CAD_EDGE_CIRCLE, "circle_square hole edge %d: %s", e,
                  cad_edge_type_name(cad_face_edge_type(f, e)));
            eval(f, e, 0.5 * cad_face_edge_length(f, e), NULL, NULL, &k);
            NEAR("circle_square hole curvature (1/mm)", k, -1.0 / 35, 1e-12);
        }
        NEAR("circle_square face 1 area (mm^2)", green(f, -1, 64), 6158.884, 1e-3);
        double lo = HUGE_VAL, hi = -HUGE_VAL;
        for (int e = 0; e < 4; ++e) {
            double p[2];
            eval(f, e, 0, p, NULL, NULL);
            lo = fmin(lo, p[0]);
            hi = fmax(hi, p[0]);
        }
        NEAR("circle_square xmin", lo, -50.14393, 1e-4);
        NEAR("circle_square xmax", hi, 49.99620, 1e-4);
        check_closed("circle_square", f, 1e-9);
        cad_face_free(&f);
    }
    cad_model_free(&m);
    return failures ? 1 : 0;
}
