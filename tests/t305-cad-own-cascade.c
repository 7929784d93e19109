/* t305 — the project's own cascade passage and aerofoil box
 * (tests/cascade_aerofoil.py, written into the build directory), read as
 * t304 reads NekMesh's T106 cascade and aerofoil box, so that every clone
 * checks what those files exercise: metres kept, one face, the outer loop
 * of straight edges, the blade a hole of two cubic B-splines joined
 * tangentially, a plane written with its axis along -z (the face's frame
 * still x, y), the area, the hole clockwise, the chord, closed loops.
 * argv: cascade.step aerofoil_box.step; their NAME.facts beside them hold
 * what the generator knows exactly (area by Green's theorem on the
 * B-splines' polynomial pieces, corners, chord).
 * Tolerances: the area here is green() (5-point Gauss on 2000 panels an
 * edge, in arc length): the code's arc-length map is exact to its 1e-9
 * slack of an edge's length, which scales the integrand's ds by as much,
 * so 1e-9 of the area (the panels straddling the B-splines' knots, where
 * the third derivative jumps, add O(h^4), h = L/2000, each: far less); the chord is a maximum over samples on both sides,
 * each short by at most its sample spacing (the facts give the
 * generator's); corner coordinates are written to 17 digits and scaled
 * twice (metres read as millimetres and back): a few U of 2.5, 1e-14;
 * frames are unit axes, exact to 1e-15 (t304); loops close within the
 * code's 1e-9 arc-length slack. */
#include "cad.h"
#include "t30x_cad.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct {
    double area, chord, spacing;
    int ncorners;
    double corner[16][3]; /* x, y, interior angle (deg) */
} facts;

/* NAME.facts beside NAME.step: "key value..." lines. */
static int read_facts(const char *step, facts *out)
{
    char path[4096], key[64];
    snprintf(path, sizeof path, "%.*s.facts", (int)(strlen(step) - 5), step);
    FILE *fp = fopen(path, "r");
    if (!fp) {
        CHECK(0, "%s: cannot open", path);
        return 0;
    }
    memset(out, 0, sizeof *out);
    while (fscanf(fp, "%63s", key) == 1) {
        if (!strcmp(key, "area")) CHECK(fscanf(fp, "%lf", &out->area) == 1, "%s: area", path);
        else if (!strcmp(key, "chord")) CHECK(fscanf(fp, "%lf", &out->chord) == 1, "%s: chord", path);
        else if (!strcmp(key, "sample_spacing")) CHECK(fscanf(fp, "%lf", &out->spacing) == 1, "%s", path);
        else if (!strcmp(key, "corner") && out->ncorners < 16) {
            double *c = out->corner[out->ncorners++];
            CHECK(fscanf(fp, "%lf %lf %lf", &c[0], &c[1], &c[2]) == 3, "%s: corner", path);
        }
        int ch;
        while ((ch = fgetc(fp)) != EOF && ch != '\n') continue; /* the rest of the line */
    }
    fclose(fp);
    return 1;
}

static cad_face *open_face(const char *path, cad_model **m)
{
    sq_error err;
    cad_face *f = NULL;
    *m = NULL;
    if (cad_model_read(path, m, &err) != SQ_OK) {
        CHECK(0, "%s: %s", path, err.msg);
        return NULL;
    }
    CHECK(!strcmp(cad_model_unit(*m), "m"), "%s: unit %s, expected m", path, cad_model_unit(*m));
    CHECK(cad_model_num_faces(*m) == 1, "%s: %d faces, expected 1", path, cad_model_num_faces(*m));
    if (cad_face_create(*m, 0, &f, &err) != SQ_OK) CHECK(0, "%s: %s", path, err.msg);
    return f;
}

/* What both faces share: an outer loop of nlines lines at the facts'
 * corners, a hole of two B-splines, clockwise; area, chord, closure. */
