#include "write_htheta.h"

#include "outfile.h"
#include "svg_mesh.h"
#include "tri_geom.h"
#include "write_vtu.h"

#include <math.h>
#include <stdlib.h>

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

static const char *origin_name(sq_origin o)
{
    return o == SQ_ORIGIN_IMPOSED ? "imposed" : o == SQ_ORIGIN_MIDPOINT ? "midpoint"
                                                                       : "critical-point";
}

void sq_json_htheta_keys(sq_json *j, const sq_htheta *f)
{
    sq_json_key(j, "singularities");
    sq_json_begin_array(j);
    for (int k = 0; k < f->npoints; k++) {
        const sq_htheta_point *p = &f->points[k];
        sq_json_begin_object(j);
        key_num(j, "x", p->x);
        key_num(j, "y", p->y);
        key_int(j, "valence", p->valence);
        sq_json_key(j, "origin");
        sq_json_string(j, origin_name(p->origin));
        sq_json_end_object(j);
    }
    sq_json_end_array(j);
    sq_json_key(j, "corners");
    sq_json_begin_array(j);
    for (int k = 0; k < f->info.nvertices; k++) {
        const sq_vertex *v = &f->info.vertices[k];
        if (v->smooth && f->balance.quads[k] == 2) continue;
        sq_json_begin_object(j);
        key_num(j, "x", v->x);
        key_num(j, "y", v->y);
        key_num(j, "angle_deg", v->angle_deg);
        key_int(j, "valence", f->balance.quads[k]);
        sq_json_end_object(j);
    }
    sq_json_end_array(j);
    sq_json_key(j, "consistency");
    sq_json_begin_object(j);
    key_int(j, "lhs", f->balance.lhs);
    key_int(j, "rhs", f->balance.rhs);
    sq_json_key(j, "holds");
    sq_json_bool(j, f->balance.lhs == f->balance.rhs);
    sq_json_end_object(j);
    sq_json_key(j, "theta_jumps");
    sq_json_begin_array(j);
    for (int k = 0; k < f->npoints; k++) {
        sq_json_begin_object(j);
        key_num(j, "x", f->points[k].x);
        key_num(j, "y", f->points[k].y);
        key_int(j, "valence", f->points[k].valence);
        key_num(j, "jump", f->points[k].jump);
        key_num(j, "expected", f->points[k].c);
        key_num(j, "error", f->points[k].jump - f->points[k].c);
        sq_json_end_object(j);
    }
    for (int l = 1; l < f->nloops; l++) {
        sq_json_begin_object(j);
        key_int(j, "loop", l);
        key_num(j, "jump", f->loops[l].jump);
        key_num(j, "expected", f->loops[l].expected_jump);
        key_num(j, "error", f->loops[l].jump - f->loops[l].expected_jump);
        sq_json_end_object(j);
    }
    sq_json_end_array(j);
    sq_json_key(j, "holonomy");
    sq_json_begin_object(j);
    int all = 1;
    for (int l = 0; l < f->nloops; l++) all &= f->loops[l].aligned;
    sq_json_key(j, "aligned");
    sq_json_bool(j, all);
    key_num(j, "tolerance_deg", f->align_tol * 180.0 / M_PI);
    sq_json_key(j, "loops");
    sq_json_begin_array(j);
    for (int l = 0; l < f->nloops; l++) {
        const sq_htheta_loop *L = &f->loops[l];
        sq_json_begin_object(j);
        key_int(j, "loop", l);
        sq_json_key(j, "hole");
        sq_json_bool(j, l > 0);
        key_num(j, "turning", L->turning);
        if (l > 0) {
            key_num(j, "jump", L->jump);
            /* a multiple of π/2 by Gauss–Bonnet */
            key_num(j, "jump_minus_turning_quarters", (L->jump - L->turning) / M_PI_2);
        }
        key_num(j, "misalignment_deg", L->misalignment * 180.0 / M_PI);
        key_num(j, "spread_deg", L->spread * 180.0 / M_PI);
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
    key_int(&j, "face", face);
    key_int(&j, "chi", f->info.chi);
    sq_json_key(&j, "field");
    sq_json_begin_object(&j);
    sq_json_key(&j, "kind");
    sq_json_string(&j, "H-theta");
    sq_json_key(&j, "method");
    sq_json_string(&j, "cg");
    key_int(&j, "order", f->h.order);
    key_int(&j, "triangles", f->tri.mesh->ntris);
    key_int(&j, "dofs", f->h.ndofs);
    key_int(&j, "dofs_theta", f->theta.ndofs);
    key_int(&j, "branch_cut_edges", f->theta.cut.nedges);
    key_num(&j, "h_data_imbalance", f->h.imbalance);
    key_num(&j, "h_data_size", f->h.data_size);
    sq_json_end_object(&j);
    sq_json_htheta_keys(&j, f);
    sq_json_key(&j, "timings_s");
    sq_json_begin_object(&j);
    key_num(&j, "read", t_read);
    key_num(&j, "triangulate", f->t_triangulate);
    key_num(&j, "solve", f->t_solve);
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

/* Isolines val = level0 + k*step of component comp (0: H, 1: θ), linear
 * pieces on a lattice of order S in every element, mapped through the
 * curved geometry; elements at a singular point are left out (H and θ are
 * not polynomial there). */
static void draw_isolines(sq_svg *svg, const sq_htheta *f, const sem_tri_lagrange *lag, int comp,
                          double level0, double step, const unsigned char *skip, const char *color)
{
    const sem_tri_mesh *m = f->tri.mesh;
    const int S = 2 * f->h.order;
    for (int e = 0; e < m->ntris; e++) {
        if (skip[e]) continue;
        const double *g = &m->gxy[2 * (size_t)m->nodes_per_tri * e];
        for (int j = 0; j < S; j++)
            for (int i = 0; i + j < S; i++)
                for (int up = 0; up < 2; up++) {
                    if (up && i + j + 1 >= S) continue;
                    int ci[3][2] = {{i, j}, {i + 1, j}, {i, j + 1}};
                    if (up) {
                        ci[0][0] = i + 1, ci[0][1] = j + 1;
                        ci[1][0] = i, ci[1][1] = j + 1;
                        ci[2][0] = i + 1, ci[2][1] = j;
                    }
                    double rs[3][2], val[3], out[2], lo = HUGE_VAL, hi = -HUGE_VAL;
                    for (int q = 0; q < 3; q++) {
                        rs[q][0] = (double)ci[q][0] / S;
                        rs[q][1] = (double)ci[q][1] / S;
                        h_theta((void *)f, e, rs[q][0], rs[q][1], out);
                        val[q] = (out[comp] - level0) / step;
                        lo = fmin(lo, val[q]);
                        hi = fmax(hi, val[q]);
                    }
                    for (double lv = ceil(lo); lv <= hi; lv += 1.0) {
                        double pts[4];
                        int np = 0;
                        for (int q = 0; q < 3 && np < 2; q++) {
                            const int w = (q + 1) % 3;
                            if ((val[q] < lv) == (val[w] < lv)) continue;
                            const double t = (lv - val[q]) / (val[w] - val[q]);
                            sem_tri_geom_map(lag, g, rs[q][0] + t * (rs[w][0] - rs[q][0]),
                                             rs[q][1] + t * (rs[w][1] - rs[q][1]), &pts[2 * np],
                                             NULL);
                            np++;
                        }
                        if (np == 2) sq_svg_polyline(svg, 2, pts, 0, color, 1.1, "none");
                    }
                }
    }
}

static const char *valence_color(int v)
{
    switch (v) {
    case 3: return "#1f5fd6";
    case 5: return "#d62020";
    case 6: return "#f08c00";
    case 8: return "#e6c700";
    default: return "#555555";
    }
}

static int cmp_double(const void *a, const void *b)
{
    const double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

sq_status sq_write_htheta_svg(const char *path, const sq_htheta *f, sq_error *err)
{
    const sem_tri_mesh *m = f->tri.mesh;
    sem_tri_lagrange *lag = NULL;
    SQ_TRY(sem_tri_lagrange_create(m->order, &lag, err));
    unsigned char *skip = calloc((size_t)m->ntris + 1, 1);
    double *hv = malloc(sizeof(double) * ((size_t)m->ntris + 1));
    sq_outfile o = {0};
    sq_status st = !skip || !hv ? SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory")
                                : sq_outfile_open(path, &o, err);
    if (st != SQ_OK) {
        free(skip);
        free(hv);
        sem_tri_lagrange_free(&lag);
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
    double bb[4];
    sq_svg_mesh_bbox(m, bb);
    sq_svg svg;
    sq_svg_begin(&svg, o.fp, bb, 900.0, 700.0);
    sq_svg_mesh_edges(&svg, m, lag, 1, "#eeeeee", 0.5, "#1a1a1a", 2.0);
    draw_isolines(&svg, f, lag, 0, hlo, hstep, skip, "#d62728");
    draw_isolines(&svg, f, lag, 1, 0.0, M_PI / 16.0, skip, "#1f77b4");
    /* the branch cut: straight segments between its vertices */
    for (int i = 0; i < f->theta.cut.nedges; i++) {
        const int a = f->theta.cut.edges[2 * i], b = f->theta.cut.edges[2 * i + 1];
        const double seg[4] = {m->vxy[2 * a], m->vxy[2 * a + 1], m->vxy[2 * b], m->vxy[2 * b + 1]};
        sq_svg_polyline(&svg, 2, seg, 0, "#000000", 2.4, "none");
    }
    for (int k = 0; k < f->npoints; k++)
        sq_svg_circle(&svg, f->points[k].x, f->points[k].y, 6.0, valence_color(f->points[k].valence));
    for (int k = 0; k < f->info.nvertices; k++) {
        const sq_vertex *v = &f->info.vertices[k];
        if (v->smooth && f->balance.quads[k] == 2) continue;
        char label[16];
        snprintf(label, sizeof label, "%d", f->balance.quads[k]);
        sq_svg_circle(&svg, v->x, v->y, 3.5, "#1a1a1a");
        sq_svg_text(&svg, v->x, v->y, 6.0, -6.0, 16.0, "#1a1a1a", label);
    }
    char caption[240];
    snprintf(caption, sizeof caption,
             "H-theta, P=%d: H isolines red (step %.3g), theta blue (pi/16), branch cut black",
             f->h.order, hstep);
    sq_svg_text(&svg, bb[0], bb[1], 0.0, 16.0, 12.0, "#333333", caption);
    sq_svg_end(&svg);
    free(skip);
    free(hv);
    sem_tri_lagrange_free(&lag);
    return sq_outfile_commit(&o, err);
}
