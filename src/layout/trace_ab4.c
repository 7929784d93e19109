/* semquad — advancing one streamline (Marcon 2019 §2.4 eq. 16, §3.3):
 * variable-step 4th-order Adams–Bashforth with the order ramped 1 -> 4,
 * branch selection at every evaluation, and the stops (boundary crossing
 * found exactly on the CAD curve, capture at singular points, length bound,
 * obstacles for sq_trace_continue). */
#include "sq_segment.h"
#include "trace_private.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define HALF_PI 1.57079632679489661923

void sq_trace_options_default(sq_trace_options *opt)
{
    opt->step_rel = 0.05;
    opt->capture_rel = 2.0;
    opt->merge_distance = 1.0;
    opt->max_length = 0.0;
    opt->tol = 1e-9;
    opt->progress = (sq_progress){NULL, NULL};
    opt->periodic = (sq_identification){0, NULL};
}

sq_status sq_tracer_init(sq_tracer *tr, const sq_cross_field *field, const cad_face *face,
                         const sq_face_info *info, int nsing, const sq_singularity *sing,
                         const sq_trace_options *opt, sq_error *err)
{
    memset(tr, 0, sizeof *tr);
    if (!field || !field->direction || !field->element_size || !face || !info ||
        (nsing > 0 && !sing))
        return SQ_FAIL(err, SQ_ERR_USAGE, "missing field, face, face info or singular points");
    tr->field = field;
    tr->face = face;
    tr->info = info;
    tr->nsing = nsing;
    tr->sing = sing;
    if (opt)
        tr->opt = *opt;
    else
        sq_trace_options_default(&tr->opt);
    if (!(tr->opt.step_rel > 0.0) || !(tr->opt.capture_rel > 0.0) ||
        !(tr->opt.merge_distance > 0.0))
        return SQ_FAIL(err, SQ_ERR_USAGE,
                       "trace options: step_rel %g, capture_rel %g, merge_distance %g must be > 0",
                       tr->opt.step_rel, tr->opt.capture_rel, tr->opt.merge_distance);
    if (!(tr->opt.tol > 0.0)) tr->opt.tol = 1e-9;
    tr->scale = hypot(info->bbox[2] - info->bbox[0], info->bbox[3] - info->bbox[1]);
    tr->nedges = cad_face_num_edges(face);
    double perim = 0.0;
    for (int e = 0; e < tr->nedges; e++) perim += cad_face_edge_length(face, e);
    tr->max_length = tr->opt.max_length > 0.0 ? tr->opt.max_length : 4.0 * perim;
    tr->obst_skip = -1;
    return SQ_OK;
}

double sq_tracer_step_at(const sq_tracer *tr, int elem)
{
    double s = elem >= 0 ? tr->field->element_size(tr->field->ctx, elem) : 0.0;
    if (!(s > 0.0)) s = 0.05 * tr->scale;
    return tr->opt.step_rel * s;
}

int sq_trace_eval(const sq_cross_field *field, const double x[2], double len, int *elem,
                  double *theta)
{
    /* sem_locator_find misses some points on element edges and near graded
     * corners; a point 1e-10 or 1e-8 of len away gives the direction to that
     * accuracy.  The hint first (a global search costs ~100 evaluations) */
    static const double off[3] = {0.0, 1e-10, 1e-8};
    for (int pass = 0; pass < 2; pass++) {
        if (pass == 1 && *elem < 0) break;
        for (int i = 0; i < 3; i++)
            for (int k = 0; k < (i ? 4 : 1); k++) {
                double q[2] = {x[0] + (i && k == 0 ? 1 : k == 1 ? -1 : 0) * off[i] * len,
                               x[1] + (k == 2 ? 1 : k == 3 ? -1 : 0) * off[i] * len};
                int e = pass ? -1 : *elem;
                if (!field->direction(field->ctx, q, &e, theta)) {
                    *elem = e;
                    return 0;
                }
            }
    }
    return 1;
}

