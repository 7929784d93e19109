#include "write_mesh_report.h"

#include "face_info.h"
#include "outfile.h"
#include "write_layout.h"

#include <string.h>

/* Named boundaries (docs/formats.md): every boundary group, its physical
 * tag in the MSH file, name and CAD edges; only when some are named, so
 * reports without names keep their keys. */
static void json_groups(sq_json *j, const sq_quad_mesh *m)
{
    if (!m->tag_name) return;
    sq_json_key(j, "groups");
    sq_json_begin_array(j);
    for (int t = 0; t < m->ntags; t++) {
        if (sq_quad_mesh_tag_group(m, t) != t) continue;
        char buf[32];
        sq_json_begin_object(j);
        sq_json_key_int(j, "dim", 1);
        sq_json_key_int(j, "tag", t + 1);
        sq_json_key(j, "name");
        sq_json_string(j, sq_quad_mesh_tag_name(m, t, buf, sizeof buf));
        sq_json_key(j, "edges");
        sq_json_begin_array(j);
        for (int u = t; u < m->ntags; u++)
            if (sq_quad_mesh_tag_group(m, u) == t) sq_json_int(j, u);
        sq_json_end_array(j);
        sq_json_end_object(j);
    }
    sq_json_end_array(j);
}

/* The user's sizes against the mesh (docs/sizes.md, "The report"); only
 * with sizes, so reports without them keep their keys. */
static void json_sizes(sq_json *j, const sq_size_report *s, double far)
{
    if (!s) return;
    sq_json_key(j, "sizes");
    sq_json_begin_object(j);
    sq_json_key_number(j, "far", far);
    sq_json_key(j, "quads");
    sq_json_begin_object(j);
    sq_json_key_number(j, "ratio_min", s->quad_ratio_min);
    sq_json_key_number(j, "ratio_median", s->quad_ratio_median);
    sq_json_key_number(j, "ratio_max", s->quad_ratio_max);
    sq_json_end_object(j);
    sq_json_key(j, "edges");
    sq_json_begin_array(j);
    for (int k = 0; k < s->nedges; k++) {
        const sq_edge_sizes *e = &s->edge[k];
        sq_json_begin_object(j);
        sq_json_key_int(j, "edge", e->edge);
        sq_json_key_int(j, "segments", e->segments);
        sq_json_key_number(j, "cells", e->cells);
        sq_json_key_int(j, "patch_sides", e->patch_sides);
        sq_json_key_number(j, "target_min", e->target_min);
        sq_json_key_number(j, "target_max", e->target_max);
        sq_json_key_number(j, "achieved_min", e->achieved_min);
        sq_json_key_number(j, "achieved_max", e->achieved_max);
        sq_json_key_number(j, "ratio_min", e->ratio_min);
        sq_json_key_number(j, "ratio_max", e->ratio_max);
        sq_json_end_object(j);
    }
    sq_json_end_array(j);
    sq_json_end_object(j);
}

/* The boundary layers achieved against those asked (docs/sizes.md, "The
 * report"); only with --bl, so reports without them keep their keys. */
static void json_boundary_layers(sq_json *j, const sq_bl_report *b)
{
    if (!b) return;
    sq_json_key(j, "boundary_layers");
    sq_json_begin_array(j);
    for (int k = 0; k < b->nedges; k++) {
        const sq_bl_edge_report *e = &b->edge[k];
        sq_json_begin_object(j);
        sq_json_key_int(j, "edge", e->edge);
        sq_json_key(j, "requested");
        sq_json_begin_object(j);
        sq_json_key_number(j, "first", b->first);
        sq_json_key_number(j, "ratio", b->ratio);
        sq_json_key_int(j, "layers", b->layers);
        sq_json_key_number(j, "thickness", b->thickness);
        sq_json_end_object(j);
        sq_json_key(j, "achieved");
        sq_json_begin_object(j);
        sq_json_key_int(j, "columns", e->columns);
        sq_json_key_number(j, "first_min", e->first_min);
        sq_json_key_number(j, "first_median", e->first_median);
        sq_json_key_number(j, "first_max", e->first_max);
        sq_json_key_number(j, "ratio_min", e->ratio_min);
        sq_json_key_number(j, "ratio_max", e->ratio_max);
        sq_json_key_int(j, "layers", e->layers);
        sq_json_key_number(j, "thickness_min", e->thickness_min);
        sq_json_key_number(j, "thickness_max", e->thickness_max);
        sq_json_end_object(j);
        sq_json_end_object(j);
    }
    sq_json_end_array(j);
}

void sq_json_periodic(sq_json *j, const sq_quad_mesh *m)
{
    if (m->nperiodic == 0) return;
    sq_json_key(j, "periodic");
    sq_json_begin_object(j);
    sq_json_key(j, "pairs");
    sq_json_begin_array(j);
    for (int l = 0; l < m->nperiodic; l++) {
        const sq_quad_periodic *p = &m->periodic[l];
        sq_json_begin_object(j);
        sq_json_key(j, "edges");
        sq_json_begin_array(j);
        sq_json_int(j, p->master);
        sq_json_int(j, p->tag);
        sq_json_end_array(j);
        sq_json_key(j, "kind");
        sq_json_string(j, p->affine[3] != 0.0 ? "rotation" : "translation");
        sq_json_key(j, "affine");
        sq_json_begin_array(j);
        for (int k = 0; k < 6; k++) sq_json_number(j, p->affine[k]);
        sq_json_end_array(j);
        sq_json_key_int(j, "nodes", p->nnodes);
        sq_json_end_object(j);
    }
    sq_json_end_array(j);
    sq_json_key_int(j, "identified_chi", m->periodic_chi);
    sq_json_key_int(j, "gauss_bonnet_index", m->periodic_index);
    sq_json_key_int(j, "gauss_bonnet_min_irregular", m->periodic_index < 0 ? -m->periodic_index
                                                                             : m->periodic_index);
    sq_json_key_int(j, "irregular_interior_vertices", m->periodic_irregular);
    sq_json_key_int(j, "mesh_index", m->periodic_mesh_index);
    sq_json_end_object(j);
}

