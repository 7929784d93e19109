/* t320 — cad_face_split: a face cut along curves given in its 2D frame.
 * (a) the unit square cut by two crossing midlines (segments, and
 *     interpolated through 11 points), by four half-lines from the centre
 *     (curves ending at one interior point), and by a T-junction;
 * (b) the half disc cut by Marcon's 5-separatrix layout: two singular points,
 *     rays to the arc and down to the segment, one curve joining them;
 * (c) its STEP export read back with cad_model_read: 4 faces, areas adding up
 *     to pi/2, no temporary file left;
 * (d) bad input: a dangling end point, a point outside the face, a one-point
 *     curve: an error and no split.
 * OpenCASCADE must print nothing (stdout and stderr are captured).
 * Tolerances (OCC, no BLAS): a split face's area is adaptive Gauss along
 * its edges to 1e-16 size^2, the tolerance halved with each of at most 20
 * splits (cad/cad_split.cpp, green_adapt): 20 x 1e-16 size^2 an edge unless
 * the depth cap ends the splitting first; interior edges are integrated
 * once each way and cancel in sums.  So 1e-12 for areas and sums of exact
 * (straight, circular) pieces; 1e-9 of the total where interpolated curves
 * (GeomAPI_Interpolate) may reach the cap; points located to the code's
 * 1e-9 size end-point snap. */
#include "cad.h"

#include <dirent.h>
#include <fcntl.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static char log_buf[16384];
static int failures = 0;

/* Failures are logged while stdout/stderr are captured, printed at the end. */
static void fail(const char *fmt, ...)
{
    size_t n = strlen(log_buf);
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(log_buf + n, sizeof log_buf - n, fmt, ap);
    va_end(ap);
    n = strlen(log_buf);
    if (n + 1 < sizeof log_buf) log_buf[n] = '\n', log_buf[n + 1] = 0;
    ++failures;
}

#define CHECK(cond, ...)                                                                           \
    do {                                                                                           \
        if (!(cond)) fail(__VA_ARGS__);                                                            \
    } while (0)
#define NEAR(ctx, what, got, want, tol)                                                            \
    CHECK(fabs((got) - (want)) <= (tol), "%s: %s = %.17g, expected %.17g (tolerance %g)", ctx,   \
          what, (double)(got), (double)(want), (double)(tol))
#define EQ(ctx, what, got, want)                                                                   \
    CHECK((got) == (want), "%s: %s = %d, expected %d", ctx, what, (int)(got), (int)(want))

static const char *examples;

static cad_model *read_model(const char *file)
{
    char path[1024];
    snprintf(path, sizeof path, "%s/%s", examples, file);
    cad_model *m = NULL;
    sq_error err;
    if (cad_model_read(path, &m, &err) != SQ_OK) fail("%s: %s", file, err.msg);
    return m;
}

/* A straight polyline of n points from a to b (ends exact). */
static double *line(double ax, double ay, double bx, double by, int n)
{
    double *p = malloc(sizeof(double) * 2 * (size_t)n);
    for (int i = 0; i < n; ++i) {
        double t = (double)i / (n - 1);
        p[2 * i] = i == n - 1 ? bx : ax + t * (bx - ax);
        p[2 * i + 1] = i == n - 1 ? by : ay + t * (by - ay);
    }
    return p;
}

static cad_split *split(const char *ctx, cad_model *m, int nc, const int *npts, double **xy)
{
    cad_split *s = NULL;
    sq_error err;
    sq_status st = cad_face_split(m, 0, NULL, nc, npts, (const double *const *)xy, &s, &err);
    if (st != SQ_OK) fail("%s: cad_face_split: status %d: %s", ctx, (int)st, err.msg);
    return s;
}

/* Every sub-face: nfaces faces, the given area (if > 0), 4 corners at 10 deg. */
static void check_quads(const char *ctx, const cad_split *s, int nfaces, double area, double total)
{
    if (!s) return;
    EQ(ctx, "faces", cad_split_num_faces(s), nfaces);
    double sum = 0;
    for (int i = 0; i < cad_split_num_faces(s); ++i) {
        double a = cad_split_face_area(s, i);
        sum += a;
        char w[64];
        snprintf(w, sizeof w, "area of face %d", i);
        if (area > 0) NEAR(ctx, w, a, area, 1e-12);
        snprintf(w, sizeof w, "corners of face %d", i);
        EQ(ctx, w, cad_split_face_num_corners(s, i, 10.0), 4);
    }
    NEAR(ctx, "area sum", sum, total, 1e-9 * total);
    NEAR(ctx, "face area", cad_split_total_area(s), total, 1e-12 * total);
}

