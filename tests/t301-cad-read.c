/* t301 — cad_model_read: every example reads as one planar face in mm; BREP
 * and IGES (by extension, case-insensitive) with their units; bad inputs give
 * SQ_ERR_INPUT with a message; OpenCASCADE prints nothing. */
#include "cad.h"
#include "t30x_cad.h"

#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

/* A 2 x 1 mm rectangle in z = 0 written by OpenCASCADE 7.6 (BREP, no unit). */
static const char rect_brep[] =
    "DBRep_DrawableShape\n"
    "\n"
    "CASCADE Topology V3, (c) Open Cascade\n"
    "Locations 0\n"
    "Curve2ds 0\n"
    "Curves 4\n"
    "1 0 0 0 1 0 0 \n"
    "1 2 0 0 0 1 0 \n"
    "1 2 1 0 -1 0 0 \n"
    "1 0 1 0 0 -1 0 \n"
    "Polygon3D 0\n"
    "PolygonOnTriangulations 0\n"
    "Surfaces 1\n"
    "1 1 0.5 0 0 0 1 1 0 -0 -0 1 0 \n"
    "Triangulations 0\n"
    "\n"
    "TShapes 10\n"
    "Ve\n"
    "1e-07\n"
    "0 0 0\n"
    "0 0\n"
    "\n"
    "0101101\n"
    "*\n"
    "Ve\n"
    "1e-07\n"
    "2 0 0\n"
    "0 0\n"
    "\n"
    "0101101\n"
    "*\n"
    "Ed\n"
    " 1e-07 1 1 0\n"
    "1  1 0 0 2\n"
    "0\n"
    "\n"
    "0101000\n"
    "+10 0 -9 0 *\n"
    "Ve\n"
    "1e-07\n"
    "2 1 0\n"
    "0 0\n"
    "\n"
    "0101101\n"
    "*\n"
    "Ed\n"
    " 1e-07 1 1 0\n"
    "1  2 0 0 1\n"
    "0\n"
    "\n"
    "0101000\n"
    "+9 0 -7 0 *\n"
    "Ve\n"
    "1e-07\n"
    "0 1 0\n"
    "0 0\n"
    "\n"
    "0101101\n"
    "*\n"
    "Ed\n"
    " 1e-07 1 1 0\n"
    "1  3 0 0 2\n"
    "0\n"
    "\n"
    "0101000\n"
    "+7 0 -5 0 *\n"
    "Ed\n"
    " 1e-07 1 1 0\n"
    "1  4 0 0 1\n"
    "0\n"
    "\n"
    "0101000\n"
    "+5 0 -10 0 *\n"
    "Wi\n"
    "\n"
    "0101100\n"
    "+8 0 +6 0 +4 0 +3 0 *\n"
    "Fa\n"
    "0  1e-07 1 0\n"
    "\n"
    "1101000\n"
    "+2 0 *\n"
    "\n"
    "+1 0 \n";

