/* The checker on hand-made defective layouts of the unit square: a
 * triangular patch (and the pentagon beside it), a crossing, an open
 * separatrix, a missing separatrix at a singular point. */
#include "layout.h"
#include "t51x_layout.h"
#include "test_util.h"

#include <gsl/gsl_errno.h>

static void line(sq_separatrix *s, const cad_face *f, double ax, double ay, double bx, double by,
                 int open_end)
{
    int n = 21;
    s->npts = n;
    s->xy = malloc(2 * (size_t)n * sizeof *s->xy);
    for (int j = 0; j < n; j++) {
        double t = (double)j / (n - 1);
        s->xy[2 * j] = ax + t * (bx - ax);
        s->xy[2 * j + 1] = ay + t * (by - ay);
    }
    double a[2] = {ax, ay}, b[2] = {bx, by};
    s->start = nearest_foot(f, a, NULL);
    s->end = open_end ? (sq_sep_end){SQ_END_OPEN, -1, 0} : nearest_foot(f, b, NULL);
    s->merged = 0;
}

typedef struct {
    const char *name;
    int counts[SQ_DEFECT_NKINDS];
} expect;

static int run(const char *name, const cad_face *f, const sq_face_info *info, int nsing,
               const sq_singularity *sing, sq_separatrix *s, int ns, const int want[SQ_DEFECT_NKINDS],
               const char *summary)
{
    int quads[8] = {1, 1, 1, 1, 1, 1, 1, 1};
    sq_separatrix_set set = {ns, ns, s};
    sq_layout L;
    sq_error err;
    SQ_TEST_OK(sq_layout_graph(f, info, quads, nsing, sing, &set, &L, &err), err);
    sq_layout_defects d;
    sq_layout_check(&L, &d);
    int fails = 0;
    static const char *kn[] = {"corners", "annular", "singular", "vertex", "foot",
                               "area",    "crossing", "open",    "T-junction"};
    for (int k = 0; k < SQ_DEFECT_NKINDS; k++) fails += sq_check_int(name, kn[k], d.count[k], want[k]);
    char buf[256];
    sq_layout_defects_summary(&d, buf, sizeof buf);
    if (summary) fails += sq_check_str(name, "summary", buf, summary);
    if (fails)
        for (int k = 0; k < d.n; k++) printf("  %s\n", d.d[k].msg);
    sq_layout_defects_free(&d);
    sq_layout_free(&L);
    for (int k = 0; k < ns; k++) free(s[k].xy);
    return fails;
}

int main(void)
{
    gsl_set_error_handler_off();
    char path[4096];
    sq_test_path(path, sizeof path, 0, "square.step");
    cad_model *m = NULL;
    cad_face *f = NULL;
    sq_error err;
    sq_face_info info;
    SQ_TEST_OK(cad_model_read(path, &m, &err), err);
    SQ_TEST_OK(cad_face_create(m, 0, &f, &err), err);
    SQ_TEST_OK(sq_face_info_compute(f, &info, &err), err);
    int fails = 0;
    sq_separatrix s[4];
    /* a quarter circle of radius 0.5 around (0,0): a triangle and a pentagon */
    {
        int n = 41;
        s[0].npts = n;
        s[0].xy = malloc(2 * (size_t)n * sizeof *s[0].xy);
        for (int j = 0; j < n; j++) {
            double a = 0.5 * M_PI * j / (n - 1);
            s[0].xy[2 * j] = 0.5 * cos(a);
            s[0].xy[2 * j + 1] = 0.5 * sin(a);
        }
        double a[2] = {0.5, 0}, b[2] = {0, 0.5};
        s[0].start = nearest_foot(f, a, NULL);
        s[0].end = nearest_foot(f, b, NULL);
        int want[SQ_DEFECT_NKINDS] = {[SQ_DEFECT_CORNERS] = 2};
        fails += run("triangle", f, &info, 0, NULL, s, 1, want,
                     "1 patch with 3 corners, 1 patch with 5 corners");
    }
    /* two midlines crossing without a node */
    line(&s[0], f, 0.5, 0.0, 0.5, 1.0, 0);
    line(&s[1], f, 0.0, 0.5, 1.0, 0.5, 0);
    {
        int want[SQ_DEFECT_NKINDS] = {[SQ_DEFECT_CROSSING] = 1};
        fails += run("crossing", f, &info, 0, NULL, s, 2, want, "1 crossing");
    }
    /* a dangling separatrix */
    line(&s[0], f, 0.5, 0.0, 0.5, 0.6, 1);
    {
        int want[SQ_DEFECT_NKINDS] = {[SQ_DEFECT_CORNERS] = 1, [SQ_DEFECT_OPEN] = 1};
        fails += run("open", f, &info, 0, NULL, s, 1, want, NULL);
    }
    /* a valence-4 node with only three separatrices: 3 patches with four
     * corners each, but the node is a corner of 2 of them (flat on the left) */
    {
        sq_singularity c = {0.5, 0.5, 4, SQ_ORIGIN_IMPOSED};
        double mids[3][2] = {{0.5, 0}, {1, 0.5}, {0.5, 1}};
        for (int k = 0; k < 3; k++) {
            line(&s[k], f, 0.5, 0.5, mids[k][0], mids[k][1], 0);
            s[k].start = (sq_sep_end){SQ_END_SINGULAR, 0, 0};
        }
        /* every sector at a pattern's singular point is a patch corner
         * (layout_patches.c): the 180-degree one left by the missing
         * separatrix makes its patch a pentagon */
        int want[SQ_DEFECT_NKINDS] = {[SQ_DEFECT_SINGULAR] = 1, [SQ_DEFECT_CORNERS] = 1};
        fails += run("missing", f, &info, 1, &c, s, 3, want, NULL);
    }
    sq_face_info_free(&info);
    cad_face_free(&f);
    cad_model_free(&m);
    return fails != 0;
}
