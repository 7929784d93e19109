#include "face_info.h"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Integrand context for gsl: evaluation errors are latched, not lost. */
typedef struct {
    const cad_face *face;
    int edge;
    sq_status status;
    sq_error *err;
} edge_ctx;

static double abs_curvature(double s, void *p)
{
    edge_ctx *c = p;
    double k = 0.0;
    if (c->status != SQ_OK) return 0.0;
    c->status = cad_face_edge_eval(c->face, c->edge, s, NULL, NULL, &k, c->err);
    return fabs(k);
}

/* Adaptive Gauss–Kronrod over the edge: B-spline edges are only piecewise
 * smooth, which fixed rules would integrate to a few digits only. */
static sq_status integrate_edge(const cad_face *face, int edge, double (*f)(double, void *),
                                double epsabs, double *value, sq_error *err)
{
    gsl_integration_workspace *ws = gsl_integration_workspace_alloc(2000);
    if (!ws) return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    edge_ctx ctx = {face, edge, SQ_OK, err};
    gsl_function F = {f, &ctx};
    double L = cad_face_edge_length(face, edge), abserr;
    int rc = gsl_integration_qag(&F, 0.0, L, epsabs, 1e-13, 2000, GSL_INTEG_GAUSS31, ws, value,
                                 &abserr);
    gsl_integration_workspace_free(ws);
    if (ctx.status != SQ_OK) return ctx.status;
    /* Round-off limits are reached before 1e-13 on long B-splines: accept
     * GSL's "roundoff" verdict, refuse real non-convergence. */
    if (rc != 0 && rc != GSL_EROUND && abserr > 1e-9 * (fabs(*value) + L))
        return SQ_FAIL(err, SQ_ERR_INTERNAL, "edge %d: boundary integral did not converge (%s)",
                       edge, "gsl_integration_qag");
    return SQ_OK;
}

sq_status sq_edge_turning(const cad_face *face, int edge, double *turning, sq_error *err)
{
    if (cad_face_edge_type(face, edge) == CAD_EDGE_LINE) {
        *turning = 0.0;
        return SQ_OK;
    }
    return integrate_edge(face, edge, abs_curvature, 1e-14, turning, err); /* radians */
}

static void bbox_add(double bb[4], const double p[2])
{
    if (p[0] < bb[0]) bb[0] = p[0];
    if (p[1] < bb[1]) bb[1] = p[1];
    if (p[0] > bb[2]) bb[2] = p[0];
    if (p[1] > bb[3]) bb[3] = p[1];
}

/* Tangents turning by +-180 degrees (two edges tangent at their vertex,
 * going back the way they came) leave the interior angle 0 (a horn of the
 * face: the edges' curvatures part them on the face's side) or 360 (a horn
 * of the outside): the sign of atan2 at +-pi is round-off.  Decided by the
 * chords to points a little way along both edges, whose angle seen from
 * the face (counter-clockwise from the outgoing to the incoming one) is
 * below or above 180 degrees. */
static sq_status cusp_side(const cad_face *face, int ein, int eout, const double v[2], double turn,
                           double *angle_deg, sq_error *err)
{
    double Lin = cad_face_edge_length(face, ein), Lout = cad_face_edge_length(face, eout);
    double d = 1e-3 * fmin(Lin, Lout), a[2], b[2];
    SQ_TRY(cad_face_edge_eval(face, ein, Lin - d, a, NULL, NULL, err));
    SQ_TRY(cad_face_edge_eval(face, eout, d, b, NULL, NULL, err));
    double ax = a[0] - v[0], ay = a[1] - v[1], bx = b[0] - v[0], by = b[1] - v[1];
    int horn = bx * ay - by * ax > 0.0; /* a within 180 degrees counter-clockwise of b */
    double t = fabs(turn) * 180.0 / M_PI;
    *angle_deg = horn ? 180.0 - t : 180.0 + t;
    return SQ_OK;
}

