#include "write_htheta.h"

#include "outfile.h"
#include "svg_mesh.h"
#include "tri_geom.h"
#include "write_vtu.h"

#include <math.h>
#include <stdlib.h>

void sq_json_htheta_keys(sq_json *j, const sq_htheta *f)
{
    sq_json_key(j, "singularities");
    sq_json_begin_array(j);
    for (int k = 0; k < f->npoints; k++) {
        const sq_htheta_point *p = &f->points[k];
        sq_json_begin_object(j);
        sq_json_key_number(j, "x", p->x);
        sq_json_key_number(j, "y", p->y);
        sq_json_key_int(j, "valence", p->valence);
        sq_json_key(j, "origin");
        sq_json_string(j, sq_origin_name(p->origin));
        sq_json_end_object(j);
    }
    sq_json_end_array(j);
    sq_json_key(j, "corners");
    sq_json_begin_array(j);
    for (int k = 0; k < f->info.nvertices; k++) {
        const sq_vertex *v = &f->info.vertices[k];
        if (v->smooth && f->balance.quads[k] == 2) continue;
        sq_json_begin_object(j);
        sq_json_key_number(j, "x", v->x);
        sq_json_key_number(j, "y", v->y);
        sq_json_key_number(j, "angle_deg", v->angle_deg);
        sq_json_key_int(j, "valence", f->balance.quads[k]);
        sq_json_end_object(j);
    }
    sq_json_end_array(j);
    sq_json_key(j, "consistency");
    sq_json_begin_object(j);
    sq_json_key_int(j, "lhs", f->balance.lhs);
    sq_json_key_int(j, "rhs", f->balance.rhs);
    sq_json_key(j, "holds");
    sq_json_bool(j, f->balance.lhs == f->balance.rhs);
    sq_json_end_object(j);
    sq_json_key(j, "theta_jumps");
    sq_json_begin_array(j);
    for (int k = 0; k < f->npoints; k++) {
        sq_json_begin_object(j);
        sq_json_key_number(j, "x", f->points[k].x);
        sq_json_key_number(j, "y", f->points[k].y);
        sq_json_key_int(j, "valence", f->points[k].valence);
        sq_json_key_number(j, "jump", f->points[k].jump);
        sq_json_key_number(j, "expected", f->points[k].c);
        sq_json_key_number(j, "error", f->points[k].jump - f->points[k].c);
        sq_json_end_object(j);
    }
    for (int l = 1; l < f->nloops; l++) {
        sq_json_begin_object(j);
        sq_json_key_int(j, "loop", l);
        sq_json_key_number(j, "jump", f->loops[l].jump);
        sq_json_key_number(j, "expected", f->loops[l].expected_jump);
        sq_json_key_number(j, "error", f->loops[l].jump - f->loops[l].expected_jump);
        sq_json_end_object(j);
    }
    sq_json_end_array(j);
    sq_json_key(j, "holonomy");
    sq_json_begin_object(j);
    int all = 1;
    for (int l = 0; l < f->nloops; l++) all &= f->loops[l].aligned;
    sq_json_key(j, "aligned");
    sq_json_bool(j, all);
    sq_json_key_number(j, "tolerance_deg", f->align_tol * 180.0 / M_PI);
    sq_json_key(j, "loops");
    sq_json_begin_array(j);
    for (int l = 0; l < f->nloops; l++) {
        const sq_htheta_loop *L = &f->loops[l];
        sq_json_begin_object(j);
        sq_json_key_int(j, "loop", l);
        sq_json_key(j, "hole");
        sq_json_bool(j, l > 0);
        sq_json_key_number(j, "turning", L->turning);
        if (l > 0) {
            sq_json_key_number(j, "jump", L->jump);
            /* a multiple of π/2 by Gauss–Bonnet */
            sq_json_key_number(j, "jump_minus_turning_quarters", (L->jump - L->turning) / M_PI_2);
        }
        sq_json_key_number(j, "misalignment_deg", L->misalignment * 180.0 / M_PI);
        sq_json_key_number(j, "spread_deg", L->spread * 180.0 / M_PI);
        sq_json_key(j, "aligned");
        sq_json_bool(j, L->aligned);
        sq_json_end_object(j);
    }
    sq_json_end_array(j);
    sq_json_end_object(j);
}

sq_status sq_write_htheta_report(const char *path, const char *input, int face,
                                 const sq_htheta *f, double t_read, sq_error *err)
{
    sq_outfile o;
    SQ_TRY(sq_outfile_open(path, &o, err));
    sq_json j;
    sq_json_init(&j, o.fp);
    sq_json_begin_object(&j);
    sq_json_key(&j, "input");
    sq_json_string(&j, input);
    sq_json_key_int(&j, "face", face);
    sq_json_key_int(&j, "chi", f->info.chi);
    sq_json_key(&j, "field");
    sq_json_begin_object(&j);
    sq_json_key(&j, "kind");
    sq_json_string(&j, "H-theta");
    sq_json_key(&j, "method");
    sq_json_string(&j, "cg");
    sq_json_key_int(&j, "order", f->h.order);
    sq_json_key_int(&j, "triangles", f->tri.mesh->ntris);
    sq_json_key_int(&j, "dofs", f->h.ndofs);
    sq_json_key_int(&j, "dofs_theta", f->theta.ndofs);
    sq_json_key_int(&j, "branch_cut_edges", f->theta.cut.nedges);
    sq_json_key_number(&j, "h_data_imbalance", f->h.imbalance);
    sq_json_key_number(&j, "h_data_size", f->h.data_size);
    sq_json_end_object(&j);
    sq_json_htheta_keys(&j, f);
    sq_json_key(&j, "timings_s");
    sq_json_begin_object(&j);
    sq_json_key_number(&j, "read", t_read);
    sq_json_key_number(&j, "triangulate", f->t_triangulate);
    sq_json_key_number(&j, "solve", f->t_solve);
    sq_json_end_object(&j);
    sq_json_end_object(&j);
    return sq_outfile_commit(&o, err);
}

