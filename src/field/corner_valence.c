#include "corner_valence.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define ARC_SAMPLES 256

static double turn(const double a[2], const double b[2])
{
    return atan2(a[0] * b[1] - a[1] * b[0], a[0] * b[0] + a[1] * b[1]);
}

/* Radius of the arc: well inside the element fan at the corner and short
 * against both edges. */
static double arc_radius(const sq_guiding_field *g, const cad_face *face, const sq_vertex *v)
{
    const sem_tri_mesh *m = g->mesh;
    double h = HUGE_VAL;
    for (int k = 0; k < m->nverts; k++) {
        double d = hypot(m->vxy[2 * k] - v->x, m->vxy[2 * k + 1] - v->y);
        if (d > 0.0 && d < h) h = d;
    }
    double L =
        fmin(cad_face_edge_length(face, v->edge_in), cad_face_edge_length(face, v->edge_out));
    return fmin(0.2 * h, 0.1 * L);
}

static sq_status one_corner(const sq_guiding_field *g, const cad_face *face, const sq_vertex *v,
                            sq_corner_valence *cv, sq_error *err)
{
    double rho = arc_radius(g, face, v), c[2] = {v->x, v->y}, A[2], B[2];
    double Lin = cad_face_edge_length(face, v->edge_in);
    SQ_TRY(cad_face_edge_eval(face, v->edge_out, rho, A, NULL, NULL, err));
    SQ_TRY(cad_face_edge_eval(face, v->edge_in, Lin - rho, B, NULL, NULL, err));
    double a0 = atan2(A[1] - c[1], A[0] - c[0]), a1 = atan2(B[1] - c[1], B[0] - c[0]);
    double sweep = fmod(a1 - a0 + 4.0 * M_PI, 2.0 * M_PI); /* counter-clockwise, into the face */
    if (sweep <= 0.0) sweep += 2.0 * M_PI;
    double prev[2], cur[2], total = 0.0;
    SQ_TRY(sq_guiding_field_data(g, face, v->edge_out, A, prev, err));
    int elem = -1;
    for (int k = 1; k < ARC_SAMPLES; k++) {
        double a = a0 + sweep * k / ARC_SAMPLES, x[2] = {c[0] + rho * cos(a), c[1] + rho * sin(a)};
        if (sq_guiding_field_eval(g, x, &elem, cur, NULL))
            continue; /* outside near a curved edge */
        total += turn(prev, cur);
        memcpy(prev, cur, sizeof prev);
    }
    SQ_TRY(sq_guiding_field_data(g, face, v->edge_in, B, cur, err));
    total += turn(prev, cur);
    /* Marcon 2019, eq. (15): ψ = atan2(v,u)/4, I in units of π/2; where
     * the data turns through a bend, the crosses at A and B are the
     * tangents' turned by the bend's corrections, which I counts too */
    double alpha = v->angle_deg * M_PI / 180.0;
    double bend = sq_guiding_field_bend(g, face, v->edge_in, Lin - rho) -
                  sq_guiding_field_bend(g, face, v->edge_out, rho);
    cv->raw = (alpha - 0.25 * total + bend) / (0.5 * M_PI);
    cv->valence = (int)lround(cv->raw);
    cv->angle_deg = v->angle_deg;
    return SQ_OK;
}

sq_status sq_corner_valences(const sq_guiding_field *g, const cad_face *face,
                             const sq_face_info *info, sq_corner_valence **out, sq_error *err)
{
    sq_corner_valence *cv = calloc(info->nvertices > 0 ? (size_t)info->nvertices : 1, sizeof *cv);
    if (!cv) return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    for (int k = 0; k < info->nvertices; k++) {
        cv[k].vertex = k;
        sq_status st = one_corner(g, face, &info->vertices[k], &cv[k], err);
        if (st != SQ_OK) {
            free(cv);
            return st;
        }
    }
    *out = cv;
    return SQ_OK;
}
