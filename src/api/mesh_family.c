/* semquad public API: mesh families for convergence studies
 * (docs/convergence-families.md): a finished mesh refined 2 × 2 per level
 * and raised or lowered to other orders (quad_refine.h), and the
 * manifest that lists a family's files. */
#include "api_private.h"
#include "json_writer.h"
#include "outfile.h"
#include "periodic.h"
#include "quad_edges.h"
#include "quad_refine.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

sq_status sq_api_refined_handle(const sq_mesh *m, sq_quad_mesh *q, sq_mesh **out, sq_error *err)
{
    sq_mesh *h = calloc(1, sizeof *h);
    if (!h || !(h->t_write = calloc(1, sizeof *h->t_write))) {
        free(h);
        sq_quad_mesh_free(&q);
        return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    }
    h->t0 = sq_now();
    h->q = q;
    h->road = m->road;
    h->progress = m->progress;
    h->nbl = m->nbl;
    h->threads = m->threads;
    sq_status st = sq_api_face_open(m->face.model, m->face.index, NULL, &h->face, err);
    if (st == SQ_OK) st = sq_face_info_compute(h->face.cad, &h->info, err);
    if (st == SQ_OK) st = sq_api_mesh_quality(h, err);
    if (st == SQ_OK) st = sq_api_mesh_arrays(h, err);
    if (st != SQ_OK) sq_mesh_free(&h);
    *out = h;
    return st;
}

sq_status sq_api_refine_levels(const sq_mesh *m, int levels, int order, const sq_options *o,
                               sq_api_refine_step step, void *ctx, sq_quad_mesh **out,
                               sq_error *err)
{
    *out = NULL;
    sq_quad_mesh *q = NULL;
    /* level by level at m's order, so each level's vertices are the last's;
     * periodic links found again on each (the new nodes of a pair's curves
     * are at the same arc-length fractions, so images of each other to the
     * curves' accuracy), the image nodes set exactly */
    const sq_quad_mesh *from = m->q;
    /* the levels, then one step to the other order (or a copy: no level) */
    const int steps = levels + (order != m->q->order || levels == 0);
    for (int k = 0; k < steps; k++) {
        const int split = k < levels;
        sq_quad_mesh *next = NULL;
        sq_status st = step(ctx, from, split ? 2 : 1, split ? m->q->order : order, o->threads,
                            &next, err);
        if (st == SQ_OK)
            st = sq_periodic_relink(m->q, next, sqrt(m->quality.area / next->nquads),
                                    SQ_PERIODIC_NODE_REL_TOL, err);
        sq_quad_mesh_free(&q);
        if (st != SQ_OK) {
            sq_quad_mesh_free(&next);
            return st;
        }
        from = q = next;
    }
    /* the curves' and faces' names, as m's (its tags and faces are q's) */
    sq_status st = sq_quad_mesh_copy_names(q, m->q, err);
    if (st != SQ_OK) {
        sq_quad_mesh_free(&q);
        return st;
    }
    sq_api_log(o, SQ_LOG_INFO, "refined %d quads of order %d to %d of order %d", m->q->nquads,
               m->q->order, q->nquads, q->order);
    *out = q;
    return SQ_OK;
}

/* One face's step: its mesh's quads refined on its CAD face. */
static sq_status face_step(void *ctx, const sq_quad_mesh *from, int n, int order, int threads,
                           sq_quad_mesh **out, sq_error *err)
{
    return sq_quad_mesh_refine(ctx, from, n, order, threads, out, err);
}

