#include "layout_pipeline.h"

#include "degenerate_split.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

void sq_layout_options_default(sq_layout_options *opt)
{
    memset(opt, 0, sizeof *opt);
    sq_field_options_default(&opt->field);
    sq_trace_options_default(&opt->trace);
    sq_htheta_options_default(&opt->htheta);
}

/* The mesh command's fields.  The mesh needs the layout's topology and
 * its singular points to a fraction of a quad: order 4 gives the guiding
 * field's layouts and mesh quality of order 8 on every example at a small
 * fraction of the solve.  The H/theta field stays at 8: at 6 its e^H sizes
 * drift (disc: 429 quads at 4, 300 at 6 and 8) and the holonomy check
 * (0.01 deg) fails on obtuse_quad_v2 (0.016 deg).  Its triangulation is
 * graded to 1e-2 of the size at the singular corners (1e-3 by default;
 * coarser breaks that check too), and only to 1/4 of it at the imposed
 * points, whose log and arg terms H and θ carry in closed form: the same
 * layouts as with the defaults (t416), meshes with the same counts and η̄
 * within 0.002, the disc's H/θ on 105 elements instead of 556 (0.17 ->
 * 0.04 s).  docs/mesh.md. */
#define MESH_FIELD_ORDER 4
#define MESH_HTHETA_ORDER 8
#define MESH_HTHETA_GRADING 1e-2
#define MESH_HTHETA_POINT_GRADING 0.25

void sq_layout_options_for_mesh(sq_layout_options *opt)
{
    sq_layout_options_default(opt);
    opt->field.order = MESH_FIELD_ORDER;
    opt->htheta.order = MESH_HTHETA_ORDER;
    opt->htheta.grading = MESH_HTHETA_GRADING;
    opt->htheta.point_grading = MESH_HTHETA_POINT_GRADING;
}

void sq_layout_result_free(sq_layout_result *r)
{
    if (!r) return;
    sq_layout_free(&r->layout);
    sq_htheta_free(&r->htheta);
    sq_separatrix_set_free(&r->traced);
    free(r->sing);
    free(r->vertex_quads);
    sq_field_analysis_free(&r->analysis);
    memset(r, 0, sizeof *r);
}

/* The guiding field's pattern: its critical points and corner valences. */
static sq_status guiding_pattern(const cad_face *face, sq_layout_result *out, sq_error *err)
{
    const sq_field_analysis *a = &out->analysis;
    out->vertex_quads = calloc((size_t)a->info.nvertices + 1, sizeof *out->vertex_quads);
    if (!out->vertex_quads) return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    /* Regular points (index 0) carry no separatrix; points on the boundary
     * are reported by the field stage but cannot start a layout. */
    SQ_TRY(sq_elementary_points(face, a, &out->sing, &out->nsing, NULL, err));
    for (int k = 0; k < a->info.nvertices; k++) out->vertex_quads[k] = a->corners[k].valence;
    out->info = &a->info;
    out->field = (sq_field_summary){"guiding", a->field.method, a->field.order,
                                    a->tri.mesh->ntris, a->field.ndofs, a->t_triangulate,
                                    a->t_solve, a->t_critical};
    return SQ_OK;
}

/* The H/θ field (Jezdimirović 2021 §4-5) of the pattern file, or of the
 * guiding field's natural pattern (out->analysis, already computed). */
static sq_status htheta_pattern(const cad_face *face, const sq_layout_options *opt,
                                int from_analysis, sq_layout_result *out, sq_error *err)
{
    sq_pattern pat = {0};
    sq_status st;
    if (from_analysis) {
        st = sq_pattern_from_analysis(face, &out->analysis, &pat, err);
        out->ndegenerate = pat.ndegenerate;
    } else {
        st = sq_pattern_read(opt->singularities, &pat, err);
    }
    if (st == SQ_OK) st = sq_htheta_compute(face, &pat, &opt->htheta, &out->htheta, err);
    sq_pattern_free(&pat);
    if (st == SQ_OK) st = sq_htheta_check_alignment(&out->htheta, opt->allow_misaligned, err);
    if (st != SQ_OK) return st;
    const sq_htheta *h = &out->htheta;
    out->sing = calloc((size_t)h->npoints + 1, sizeof *out->sing);
    out->vertex_quads = calloc((size_t)h->info.nvertices + 1, sizeof *out->vertex_quads);
    if (!out->sing || !out->vertex_quads) return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    for (int k = 0; k < h->npoints; k++)
        if (h->points[k].valence != 4)
            out->sing[out->nsing++] = (sq_singularity){h->points[k].x, h->points[k].y,
                                                       h->points[k].valence, h->points[k].origin};
    for (int k = 0; k < h->info.nvertices; k++) out->vertex_quads[k] = h->balance.quads[k];
    out->info = &h->info;
    out->field = (sq_field_summary){"H-theta", SEM_CG, opt->htheta.order, h->tri.mesh->ntris,
                                    0, h->t_triangulate, h->t_solve, 0.0};
    if (from_analysis) { /* the guiding field's stage ran first */
        out->field.t_triangulate += out->analysis.t_triangulate;
        out->field.t_solve += out->analysis.t_solve;
        out->field.t_critical = out->analysis.t_critical;
    }
    return SQ_OK;
}

sq_status sq_layout_run(const cad_face *face, const sq_layout_options *opt, sq_layout_result *out,
                        sq_error *err)
{
    memset(out, 0, sizeof *out);
    sq_status st = SQ_OK;
    sq_cross_field field;
    const int natural = opt->singularities && !strcmp(opt->singularities, "natural");
    if (!opt->singularities || natural)
        st = sq_field_analyse(face, &opt->field, &out->analysis, err);
    /* a degenerate zero of the guiding field is split into elementary
     * points, whose layout the H/θ field of that pattern gives */
    if (st == SQ_OK && (opt->singularities || sq_has_degenerate_point(&out->analysis))) {
        st = htheta_pattern(face, opt, !opt->singularities || natural, out, err);
        field = sq_htheta_cross_field(&out->htheta);
    } else if (st == SQ_OK) {
        st = guiding_pattern(face, out, err);
        field = sq_guiding_cross_field(&out->analysis.field);
    }
    if (st != SQ_OK) {
        sq_layout_result_free(out);
        return st;
    }
    double t0 = sq_now();
    st = sq_trace_separatrices_stats(&field, face, out->info, out->vertex_quads, out->nsing,
                                     out->sing, &opt->trace, &out->traced, &out->trace_stats, err);
    double t1 = sq_now();
    if (st == SQ_OK)
        st = sq_layout_build(face, out->info, out->vertex_quads, out->nsing, out->sing,
                             &out->traced, &field, &opt->trace, &out->layout, err);
    out->t_trace = t1 - t0;
    out->t_layout = sq_now() - t1;
    out->valid = st == SQ_OK;
    if (st != SQ_OK && st != SQ_ERR_LAYOUT) sq_layout_result_free(out);
    return st;
}

int sq_layout_note(const sq_layout_result *r, char *buf, size_t n)
{
    if (r->ndegenerate == 0) return 0;
    int nsplit = 0;
    for (int k = 0; k < r->nsing; k++) nsplit += r->sing[k].origin == SQ_ORIGIN_SPLIT;
    snprintf(buf, n,
             "%d degenerate singular point%s of the guiding field (|index| > 1) split into %d "
             "elementary points at %g x the distance to the boundary; layout traced on the "
             "H/theta field of that pattern",
             r->ndegenerate, r->ndegenerate == 1 ? "" : "s", nsplit, SQ_SPLIT_FRACTION);
    return 1;
}