sq_status sq_walker_push(sq_walker *w, const double p[2], sq_error *err)
{
    if (w->npts == w->cap) {
        int cap = w->cap ? 2 * w->cap : 256;
        double *nx = realloc(w->xy, 2 * (size_t)cap * sizeof *nx);
        if (!nx) return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory (%d points)", cap);
        w->xy = nx;
        w->cap = cap;
    }
    w->xy[2 * w->npts] = p[0];
    w->xy[2 * w->npts + 1] = p[1];
    if (w->npts == 0) {
        w->bb[0] = w->bb[2] = p[0];
        w->bb[1] = w->bb[3] = p[1];
    } else {
        w->bb[0] = fmin(w->bb[0], p[0]);
        w->bb[1] = fmin(w->bb[1], p[1]);
        w->bb[2] = fmax(w->bb[2], p[0]);
        w->bb[3] = fmax(w->bb[3], p[1]);
    }
    w->npts++;
    return SQ_OK;
}

sq_status sq_walker_init(sq_tracer *tr, sq_walker *w, const double p0[2], double alpha, double h0,
                         sq_error *err)
{
    memset(w, 0, sizeof *w);
    w->start_sing = -1;
    w->start_vertex = -1;
    w->elem = -1;
    w->alpha = alpha;
    w->start_angle = alpha;
    w->end_angle = alpha;
    w->f[0][0] = cos(alpha);
    w->f[0][1] = sin(alpha);
    w->tau[0] = 0.0;
    w->nh = 1;
    w->h = h0 / 1.25; /* the first step is h0 (growth 1.25 per step) */
    w->ht = h0;
    w->start_xy[0] = p0[0];
    w->start_xy[1] = p0[1];
    w->start.kind = SQ_END_OPEN;
    w->start.id = -1;
    w->end.kind = SQ_END_OPEN;
    w->end.id = -1;
    w->active = 1;
    /* element hint near the start (p0 may be a boundary vertex) */
    double q[2] = {p0[0] + 1e-3 * h0 * w->f[0][0], p0[1] + 1e-3 * h0 * w->f[0][1]}, th;
    if (tr->field->direction(tr->field->ctx, q, &w->elem, &th)) w->elem = -1;
    return sq_walker_push(w, p0, err);
}

void sq_walker_free(sq_walker *w)
{
    free(w->xy);
    w->xy = NULL;
    w->npts = w->cap = 0;
}

/* Variable-step Adams–Bashforth weights: w_j = ∫_0^h L_j(τ) dτ for the
 * Lagrange basis on the nodes tau[j] (relative to the front, tau[0] = 0). */
static void ab_weights(int k, const double *tau, double h, double *wts)
{
    for (int j = 0; j < k; j++) {
        double c[4] = {1.0, 0.0, 0.0, 0.0}, den = 1.0; /* polynomial in τ, low first */
        int deg = 0;
        for (int m = 0; m < k; m++) {
            if (m == j) continue;
            /* multiply by (τ - tau[m]) */
            for (int d = deg + 1; d >= 1; d--) c[d] = c[d - 1] - tau[m] * c[d];
            c[0] = -tau[m] * c[0];
            deg++;
            den *= tau[j] - tau[m];
        }
        double s = 0.0, hp = h;
        for (int d = 0; d <= deg; d++, hp *= h) s += c[d] * hp / (d + 1);
        wts[j] = s / den;
    }
}

static double wrap_pi(double a)
{
    return a - 2.0 * M_PI * floor((a + M_PI) / (2.0 * M_PI));
}

/* Signed distance-like side function of p with respect to edge e: > 0 on
 * the face's side (the face is on the left of the direction of travel). */
static sq_status edge_side(const sq_tracer *tr, int e, const double p[2], double *g, double *s,
                           double *dist, sq_error *err)
{
    double foot[2], t[2];
    SQ_TRY(cad_face_edge_project(tr->face, e, p, s, foot, dist, err));
    SQ_TRY(cad_face_edge_eval(tr->face, e, *s, NULL, t, NULL, err));
    *g = t[0] * (p[1] - foot[1]) - t[1] * (p[0] - foot[0]);
    return SQ_OK;
}