static void square_tests(void)
{
    cad_model *m = read_model("square.step");
    if (!m) return;

    /* (a1) two crossing midlines, 2 points each. */
    {
        double *xy[2] = {line(0, 0.5, 1, 0.5, 2), line(0.5, 0, 0.5, 1, 2)};
        int np[2] = {2, 2};
        cad_split *s = split("square, crossing segments", m, 2, np, xy);
        check_quads("square, crossing segments", s, 4, 0.25, 1.0);
        /* Each quadrant is its own face, and the centre is a corner of each. */
        if (s) {
            const double q[4][2] = {{0.25, 0.25}, {0.75, 0.25}, {0.75, 0.75}, {0.25, 0.75}};
            int seen = 0;
            for (int k = 0; k < 4; ++k) {
                int f = cad_split_locate(s, q[k]);
                CHECK(f >= 0 && f < 4, "square: quadrant %d not located (%d)", k, f);
                if (f >= 0 && f < 4) seen |= 1 << f;
                double c[8];
                int nc = f >= 0 ? cad_split_face_corners(s, f, 10.0, c, 4) : 0;
                int centre = 0;
                for (int j = 0; j < nc && j < 4; ++j)
                    if (fabs(c[2 * j] - 0.5) < 1e-9 && fabs(c[2 * j + 1] - 0.5) < 1e-9) ++centre;
                EQ("square, crossing segments", "centre among corners", centre, 1);
            }
            EQ("square, crossing segments", "located faces mask", seen, 15);
            double out_pt[2] = {1.5, 0.5};
            EQ("square, crossing segments", "locate outside", cad_split_locate(s, out_pt), -1);
        }
        cad_split_free(&s);
        CHECK(s == NULL, "cad_split_free did not NULL");
        free(xy[0]), free(xy[1]);
    }
    /* (a2) the same through 11 points each (interpolated B-splines). */
    {
        double *xy[2] = {line(0, 0.5, 1, 0.5, 11), line(0.5, 1, 0.5, 0, 11)};
        int np[2] = {11, 11};
        cad_split *s = split("square, crossing interpolated", m, 2, np, xy);
        check_quads("square, crossing interpolated", s, 4, 0.25, 1.0);
        cad_split_free(&s);
        free(xy[0]), free(xy[1]);
    }
    /* (a3) four half-lines from the centre to the sides: one shared vertex. */
    {
        double *xy[4] = {line(0.5, 0.5, 1, 0.5, 6), line(0.5, 0.5, 0.5, 1, 2),
                         line(0.5, 0.5, 0, 0.5, 6), line(0.5, 0.5, 0.5, 0, 2)};
        int np[4] = {6, 2, 6, 2};
        cad_split *s = split("square, four half-lines", m, 4, np, xy);
        check_quads("square, four half-lines", s, 4, 0.25, 1.0);
        cad_split_free(&s);
        for (int k = 0; k < 4; ++k) free(xy[k]);
    }
    /* (a4) T-junction: a half-line from the centre up, ending on the full
     * horizontal midline: 3 faces, the bottom one a 1 x 0.5 rectangle whose
     * side through the junction is straight (not a corner). */
    {
        double *xy[2] = {line(0, 0.5, 1, 0.5, 5), line(0.5, 1, 0.5, 0.5, 2)};
        int np[2] = {5, 2};
        cad_split *s = split("square, T-junction", m, 2, np, xy);
        if (s) {
            EQ("square, T-junction", "faces", cad_split_num_faces(s), 3);
            double p[2] = {0.5, 0.25};
            int b = cad_split_locate(s, p);
            CHECK(b >= 0, "square, T-junction: bottom face not located");
            if (b >= 0) {
                NEAR("square, T-junction", "bottom area", cad_split_face_area(s, b), 0.5, 1e-12);
                EQ("square, T-junction", "bottom corners", cad_split_face_num_corners(s, b, 10), 4);
            }
            double sum = 0;
            for (int i = 0; i < cad_split_num_faces(s); ++i) {
                sum += cad_split_face_area(s, i);
                EQ("square, T-junction", "corners", cad_split_face_num_corners(s, i, 10), 4);
            }
            NEAR("square, T-junction", "area sum", sum, 1.0, 1e-12);
        }
        cad_split_free(&s);
        free(xy[0]), free(xy[1]);
    }
    /* (d) bad input: an error, *out NULL. */
    {
        sq_error err;
        cad_split *s = (cad_split *)&err; /* must be reset to NULL */
        /* dangling: starts inside the face */
        double *xy[1] = {line(0.2, 0.5, 1, 0.5, 4)};
        int np[1] = {4};
        sq_status st = cad_face_split(m, 0, NULL, 1, np, (const double *const *)xy, &s, &err);
        EQ("dangling", "status", st, SQ_ERR_LAYOUT);
        CHECK(s == NULL, "dangling: out not NULL");
        CHECK(strstr(err.msg, "curve 0") && strstr(err.msg, "dangling"),
              "dangling: message '%s'", err.msg);
        free(xy[0]);
        /* dangling: two curves meeting at an interior point, one end free */
        double *xy2[2] = {line(0, 0.5, 0.5, 0.5, 3), line(0.5, 0.5, 0.7, 0.7, 2)};
        int np2[2] = {3, 2};
        st = cad_face_split(m, 0, NULL, 2, np2, (const double *const *)xy2, &s, &err);
        EQ("dangling chain", "status", st, SQ_ERR_LAYOUT);
        CHECK(strstr(err.msg, "curve 1"), "dangling chain: message '%s'", err.msg);
        free(xy2[0]), free(xy2[1]);
        /* a point outside the face */
        double out3[6] = {0, 0.5, 0.5, 1.5, 1, 0.5};
        const double *xy3[1] = {out3};
        int np3[1] = {3};
        st = cad_face_split(m, 0, NULL, 1, np3, xy3, &s, &err);
        EQ("outside", "status", st, SQ_ERR_LAYOUT);
        CHECK(s == NULL, "outside: out not NULL");
        /* one point, NULL arrays, bad face index */
        int np4[1] = {1};
        st = cad_face_split(m, 0, NULL, 1, np4, xy3, &s, &err);
        EQ("one point", "status", st, SQ_ERR_USAGE);
        st = cad_face_split(m, 0, NULL, 1, NULL, NULL, &s, &err);
        EQ("NULL arrays", "status", st, SQ_ERR_USAGE);
        st = cad_face_split(m, 3, NULL, 0, NULL, NULL, &s, &err);
        EQ("face index", "status", st, SQ_ERR_USAGE);
        /* no curve: the face itself */
        st = cad_face_split(m, 0, NULL, 0, NULL, NULL, &s, &err);
        EQ("no curve", "status", st, SQ_OK);
        check_quads("no curve", s, 1, 1.0, 1.0);
        cad_split_free(&s);
    }
    cad_model_free(&m);
}

