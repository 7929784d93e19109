#include "write_mesh_report.h"

#include "outfile.h"
#include "write_layout.h"

static void key_num(sq_json *j, const char *k, double v)
{
    sq_json_key(j, k);
    sq_json_number(j, v);
}

static void key_int(sq_json *j, const char *k, long v)
{
    sq_json_key(j, k);
    sq_json_int(j, v);
}

sq_status sq_write_mesh_report(const char *path, const char *input, int face,
                               const sq_layout_result *r, const sq_quad_mesh *m,
                               const sq_quad_quality *q, const sq_mesh_timings *t, sq_error *err)
{
    sq_outfile f;
    SQ_TRY(sq_outfile_open(path, &f, err));
    sq_json j;
    sq_json_init(&j, f.fp);
    sq_json_begin_object(&j);
    sq_json_key(&j, "input");
    sq_json_string(&j, input);
    key_int(&j, "face", face);
    sq_json_field_summary(&j, r);
    sq_json_layout_keys(&j, r);
    sq_json_key(&j, "mesh");
    sq_json_begin_object(&j);
    key_int(&j, "quads", m->nquads);
    key_int(&j, "order", m->order);
    key_int(&j, "nodes", m->nnodes);
    key_int(&j, "irregular_interior_vertices", q->irregular_interior);
    key_int(&j, "irregular_boundary_vertices", q->irregular_boundary);
    sq_json_key(&j, "quality");
    sq_json_begin_object(&j);
    key_num(&j, "mean", q->eta_mean);
    key_num(&j, "min", q->eta_min);
    key_num(&j, "above_0_9_percent", q->tau_percent);
    sq_json_end_object(&j);
    sq_json_key(&j, "quality_curved");
    sq_json_begin_object(&j);
    key_num(&j, "mean", q->eta_curved_mean);
    key_num(&j, "min", q->eta_curved_min);
    key_num(&j, "above_0_9_percent", q->tau_curved_percent);
    sq_json_end_object(&j);
    key_num(&j, "min_scaled_jacobian", q->min_scaled_jacobian);
    key_int(&j, "inverted", q->inverted);
    key_num(&j, "area", q->area);
    sq_json_end_object(&j);
    sq_json_key(&j, "timings_s");
    sq_json_begin_object(&j);
    key_num(&j, "read", t->read);
    key_num(&j, "triangulate", t->triangulate);
    key_num(&j, "solve", t->solve);
    key_num(&j, "critical_points", t->critical_points);
    key_num(&j, "trace", t->trace);
    key_num(&j, "layout", t->layout);
    key_num(&j, "mesh", t->mesh);
    key_num(&j, "write", t->write);
    sq_json_end_object(&j);
    sq_json_end_object(&j);
    return sq_outfile_commit(&f, err);
}
