/* t321 — cad_face_split and its STEP export keep the file's 3D frame and
 * length unit:
 *  - the unit square rotated into the plane x = 0 (every 3D point and
 *    direction of the example permuted (x, y, z) -> (y, z, x), the
 *    representation's own placement too, so the face is turned twice:
 *    (a, b, 0) -> (0, a, b)): curves given in the face's own 2D frame, 4
 *    faces of area 0.25, read back in the plane x = 0 inside [0, 1] x [0, 1]
 *    in (y, z);
 *  - the square in metres (its unit entity rewritten): written and read back
 *    in metres, total area 1 (not 1e6 or 1e-6); a millimetre file read
 *    afterwards is unaffected;
 *  - a diagonal cut ending at two corners: 2 triangles of 3 corners;
 *  - end points up to 1e-9 off the boundary are snapped onto it (areas as
 *    in t320: 1e-12 for exact pieces, 1e-9 of the total where curves are
 *    interpolated; 1e-6 against the 7-digit area in the real file's
 *    README; the interpolated wave's 1e-8 is its interpolation error);
 *  - long separatrix-like curves (hundreds of points);
 *  - writing into a missing directory: SQ_ERR_OUTPUT, nothing left;
 *  - the aerofoil box in metres, a face with a hole, cut from the hole's
 *    two vertices to the outer sides: 2 faces; on the project's own
 *    aerofoil box (argv[1], written by tests/cascade_aerofoil.py) and, if
 *    $SEMQUAD_REAL_GEOMETRIES holds it, on NekMesh's (a line says so when
 *    it does not, tests/README.md). */
#include "cad.h"
#include "test_util.h"

#include <dirent.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static int failures = 0;

#define CHECK(cond, ...)                                                                           \
    do {                                                                                           \
        if (!(cond)) {                                                                             \
            printf("%s:%d: ", __FILE__, __LINE__);                                                 \
            printf(__VA_ARGS__);                                                                   \
            printf("\n");                                                                          \
            ++failures;                                                                            \
        }                                                                                          \
    } while (0)
#define NEAR(what, got, want, tol)                                                                 \
    CHECK(fabs((got) - (want)) <= (tol), "%s = %.17g, expected %.17g (tolerance %g)", what,       \
          (double)(got), (double)(want), (double)(tol))
#define EQ(what, got, want) CHECK((got) == (want), "%s = %d, expected %d", what, (int)(got), (int)(want))

static char *slurp(const char *path)
{
    FILE *f = fopen(path, "rb");
    if (!f) return NULL;
    fseek(f, 0, SEEK_END);
    long n = ftell(f);
    fseek(f, 0, SEEK_SET);
    char *b = malloc((size_t)n + 1);
    if (b && fread(b, 1, (size_t)n, f) != (size_t)n) n = 0;
    if (b) b[n] = 0;
    fclose(f);
    return b;
}

/* Copy a STEP file, permuting the 3-component CARTESIAN_POINTs and
 * DIRECTIONs (x, y, z) -> (y, z, x) if rotate, and replacing the length unit
 * by `unit` (e.g. "SI_UNIT($,.METRE.)") if not NULL. */
static int rewrite_step(const char *in, const char *out, int rotate, const char *unit)
{
    char *text = slurp(in);
    if (!text) return 0;
    FILE *f = fopen(out, "wb");
    if (!f) return 0;
    for (char *line = text; *line;) {
        char *end = strchr(line, '\n');
        size_t len = end ? (size_t)(end - line) : strlen(line);
        char buf[1024];
        if (len >= sizeof buf) len = sizeof buf - 1;
        memcpy(buf, line, len);
        buf[len] = 0;
        line += len + (end ? 1 : 0);
        const char *tags[2] = {"CARTESIAN_POINT('',(", "DIRECTION('',("};
        int done = 0;
        for (int t = 0; t < 2 && rotate && !done; ++t) {
            char *p = strstr(buf, tags[t]);
            if (!p) continue;
            char *q = p + strlen(tags[t]);
            double v[3];
            char *e1, *e2, *e3;
            v[0] = strtod(q, &e1);
            if (*e1 != ',') continue;
            v[1] = strtod(e1 + 1, &e2);
            if (*e2 != ',') continue; /* a 2D point: unchanged */
            v[2] = strtod(e2 + 1, &e3);
            *q = 0;
            fprintf(f, "%s%.17g,%.17g,%.17g%s\n", buf, v[1], v[2], v[0], e3);
            done = 1;
        }
        if (done) continue;
        char *u = unit ? strstr(buf, "SI_UNIT(.MILLI.,.METRE.)") : NULL;
        if (u) {
            *u = 0;
            fprintf(f, "%s%s%s\n", buf, unit, u + strlen("SI_UNIT(.MILLI.,.METRE.)"));
        } else {
            fprintf(f, "%s\n", buf);
        }
    }
    fclose(f);
    free(text);
    return 1;
}