/* The same rectangle written to IGES with unit metre: 0.002 x 0.001 m. */
static const char rect_iges[] =
    "                                                                        S0000001\n"
    ",,31HOpen CASCADE IGES processor 7.6,13HFilename.iges,                  G0000001\n"
    "16HOpen CASCADE 7.6,31HOpen CASCADE IGES processor 7.6,32,308,15,308,15,G0000002\n"
    ",1.,6,1HM,1,0.00001,15H20261122.001618,1E-10,0.002,4Hroot,,11,0,        G0000003\n"
    "15H20261122.001618,;                                                    G0000004\n"
    "     510       1       0       0       0       0       0       000010000D0000001\n"
    "     510       0       0       1       1                               0D0000002\n"
    "     190       2       0       0       0       0       0       000010000D0000003\n"
    "     190       0       0       1       1                               0D0000004\n"
    "     116       3       0       0       0       0       0       000010400D0000005\n"
    "     116       0       0       1       0                               0D0000006\n"
    "     123       4       0       0       0       0       0       000010200D0000007\n"
    "     123       0       0       1       0                               0D0000008\n"
    "     123       5       0       0       0       0       0       000010200D0000009\n"
    "     123       0       0       1       0                               0D0000010\n"
    "     508       6       0       0       0       0       0       000010000D0000011\n"
    "     508       0       0       1       1                               0D0000012\n"
    "     504       7       0       0       0       0       0       000010001D0000013\n"
    "     504       0       0       1       1                               0D0000014\n"
    "     110       8       0       0       0       0       0       000010000D0000015\n"
    "     110       0       0       1       0                               0D0000016\n"
    "     502       9       0       0       0       0       0       000010000D0000017\n"
    "     502       0       0       1       1                               0D0000018\n"
    "     110      10       0       0       0       0       0       000010000D0000019\n"
    "     110       0       0       1       0                               0D0000020\n"
    "     110      11       0       0       0       0       0       000010000D0000021\n"
    "     110       0       0       1       0                               0D0000022\n"
    "     110      12       0       0       0       0       0       000010000D0000023\n"
    "     110       0       0       1       0                               0D0000024\n"
    "510,3,1,1,11;                                                    0000001P0000001\n"
    "190,5,7,9;                                                       0000003P0000002\n"
    "116,1.E-03,5.E-04,0.,0;                                          0000005P0000003\n"
    "123,0.,0.,1.;                                                    0000007P0000004\n"
    "123,1.,0.,-0.;                                                   0000009P0000005\n"
    "508,4,0,13,1,1,0,0,13,2,1,0,0,13,3,1,0,0,13,4,1,0;               0000011P0000006\n"
    "504,4,15,17,1,17,2,19,17,2,17,3,21,17,3,17,4,23,17,4,17,1;       0000013P0000007\n"
    "110,0.,0.,0.,2.E-03,0.,0.;                                       0000015P0000008\n"
    "502,4,0.,0.,0.,2.E-03,0.,0.,2.E-03,1.E-03,0.,0.,1.E-03,0.;       0000017P0000009\n"
    "110,2.E-03,0.,0.,2.E-03,1.E-03,0.;                               0000019P0000010\n"
    "110,2.E-03,1.E-03,0.,0.,1.E-03,0.;                               0000021P0000011\n"
    "110,0.,1.E-03,0.,0.,0.,0.;                                       0000023P0000012\n"
    "S      1G      4D     24P     12                                        T0000001\n";

static void write_file(const char *path, const char *data, size_t n)
{
    FILE *f = fopen(path, "wb");
    if (!f) {
        fprintf(stderr, "cannot write %s\n", path);
        exit(1);
    }
    if (n) fwrite(data, 1, n, f);
    fclose(f);
}

static char *slurp(const char *path, size_t *n)
{
    FILE *f = fopen(path, "rb");
    if (!f) return NULL;
    fseek(f, 0, SEEK_END);
    long len = ftell(f);
    fseek(f, 0, SEEK_SET);
    char *buf = malloc((size_t)len + 1);
    *n = fread(buf, 1, (size_t)len, f);
    fclose(f);
    return buf;
}

/* The file must be rejected with SQ_ERR_INPUT, a message naming it, no model. */
static void expect_input_error(const char *path)
{
    sq_error err;
    sq_error_clear(&err);
    cad_model *m = (cad_model *)&err; /* must be reset to NULL */
    sq_status s = cad_model_read(path, &m, &err);
    CHECK(s == SQ_ERR_INPUT, "%s: status %d, expected %d (SQ_ERR_INPUT)", path, s, SQ_ERR_INPUT);
    CHECK(m == NULL, "%s: model not NULL on failure", path);
    CHECK(err.msg[0] != '\0' && strstr(err.msg, path) != NULL && !strchr(err.msg, '\n'),
          "%s: message '%s' should be one line naming the file", path, err.msg);
    cad_model_free(&m);
}

