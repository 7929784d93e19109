/* Layouts traced through the H/θ cross field (Jezdimirović 2021): the
 * high-valence patterns on the square — (a) four V5 + four V3, (b) two V6
 * + four V3, (c) one V8 at the centre + four V3 — give valid layouts (all
 * patches quads, each valence-V point a corner of exactly V patches, areas
 * summing to the face's); and the two-step pipeline (natural pattern of
 * the guiding field -> H/θ) reproduces the guiding field's layout topology
 * on half_disc, quarter_circle and square_hole. */
#include "layout_pipeline.h"
#include "test_util.h"

#include <gsl/gsl_errno.h>

static int run(const char *file, const char *pattern, sq_layout_stats *stats, int *nsing)
{
    char path[4096], pat[4096];
    sq_test_path(path, sizeof path, 0, file);
    if (pattern && strcmp(pattern, "natural")) sq_test_path(pat, sizeof pat, 0, pattern);
    else if (pattern) snprintf(pat, sizeof pat, "natural");
    cad_model *m = NULL;
    cad_face *f = NULL;
    sq_error err;
    SQ_TEST_OK(cad_model_read(path, &m, &err), err);
    SQ_TEST_OK(cad_face_create(m, 0, &f, &err), err);
    sq_layout_options lo;
    sq_layout_options_default(&lo);
    lo.singularities = pattern ? pat : NULL;
    sq_layout_result r;
    sq_status st = sq_layout_run(f, &lo, &r, &err);
    int fails = 0;
    if (st != SQ_OK) {
        printf("%s %s: %s\n", file, pattern ? pattern : "guiding", err.msg);
        fails++;
    } else {
        sq_layout_defects d;
        fails += sq_check_int(file, "layout defects", sq_layout_check(&r.layout, &d), 0);
        sq_layout_defects_free(&d);
        *stats = r.layout.stats;
        *nsing = r.nsing;
        fails += sq_check_int(file, "quad patches", r.layout.stats.quad_patches, r.layout.stats.patches);
        double sum = 0.0;
        for (int p = 0; p < r.layout.npatches; p++) sum += r.layout.patches[p].area;
        fails += sq_check_rel(file, "area sum", sum, r.info->area, 1e-9);
    }
    sq_layout_result_free(&r);
    cad_face_free(&f);
    cad_model_free(&m);
    return fails;
}

int main(void)
{
    gsl_set_error_handler_off();
    int fails = 0, n = 0;
    sq_layout_stats s;
    const char *patterns[] = {"square_v5.txt", "square_v6.txt", "square_v8.txt"};
    const int npoints[] = {8, 6, 5};
    for (int i = 0; i < 3; i++) {
        fails += run("square.step", patterns[i], &s, &n);
        fails += sq_check_int(patterns[i], "singular points traced", n, npoints[i]);
    }
    const char *files[] = {"half_disc.step", "quarter_circle.step", "square_hole.step"};
    for (int i = 0; i < 3; i++) {
        sq_layout_stats g, h;
        int ng = 0, nh = 0;
        fails += run(files[i], NULL, &g, &ng);
        fails += run(files[i], "natural", &h, &nh);
        fails += sq_check_int(files[i], "singular points (two-step = guiding)", nh, ng);
        fails += sq_check_int(files[i], "separatrices (two-step = guiding)", h.separatrices, g.separatrices);
        fails += sq_check_int(files[i], "patches (two-step = guiding)", h.patches, g.patches);
    }
    return fails ? 1 : 0;
}