static cad_model *read_model(const char *path)
{
    cad_model *m = NULL;
    sq_error err;
    if (cad_model_read(path, &m, &err) != SQ_OK) CHECK(0, "%s: %s", path, err.msg);
    return m;
}

/* Area of face i of a model: the split with no curve. */
static double model_face_area(const cad_model *m, int i)
{
    cad_split *s = NULL;
    sq_error err;
    if (cad_face_split(m, i, NULL, 0, NULL, NULL, &s, &err) != SQ_OK) {
        CHECK(0, "face %d: %s", i, err.msg);
        return 0;
    }
    double a = cad_split_total_area(s);
    cad_split_free(&s);
    return a;
}

static int count_files(const char *dir)
{
    DIR *d = opendir(dir);
    int n = 0;
    for (struct dirent *e; d && (e = readdir(d));)
        if (strcmp(e->d_name, ".") && strcmp(e->d_name, "..")) ++n;
    if (d) closedir(d);
    return n;
}

/* The square's midlines as curves in the face's 2D frame, from 3D points
 * map(x, y) of the original square. */
static void rotated_square(const char *tmp, const char *ex)
{
    char in[1024], path[1100], out[1100];
    snprintf(in, sizeof in, "%s/square.step", ex);
    snprintf(path, sizeof path, "%s/rotated.step", tmp);
    snprintf(out, sizeof out, "%s/rotated_split.step", tmp);
    if (!rewrite_step(in, path, 1, NULL)) {
        CHECK(0, "cannot rewrite %s", in);
        return;
    }
    cad_model *m = read_model(path);
    if (!m) return;
    cad_face *f = NULL;
    sq_error err;
    if (cad_face_create(m, 0, &f, &err) != SQ_OK) {
        CHECK(0, "rotated: %s", err.msg);
        cad_model_free(&m);
        return;
    }
    double O[3], X[3], Y[3];
    cad_face_frame(f, O, X, Y);
    /* original (a, b) -> 3D (0, a, b) -> frame coordinates */
    double mid[4][2] = {{0, 0.5}, {1, 0.5}, {0.5, 0}, {0.5, 1}};
    double c[2][8];
    for (int k = 0; k < 4; ++k) {
        double P[3] = {0 - O[0], mid[k][0] - O[1], mid[k][1] - O[2]};
        double u = P[0] * X[0] + P[1] * X[1] + P[2] * X[2];
        double v = P[0] * Y[0] + P[1] * Y[1] + P[2] * Y[2];
        /* curve k/2: start, a mid point, end */
        double *cc = c[k / 2];
        if (k % 2 == 0) cc[0] = u, cc[1] = v;
        else cc[6] = u, cc[7] = v;
    }
    for (int j = 0; j < 2; ++j) {
        c[j][2] = 0.6 * c[j][0] + 0.4 * c[j][6], c[j][3] = 0.6 * c[j][1] + 0.4 * c[j][7];
        c[j][4] = 0.3 * c[j][0] + 0.7 * c[j][6], c[j][5] = 0.3 * c[j][1] + 0.7 * c[j][7];
    }
    const double *xy[2] = {c[0], c[1]};
    int np[2] = {4, 4};
    cad_split *s = NULL;
    if (cad_face_split(m, 0, f, 2, np, xy, &s, &err) != SQ_OK) {
        CHECK(0, "rotated: split: %s", err.msg);
    } else {
        EQ("rotated: faces", cad_split_num_faces(s), 4);
        for (int i = 0; i < cad_split_num_faces(s); ++i) {
            NEAR("rotated: area", cad_split_face_area(s, i), 0.25, 1e-12);
            EQ("rotated: corners", cad_split_face_num_corners(s, i, 10), 4);
        }
        if (cad_split_write_step(s, out, &err) != SQ_OK) CHECK(0, "rotated: write: %s", err.msg);
    }
    cad_split_free(&s);
    cad_face_free(&f);
    cad_model_free(&m);

    cad_model *b = read_model(out);
    if (!b) return;
    EQ("rotated, read back: faces", cad_model_num_faces(b), 4);
    double sum = 0;
    for (int i = 0; i < cad_model_num_faces(b); ++i) {
        sum += model_face_area(b, i);
        cad_face *g = NULL;
        if (cad_face_create(b, i, &g, &err) != SQ_OK) {
            CHECK(0, "rotated, read back: face %d: %s", i, err.msg);
            continue;
        }
        double o[3], x[3], y[3];
        cad_face_frame(g, o, x, y);
        for (int e = 0; e < cad_face_num_edges(g); ++e) {
            double p[2];
            if (cad_face_edge_eval(g, e, 0, p, NULL, NULL, &err) != SQ_OK) continue;
            double P[3];
            for (int d = 0; d < 3; ++d) P[d] = o[d] + p[0] * x[d] + p[1] * y[d];
            CHECK(fabs(P[0]) < 1e-12 && P[1] > -1e-12 && P[1] < 1 + 1e-12 && P[2] > -1e-12 &&
                      P[2] < 1 + 1e-12,
                  "rotated, read back: face %d vertex at (%g, %g, %g)", i, P[0], P[1], P[2]);
        }
        cad_face_free(&g);
    }
    NEAR("rotated, read back: area sum", sum, 1.0, 1e-12);
    cad_model_free(&b);
}