/* Set w's end on the boundary at (edge e, arc length s): the point is the
 * curve's own evaluation, or a face vertex when the foot is within the
 * capture radius of a corner (1e-9 of the face size for smooth junctions). */
static sq_status end_on_boundary(sq_tracer *tr, sq_walker *w, int e, double s, double rc,
                                 sq_error *err)
{
    double p[2];
    SQ_TRY(cad_face_edge_eval(tr->face, e, s, p, NULL, NULL, err));
    w->end.kind = SQ_END_BOUNDARY;
    w->end.id = e;
    w->end.s = s;
    int best = -1;
    double bd = HUGE_VAL;
    for (int k = 0; k < tr->info->nvertices; k++) {
        const sq_vertex *v = &tr->info->vertices[k];
        if (v->edge_in != e && v->edge_out != e) continue;
        if (k == w->start_vertex && w->length < 4.0 * rc) continue;
        double d = hypot(p[0] - v->x, p[1] - v->y);
        double tol = v->smooth ? 1e-9 * tr->scale : rc;
        if (d < tol && d < bd) bd = d, best = k;
    }
    if (best >= 0) {
        p[0] = tr->info->vertices[best].x;
        p[1] = tr->info->vertices[best].y;
        w->end.kind = SQ_END_CORNER;
        w->end.id = best;
        w->end.s = 0.0;
    }
    /* a foot that (almost) repeats the last point replaces it */
    const double *last = &w->xy[2 * (w->npts - 1)];
    if (w->npts > 1 && hypot(p[0] - last[0], p[1] - last[1]) < 1e-2 * w->h) {
        w->npts--;
        w->length -= hypot(last[0] - w->xy[2 * w->npts - 2], last[1] - w->xy[2 * w->npts - 1]);
    }
    last = &w->xy[2 * (w->npts - 1)];
    double dx = p[0] - last[0], dy = p[1] - last[1];
    w->length += hypot(dx, dy);
    if (dx != 0.0 || dy != 0.0) w->end_angle = w->alpha + wrap_pi(atan2(dy, dx) - w->alpha);
    SQ_TRY(sq_walker_push(w, p, err));
    w->active = 0;
    return SQ_OK;
}

/* Side function, foot and distance of p for every edge e (edge_side). */
typedef struct {
    double g, s, d;
} edge_pos;

/* The segment a -> b left the face: its crossing with the CAD boundary
 * (Illinois regula falsi on the side function along the segment); at[e]
 * holds edge_side of b for every edge (the caller's inside test computed
 * them already: a projection on a B-spline edge costs more than a step). */
static sq_status stop_at_boundary(sq_tracer *tr, sq_walker *w, const double a[2],
                                  const double b[2], const edge_pos *at, double rc, sq_error *err)
{
    double len = hypot(b[0] - a[0], b[1] - a[1]), tol = 1e-9 * tr->scale;
    int best_e = -1, near_e = -1;
    double best_t = HUGE_VAL, best_s = 0.0, near_d = HUGE_VAL, near_s = 0.0;
    for (int e = 0; e < tr->nedges; e++) {
        double g1 = at[e].g, s1 = at[e].s, d1 = at[e].d, g0, s0, d0;
        if (d1 < near_d) near_d = d1, near_e = e, near_s = s1;
        if (d1 > len + tol) continue; /* the segment cannot reach this edge */
        SQ_TRY(edge_side(tr, e, a, &g0, &s0, &d0, err));
        if (!(g0 >= 0.0 && g1 < 0.0)) continue;
        double t0 = 0.0, t1 = 1.0, gs = 0.0, ss = s1, ds = d1;
        int side = 0;
        for (int it = 0; it < 100; it++) {
            double t = (t0 * g1 - t1 * g0) / (g1 - g0);
            if (!(t > t0 && t < t1)) t = 0.5 * (t0 + t1);
            double p[2] = {a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])};
            SQ_TRY(edge_side(tr, e, p, &gs, &ss, &ds, err));
            if (gs >= 0.0) {
                t0 = t, g0 = gs;
                if (side == 1) g1 *= 0.5;
                side = 1;
            } else {
                t1 = t, g1 = gs;
                if (side == -1) g0 *= 0.5;
                side = -1;
            }
            if (fabs(gs) < 1e-15 * tr->scale || (t1 - t0) * len < 1e-15 * tr->scale) break;
        }
        double tm = 0.5 * (t0 + t1);
        if (ds < tol && tm < best_t) best_t = tm, best_e = e, best_s = ss;
    }
    if (best_e >= 0) return end_on_boundary(tr, w, best_e, best_s, rc, err);
    /* no sign change: b is outside the field's triangulation but not (or
     * hardly) outside the CAD face; end at its foot on the nearest edge */
    if (near_e < 0) return SQ_FAIL(err, SQ_ERR_INTERNAL, "face has no edges");
    return end_on_boundary(tr, w, near_e, near_s, rc, err);
}

