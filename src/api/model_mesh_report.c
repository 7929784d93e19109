/* semquad public API: the JSON report of a mesh of several faces
 * (docs/domains.md, docs/formats.md): the faces, the curves they share,
 * the groups the writers make, the mesh's counts and quality. */
#include "api_private.h"
#include "outfile.h"

static const char *kind_name(int kind)
{
    return kind == CAD_SHARED_SAME ? "same edge" : "coincident";
}

/* The groups, as write_msh.c numbers them: boundary curves 1..ntags,
 * then one surface per face. */
static void print_groups(FILE *fp, const sq_api_domain *d, const sq_quad_mesh *m)
{
    fputs("  \"groups\": [", fp);
    int first = 1;
    for (int c = 0; c < d->ncurves; c++) {
        const sq_domain_curve *cv = &d->curves[c];
        if (cv->tag < 0) continue;
        /* named curves (docs/formats.md): the group's physical tag */
        char buf[32];
        fprintf(fp, "%s\n    {\"dim\": 1, \"tag\": %d, \"name\": \"%s\", \"face\": %d, "
                    "\"edge\": %d}",
                first ? "" : ",", sq_quad_mesh_tag_group(m, cv->tag) + 1,
                sq_quad_mesh_tag_name(m, cv->tag, buf, sizeof buf), d->face[cv->face[0]],
                cv->edge[0]);
        first = 0;
    }
    for (int k = 0; k < d->nfaces; k++) {
        char buf[32];
        fprintf(fp, ",\n    {\"dim\": 2, \"tag\": %d, \"name\": \"%s\", \"face\": %d}",
                d->ntags + 1 + k, sq_quad_mesh_region_name(m, k, buf, sizeof buf), d->face[k]);
    }
    fputs("\n  ],\n", fp);
}

static void print_report(FILE *fp, const sq_mesh *m, const sq_mesh_timings *t)
{
    const sq_api_domain *d = m->dom;
    const sq_quad_quality *q = &m->quality;
    double exact = 0.0;
    fprintf(fp, "{\n  \"input\": \"%s\",\n  \"faces\": [", m->face.model->path);
    for (int k = 0; k < d->nfaces; k++) {
        int nq = 0;
        for (int e = 0; e < m->q->nquads; e++) nq += m->q->region[e] == k;
        exact += d->area[k];
        fprintf(fp, "%s\n    {\"index\": %d, \"road\": \"%s\", \"quads\": %d, \"area\": %.17g}",
                k ? "," : "", d->face[k], d->road[k], nq, d->area[k]);
    }
    fputs("\n  ],\n  \"shared_edges\": [", fp);
    int first = 1;
    for (int c = 0; c < d->ncurves; c++) {
        const sq_domain_curve *cv = &d->curves[c];
        if (cv->face[1] < 0) continue;
        fprintf(fp, "%s\n    {\"faces\": [%d, %d], \"edges\": [%d, %d], \"kind\": \"%s\", "
                    "\"reversed\": %s}",
                first ? "" : ",", d->face[cv->face[0]], d->face[cv->face[1]], cv->edge[0],
                cv->edge[1], kind_name(cv->kind), cv->reversed ? "true" : "false");
        first = 0;
    }
    fprintf(fp, "\n  ],\n  \"shared_edge_rounds\": %d,\n", d->rounds);
    print_groups(fp, d, m->q);
    fprintf(fp,
            "  \"mesh\": {\"quads\": %d, \"nodes\": %d, \"order\": %d, \"area\": %.17g, "
            "\"area_exact\": %.17g,\n    \"irregular_interior_vertices\": %d, \"quality\": "
            "{\"mean\": %.6g, \"min\": %.6g, \"above_0_9_percent\": %.4g},\n    "
            "\"min_scaled_jacobian\": %.6g, \"inverted\": %d},\n",
            m->q->nquads, m->q->nnodes, m->q->order, q->area, exact, q->irregular_interior,
            q->eta_mean, q->eta_min, q->tau_percent, q->min_scaled_jacobian, q->inverted);
    fprintf(fp, "  \"timings_s\": {\"read\": %.3f, \"mesh\": %.3f, \"write\": %.3f, \"total\": %.3f}",
            t->read, t->mesh, t->write, t->total);
    sq_json j;
    sq_json_init_in_object(&j, fp);
    sq_json_periodic(&j, m->q); /* periodic pairs (docs/domains.md), if any */
    fputs("\n}\n", fp);
}

sq_status sq_api_domain_report(const sq_mesh *m, const sq_mesh_timings *t, char **json,
                               sq_error *err)
{
    sq_api_text txt;
    SQ_TRY(sq_api_text_open(&txt, err));
    print_report(txt.fp, m, t);
    return sq_api_text_close(&txt, json, err);
}

sq_status sq_api_domain_write_report(const sq_mesh *m, const sq_mesh_timings *t,
                                     const char *path, sq_error *err)
{
    sq_outfile f = {0};
    SQ_TRY(sq_outfile_open(path, &f, err));
    print_report(f.fp, m, t);
    sq_status st = sq_outfile_commit(&f, err);
    sq_outfile_abort(&f);
    return st;
}