static void metre_square(const char *tmp, const char *ex)
{
    char in[1024], path[1100], out[1100];
    snprintf(in, sizeof in, "%s/square.step", ex);
    snprintf(path, sizeof path, "%s/square_m.step", tmp);
    snprintf(out, sizeof out, "%s/square_m_split.step", tmp);
    if (!rewrite_step(in, path, 0, "SI_UNIT($,.METRE.)")) {
        CHECK(0, "cannot rewrite %s", in);
        return;
    }
    cad_model *m = read_model(path);
    if (!m) return;
    CHECK(!strcmp(cad_model_unit(m), "m"), "metre square: unit %s", cad_model_unit(m));
    double h[4] = {0, 0.5, 1, 0.5}, v[4] = {0.5, 0, 0.5, 1};
    const double *xy[2] = {h, v};
    int np[2] = {2, 2};
    cad_split *s = NULL;
    sq_error err;
    if (cad_face_split(m, 0, NULL, 2, np, xy, &s, &err) != SQ_OK) {
        CHECK(0, "metre square: split: %s", err.msg);
    } else {
        EQ("metre square: faces", cad_split_num_faces(s), 4);
        if (cad_split_write_step(s, out, &err) != SQ_OK) CHECK(0, "metre square: write: %s", err.msg);
        /* Overwrite in place. */
        if (cad_split_write_step(s, out, &err) != SQ_OK) CHECK(0, "metre square: rewrite: %s", err.msg);
    }
    cad_split_free(&s);
    cad_model_free(&m);
    char *text = slurp(out);
    CHECK(text && strstr(text, "SI_UNIT($,.METRE.)") && !strstr(text, ".MILLI."),
          "metre square: the written file's length unit is not the metre");
    free(text);
    cad_model *b = read_model(out);
    if (b) {
        CHECK(!strcmp(cad_model_unit(b), "m"), "metre square, read back: unit %s", cad_model_unit(b));
        EQ("metre square, read back: faces", cad_model_num_faces(b), 4);
        double sum = 0;
        for (int i = 0; i < cad_model_num_faces(b); ++i) sum += model_face_area(b, i);
        NEAR("metre square, read back: area", sum, 1.0, 1e-12);
        cad_model_free(&b);
    }
    /* A millimetre file read and written afterwards keeps its numbers. */
    cad_model *mm = read_model(in);
    if (mm) {
        NEAR("mm square after metres: area", model_face_area(mm, 0), 1.0, 1e-12);
        cad_model_free(&mm);
    }
}