sq_status sq_face_info_compute(const cad_face *face, sq_face_info *info, sq_error *err)
{
    memset(info, 0, sizeof *info);
    info->nloops = cad_face_num_loops(face);
    info->nholes = info->nloops - 1;
    info->chi = 1 - info->nholes;
    info->bbox[0] = info->bbox[1] = HUGE_VAL;
    info->bbox[2] = info->bbox[3] = -HUGE_VAL;
    int ne = cad_face_num_edges(face);
    info->vertices = calloc(ne > 0 ? (size_t)ne : 1, sizeof *info->vertices);
    if (!info->vertices) return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    sq_status st = SQ_OK;
    double twice_area = 0.0, perimeter = 0.0;
    for (int e = 0; e < ne && st == SQ_OK; e++) {
        /* Green's integral in the curve's own parameter (cad_face_edge_green),
         * the one the layout's patch areas use: a unit 2D tangent against 3D
         * arc length would inflate the area by tilt^2/2 where an edge leaves
         * the face's plane within the file's tolerance (7.6e-8 of the area on
         * sheet_metal_54's face 7, whose one patch then "mismatched"). */
        double a = 0.0, L = cad_face_edge_length(face, e);
        perimeter += L;
        st = cad_face_edge_green(face, e, 0.0, L, &a, err);
        twice_area += a;
        /* Bounding box from a dense sample (exact enough for framing). */
        for (int k = 0; k <= 64 && st == SQ_OK; k++) {
            double p[2];
            st = cad_face_edge_eval(face, e, L * k / 64.0, p, NULL, NULL, err);
            if (st == SQ_OK) bbox_add(info->bbox, p);
        }
    }
    info->area = 0.5 * twice_area;
    for (int l = 0; l < info->nloops && st == SQ_OK; l++) {
        int first = cad_face_loop_first_edge(face, l), n = cad_face_loop_num_edges(face, l);
        for (int k = 0; k < n && st == SQ_OK; k++) {
            int ein = first + (k + n - 1) % n, eout = first + k;
            double tin[2], tout[2], p[2];
            st = cad_face_edge_eval(face, ein, cad_face_edge_length(face, ein), NULL, tin, NULL,
                                    err);
            if (st == SQ_OK) st = cad_face_edge_eval(face, eout, 0.0, p, tout, NULL, err);
            if (st != SQ_OK) break;
            /* Turning angle from incoming to outgoing tangent; the face is on
             * the left, so the interior angle is pi minus the turning. */
            double turn = atan2(tin[0] * tout[1] - tin[1] * tout[0],
                                tin[0] * tout[0] + tin[1] * tout[1]);
            sq_vertex *v = &info->vertices[info->nvertices++];
            v->x = p[0];
            v->y = p[1];
            v->angle_deg = 180.0 - turn * 180.0 / M_PI;
            v->cusp_tol_deg = SQ_CUSP_REL_TOL * perimeter * 180.0 / M_PI /
                              fmin(cad_face_edge_length(face, ein), cad_face_edge_length(face, eout));
            if (180.0 - fabs(turn) * 180.0 / M_PI < v->cusp_tol_deg)
                st = cusp_side(face, ein, eout, p, turn, &v->angle_deg, err);
            v->loop = l;
            v->edge_in = ein;
            v->edge_out = eout;
            v->smooth = fabs(turn) * 180.0 / M_PI < SQ_SMOOTH_TOL_DEG;
            if (!v->smooth) info->ncorners++;
        }
    }
    if (st != SQ_OK) sq_face_info_free(info);
    return st;
}

sq_status sq_face_check_cusps(const sq_face_info *info, sq_error *err)
{
    for (int k = 0; k < info->nvertices; k++) {
        const sq_vertex *v = &info->vertices[k];
        if (v->angle_deg < v->cusp_tol_deg)
            return SQ_FAIL(err, SQ_ERR_LAYOUT,
                           "no all-quad mesh with positive Jacobians: the corner at (%.10g, %.10g) "
                           "is a cusp (interior angle %.2g deg, below %.2g: its two edges are "
                           "tangent as far as the face is resolved, %g of its boundary's length), "
                           "and a quad's corner there has a zero angle",
                           v->x, v->y, v->angle_deg, v->cusp_tol_deg, SQ_CUSP_REL_TOL);
    }
    return SQ_OK;
}

void sq_face_info_free(sq_face_info *info)
{
    if (!info) return;
    free(info->vertices);
    memset(info, 0, sizeof *info);
}

const char *sq_face_status_name(cad_face_status s)
{
    switch (s) {
    case CAD_FACE_OK: return "ok";
    case CAD_FACE_HEALED: return "healed";
    case CAD_FACE_NOT_PLANAR: return "not planar";
    case CAD_FACE_BROKEN: return "broken";
    }
    return "broken";
}