static void check_face(const char *name, const cad_face *f, const facts *k, int nlines)
{
    CHECK(cad_face_num_loops(f) == 2, "%s: %d loops, expected 2", name, cad_face_num_loops(f));
    if (cad_face_num_loops(f) != 2) return;
    CHECK(cad_face_loop_num_edges(f, 0) == nlines && cad_face_loop_num_edges(f, 1) == 2,
          "%s: %d outer + %d hole edges, expected %d + 2", name, cad_face_loop_num_edges(f, 0),
          cad_face_loop_num_edges(f, 1), nlines);
    for (int e = 0; e < cad_face_num_edges(f); ++e) {
        cad_edge_type want = cad_face_edge_loop(f, e) == 0 ? CAD_EDGE_LINE : CAD_EDGE_BSPLINE;
        CHECK(cad_face_edge_type(f, e) == want, "%s: edge %d is a %s, expected a %s", name, e,
              cad_edge_type_name(cad_face_edge_type(f, e)), cad_edge_type_name(want));
    }
    /* every corner of the facts is the start of an outer edge */
    CHECK(k->ncorners == nlines, "%s: %d corners in the facts", name, k->ncorners);
    for (int c = 0; c < k->ncorners; ++c) {
        double best = HUGE_VAL, p[2];
        for (int e = 0; e < cad_face_loop_num_edges(f, 0); ++e) {
            eval(f, e, 0, p, NULL, NULL);
            best = fmin(best, hypot(p[0] - k->corner[c][0], p[1] - k->corner[c][1]));
        }
        char what[160];
        snprintf(what, sizeof what, "%s: corner (%g, %g), distance to the nearest vertex", name,
                 k->corner[c][0], k->corner[c][1]);
        NEAR(what, best, 0.0, 1e-14);
    }
    char what[160];
    snprintf(what, sizeof what, "%s: area (m^2)", name);
    NEAR(what, green(f, -1, 2000), k->area, 1e-9 * k->area);
    CHECK(green(f, 1, 2000) < 0, "%s: the hole must be clockwise", name);
    snprintf(what, sizeof what, "%s: chord (m)", name);
    double spacing = 0;
    for (int e = cad_face_loop_first_edge(f, 1); e < cad_face_num_edges(f); ++e)
        spacing = fmax(spacing, cad_face_edge_length(f, e) / 400);
    NEAR(what, loop_diameter(f, 1), k->chord, fmax(spacing, k->spacing));
    check_closed(name, f, 1e-9);
}

int main(int argc, char **argv)
{
    if (argc != 3) {
        printf("usage: t305-cad-own-cascade cascade.step aerofoil_box.step\n");
        return 1;
    }
    facts k;
    cad_model *m = NULL;
    cad_face *f = NULL;

    /* the cascade: 10 lines, the blade two B-splines joined tangentially */
    if (read_facts(argv[1], &k) && (f = open_face(argv[1], &m))) {
        check_face("cascade", f, &k, 10);
        double o[3], x[3], y[3];
        cad_face_frame(f, o, x, y);
        NEAR("cascade frame: x axis", x[0], 1.0, 1e-15);
        NEAR("cascade frame: y axis", y[1], 1.0, 1e-15);
        if (cad_face_num_loops(f) == 2) {
            int a = cad_face_loop_first_edge(f, 1), b = a + 1;
            double ta[2], tb[2];
            eval(f, a, cad_face_edge_length(f, a), NULL, ta, NULL);
            eval(f, b, 0, NULL, tb, NULL);
            /* the generator clamps both ends to one unit tangent, to 1e-8 rad
             * (its Richardson secant): the cross product of the two */
            NEAR("cascade: blade junction, sine of the tangent jump", ta[0] * tb[1] - ta[1] * tb[0],
                 0.0, 1e-7);
        }
    }
    cad_face_free(&f);
    cad_model_free(&m);

    /* the aerofoil box: 4 lines of the box [-0.5, 1.5] x [-0.75, 0.75] */
    if (read_facts(argv[2], &k) && (f = open_face(argv[2], &m))) {
        check_face("aerofoil box", f, &k, 4);
        check_box("aerofoil", f, 4, (const double[4]){-0.5, -0.75, 1.5, 0.75}, 1e-14);
    }
    cad_face_free(&f);
    cad_model_free(&m);
    return failures ? 1 : 0;
}