static void square_cases(const char *tmp, const char *ex)
{
    char in[1024];
    snprintf(in, sizeof in, "%s/square.step", ex);
    cad_model *m = read_model(in);
    if (!m) return;
    sq_error err;
    cad_split *s = NULL;

    /* Diagonal from corner to corner: 2 triangles. */
    double d[6] = {0, 0, 0.5, 0.5, 1, 1};
    const double *xy[1] = {d};
    int np[1] = {3};
    if (cad_face_split(m, 0, NULL, 1, np, xy, &s, &err) != SQ_OK) {
        CHECK(0, "diagonal: %s", err.msg);
    } else {
        EQ("diagonal: faces", cad_split_num_faces(s), 2);
        for (int i = 0; i < cad_split_num_faces(s); ++i) {
            NEAR("diagonal: area", cad_split_face_area(s, i), 0.5, 1e-12);
            EQ("diagonal: corners", cad_split_face_num_corners(s, i, 10), 3);
        }
    }
    cad_split_free(&s);

    /* End points 1e-9 inside and outside the sides: snapped. */
    double h[4] = {1e-9, 0.5, 1 + 1e-9, 0.5};
    xy[0] = h;
    np[0] = 2;
    if (cad_face_split(m, 0, NULL, 1, np, xy, &s, &err) != SQ_OK) {
        CHECK(0, "snapped: %s", err.msg);
    } else {
        EQ("snapped: faces", cad_split_num_faces(s), 2);
        for (int i = 0; i < cad_split_num_faces(s); ++i) {
            NEAR("snapped: area", cad_split_face_area(s, i), 0.5, 1e-12);
            EQ("snapped: corners", cad_split_face_num_corners(s, i, 10), 4);
        }
    }
    cad_split_free(&s);

    /* Long curves: a wavy line across (601 points) and a quarter circle
     * around (0, 0) of radius 0.8 (400 points) from the bottom side to the
     * left one, crossing the wavy line: 4 faces. */
    enum { NW = 601, NA = 400 };
    static double wave[2 * NW], arc[2 * NA];
    for (int i = 0; i < NW; ++i) {
        double x = (double)i / (NW - 1);
        wave[2 * i] = x;
        wave[2 * i + 1] = 0.5 + 0.05 * sin(2 * M_PI * x);
    }
    for (int i = 0; i < NA; ++i) {
        double t = 0.5 * M_PI * i / (NA - 1);
        arc[2 * i] = i == NA - 1 ? 0 : 0.8 * cos(t);
        arc[2 * i + 1] = i == 0 ? 0 : 0.8 * sin(t);
    }
    const double *xy2[2] = {wave, arc};
    int np2[2] = {NW, NA};
    if (cad_face_split(m, 0, NULL, 2, np2, xy2, &s, &err) != SQ_OK) {
        CHECK(0, "long curves: %s", err.msg);
    } else {
        EQ("long curves: faces", cad_split_num_faces(s), 4);
        double sum = 0;
        for (int i = 0; i < cad_split_num_faces(s); ++i) sum += cad_split_face_area(s, i);
        NEAR("long curves: area sum", sum, 1.0, 1e-12);
        /* Below the wave: its area is 0.5 exactly (the sine integrates to 0);
         * the interpolated wave is within ~1e-9 of it. */
        double p1[2] = {0.95, 0.1}, p2[2] = {0.1, 0.1};
        int f1 = cad_split_locate(s, p1), f2 = cad_split_locate(s, p2);
        CHECK(f1 >= 0 && f2 >= 0 && f1 != f2, "long curves: faces %d %d", f1, f2);
        if (f1 >= 0 && f2 >= 0)
            NEAR("long curves: area below the wave", cad_split_face_area(s, f1) + cad_split_face_area(s, f2),
                 0.5, 1e-8);
    }
    cad_split_free(&s);

    /* A missing directory: SQ_ERR_OUTPUT. */
    double mid[4] = {0, 0.5, 1, 0.5};
    xy[0] = mid;
    if (cad_face_split(m, 0, NULL, 1, np, xy, &s, &err) == SQ_OK) {
        char bad[1100];
        snprintf(bad, sizeof bad, "%s/missing/out.step", tmp);
        EQ("missing directory: status", cad_split_write_step(s, bad, &err), SQ_ERR_OUTPUT);
        EQ("NULL path: status", cad_split_write_step(s, NULL, &err), SQ_ERR_USAGE);
    }
    cad_split_free(&s);
    cad_model_free(&m);
}