int main(void)
{
    const char *ex = getenv("SQ_EXAMPLES");
    if (!ex) {
        fprintf(stderr, "SQ_EXAMPLES not set\n");
        return 1;
    }
    char tmpdir[] = "/tmp/t301-XXXXXX";
    if (!mkdtemp(tmpdir)) {
        perror("mkdtemp");
        return 1;
    }
    char path[4096], out_path[4200];

    /* Capture stdout and stderr while reading: OpenCASCADE must stay silent. */
    snprintf(out_path, sizeof out_path, "%s/output.txt", tmpdir);
    fflush(stdout);
    fflush(stderr);
    int save1 = dup(1), save2 = dup(2);
    int fd = open(out_path, O_WRONLY | O_CREAT | O_TRUNC, 0600);
    dup2(fd, 1);
    dup2(fd, 2);

    static const char *examples[] = {"annulus",   "half_disc",     "lshape", "naca0012",
                                     "nautilus",  "polygon",       "quarter_circle", "square",
                                     "square_hole", "triangle",    "two_holes"};
    int nex = (int)(sizeof examples / sizeof examples[0]);
    char results[16][1024];
    for (int i = 0; i < nex; ++i) {
        snprintf(path, sizeof path, "%s/%s.step", ex, examples[i]);
        sq_error err;
        cad_model *m = NULL;
        sq_status s = cad_model_read(path, &m, &err);
        const char *note = "x";
        if (s != SQ_OK)
            snprintf(results[i], sizeof results[i], "%s: status %d: %s", examples[i], s, err.msg);
        else if (cad_model_num_faces(m) != 1 || strcmp(cad_model_unit(m), "mm") ||
                 strcmp(cad_model_face_surface(m, 0), "plane") || cad_model_default_face(m, &note) != 0 ||
                 note != NULL || cad_model_face_surface(m, 1) != NULL ||
                 cad_model_face_surface(m, -1) != NULL)
            snprintf(results[i], sizeof results[i],
                     "%s: faces %d (expected 1), unit %s (mm), surface %s (plane), note %s (none)",
                     examples[i], cad_model_num_faces(m), cad_model_unit(m),
                     cad_model_face_surface(m, 0), note ? note : "none");
        else
            results[i][0] = '\0';
        cad_model_free(&m);
        if (m != NULL) snprintf(results[i], sizeof results[i], "%s: free did not NULL", examples[i]);
    }

    /* Upper-case extension, BREP: unit unknown. */
    snprintf(path, sizeof path, "%s/rect.BRP", tmpdir);
    write_file(path, rect_brep, strlen(rect_brep));
    cad_model *mb = NULL;
    sq_error errb;
    sq_status sb = cad_model_read(path, &mb, &errb);
    /* IGES in metres. */
    snprintf(path, sizeof path, "%s/rect.Igs", tmpdir);
    write_file(path, rect_iges, strlen(rect_iges));
    cad_model *mi = NULL;
    sq_error erri;
    sq_status si = cad_model_read(path, &mi, &erri);

    /* A sphere: reads, but has no planar face. */
    snprintf(path, sizeof path, "%s/sphere.step", ex);
    cad_model *ms = NULL;
    sq_error errs;
    sq_status ss = cad_model_read(path, &ms, &errs);

    fflush(stdout);
    fflush(stderr);
    dup2(save1, 1);
    dup2(save2, 2);
    close(fd);
    close(save1);
    close(save2);
    struct stat st;
    CHECK(stat(out_path, &st) == 0 && st.st_size == 0,
          "reading printed %ld bytes to stdout/stderr, expected 0 (see %s)", (long)st.st_size,
          out_path);

    for (int i = 0; i < nex; ++i) CHECK(results[i][0] == '\0', "%s", results[i]);

    CHECK(sb == SQ_OK, "rect.BRP: status %d (%s), expected 0", sb, errb.msg);
    if (sb == SQ_OK) {
        CHECK(cad_model_num_faces(mb) == 1, "rect.BRP: %d faces, expected 1", cad_model_num_faces(mb));
        CHECK(!strcmp(cad_model_unit(mb), "unknown"), "rect.BRP: unit %s, expected unknown",
              cad_model_unit(mb));
        cad_face *f = NULL;
        sq_error e2;
        CHECK(cad_face_create(mb, 0, &f, &e2) == SQ_OK, "rect.BRP face: %s", e2.msg);
        double len = 0;
        for (int k = 0; f && k < cad_face_num_edges(f); ++k) len += cad_face_edge_length(f, k);
        /* four closed-form line lengths: a few U of 6 */
        CHECK(f && len > 6 - 1e-12 && len < 6 + 1e-12, "rect.BRP perimeter %.17g, expected 6 (tol 1e-12)", len);
        cad_face_free(&f);
    }
    cad_model_free(&mb);

    CHECK(si == SQ_OK, "rect.Igs: status %d (%s), expected 0", si, erri.msg);
    if (si == SQ_OK) {
        CHECK(!strcmp(cad_model_unit(mi), "m"), "rect.Igs: unit %s, expected m", cad_model_unit(mi));
        cad_face *f = NULL;
        sq_error e2;
        CHECK(cad_face_create(mi, 0, &f, &e2) == SQ_OK, "rect.Igs face: %s", e2.msg);
        double len = 0;
        for (int k = 0; f && k < cad_face_num_edges(f); ++k) len += cad_face_edge_length(f, k);
        /* a few U of 0.006 (1e-18); a unit slip is off by 1e3 */
        CHECK(f && len > 0.006 - 1e-15 && len < 0.006 + 1e-15,
              "rect.Igs perimeter %.17g, expected 0.006 m (tol 1e-15): lengths must stay in metres", len);
        cad_face_free(&f);
    }
    cad_model_free(&mi);

    CHECK(ss == SQ_OK, "sphere.step: status %d (%s), expected 0", ss, errs.msg);
    if (ss == SQ_OK) {
        const char *note = NULL;
        CHECK(cad_model_num_faces(ms) == 1, "sphere: %d faces, expected 1", cad_model_num_faces(ms));
        CHECK(!strcmp(cad_model_face_surface(ms, 0), "sphere"), "sphere: surface %s, expected sphere",
              cad_model_face_surface(ms, 0));
        CHECK(cad_model_default_face(ms, &note) == 0 && note && note[0],
              "sphere: default face should be 0 with a note");
        cad_face *f = (cad_face *)&errs;
        sq_error e2;
        sq_status s = cad_face_create(ms, 0, &f, &e2);
        CHECK(s == SQ_ERR_GEOMETRY && strstr(e2.msg, "sphere") && f == NULL,
              "sphere: cad_face_create status %d message '%s', expected %d mentioning sphere", s,
              e2.msg, SQ_ERR_GEOMETRY);
        s = cad_face_create(ms, 1, &f, &e2);
        CHECK(s == SQ_ERR_USAGE && f == NULL, "face index 1 of 1: status %d, expected %d", s, SQ_ERR_USAGE);
    }
    cad_model_free(&ms);
    cad_model_free(&ms); /* NULL-safe */
    cad_model_free(NULL);

    /* Bad inputs. */
    snprintf(path, sizeof path, "%s/missing.step", tmpdir);
    expect_input_error(path);
    snprintf(path, sizeof path, "%s/empty.step", tmpdir);
    write_file(path, "", 0);
    expect_input_error(path);
    snprintf(path, sizeof path, "%s/text.step", tmpdir);
    write_file(path, "This is not a STEP file.\nJust text.\n", 36);
    expect_input_error(path);
    snprintf(path, sizeof path, "%s/text.iges", tmpdir);
    write_file(path, "This is not an IGES file.\n", 26);
    expect_input_error(path);
    snprintf(path, sizeof path, "%s/text.brep", tmpdir);
    write_file(path, "This is not a BREP file.\n", 25);
    expect_input_error(path);
    snprintf(path, sizeof path, "%s/square.txt", tmpdir);
    write_file(path, rect_brep, strlen(rect_brep));
    expect_input_error(path); /* unknown extension */
    {
        char src[4096];
        size_t n = 0;
        snprintf(src, sizeof src, "%s/square_hole.step", ex);
        char *data = slurp(src, &n);
        CHECK(data != NULL, "cannot read %s", src);
        if (data) {
            snprintf(path, sizeof path, "%s/truncated.step", tmpdir);
            write_file(path, data, n / 2);
            expect_input_error(path);
            free(data);
        }
    }
    /* A STEP file without any face: the header and an empty data section. */
    snprintf(path, sizeof path, "%s/noface.stp", tmpdir);
    {
        const char *noface = "ISO-10303-21;\nHEADER;\nFILE_DESCRIPTION(('empty'),'2;1');\n"
                             "FILE_NAME('noface.stp','2024-01-01T00:00:00',(''),(''),'','','');\n"
                             "FILE_SCHEMA(('AUTOMOTIVE_DESIGN { 1 0 10303 214 1 1 1 1 }'));\n"
                             "ENDSEC;\nDATA;\n#1=CARTESIAN_POINT('',(0.,0.,0.));\nENDSEC;\n"
                             "END-ISO-10303-21;\n";
        write_file(path, noface, strlen(noface));
        expect_input_error(path);
    }
    /* Usage errors. */
    {
        sq_error err;
        CHECK(cad_model_read(NULL, NULL, &err) == SQ_ERR_USAGE, "NULL out: expected SQ_ERR_USAGE");
    }

    /* Clean up the temporary folder. */
    static const char *tmpfiles[] = {"output.txt", "rect.BRP", "rect.Igs", "empty.step",
                                     "text.step", "text.iges", "text.brep", "square.txt",
                                     "truncated.step", "noface.stp"};
    if (!failures) {
        for (size_t i = 0; i < sizeof tmpfiles / sizeof tmpfiles[0]; ++i) {
            snprintf(path, sizeof path, "%s/%s", tmpdir, tmpfiles[i]);
            unlink(path);
        }
        rmdir(tmpdir);
    }
    return failures ? 1 : 0;
}
