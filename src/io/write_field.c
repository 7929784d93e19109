#include "write_field.h"

#include "outfile.h"
#include "svg_mesh.h"
#include "tri_geom.h"
#include "write_vtu.h"

#include <math.h>
#include <stdlib.h>

void sq_json_field_keys(sq_json *j, const sq_field_analysis *a)
{
    sq_json_key(j, "singularities");
    sq_json_begin_array(j);
    for (int k = 0; k < a->npoints; k++) {
        const sq_critical_point *p = &a->points[k];
        sq_json_begin_object(j);
        sq_json_key_number(j, "x", p->x);
        sq_json_key_number(j, "y", p->y);
        sq_json_key_int(j, "valence", p->valence);
        sq_json_key_int(j, "index", p->index);
        sq_json_key(j, "origin");
        sq_json_string(j, "critical-point");
        sq_json_key_number(j, "distance_to_boundary", p->dist_boundary);
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
        sq_json_key_number(j, "x", v->x);
        sq_json_key_number(j, "y", v->y);
        sq_json_key_number(j, "angle_deg", v->angle_deg);
        sq_json_key_int(j, "valence", a->corners[k].valence);
        sq_json_key_number(j, "valence_raw", a->corners[k].raw);
        sq_json_end_object(j);
    }
    sq_json_end_array(j);
    sq_json_key(j, "consistency");
    sq_json_begin_object(j);
    sq_json_key_int(j, "lhs", a->ph_lhs);
    sq_json_key_int(j, "rhs", a->ph_rhs);
    sq_json_key(j, "holds");
    sq_json_bool(j, a->ph_lhs == a->ph_rhs);
    sq_json_end_object(j);
}

sq_status sq_write_field_report(const char *path, const char *input, int face,
                                const sq_field_analysis *a, double t_read, sq_error *err)
{
    double l2[2];
    SQ_TRY(sq_guiding_field_norms(&a->field, &l2[0], &l2[1], err));
    sq_outfile f;
    SQ_TRY(sq_outfile_open(path, &f, err));
    sq_json j;
    sq_json_init(&j, f.fp);
    sq_json_begin_object(&j);
    sq_json_key(&j, "input");
    sq_json_string(&j, input);
    sq_json_key_int(&j, "face", face);
    sq_json_key_int(&j, "chi", a->info.chi);
    sq_json_key(&j, "field");
    sq_json_begin_object(&j);
    sq_json_key(&j, "kind");
    sq_json_string(&j, "guiding");
    sq_json_key(&j, "method");
    sq_json_string(&j, a->field.method == SEM_CG ? "cg" : "dg");
    sq_json_key_int(&j, "order", a->field.order);
    sq_json_key_int(&j, "triangles", a->tri.mesh->ntris);
    sq_json_key_int(&j, "dofs", a->field.ndofs);
    sq_json_key_number(&j, "l2_u", l2[0]);
    sq_json_key_number(&j, "l2_v", l2[1]);
    sq_json_end_object(&j);
    sq_json_field_keys(&j, a);
    sq_json_key(&j, "timings_s");
    sq_json_begin_object(&j);
    sq_json_key_number(&j, "read", t_read);
    sq_json_key_number(&j, "triangulate", a->t_triangulate);
    sq_json_key_number(&j, "solve", a->t_solve);
    sq_json_key_number(&j, "critical_points", a->t_critical);
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

typedef struct {
    const sem_field *f;
    int comp;
} comp_ctx;

static double field_component(void *p, int e, double r, double s)
{
    const comp_ctx *c = p;
    double uv[2];
    sem_field_eval_ref(c->f, e, r, s, uv, NULL, NULL);
    return uv[c->comp];
}

sq_status sq_write_field_svg(const char *path, const sq_field_analysis *a, sq_error *err)
{
    const sem_tri_mesh *m = a->tri.mesh;
    sq_svg_mesh_picture pic;
    SQ_TRY(sq_svg_mesh_open(path, m, "#dddddd", 0.6, &pic, err));
    sq_svg *svgp = &pic.svg;
    const double *bb = pic.bbox;
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
            sq_svg_polyline(svgp, 2, seg1, 0, "#777777", 1.0, "none");
            sq_svg_polyline(svgp, 2, seg2, 0, "#777777", 1.0, "none");
        }
    /* u = 0 and v = 0; round-off around an identically zero boundary value
     * is not a contour */
    for (int c = 0; c < 2; c++) {
        comp_ctx cc = {a->field.uv, c};
        sq_svg_mesh_isolines(svgp, m, pic.lag, 3 * a->field.order, field_component, &cc, 0.0, 0.0, 1e-10,
                             NULL, c ? "#8e44ad" : "#1e9e3a", 1.6);
    }
    for (int k = 0; k < a->npoints; k++)
        sq_svg_circle(svgp, a->points[k].x, a->points[k].y, 6.0,
                      sq_svg_valence_color(a->points[k].valence));
    for (int k = 0; k < a->info.nvertices; k++) {
        const sq_vertex *v = &a->info.vertices[k];
        if (v->smooth) continue;
        char label[16];
        snprintf(label, sizeof label, "%d", a->corners[k].valence);
        sq_svg_circle(svgp, v->x, v->y, 3.5, "#1a1a1a");
        sq_svg_text(svgp, v->x, v->y, 6.0, -6.0, 16.0, "#1a1a1a", label);
    }
    char caption[200];
    snprintf(caption, sizeof caption,
             "guiding field, %s P=%d: %d singular points; u=0 green, v=0 purple; "
             "valence 3 blue, 5 red, 6 orange, 8 yellow",
             a->field.method == SEM_CG ? "CG" : "DG", a->field.order, a->npoints);
    sq_svg_text(svgp, bb[0], bb[1], 0.0, 16.0, 12.0, "#333333", caption);
    return sq_svg_mesh_close(&pic, SQ_OK, err);
}
