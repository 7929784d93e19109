#include "write_field.h"

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

void sq_json_field_keys(sq_json *j, const sq_field_analysis *a)
{
    sq_json_key(j, "singularities");
    sq_json_begin_array(j);
    for (int k = 0; k < a->npoints; k++) {
        const sq_critical_point *p = &a->points[k];
        sq_json_begin_object(j);
        key_num(j, "x", p->x);
        key_num(j, "y", p->y);
        key_int(j, "valence", p->valence);
        key_int(j, "index", p->index);
        sq_json_key(j, "origin");
        sq_json_string(j, "critical-point");
        key_num(j, "distance_to_boundary", p->dist_boundary);
        sq_json_key(j, "near_boundary");
        sq_json_bool(j, p->near_boundary);
        sq_json_end_object(j);
    }
    sq_json_end_array(j);
    sq_json_key(j, "corners");
    sq_json_begin_array(j);
    for (int k = 0; k < a->info.nvertices; k++) {
        const sq_vertex *v = &a->info.vertices[k];
        if (v->smooth) continue;
        sq_json_begin_object(j);
        key_num(j, "x", v->x);
        key_num(j, "y", v->y);
        key_num(j, "angle_deg", v->angle_deg);
        key_int(j, "valence", a->corners[k].valence);
        key_num(j, "valence_raw", a->corners[k].raw);
        sq_json_end_object(j);
    }
    sq_json_end_array(j);
    sq_json_key(j, "consistency");
    sq_json_begin_object(j);
    key_int(j, "lhs", a->ph_lhs);
    key_int(j, "rhs", a->ph_rhs);
    sq_json_key(j, "holds");
    sq_json_bool(j, a->ph_lhs == a->ph_rhs);
    sq_json_end_object(j);
}

sq_status sq_write_field_report(const char *path, const char *input, int face,
                                const sq_field_analysis *a, double t_read, sq_error *err)
{
    sq_outfile f;
    SQ_TRY(sq_outfile_open(path, &f, err));
    sq_json j;
    sq_json_init(&j, f.fp);
    sq_json_begin_object(&j);
    sq_json_key(&j, "input");
    sq_json_string(&j, input);
    key_int(&j, "face", face);
    key_int(&j, "chi", a->info.chi);
    sq_json_key(&j, "field");
    sq_json_begin_object(&j);
    sq_json_key(&j, "kind");
    sq_json_string(&j, "guiding");
    sq_json_key(&j, "method");
    sq_json_string(&j, a->field.method == SEM_CG ? "cg" : "dg");
    key_int(&j, "order", a->field.order);
    key_int(&j, "triangles", a->tri.mesh->ntris);
    key_int(&j, "dofs", a->field.ndofs);
    key_num(&j, "l2_u", a->field.l2_u);
    key_num(&j, "l2_v", a->field.l2_v);
    sq_json_end_object(&j);
    sq_json_field_keys(&j, a);
    sq_json_key(&j, "timings_s");
    sq_json_begin_object(&j);
    key_num(&j, "read", t_read);
    key_num(&j, "triangulate", a->t_triangulate);
    key_num(&j, "solve", a->t_solve);
    key_num(&j, "critical_points", a->t_critical);
    sq_json_end_object(&j);
    sq_json_end_object(&j);
    return sq_outfile_commit(&f, err);
}

static void uv_psi(void *ctx, int e, double r, double s, double *out)
{
    const sq_guiding_field *g = ctx;
    sem_field_eval_ref(g->uv, e, r, s, out, NULL, NULL);
    out[2] = 0.25 * atan2(out[1], out[0]); /* Marcon 2019, eq. (2) */
}

sq_status sq_write_field_vtu(const char *path, const sq_field_analysis *a, sq_error *err)
{
    const char *const names[] = {"u", "v", "psi"};
    const char *const cells[] = {"scaled_jacobian"};
    const double *const cdata[] = {a->tri.jac};
    sq_vtu_data d = {3, names, uv_psi, (void *)&a->field, 1, cells, cdata};
    return sq_write_vtu(path, a->tri.mesh, a->field.order, &d, err);
}

/* Zero contour of component comp: linear pieces on a lattice of order S in
 * every element, mapped through the curved geometry. */
