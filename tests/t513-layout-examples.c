/* The full pipeline on every example (sq_field_analyse ->
 * sq_trace_separatrices -> sq_layout_build): a valid layout (four corners
 * per patch, singular points and corners with the right patch counts,
 * areas summing to the face area, no crossing); half_disc: 5 separatrices
 * and 4 patches; annulus: cut into at least two quad patches. */
#include "field_analysis.h"
#include "layout.h"
#include "test_util.h"
#include "trace.h"

#include <gsl/gsl_errno.h>

static int run(const char *file, int verbose)
{
    char path[4096];
    sq_test_path(path, sizeof path, 0, file);
    cad_model *m = NULL;
    cad_face *f = NULL;
    sq_error err;
    SQ_TEST_OK(cad_model_read(path, &m, &err), err);
    SQ_TEST_OK(cad_face_create(m, cad_model_default_face(m, &(const char *){NULL}), &f, &err), err);
    sq_field_options fo;
    sq_field_options_default(&fo);
    sq_field_analysis a;
    SQ_TEST_OK(sq_field_analyse(f, &fo, &a, &err), err);
    int nsing = 0;
    sq_singularity *sing = calloc((size_t)a.npoints + 1, sizeof *sing);
    for (int k = 0; k < a.npoints; k++)
        if (a.points[k].valence != 4 && !a.points[k].near_boundary)
            sing[nsing++] = (sq_singularity){a.points[k].x, a.points[k].y, a.points[k].valence,
                                             SQ_ORIGIN_CRITICAL};
    int *quads = malloc((size_t)a.info.nvertices * sizeof *quads + 1);
    for (int k = 0; k < a.info.nvertices; k++) quads[k] = a.corners[k].valence;
    sq_cross_field field = sq_guiding_cross_field(&a.field);
    sq_trace_options to;
    sq_trace_options_default(&to);
    sq_separatrix_set set = {0, 0, NULL};
    SQ_TEST_OK(sq_trace_separatrices(&field, f, &a.info, quads, nsing, sing, &to, &set, &err), err);
    sq_layout L;
    sq_status st = sq_layout_build(f, &a.info, quads, nsing, sing, &set, &field, &to, &L, &err);
    int fails = 0;
    if (st != SQ_OK) {
        printf("%s: sq_layout_build: %s\n", file, err.msg);
        fails++;
    }
    if (st == SQ_OK || st == SQ_ERR_LAYOUT) {
        if (verbose || st != SQ_OK) {
            printf("%s: sing %d traced %d -> seps %d patches %d quads %d  T %d lc %d tri %d ann %d "
                   "dup %d cross %d it %d\n",
                   file, nsing, set.n, L.stats.separatrices, L.stats.patches,
                   L.stats.quad_patches, L.stats.t_junctions, L.stats.limit_cycles_cut,
                   L.stats.triangles_repaired, L.stats.annuli_cut, L.stats.duplicates_removed,
                   L.stats.crossings_split, L.stats.iterations);
            sq_layout_defects d;
            sq_layout_check(&L, &d);
            for (int k = 0; k < d.n && k < 12; k++) printf("   %s\n", d.d[k].msg);
            sq_layout_defects_free(&d);
        }
        if (!strcmp(file, "half_disc.step")) {
            fails += sq_check_int(file, "separatrices", L.stats.separatrices, 5);
            fails += sq_check_int(file, "patches", L.stats.patches, 4);
        }
        if (!strcmp(file, "annulus.step")) {
            fails += sq_check_int(file, "annuli cut", L.stats.annuli_cut, 1);
            fails += L.stats.quad_patches < 2;
        }
        double sum = 0.0;
        for (int p = 0; p < L.npatches; p++) sum += L.patches[p].area;
        /* patch areas by cad_split's adaptive Green rule: 1e-9 (t320) */
        fails += sq_check_rel(file, "area sum", sum, a.info.area, 1e-9);
        sq_layout_free(&L);
    }
    sq_separatrix_set_free(&set);
    free(sing);
    free(quads);
    sq_field_analysis_free(&a);
    cad_face_free(&f);
    cad_model_free(&m);
    return fails;
}

int main(int argc, char **argv)
{
    gsl_set_error_handler_off();
    static const char *ex[] = {"half_disc.step", "quarter_circle.step", "square.step",
                               "triangle.step", "square_hole.step", "two_holes.step",
                               "nautilus.step", "polygon.step", "naca0012.step", "annulus.step",
                               "lshape.step"};
    int fails = 0;
    for (size_t k = 0; k < sizeof ex / sizeof *ex; k++)
        if (argc < 2 || strstr(ex[k], argv[1])) fails += run(ex[k], argc > 2) != 0;
    return fails != 0;
}