static void half_disc_tests(const char *tmpdir)
{
    cad_model *m = read_model("half_disc.step");
    if (!m) return;
    cad_face *f = NULL;
    sq_error err;
    if (cad_face_create(m, 0, &f, &err) != SQ_OK) {
        fail("half_disc: %s", err.msg);
        cad_model_free(&m);
        return;
    }
    /* (b) Marcon's layout: singular points S1, S2 = (-/+a, a); rays along the
     * diagonals to the arc, rays down to y = 0, a curve S1 -> (0, 0.6) -> S2. */
    const double a = 0.505081, r = sqrt(0.5);
    double *xy[5] = {line(-a, a, -r, r, 5), line(a, a, r, r, 5), line(-a, a, -a, 0, 4),
                     line(a, a, a, 0, 4), NULL};
    double join[6] = {-a, a, 0, 0.6, a, a};
    xy[4] = join;
    int np[5] = {5, 5, 4, 4, 3};
    cad_split *s = NULL;
    sq_status st = cad_face_split(m, 0, f, 5, np, (const double *const *)xy, &s, &err);
    if (st != SQ_OK) fail("half_disc: cad_face_split: status %d: %s", (int)st, err.msg);
    const double half_pi = 2 * atan(1.0);
    check_quads("half_disc", s, 4, -1, half_pi);
    if (s) {
        /* Left and right faces: mirror images. */
        double pl[2] = {-0.8, 0.1}, pr[2] = {0.8, 0.1};
        int il = cad_split_locate(s, pl), ir = cad_split_locate(s, pr);
        CHECK(il >= 0 && ir >= 0 && il != ir, "half_disc: side faces %d %d", il, ir);
        if (il >= 0 && ir >= 0)
            NEAR("half_disc", "left - right area", cad_split_face_area(s, il),
                 cad_split_face_area(s, ir), 1e-12);
        /* The side face's corners: (-1,0), (-a,0), S1, (-r,r) in some order. */
        if (il >= 0) {
            double c[16];
            int nc = cad_split_face_corners(s, il, 10.0, c, 8);
            const double want[4][2] = {{-1, 0}, {-a, 0}, {-a, a}, {-r, r}};
            for (int k = 0; k < 4; ++k) {
                int hit = 0;
                for (int j = 0; j < nc && j < 8; ++j)
                    if (hypot(c[2 * j] - want[k][0], c[2 * j + 1] - want[k][1]) < 1e-9) ++hit;
                CHECK(hit == 1, "half_disc: corner (%g, %g) of the left face found %d times",
                      want[k][0], want[k][1], hit);
            }
        }

        /* (c) STEP export and read back. */
        char path[1024];
        snprintf(path, sizeof path, "%s/patches.step", tmpdir);
        if (cad_split_write_step(s, path, &err) != SQ_OK) {
            fail("half_disc: write: %s", err.msg);
        } else {
            cad_model *back = NULL;
            if (cad_model_read(path, &back, &err) != SQ_OK) {
                fail("half_disc: read back: %s", err.msg);
            } else {
                EQ("read back", "faces", cad_model_num_faces(back), 4);
                CHECK(!strcmp(cad_model_unit(back), "mm"), "read back: unit %s",
                      cad_model_unit(back));
                double sum = 0;
                for (int i = 0; i < cad_model_num_faces(back); ++i) {
                    cad_split *one = NULL;
                    if (cad_face_split(back, i, NULL, 0, NULL, NULL, &one, &err) != SQ_OK) {
                        fail("read back: face %d: %s", i, err.msg);
                        continue;
                    }
                    sum += cad_split_total_area(one);
                    EQ("read back", "corners", cad_split_face_num_corners(one, 0, 10.0), 4);
                    cad_split_free(&one);
                }
                NEAR("read back", "area sum", sum, half_pi, 1e-9 * half_pi);
                cad_model_free(&back);
            }
        }
        /* Only patches.step in the directory: no temporary file left. */
        DIR *d = opendir(tmpdir);
        int nfiles = 0;
        for (struct dirent *e; d && (e = readdir(d));)
            if (strcmp(e->d_name, ".") && strcmp(e->d_name, "..") &&
                strcmp(e->d_name, "output.txt"))
                ++nfiles;
        if (d) closedir(d);
        EQ("write", "files in the directory", nfiles, 1);
        unlink(path);
    }
    cad_split_free(&s);
    for (int k = 0; k < 4; ++k) free(xy[k]);
    cad_face_free(&f);
    cad_model_free(&m);
}