sq_status sq_mesh_refine(const sq_mesh *m, int levels, int order, const sq_options *o,
                         sq_mesh **out, sq_error *err)
{
    *out = NULL;
    sq_options def;
    o = sq_api_options(o, &def);
    if (order == 0) order = m->q->order;
    if (levels < 0 || order < 1 || order > 10)
        return SQ_FAIL(err, SQ_ERR_USAGE, "refinement: %d levels (0 or more), order %d (1..10)",
                       levels, order);
    if ((double)m->q->nquads * pow(4.0, levels) > o->max_quads)
        return SQ_FAIL(err, SQ_ERR_USAGE,
                       "%d quads split 2 x 2 %d time%s give %.0f quads, more than --max-quads %.3g",
                       m->q->nquads, levels, levels == 1 ? "" : "s",
                       (double)m->q->nquads * pow(4.0, levels), o->max_quads);
    if (m->dom) return sq_api_domain_refine(m, levels, order, o, out, err);
    sq_quad_mesh *q = NULL;
    SQ_TRY(sq_api_refine_levels(m, levels, order, o, face_step, m->face.cad, &q, err));
    return sq_api_refined_handle(m, q, out, err);
}

sq_status sq_mesh_edge_lengths(const sq_mesh *m, double *mean, double *max, sq_error *err)
{
    sq_quad_edges e;
    SQ_TRY(sq_quad_edges_build(m->q, m->threads, &e, err));
    sq_quad_edges_lengths(m->q, &e, mean, max);
    sq_quad_edges_free(&e);
    return SQ_OK;
}

/* One file of the family: the numbers a grid-convergence table needs. */
static sq_status manifest_entry(sq_json *j, const sq_mesh *m, const char *file, int level,
                                sq_error *err)
{
    double mean, max;
    SQ_TRY(sq_mesh_edge_lengths(m, &mean, &max, err));
    const sq_quad_mesh *q = m->q;
    sq_json_begin_object(j);
    sq_json_key_string(j, "file", file);
    sq_json_key_int(j, "level", level);
    sq_json_key_int(j, "order", q->order);
    sq_json_key_int(j, "quads", q->nquads);
    sq_json_key_int(j, "nodes", q->nnodes);
    /* a scalar continuous field of order Q has one unknown per node */
    sq_json_key_int(j, "dofs", q->nnodes);
    sq_json_key_number(j, "h_mean", mean);
    sq_json_key_number(j, "h_max", max);
    sq_json_key_number(j, "h_area", sqrt(m->quality.area / q->nquads));
    sq_json_key_number(j, "area", m->quality.area);
    sq_json_key_number(j, "min_scaled_jacobian", m->quality.min_scaled_jacobian);
    sq_json_key_int(j, "inverted", m->quality.inverted);
    sq_json_end_object(j);
    return SQ_OK;
}

sq_status sq_mesh_family_write_manifest(const char *path, int n, const sq_mesh *const *meshes,
                                        const char *const *files, const int *levels,
                                        sq_error *err)
{
    if (n < 1) return SQ_FAIL(err, SQ_ERR_USAGE, "a manifest needs at least one mesh");
    const sq_mesh *m0 = meshes[0];
    sq_outfile f;
    SQ_TRY(sq_outfile_open(path, &f, err));
    sq_json j;
    sq_json_init(&j, f.fp);
    sq_json_begin_object(&j);
    sq_json_key_string(&j, "input", m0->face.model->path);
    sq_json_key_int(&j, "face", m0->face.index);
    /* a domain: its faces, and the sum of their exact areas */
    double area = m0->dom ? 0.0 : m0->info.area;
    if (m0->dom) {
        sq_json_key(&j, "faces");
        sq_json_begin_array(&j);
        for (int k = 0; k < m0->dom->nfaces; k++) {
            sq_json_int(&j, m0->dom->face[k]);
            area += m0->dom->area[k];
        }
        sq_json_end_array(&j);
    }
    sq_json_key_string(&j, "unit", cad_model_unit(m0->face.model->cad));
    sq_json_key_number(&j, "face_area", area);
    sq_json_key_string(&j, "road", m0->road.name);
    sq_json_key(&j, "meshes");
    sq_json_begin_array(&j);
    sq_status st = SQ_OK;
    for (int k = 0; k < n && st == SQ_OK; k++)
        st = manifest_entry(&j, meshes[k], files[k], levels[k], err);
    sq_json_end_array(&j);
    sq_json_end_object(&j);
    fputc('\n', f.fp);
    if (st != SQ_OK) {
        sq_outfile_abort(&f);
        return st;
    }
    return sq_outfile_commit(&f, err);
}
