#include "layout_pipeline.h"

#include <stdlib.h>
#include <string.h>

void sq_layout_options_default(sq_layout_options *opt)
{
    sq_field_options_default(&opt->field);
    sq_trace_options_default(&opt->trace);
}

void sq_layout_result_free(sq_layout_result *r)
{
    if (!r) return;
    sq_layout_free(&r->layout);
    sq_separatrix_set_free(&r->traced);
    free(r->sing);
    free(r->vertex_quads);
    sq_field_analysis_free(&r->analysis);
    memset(r, 0, sizeof *r);
}

sq_status sq_layout_run(const cad_face *face, const sq_layout_options *opt, sq_layout_result *out,
                        sq_error *err)
{
    memset(out, 0, sizeof *out);
    SQ_TRY(sq_field_analyse(face, &opt->field, &out->analysis, err));
    const sq_field_analysis *a = &out->analysis;
    out->sing = calloc((size_t)a->npoints + 1, sizeof *out->sing);
    out->vertex_quads = calloc((size_t)a->info.nvertices + 1, sizeof *out->vertex_quads);
    if (!out->sing || !out->vertex_quads) {
        sq_layout_result_free(out);
        return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    }
    /* Regular points (index 0) carry no separatrix; points on the boundary
     * are reported by the field stage but cannot start a layout. */
    for (int k = 0; k < a->npoints; k++)
        if (a->points[k].valence != 4 && !a->points[k].near_boundary)
            out->sing[out->nsing++] = (sq_singularity){a->points[k].x, a->points[k].y,
                                                       a->points[k].valence, SQ_ORIGIN_CRITICAL};
    for (int k = 0; k < a->info.nvertices; k++) out->vertex_quads[k] = a->corners[k].valence;
    sq_cross_field field = sq_guiding_cross_field(&a->field);
    double t0 = sq_now();
    sq_status st = sq_trace_separatrices_stats(&field, face, &a->info, out->vertex_quads,
                                               out->nsing, out->sing, &opt->trace, &out->traced,
                                               &out->trace_stats, err);
    double t1 = sq_now();
    if (st == SQ_OK)
        st = sq_layout_build(face, &a->info, out->vertex_quads, out->nsing, out->sing,
                             &out->traced, &field, &opt->trace, &out->layout, err);
    out->t_trace = t1 - t0;
    out->t_layout = sq_now() - t1;
    out->valid = st == SQ_OK;
    if (st != SQ_OK && st != SQ_ERR_LAYOUT) sq_layout_result_free(out);
    return st;
}