void sq_print_mesh_report(FILE *fp, const char *input, const cad_model *model, int face,
                          const sq_face_info *info, const sq_road_choice *road,
                          const sq_layout_result *r, const sq_quad_mesh *m,
                          const sq_quad_quality *q, const sq_report_sizes *sz,
                          const sq_mesh_timings *t)
{
    sq_json j;
    sq_json_init(&j, fp);
    sq_json_begin_object(&j);
    int by_layout = !strcmp(road->name, "layout") && r->info; /* not a refined mesh */
    if (by_layout) {
        sq_json_layout_head(&j, input, face, r);
    } else {
        sq_json_key(&j, "input");
        sq_json_string(&j, input);
        sq_json_key_int(&j, "face", face);
        sq_json_key_int(&j, "chi", info->chi);
    }
    sq_json_key(&j, "road");
    sq_json_string(&j, road->name);
    if (road->reason[0]) {
        sq_json_key(&j, "road_reason");
        sq_json_string(&j, road->reason);
    }
    sq_json_healing(&j, model, face);
    sq_json_key(&j, "mesh");
    sq_json_begin_object(&j);
    sq_json_key_int(&j, "quads", m->nquads);
    sq_json_key_int(&j, "order", m->order);
    sq_json_key_int(&j, "nodes", m->nnodes);
    /* a large mesh relaxed coarser (docs/mesh.md, "Large meshes") */
    if (m->relaxed_quads > 0) sq_json_key_int(&j, "relaxed_at_quads", m->relaxed_quads);
    sq_json_key_int(&j, "irregular_interior_vertices", q->irregular_interior);
    sq_json_key_int(&j, "irregular_boundary_vertices", q->irregular_boundary);
    sq_json_key(&j, "quality");
    sq_json_begin_object(&j);
    sq_json_key_number(&j, "mean", q->eta_mean);
    sq_json_key_number(&j, "min", q->eta_min);
    sq_json_key_number(&j, "above_0_9_percent", q->tau_percent);
    sq_json_end_object(&j);
    sq_json_key(&j, "quality_curved");
    sq_json_begin_object(&j);
    sq_json_key_number(&j, "mean", q->eta_curved_mean);
    sq_json_key_number(&j, "min", q->eta_curved_min);
    sq_json_key_number(&j, "above_0_9_percent", q->tau_curved_percent);
    sq_json_end_object(&j);
    sq_json_key_number(&j, "min_scaled_jacobian", q->min_scaled_jacobian);
    sq_json_key_number(&j, "min_scaled_jacobian_nodes", q->min_scaled_jacobian_nodes);
    sq_json_key_int(&j, "jacobian_capped", q->jacobian_capped);
    sq_json_key(&j, "worst_quad");
    sq_json_begin_object(&j);
    sq_json_key_int(&j, "index", q->worst_quad);
    sq_json_key_number(&j, "x", q->worst_xy[0]);
    sq_json_key_number(&j, "y", q->worst_xy[1]);
    sq_json_key_number(&j, "scaled_jacobian", q->min_scaled_jacobian);
    sq_json_end_object(&j);
    sq_json_key_int(&j, "inverted", q->inverted);
    sq_json_key_number(&j, "area", q->area);
    sq_json_end_object(&j);
    json_groups(&j, m);
    json_sizes(&j, sz ? sz->report : NULL, sz ? sz->far : 0.0);
    json_boundary_layers(&j, sz ? sz->bl : NULL);
    sq_json_periodic(&j, m);
    sq_json_key(&j, "timings_s");
    sq_json_begin_object(&j);
    sq_json_key_number(&j, "read", t->read);
    sq_json_key_number(&j, "triangulate", t->triangulate);
    sq_json_key_number(&j, "solve", t->solve);
    sq_json_key_number(&j, "critical_points", t->critical_points);
    sq_json_key_number(&j, "trace", t->trace);
    sq_json_key_number(&j, "layout", t->layout);
    sq_json_key_number(&j, "mesh", t->mesh);
    sq_json_key_number(&j, "write", t->write);
    sq_json_key_number(&j, "total", t->total);
    sq_json_end_object(&j);
    sq_json_end_object(&j);
}

sq_status sq_write_mesh_report(const char *path, const char *input, const cad_model *model,
                               int face, const sq_face_info *info, const sq_road_choice *road,
                               const sq_layout_result *r, const sq_quad_mesh *m,
                               const sq_quad_quality *q, const sq_report_sizes *sz,
                               const sq_mesh_timings *t, sq_error *err)
{
    sq_outfile f;
    SQ_TRY(sq_outfile_open(path, &f, err));
    sq_print_mesh_report(f.fp, input, model, face, info, road, r, m, q, sz, t);
    return sq_outfile_commit(&f, err);
}