/* Crossing of segment [a, b] with the polylines of the obstacle set. */
static int hit_obstacle(const sq_tracer *tr, const double a[2], const double b[2], double *ub,
                        int *id, double *s, double p[2])
{
    const sq_separatrix_set *set = tr->obst;
    double best = HUGE_VAL;
    int found = 0;
    double rx = b[0] - a[0], ry = b[1] - a[1];
    for (int j = 0; j < set->n; j++) {
        if (j == tr->obst_skip) continue;
        const sq_separatrix *o = &set->s[j];
        double acc = 0.0;
        for (int i = 0; i + 1 < o->npts; i++) {
            const double *q0 = &o->xy[2 * i], *q1 = &o->xy[2 * i + 2];
            double sx = q1[0] - q0[0], sy = q1[1] - q0[1], sl = hypot(sx, sy);
            double den = rx * sy - ry * sx;
            if (den != 0.0) {
                double qx = q0[0] - a[0], qy = q0[1] - a[1];
                double t = (qx * sy - qy * sx) / den, u = (qx * ry - qy * rx) / den;
                if (t > 1e-12 && t <= 1.0 && u >= 0.0 && u <= 1.0 && t < best) {
                    best = t;
                    *id = j;
                    *s = acc + u * sl;
                    p[0] = q0[0] + u * sx;
                    p[1] = q0[1] + u * sy;
                    found = 1;
                }
            }
            acc += sl;
        }
    }
    *ub = best;
    return found;
}

