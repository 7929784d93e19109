/* semquad — the correction loop (layout.h design 4; Jezdimirović 2021
 * journal §6, Marcon 2019 §3.4): the repairs in their order until the
 * layout is valid or stuck, within the work bound. */
#include "repair_private.h"

#include <stdlib.h>
#include <string.h>

sq_status lay_repair_begin(lay_repair *r, sq_layout *L, const cad_face *face,
                           const sq_face_info *info, const sq_cross_field *field,
                           const sq_trace_options *opt, sq_error *err)
{
    memset(r, 0, sizeof *r);
    r->L = L;
    r->face = face;
    r->info = info;
    r->field = field;
    r->tol = 1e-9 * L->scale;
    r->step = 0.004 * L->scale;
    double perim = 0.0;
    for (int e = 0; e < cad_face_num_edges(face); e++) perim += cad_face_edge_length(face, e);
    r->maxlen = opt && opt->max_length > 0 ? opt->max_length : 4.0 * perim;
    return lay_sample_boundary(r, err);
}

void lay_repair_end(lay_repair *r)
{
    free(r->bxy);
    free(r->bs);
    free(r->bedge);
    free(r->hit);
    /* the counters stay: the caller reads whether the work bound ended it */
    r->bxy = r->bs = NULL;
    r->bedge = NULL;
    r->hit = NULL;
}

sq_status sq_layout_build(const cad_face *face, const sq_face_info *info, const int *vertex_quads,
                          int nsing, const sq_singularity *sing, const sq_separatrix_set *seps,
                          const sq_cross_field *field, const sq_trace_options *opt,
                          sq_layout *out, sq_error *err)
{
    SQ_TRY(sq_layout_graph(face, info, vertex_quads, nsing, sing, seps, out, err));
    sq_layout *L = out;
    lay_repair r;
    sq_status st = lay_repair_begin(&r, L, face, info, field, opt, err);
    sq_layout_defects d;
    memset(&d, 0, sizeof d);
    int it;
    for (it = 0; it < 400 && st == SQ_OK && r.work <= WORK_MAX && r.lwork <= LINE_WORK_MAX; it++) {
        /* set-level repairs first, the graph rebuilt after them; each
         * iteration follows a change of the set */
        int done = 0;
        st = lay_set_repair(&r, &done, err);
        if (st != SQ_OK) break;
        if (done) continue;
        st = lay_graph_build(L, face, info, err);
        if (st != SQ_OK) break;
        sq_layout_defects_free(&d);
        if (sq_layout_check(L, &d) == 0) break;
        st = lay_cut_annulus(&r, &done, err);
        if (st == SQ_OK && !done) st = lay_split_valence2(&r, &done, err);
        if (st == SQ_OK && !done) st = lay_split_triangle(&r, &done, err);
        if (st == SQ_OK && !done) st = lay_repair_polygon(&r, d.n, &done, err);
        if (st == SQ_OK && !done) break; /* stuck */
    }
    L->stats.iterations = it;
    if (st == SQ_OK || st == SQ_ERR_LAYOUT) { /* the graph of the final set */
        sq_error e2;
        sq_status s2 = lay_graph_build(L, face, info, &e2);
        if (s2 != SQ_OK) {
            st = s2;
            if (err) *err = e2;
        }
    }
    lay_repair_end(&r);
    if (st == SQ_OK || st == SQ_ERR_LAYOUT) {
        L->stats.separatrices = L->seps.n;
        L->stats.patches = L->npatches;
        L->stats.quad_patches = 0;
        for (int p = 0; p < L->npatches; p++)
            L->stats.quad_patches += L->patches[p].ncorners == 4 && L->patches[p].ncycles == 1;
        sq_layout_defects_free(&d);
        if (sq_layout_check(L, &d) > 0 && st == SQ_OK) {
            char buf[400];
            sq_layout_defects_summary(&d, buf, sizeof buf);
            st = SQ_FAIL(err, SQ_ERR_LAYOUT, "%s%s", buf,
                         r.work > WORK_MAX || r.lwork > LINE_WORK_MAX
                             ? " (repairs stopped at their work bound)"
                             : "");
        }
    } else if (st != SQ_ERR_LAYOUT) {
        sq_layout_free(L);
    }
    sq_layout_defects_free(&d);
    return st;
}
