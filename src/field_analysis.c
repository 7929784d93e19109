#include "field_analysis.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

double sq_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

void sq_field_options_default(sq_field_options *opt)
{
    memset(opt, 0, sizeof *opt);
    opt->order = 8;
    opt->method = SQ_METHOD_AUTO;
    sq_tri_options_default(&opt->tri);
    opt->tri.order = 8;
    opt->grading = 1e-3;
}

int sq_vertex_near_straight(const sq_vertex *v)
{
    return !v->smooth && fabs(v->angle_deg - 180.0) < SQ_NEAR_STRAIGHT_TOL_DEG;
}

sq_status sq_singular_vertices(const cad_face *face, const sq_face_info *info, double *xy, int *n,
                               sq_error *err)
{
    *n = 0;
    for (int k = 0; k < info->nvertices; k++) {
        const sq_vertex *v = &info->vertices[k];
        double q = v->angle_deg / 90.0, kin, kout;
        int singular = fabs(q - round(q)) * 90.0 > SQ_RIGHT_ANGLE_TOL_DEG ||
                       v->angle_deg > 180.0 + SQ_SMOOTH_TOL_DEG;
        if (!singular) {
            double Lin = cad_face_edge_length(face, v->edge_in);
            SQ_TRY(cad_face_edge_eval(face, v->edge_in, Lin, NULL, NULL, &kin, err));
            SQ_TRY(cad_face_edge_eval(face, v->edge_out, 0.0, NULL, NULL, &kout, err));
            /* a jump of curvature against the face's scale */
            double scale = hypot(info->bbox[2] - info->bbox[0], info->bbox[3] - info->bbox[1]);
            singular = v->smooth && fabs(kin - kout) * scale > 1e-6;
        }
        if (!singular || sq_vertex_near_straight(v)) continue;
        xy[2 * *n] = v->x;
        xy[2 * *n + 1] = v->y;
        (*n)++;
    }
    return SQ_OK;
}

void sq_field_analysis_free(sq_field_analysis *a)
{
    if (!a) return;
    free(a->points);
    free(a->corners);
    sq_guiding_field_free(&a->field);
    sq_triangulation_free(&a->tri);
    sq_face_info_free(&a->info);
    memset(a, 0, sizeof *a);
}

sq_status sq_field_analyse(const cad_face *face, const sq_field_options *opt,
                           sq_field_analysis *out, sq_error *err)
{
    memset(out, 0, sizeof *out);
    double t0 = sq_now();
    sq_status st = sq_face_info_compute(face, &out->info, err);
    sq_tri_options tri = opt->tri;
    tri.size = sq_tri_size(&tri, out->info.area);
    double *graded = malloc(sizeof(double) * 2 * (size_t)(out->info.nvertices + 1));
    if (st == SQ_OK && !graded) st = SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    if (st == SQ_OK && opt->grading > 0.0 && tri.nextra == 0) {
        st = sq_singular_vertices(face, &out->info, graded, &tri.nextra, err);
        tri.extra_xy = graded;
        tri.extra_size = opt->grading * tri.size;
        tri.extra_growth = 1.0; /* hp: element size proportional to the distance */
    }
    if (st == SQ_OK) st = sq_triangulate(face, &tri, &out->tri, err);
    free(graded);
    double t1 = sq_now();
    if (st == SQ_OK)
        st = sq_guiding_field_solve(face, &out->info, out->tri.mesh, opt->order, opt->method,
                                    &out->field, err);
    double t2 = sq_now();
    if (st == SQ_OK)
        st = sq_critical_points_find(&out->field, face, &out->info, &out->points, &out->npoints,
                                     err);
    if (st == SQ_OK) st = sq_corner_valences(&out->field, face, &out->info, &out->corners, err);
    double t3 = sq_now();
    if (st != SQ_OK) {
        sq_field_analysis_free(out);
        return st;
    }
    out->t_triangulate = t1 - t0;
    out->t_solve = t2 - t1;
    out->t_critical = t3 - t2;
    /* Poincaré–Hopf with Gauss–Bonnet (../shared/DESIGN.md) */
    for (int k = 0; k < out->npoints; k++) out->ph_lhs += 4 - out->points[k].valence;
    for (int k = 0; k < out->info.nvertices; k++) out->ph_lhs += 2 - out->corners[k].valence;
    out->ph_rhs = 4 * out->info.chi;
    return SQ_OK;
}