sq_status sq_walker_step(sq_tracer *tr, sq_walker *w, sq_error *err)
{
    if (!w->active) return SQ_OK;
    const double *x = &w->xy[2 * (w->npts - 1)];
    double ht = sq_tracer_step_at(tr, w->elem);
    double rc = tr->opt.capture_rel * ht;
    w->ht = ht;
    /* smooth growth of the step; smaller steps near other singular points,
     * where the direction turns on the scale of the distance to them */
    double h = fmin(ht, 1.25 * w->h);
    for (int j = 0; j < tr->nsing; j++) {
        if (j == w->start_sing && w->length < 8.0 * rc) continue;
        double d = hypot(x[0] - tr->sing[j].x, x[1] - tr->sing[j].y);
        h = fmin(h, fmax(0.25 * d, 0.125 * ht));
    }
    /* Adams–Bashforth of order nh (1..4): x_{n+1} = x_n + Σ w_j f_{n-j} */
    double rel[4], wts[4];
    for (int j = 0; j < w->nh; j++) rel[j] = w->tau[j] - w->tau[0];
    ab_weights(w->nh, rel, h, wts);
    double xn[2] = {x[0], x[1]};
    for (int j = 0; j < w->nh; j++) {
        xn[0] += wts[j] * w->f[j][0];
        xn[1] += wts[j] * w->f[j][1];
    }
    tr->steps++;
    int elem = w->elem;
    double theta;
    if (sq_trace_eval(tr->field, xn, h, &elem, &theta)) {
        /* outside the field's triangulation: a boundary crossing, unless
         * the CAD face says xn is well inside (then keep the direction) */
        int inside = 0;
        double best = HUGE_VAL, g = 0.0;
        edge_pos *at = malloc((size_t)(tr->nedges ? tr->nedges : 1) * sizeof *at);
        if (!at) return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory (%d edges)", tr->nedges);
        sq_status st = SQ_OK;
        for (int e = 0; e < tr->nedges && st == SQ_OK; e++) {
            st = edge_side(tr, e, xn, &at[e].g, &at[e].s, &at[e].d, err);
            if (st == SQ_OK && at[e].d < best) best = at[e].d, g = at[e].g;
        }
        inside = g > 0.0 && best > 1e-7 * tr->scale;
        if (st == SQ_OK && !inside) {
            double a[2] = {x[0], x[1]};
            st = stop_at_boundary(tr, w, a, xn, at, rc, err);
        }
        free(at);
        if (st != SQ_OK || !inside) return st;
        elem = w->elem;
        theta = w->alpha;
    }
    /* the branch of the cross nearest to the previous direction (§3.3: ψ
     * jumps by ±π/2 across jump lines, the line must not turn) */
    double alpha = theta + HALF_PI * nearbyint((w->alpha - theta) / HALF_PI);
    double seg = hypot(xn[0] - x[0], xn[1] - x[1]);
    if (tr->obst) {
        double ub, s, p[2];
        int id;
        double a[2] = {x[0], x[1]};
        if (hit_obstacle(tr, a, xn, &ub, &id, &s, p)) {
            SQ_TRY(sq_walker_push(w, p, err));
            w->length += ub * seg;
            w->end.kind = SQ_END_SEPARATRIX;
            w->end.id = id;
            w->end.s = s;
            w->end_angle = w->alpha;
            w->active = 0;
            return SQ_OK;
        }
    }
    /* capture at a singular point: the new segment passes within rc */
    for (int j = 0; j < tr->nsing; j++) {
        if (j == w->start_sing && w->length < 4.0 * rc) continue;
        double sp[2] = {tr->sing[j].x, tr->sing[j].y}, u;
        if (sq_segment_distance(sp, x, xn, &u) < rc) {
            double dlast = hypot(xn[0] - sp[0], xn[1] - sp[1]);
            if (u < 1.0 || dlast < 0.5 * h) {
                SQ_TRY(sq_walker_push(w, sp, err)); /* x may move: not used below */
            } else {
                SQ_TRY(sq_walker_push(w, xn, err));
                SQ_TRY(sq_walker_push(w, sp, err));
            }
            int n = w->npts;
            w->length += hypot(w->xy[2 * n - 2] - w->xy[2 * n - 4], w->xy[2 * n - 1] - w->xy[2 * n - 3]);
            w->end.kind = SQ_END_SINGULAR;
            w->end.id = j;
            w->end.s = 0.0;
            w->end_angle = alpha;
            w->active = 0;
            return SQ_OK;
        }
    }
    SQ_TRY(sq_walker_push(w, xn, err));
    w->length += seg;
    w->h = h;
    w->elem = elem;
    w->alpha = alpha;
    w->end_angle = alpha;
    for (int j = 3; j > 0; j--) {
        w->f[j][0] = w->f[j - 1][0];
        w->f[j][1] = w->f[j - 1][1];
        w->tau[j] = w->tau[j - 1];
    }
    w->f[0][0] = cos(alpha);
    w->f[0][1] = sin(alpha);
    w->tau[0] = w->tau[1] + h;
    if (w->nh < 4) w->nh++;
    if (w->length > tr->max_length) {
        w->end.kind = SQ_END_OPEN;
        w->end.id = -1;
        w->active = 0;
    }
    return SQ_OK;
}