static void h_theta(void *ctx, int e, double r, double s, double *out)
{
    const sq_htheta *f = ctx;
    out[0] = sq_h_field_eval_ref(&f->h, e, r, s, NULL, NULL);
    out[1] = sq_theta_field_eval_ref(&f->theta, e, r, s, NULL);
}

sq_status sq_write_htheta_vtu(const char *path, const sq_htheta *f, sq_error *err)
{
    const char *const names[] = {"H", "theta"};
    const char *const cells[] = {"scaled_jacobian"};
    const double *const cdata[] = {f->tri.jac};
    sq_vtu_data d = {2, names, h_theta, (void *)f, 1, cells, cdata};
    return sq_write_vtu(path, f->tri.mesh, f->h.order, &d, err);
}

typedef struct {
    const sq_htheta *f;
    int comp; /* 0: H, 1: θ */
} comp_ctx;

static double h_or_theta(void *ctx, int e, double r, double s)
{
    const comp_ctx *c = ctx;
    double out[2];
    h_theta((void *)c->f, e, r, s, out);
    return out[c->comp];
}

static int cmp_double(const void *a, const void *b)
{
    const double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

sq_status sq_write_htheta_svg(const char *path, const sq_htheta *f, sq_error *err)
{
    const sem_tri_mesh *m = f->tri.mesh;
    unsigned char *skip = calloc((size_t)m->ntris + 1, 1);
    double *hv = malloc(sizeof(double) * ((size_t)m->ntris + 1));
    sq_svg_mesh_picture pic;
    sq_status st = !skip || !hv ? SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory")
                                : sq_svg_mesh_open(path, m, "#eeeeee", 0.5, &pic, err);
    if (st != SQ_OK) {
        free(skip);
        free(hv);
        return st;
    }
    for (int e = 0; e < m->ntris; e++)
        for (int k = 0; k < 3; k++)
            for (int j = 0; j < f->npoints; j++) skip[e] |= m->tri[3 * e + k] == f->points[j].vertex;
    /* H levels: 24 steps over its 2–98 % range at the element centroids */
    for (int e = 0; e < m->ntris; e++)
        hv[e] = sq_h_field_eval_ref(&f->h, e, 1.0 / 3.0, 1.0 / 3.0, NULL, NULL);
    qsort(hv, (size_t)m->ntris, sizeof(double), cmp_double);
    const double hlo = hv[(int)(0.02 * (m->ntris - 1))], hhi = hv[(int)(0.98 * (m->ntris - 1))];
    const double hstep = hhi > hlo + 1e-12 ? (hhi - hlo) / 24.0 : 1.0;
    const double *bb = pic.bbox;
    sq_svg *svg = &pic.svg;
    /* elements at a singular point are left out: H and θ are not
     * polynomial there */
    comp_ctx ch = {f, 0}, ct = {f, 1};
    sq_svg_mesh_isolines(svg, f->tri.mesh, pic.lag, 2 * f->h.order, h_or_theta, &ch, hlo, hstep, 0.0,
                         skip, "#d62728", 1.1);
    sq_svg_mesh_isolines(svg, f->tri.mesh, pic.lag, 2 * f->h.order, h_or_theta, &ct, 0.0, M_PI / 16.0,
                         0.0, skip, "#1f77b4", 1.1);
    /* the branch cut: straight segments between its vertices */
    for (int i = 0; i < f->theta.cut.nedges; i++) {
        const int a = f->theta.cut.edges[2 * i], b = f->theta.cut.edges[2 * i + 1];
        const double seg[4] = {m->vxy[2 * a], m->vxy[2 * a + 1], m->vxy[2 * b], m->vxy[2 * b + 1]};
        sq_svg_polyline(svg, 2, seg, 0, "#000000", 2.4, "none");
    }
    for (int k = 0; k < f->npoints; k++)
        sq_svg_circle(svg, f->points[k].x, f->points[k].y, 6.0, sq_svg_valence_color(f->points[k].valence));
    for (int k = 0; k < f->info.nvertices; k++) {
        const sq_vertex *v = &f->info.vertices[k];
        if (v->smooth && f->balance.quads[k] == 2) continue;
        char label[16];
        snprintf(label, sizeof label, "%d", f->balance.quads[k]);
        sq_svg_circle(svg, v->x, v->y, 3.5, "#1a1a1a");
        sq_svg_text(svg, v->x, v->y, 6.0, -6.0, 16.0, "#1a1a1a", label);
    }
    char caption[240];
    snprintf(caption, sizeof caption,
             "H-theta, P=%d: H isolines red (step %.3g), theta blue (pi/16), branch cut black",
             f->h.order, hstep);
    sq_svg_text(svg, bb[0], bb[1], 0.0, 16.0, 12.0, "#333333", caption);
    free(skip);
    free(hv);
    return sq_svg_mesh_close(&pic, SQ_OK, err);
}