int main(void)
{
    examples = getenv("SQ_EXAMPLES");
    if (!examples) examples = "examples";
    char tmpdir[] = "/tmp/t320-XXXXXX";
    if (!mkdtemp(tmpdir)) {
        fprintf(stderr, "mkdtemp failed\n");
        return 1;
    }
    /* Capture stdout and stderr: OpenCASCADE must stay silent. */
    char out_path[1100];
    snprintf(out_path, sizeof out_path, "%s/output.txt", tmpdir);
    fflush(stdout), fflush(stderr);
    int fd = open(out_path, O_WRONLY | O_CREAT | O_TRUNC, 0600);
    int save1 = dup(1), save2 = dup(2);
    dup2(fd, 1), dup2(fd, 2);

    square_tests();
    half_disc_tests(tmpdir);

    fflush(stdout), fflush(stderr);
    dup2(save1, 1), dup2(save2, 2);
    close(fd), close(save1), close(save2);
    FILE *fp = fopen(out_path, "rb");
    long printed = 0;
    if (fp) {
        fseek(fp, 0, SEEK_END);
        printed = ftell(fp);
        fclose(fp);
    }
    if (printed != 0) fail("OpenCASCADE printed %ld bytes (see %s)", printed, out_path);
    else unlink(out_path), rmdir(tmpdir);
    fputs(log_buf, stdout);
    return failures ? 1 : 0;
}