void sq_heal_text(const cad_heal *h, const char *unit_name, char *buf, size_t n)
{
    const double *p = h->at;
    char unit[32] = ""; /* " mm", or nothing when the file has no unit */
    if (strcmp(unit_name, "unknown")) snprintf(unit, sizeof unit, " %s", unit_name);
    if (!strcmp(h->kind, "gap"))
        snprintf(buf, n, "closed a %.3g%s gap between edges %d and %d of wire %d at (%.6g, %.6g, %.6g)",
                 h->size, unit, h->edge_a, h->edge_b, h->wire, p[0], p[1], p[2]);
    else if (!strcmp(h->kind, "connection"))
        snprintf(buf, n, "joined edges %d and %d of wire %d, their vertices %.3g%s apart, at (%.6g, %.6g, %.6g)",
                 h->edge_a, h->edge_b, h->wire, h->size, unit, p[0], p[1], p[2]);
    else if (!strcmp(h->kind, "small edge"))
        snprintf(buf, n, "merged edge %d of wire %d, %.3g%s long, at (%.6g, %.6g, %.6g)", h->edge_a,
                 h->wire, h->size, unit, p[0], p[1], p[2]);
    else if (!strcmp(h->kind, "cusp"))
        snprintf(buf, n, "blunted a cusp between edges %d and %d of wire %d at (%.6g, %.6g, %.6g): cut %.3g%s and %.3g%s off them, joined by a %.3g%s segment",
                 h->edge_a, h->edge_b, h->wire, p[0], p[1], p[2], h->cut[0], unit, h->cut[1], unit,
                 h->size, unit);
    else if (!strcmp(h->kind, "as read") && !strcmp(h->defect, "no face"))
        snprintf(buf, n, "kept the face as read: healing gave no face");
    else if (!strcmp(h->kind, "as read") && h->edge_b >= 0)
        snprintf(buf, n, "kept the face as read: healing would leave a %s of %.3g%s between edges %d and %d of wire %d at (%.6g, %.6g, %.6g)",
                 h->defect, h->size, unit, h->edge_a, h->edge_b, h->wire, p[0], p[1], p[2]);
    else if (!strcmp(h->kind, "as read"))
        snprintf(buf, n, "kept the face as read: healing would leave a %s %d of wire %d (length %.3g%s) at (%.6g, %.6g, %.6g)",
                 h->defect, h->edge_a, h->wire, h->size, unit, p[0], p[1], p[2]);
    else
        snprintf(buf, n, "fixed a %s in wire %d", h->kind, h->wire);
}

void sq_json_healing(sq_json *j, const cad_model *m, int face)
{
    sq_json_key(j, "healing");
    sq_json_begin_object(j);
    sq_json_key_number(j, "tolerance", cad_model_heal_tolerance(m));
    sq_json_key(j, "fixes");
    sq_json_begin_array(j);
    cad_heal h;
    for (int k = 0; cad_model_face_heal(m, face, k, &h) == 0; k++) {
        sq_json_begin_object(j);
        sq_json_key_string(j, "kind", h.kind);
        if (!strcmp(h.kind, "as read")) sq_json_key_string(j, "defect", h.defect);
        sq_json_key_int(j, "wire", h.wire);
        sq_json_key(j, "edges");
        sq_json_begin_array(j);
        if (h.edge_a >= 0) sq_json_int(j, h.edge_a);
        if (h.edge_b >= 0) sq_json_int(j, h.edge_b);
        sq_json_end_array(j);
        sq_json_key_number(j, "size", h.size);
        if (!strcmp(h.kind, "cusp")) { /* lengths cut off edge_a and edge_b */
            sq_json_key(j, "cut");
            sq_json_begin_array(j);
            sq_json_number(j, h.cut[0]);
            sq_json_number(j, h.cut[1]);
            sq_json_end_array(j);
        }
        sq_json_key(j, "at");
        sq_json_begin_array(j);
        for (int d = 0; d < 3; d++)
            sq_json_number(j, h.at[d]);
        sq_json_end_array(j);
        sq_json_end_object(j);
    }
    sq_json_end_array(j);
    sq_json_end_object(j);
}