/* An aerofoil box ([-0.5, 1.5] x [-0.75, 0.75], metres) of the given area:
 * cut from the hole's vertices horizontally to the sides. */
static void aerofoil_box(const char *path, double area, double area_tol)
{
    cad_model *m = read_model(path);
    if (!m) return;
    cad_face *f = NULL;
    sq_error err;
    int fi = cad_model_default_face(m, NULL);
    if (cad_face_create(m, fi, &f, &err) != SQ_OK) {
        CHECK(0, "aerofoil box: %s", err.msg);
        cad_model_free(&m);
        return;
    }
    /* The hole's vertices: the start points of loop 1's edges; the leftmost
     * and the rightmost. */
    double lo[2] = {1e30, 0}, hi[2] = {-1e30, 0};
    for (int e = 0; e < cad_face_loop_num_edges(f, 1); ++e) {
        double p[2];
        if (cad_face_edge_eval(f, cad_face_loop_first_edge(f, 1) + e, 0, p, NULL, NULL, &err))
            continue;
        if (p[0] < lo[0]) lo[0] = p[0], lo[1] = p[1];
        if (p[0] > hi[0]) hi[0] = p[0], hi[1] = p[1];
    }
    double c0[4] = {-0.5, lo[1], lo[0], lo[1]}, c1[4] = {hi[0], hi[1], 1.5, hi[1]};
    const double *xy[2] = {c0, c1};
    int np[2] = {2, 2};
    cad_split *s = NULL;
    if (cad_face_split(m, fi, f, 2, np, xy, &s, &err) != SQ_OK) {
        CHECK(0, "aerofoil box: split: %s", err.msg);
    } else {
        EQ("aerofoil box: faces", cad_split_num_faces(s), 2);
        double sum = 0;
        for (int i = 0; i < cad_split_num_faces(s); ++i) sum += cad_split_face_area(s, i);
        NEAR("aerofoil box: area sum", sum, cad_split_total_area(s), 1e-9 * sum);
        NEAR("aerofoil box: area", sum, area, area_tol);
    }
    cad_split_free(&s);
    cad_face_free(&f);
    cad_model_free(&m);
}

int main(int argc, char **argv)
{
    if (argc != 2) {
        printf("usage: t321-cad-split-frames aerofoil_box.step\n");
        return 1;
    }
    const char *ex = getenv("SQ_EXAMPLES");
    if (!ex) ex = "examples";
    char tmp[] = "/tmp/t321-XXXXXX";
    if (!mkdtemp(tmp)) {
        printf("mkdtemp failed\n");
        return 1;
    }
    rotated_square(tmp, ex);
    metre_square(tmp, ex);
    square_cases(tmp, ex);
    /* the project's own (its exact area in NAME.facts, tests/cascade_aerofoil.py) */
    char facts[4096];
    double area = 0;
    snprintf(facts, sizeof facts, "%.*s.facts", (int)strlen(argv[1]) - 5, argv[1]);
    FILE *fp = fopen(facts, "r");
    CHECK(fp && fscanf(fp, "area %lf", &area) == 1, "%s: no area", facts);
    if (fp) fclose(fp);
    aerofoil_box(argv[1], area, 1e-9 * area);
    /* NekMesh's, if present (area to the 7 digits of its README) */
    char real[4096];
    if (sq_test_path(real, sizeof real, 1, "real_aerofoil_box.step")) aerofoil_box(real, 2.989443, 1e-6);
    /* Only the files written on purpose are left: no temporary files. */
    EQ("files in the temporary directory", count_files(tmp), 4);
    char p[1100];
    const char *names[4] = {"rotated.step", "rotated_split.step", "square_m.step",
                            "square_m_split.step"};
    for (int i = 0; i < 4; ++i) {
        snprintf(p, sizeof p, "%s/%s", tmp, names[i]);
        unlink(p);
    }
    if (!failures) rmdir(tmp);
    return failures ? 1 : 0;
}