static void draw_contour(sq_svg *svg, const sq_field_analysis *a, const sem_tri_lagrange *lag,
                         int comp, const char *color)
{
    const sem_tri_mesh *m = a->tri.mesh;
    const sem_field *f = a->field.uv;
    int S = 3 * a->field.order;
    for (int e = 0; e < m->ntris; e++) {
        const double *g = &m->gxy[2 * (size_t)m->nodes_per_tri * e];
        for (int j = 0; j < S; j++)
            for (int i = 0; i + j < S; i++)
                for (int up = 0; up < 2; up++) {
                    if (up && i + j + 1 >= S) continue;
                    /* sub-triangle corners in lattice units */
                    int ci[3][2] = {{i, j}, {i + 1, j}, {i, j + 1}};
                    if (up) {
                        ci[0][0] = i + 1;
                        ci[0][1] = j + 1;
                        ci[1][0] = i;
                        ci[1][1] = j + 1;
                        ci[2][0] = i + 1;
                        ci[2][1] = j;
                    }
                    double rs[3][2], val[3];
                    for (int q = 0; q < 3; q++) {
                        double uv[2];
                        rs[q][0] = (double)ci[q][0] / S;
                        rs[q][1] = (double)ci[q][1] / S;
                        sem_field_eval_ref(f, e, rs[q][0], rs[q][1], uv, NULL, NULL);
                        val[q] = uv[comp];
                    }
                    double pts[4];
                    int np = 0;
                    for (int q = 0; q < 3 && np < 2; q++) {
                        int w = (q + 1) % 3;
                        /* round-off around an identically zero boundary value
                         * is not a contour */
                        if ((val[q] < -1e-10) == (val[w] < -1e-10)) continue;
                        double t = val[q] / (val[q] - val[w]);
                        sem_tri_geom_map(lag, g, rs[q][0] + t * (rs[w][0] - rs[q][0]),
                                         rs[q][1] + t * (rs[w][1] - rs[q][1]), &pts[2 * np], NULL);
                        np++;
                    }
                    if (np == 2) sq_svg_polyline(svg, 2, pts, 0, color, 1.6, "none");
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

sq_status sq_write_field_svg(const char *path, const sq_field_analysis *a, sq_error *err)
{
    const sem_tri_mesh *m = a->tri.mesh;
    sem_tri_lagrange *lag = NULL;
    SQ_TRY(sem_tri_lagrange_create(m->order, &lag, err));
    sq_outfile f;
    sq_status st = sq_outfile_open(path, &f, err);
    if (st != SQ_OK) {
        sem_tri_lagrange_free(&lag);
        return st;
    }
    double bb[4];
    sq_svg_mesh_bbox(m, bb);
    sq_svg svg;
    sq_svg_begin(&svg, f.fp, bb, 900.0, 700.0);
    sq_svg_mesh_edges(&svg, m, lag, 1, "#dddddd", 0.6, "#1a1a1a", 2.0);
    /* crosses on a grid */
    double w = bb[2] - bb[0], h = bb[3] - bb[1], step = fmax(w, h) / 28.0;
    int elem = -1;
    for (double y = bb[1] + 0.5 * step; y < bb[3]; y += step)
        for (double x = bb[0] + 0.5 * step; x < bb[2]; x += step) {
            double p[2] = {x, y}, uv[2];
            if (sq_guiding_field_eval(&a->field, p, &elem, uv, NULL)) continue;
            double psi = 0.25 * atan2(uv[1], uv[0]), l = 0.33 * step;
            double c = l * cos(psi), s = l * sin(psi);
            double seg1[4] = {x - c, y - s, x + c, y + s}, seg2[4] = {x + s, y - c, x - s, y + c};
            sq_svg_polyline(&svg, 2, seg1, 0, "#777777", 1.0, "none");
            sq_svg_polyline(&svg, 2, seg2, 0, "#777777", 1.0, "none");
        }
    draw_contour(&svg, a, lag, 0, "#1e9e3a");
    draw_contour(&svg, a, lag, 1, "#8e44ad");
    for (int k = 0; k < a->npoints; k++)
        sq_svg_circle(&svg, a->points[k].x, a->points[k].y, 6.0, valence_color(a->points[k].valence));
    for (int k = 0; k < a->info.nvertices; k++) {
        const sq_vertex *v = &a->info.vertices[k];
        if (v->smooth) continue;
        char label[16];
        snprintf(label, sizeof label, "%d", a->corners[k].valence);
        sq_svg_circle(&svg, v->x, v->y, 3.5, "#1a1a1a");
        sq_svg_text(&svg, v->x, v->y, 6.0, -6.0, 16.0, "#1a1a1a", label);
    }
    char caption[200];
    snprintf(caption, sizeof caption,
             "guiding field, %s P=%d: %d singular points; u=0 green, v=0 purple; "
             "valence 3 blue, 5 red, 6 orange, 8 yellow",
             a->field.method == SEM_CG ? "CG" : "DG", a->field.order, a->npoints);
    sq_svg_text(&svg, bb[0], bb[1], 0.0, 16.0, 12.0, "#333333", caption);
    sq_svg_end(&svg);
    sem_tri_lagrange_free(&lag);
    return sq_outfile_commit(&f, err);
}
