/* semquad — the separatrix set: start, synchronous advance, meeting and
 * merging (Marcon 2019 §3.3, §3.3.1), continuation for layout repairs.
 * The integrator and the stops are in trace_ab4.c, Algorithm 1 in
 * trace_start.c. */
#include "trace_private.h"
#include "layout.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define HALF_PI 1.57079632679489661923

static double seg_seg(const double *a0, const double *a1, const double *b0, const double *b1)
{
    double rx = a1[0] - a0[0], ry = a1[1] - a0[1], sx = b1[0] - b0[0], sy = b1[1] - b0[1];
    double den = rx * sy - ry * sx;
    if (den != 0.0) {
        double qx = b0[0] - a0[0], qy = b0[1] - a0[1];
        double t = (qx * sy - qy * sx) / den, u = (qx * ry - qy * rx) / den;
        if (t >= 0.0 && t <= 1.0 && u >= 0.0 && u <= 1.0) return 0.0;
    }
    const double *p[4] = {a0, a1, b0, b1};
    const double *s0[4] = {b0, b0, a0, a0}, *s1[4] = {b1, b1, a1, a1};
    double best = HUGE_VAL;
    for (int i = 0; i < 4; i++) {
        double dx = s1[i][0] - s0[i][0], dy = s1[i][1] - s0[i][1], l2 = dx * dx + dy * dy;
        double t = l2 > 0.0 ? ((p[i][0] - s0[i][0]) * dx + (p[i][1] - s0[i][1]) * dy) / l2 : 0.0;
        t = t < 0.0 ? 0.0 : (t > 1.0 ? 1.0 : t);
        best = fmin(best, hypot(s0[i][0] + t * dx - p[i][0], s0[i][1] + t * dy - p[i][1]));
    }
    return best;
}

/* Direction of segment i of a polyline (unit vector). */
static void seg_dir(const double *xy, int i, double d[2])
{
    double dx = xy[2 * i + 2] - xy[2 * i], dy = xy[2 * i + 3] - xy[2 * i + 1], l = hypot(dx, dy);
    d[0] = l > 0.0 ? dx / l : 0.0;
    d[1] = l > 0.0 ? dy / l : 0.0;
}

/* cos 45°: Marcon's test for opposite directions (|Δα| rounds to π at π/2
 * resolution) as a dot product. */
#define OPPOSITE_COS 0.70710678118654752

/* Distance from segment [p0, p1] to the segments of polyline xy[npts] that
 * run against direction f (f·seg <= -OPPOSITE_COS); HUGE_VAL if none is
 * within r.  Comparing with every segment, not only the other front, catches
 * fronts that pass each other between two rounds (different step sizes). */
static double against_polyline(const double *p0, const double *p1, const double f[2],
                               const double *xy, int npts, double r)
{
    double best = HUGE_VAL, sl = hypot(p1[0] - p0[0], p1[1] - p0[1]);
    for (int i = 0; i + 1 < npts; i++) {
        const double *q0 = &xy[2 * i], *q1 = &xy[2 * i + 2];
        /* the test below, first with the 1-norm bound of the length and
         * squares (no hypot: most segments are far) */
        double dx = q0[0] - p1[0], dy = q0[1] - p1[1];
        double far = r + sl + fabs(q1[0] - q0[0]) + fabs(q1[1] - q0[1]);
        if (dx * dx + dy * dy > far * far) continue;
        /* and the direction test first without the length: with
         * m = max |q1 - q0|_i <= |q1 - q0|, (q1 - q0)·f > -0.7 m means
         * d·f > -0.7 > -OPPOSITE_COS (the rounding is far below the
         * margin); most segments near a front run along it */
        double vx = q1[0] - q0[0], vy = q1[1] - q0[1];
        if (vx * f[0] + vy * f[1] > -0.7 * fmax(fabs(vx), fabs(vy))) continue;
        double ql = hypot(q1[0] - q0[0], q1[1] - q0[1]);
        if (hypot(dx, dy) > r + sl + ql) continue;
        double d[2];
        seg_dir(xy, i, d);
        if (d[0] * f[0] + d[1] * f[1] > -OPPOSITE_COS) continue;
        double g = seg_seg(p0, p1, q0, q1);
        if (g < best) best = g;
    }
    return best < r ? best : HUGE_VAL;
}

/* Closest approach of polyline xy[from..npts-1] to point t among points
 * where the line runs along direction f (f·seg >= OPPOSITE_COS; f NULL: any
 * direction): distance and vertex index. */
static double closest_vertex(const double *xy, int npts, int from, const double t[2],
                             const double *f, int *idx)
{
    double best = HUGE_VAL;
    *idx = -1;
    for (int i = from < 0 ? 0 : from; i < npts; i++) {
        if (f) {
            double d[2];
            if (npts < 2) break;
            seg_dir(xy, i + 1 < npts ? i : i - 1, d);
            if (d[0] * f[0] + d[1] * f[1] < OPPOSITE_COS) continue;
        }
        double g = hypot(xy[2 * i] - t[0], xy[2 * i + 1] - t[1]);
        if (g < best) best = g, *idx = i;
    }
    return best;
}

static int same_node(const sq_sep_end *a, const sq_sep_end *b)
{
    return a->kind == b->kind && a->id == b->id;
}

/* Meeting distance in steps: Marcon's merge distance, but at least
 * SQ_TRACE_PASS_STEPS for two lines that are one separatrix traced from both
 * ends (the mutual test below): these must meet whatever their small
 * lateral offset (Marcon 2019 §3.3 compares fronts within one step; lines
 * "that would normally just miss each other" are §3.3.1's aggressive case,
 * merge_distance > SQ_TRACE_PASS_STEPS). */
static double meet_radius(const sq_tracer *tr, const sq_walker *a, const sq_walker *b)
{
    return fmax(tr->opt.merge_distance, SQ_TRACE_PASS_STEPS) * fmax(a->ht, b->ht);
}

/* Marcon 2019 §3.3, generalized: a (advancing) and b (advancing or ended,
 * not merged) are one separatrix traced from both ends when
 *  - a's newest segment comes within r of a segment of b running the
 *    opposite way (the front against b's recent segments, not only b's
 *    front: fronts with different steps cannot jump past each other), and
 *  - b's newest segment likewise comes within r of a running the opposite
 *    way, or b has already passed a's start within r running against a's
 *    start direction (b is ahead, or ended beyond a's start).
 * A front that passes b's start (a singular point or corner) against b's
 * start direction is the special case where b is the arm it merges with. */
static int meet(const sq_tracer *tr, const sq_walker *a, const sq_walker *b)
{
    if (a->npts < 2 || b->npts < 2 || same_node(&a->start, &b->start)) return 0;
    double r = meet_radius(tr, a, b);
    const double *a0 = &a->xy[2 * (a->npts - 2)], *a1 = &a->xy[2 * (a->npts - 1)];
    double m = r + hypot(a1[0] - a0[0], a1[1] - a0[1]); /* a's segment off b's box */
    if (a1[0] < b->bb[0] - m || a1[0] > b->bb[2] + m || a1[1] < b->bb[1] - m ||
        a1[1] > b->bb[3] + m)
        return 0;
    double fa[2] = {cos(a->alpha), sin(a->alpha)};
    /* b's start lies ahead of a's front (two nodes closer than r with arms
     * pointing away from each other do not meet) */
    const double *q = b->start_xy, *p = a->start_xy;
    if ((q[0] - a1[0]) * fa[0] + (q[1] - a1[1]) * fa[1] <= 0.0) return 0;
    if (against_polyline(a0, a1, fa, b->xy, b->npts, r) == HUGE_VAL) return 0;
    if (b->active) {
        const double *b0 = &b->xy[2 * (b->npts - 2)], *b1 = &b->xy[2 * (b->npts - 1)];
        double fb[2] = {cos(b->alpha), sin(b->alpha)};
        if ((p[0] - b1[0]) * fb[0] + (p[1] - b1[1]) * fb[1] > 0.0 &&
            against_polyline(b0, b1, fb, a->xy, a->npts, r) != HUGE_VAL)
            return 1;
    }
    /* b passed a's start, running against a's start direction, after
     * travelling away from its own start */
    double back[2] = {-cos(a->start_angle), -sin(a->start_angle)};
    int idx;
    if (closest_vertex(b->xy, b->npts, 1, p, back, &idx) >= r) return 0;
    return hypot(b->xy[2 * idx] - q[0], b->xy[2 * idx + 1] - q[1]) > r;
}

/* Bring w to the other line's start (target at txy): §3.3 "each of two
 * meeting streamlines are then advanced to the starting point of the
 * other".  If w has already passed it within `accept` (b ahead of a), w is
 * cut at its closest approach and ends exactly on the target; if w is still
 * advancing it is advanced (advance_to).  *ok = 0 if neither works. */
static sq_status advance_to(sq_tracer *tr, sq_walker *w, const sq_sep_end *target,
                            const double txy[2], double budget, double accept, int *ok,
                            sq_error *err);

static sq_status reach(sq_tracer *tr, sq_walker *w, const sq_sep_end *target, const double txy[2],
                       double budget, double accept, int *ok, sq_error *err)
{
    *ok = 0;
    if (!w->active && same_node(&w->end, target)) {
        *ok = 1;
        return SQ_OK;
    }
    int idx;
    double d = closest_vertex(w->xy, w->npts, 1, txy, NULL, &idx);
    if (idx >= 1 && d < accept && (idx < w->npts - 1 || !w->active)) {
        /* passed (or ended next to) the target: cut there, end on it */
        w->npts = idx;
        w->length = 0.0;
        for (int i = 1; i < w->npts; i++)
            w->length += hypot(w->xy[2 * i] - w->xy[2 * i - 2], w->xy[2 * i + 1] - w->xy[2 * i - 1]);
        SQ_TRY(sq_walker_push(w, txy, err));
        w->active = 0;
        w->end = *target;
        *ok = 1;
        return SQ_OK;
    }
    if (!w->active) return SQ_OK;
    return advance_to(tr, w, target, txy, budget, accept, ok, err);
}

/* Advance w until it reaches target at txy: captured there, ended on the
 * boundary next to it, or passing it at its closest approach within
 * `accept`.  Gives up after `budget` more length. */
static sq_status advance_to(sq_tracer *tr, sq_walker *w, const sq_sep_end *target,
                            const double txy[2], double budget, double accept, int *ok,
                            sq_error *err)
{
    *ok = 0;
    double len0 = w->length, dmin = HUGE_VAL;
    while (w->active) {
        SQ_TRY(sq_walker_step(tr, w, err));
        const double *x = &w->xy[2 * (w->npts - 1)];
        double d = hypot(x[0] - txy[0], x[1] - txy[1]);
        double rc = tr->opt.capture_rel * w->ht;
        double acc = fmax(fmax(accept, 2.0 * rc), 0.05 * len0);
        if (!w->active) {
            if (same_node(&w->end, target)) {
                *ok = 1;
            } else if (w->end.kind != SQ_END_OPEN && d < acc) {
                /* ended next to the target (e.g. on the boundary beside the
                 * corner): the end is moved onto it */
                w->xy[2 * (w->npts - 1)] = txy[0];
                w->xy[2 * (w->npts - 1) + 1] = txy[1];
                *ok = 1;
            }
            break;
        }
        if (d < rc) {
            SQ_TRY(sq_walker_push(w, txy, err));
            *ok = 1;
            break;
        }
        /* passing the target at a distance: the closest approach is
         * accepted if within `accept` (or close relative to the line) */
        if (d > dmin && dmin < acc) {
            w->npts--;
            SQ_TRY(sq_walker_push(w, txy, err));
            *ok = 1;
            break;
        }
        dmin = fmin(dmin, d);
        if (w->length - len0 > budget) break;
    }
    w->active = 0;
    if (*ok) w->end = *target;
    return SQ_OK;
}

/* Point at normalized arc length x of a polyline (cum: cumulative lengths). */
static void at_length(const double *xy, const double *cum, int n, double x, double p[2])
{
    double s = x * cum[n - 1];
    int lo = 0, hi = n - 1;
    while (hi - lo > 1) {
        int mid = (lo + hi) / 2;
        if (cum[mid] <= s)
            lo = mid;
        else
            hi = mid;
    }
    double l = cum[hi] - cum[lo], t = l > 0.0 ? (s - cum[lo]) / l : 0.0;
    p[0] = xy[2 * lo] + t * (xy[2 * hi] - xy[2 * lo]);
    p[1] = xy[2 * lo + 1] + t * (xy[2 * hi + 1] - xy[2 * lo + 1]);
}

/* Blend of a (start of a -> start of b) and b reversed with W0 = cos^2(πx/2)
 * on a and W1 = sin^2(πx/2) on b (Marcon 2019 §3.3): the weights' slopes
 * vanish at both ends, so both start directions are kept. */
static sq_status blend(const double *axy, int na, const double *bxy, int nb, sq_separatrix *out,
                       sq_error *err)
{
    int n = na > nb ? na : nb;
    double *ca = malloc((size_t)na * sizeof *ca), *cb = malloc((size_t)nb * sizeof *cb);
    double *rb = malloc(2 * (size_t)nb * sizeof *rb), *xy = malloc(2 * (size_t)n * sizeof *xy);
    if (!ca || !cb || !rb || !xy) {
        free(ca), free(cb), free(rb), free(xy);
        return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory (merging %d + %d points)", na, nb);
    }
    for (int i = 0; i < nb; i++) {
        rb[2 * i] = bxy[2 * (nb - 1 - i)];
        rb[2 * i + 1] = bxy[2 * (nb - 1 - i) + 1];
    }
    ca[0] = cb[0] = 0.0;
    for (int i = 1; i < na; i++)
        ca[i] = ca[i - 1] + hypot(axy[2 * i] - axy[2 * i - 2], axy[2 * i + 1] - axy[2 * i - 1]);
    for (int i = 1; i < nb; i++)
        cb[i] = cb[i - 1] + hypot(rb[2 * i] - rb[2 * i - 2], rb[2 * i + 1] - rb[2 * i - 1]);
    for (int i = 0; i < n; i++) {
        double x = (double)i / (n - 1), pa[2], pb[2];
        at_length(axy, ca, na, x, pa);
        at_length(rb, cb, nb, x, pb);
        double c = cos(HALF_PI * x), w0 = c * c, w1 = 1.0 - w0;
        xy[2 * i] = w0 * pa[0] + w1 * pb[0];
        xy[2 * i + 1] = w0 * pa[1] + w1 * pb[1];
    }
    /* the ends exactly: the two starts */
    xy[0] = axy[0], xy[1] = axy[1];
    xy[2 * n - 2] = bxy[0], xy[2 * n - 1] = bxy[1];
    free(ca), free(cb), free(rb);
    out->xy = xy;
    out->npts = n;
    return SQ_OK;
}

/* Largest turning (radians) between consecutive segments of a polyline,
 * its first and last `skip` segments left out (there the blend follows one
 * line exactly: its own start turning near the singular point). */
static double max_turning(const double *xy, int n, int skip)
{
    double best = 0.0;
    for (int i = 1 + skip; i + 1 + skip < n; i++) {
        double d0[2], d1[2];
        seg_dir(xy, i - 1, d0);
        seg_dir(xy, i, d1);
        double t = fabs(atan2(d0[0] * d1[1] - d0[1] * d1[0], d0[0] * d1[0] + d0[1] * d1[1]));
        if (t > best) best = t;
    }
    return best;
}

/* A merged line turning more than this between consecutive segments has a
 * kink: the two lines were not one separatrix (radians, 10 degrees). */
#define MERGE_MAX_TURN 0.17453292519943295

/* Does a blended line leave the face?  Lines running on either side of a
 * hole thinner than the meeting radius (a slot, a blade's rounded edge)
 * pass the meeting test but are not one separatrix: their blend cuts
 * across the hole.  Its inner points and the midpoints of its inner
 * segments are located in the field's triangulation (the ends may lie on
 * the boundary). */
static int leaves_face(const sq_tracer *tr, const double *xy, int n)
{
    int elem = -1;
    double th;
    for (int i = 1; i + 1 < n; i++) {
        const double *p = &xy[2 * i], mid[2] = {0.5 * (p[0] + p[2]), 0.5 * (p[1] + p[3])};
        double len = hypot(p[2] - p[0], p[3] - p[1]);
        if (sq_trace_eval(tr->field, p, len, &elem, &th)) return 1;
        if (i + 2 < n && sq_trace_eval(tr->field, mid, len, &elem, &th)) return 1;
    }
    return 0;
}

static sq_status walker_copy(const sq_walker *w, sq_walker *c, sq_error *err)
{
    *c = *w;
    c->xy = malloc(2 * (size_t)(w->cap ? w->cap : 1) * sizeof *c->xy);
    if (!c->xy) return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory (%d points)", w->cap);
    memcpy(c->xy, w->xy, 2 * (size_t)w->npts * sizeof *c->xy);
    return SQ_OK;
}

/* Merge walkers a and b that met: each is brought to the other's start
 * (reach), then the two are blended with the cos^2/sin^2 weights.  Done on
 * copies: if either cannot reach the other's start, *done = 0 and a, b are
 * left as they were (they were not one separatrix after all). */
static sq_status merge(sq_tracer *tr, sq_walker *a, sq_walker *b, sq_separatrix *out, int *done,
                       sq_error *err)
{
    int oka = 0, okb = 0;
    double budget = 2.0 * (a->length + b->length) + 10.0 * (a->ht + b->ht);
    double accept = 1.5 * meet_radius(tr, a, b);
    sq_walker ca, cb;
    *done = 0;
    memset(out, 0, sizeof *out);
    SQ_TRY(walker_copy(a, &ca, err));
    sq_status st = walker_copy(b, &cb, err);
    if (st != SQ_OK) {
        sq_walker_free(&ca);
        return st;
    }
    st = reach(tr, &ca, &b->start, b->start_xy, budget, accept, &oka, err);
    if (st == SQ_OK && oka) st = reach(tr, &cb, &a->start, a->start_xy, budget, accept, &okb, err);
    if (st == SQ_OK && oka && okb) st = blend(ca.xy, ca.npts, cb.xy, cb.npts, out, err);
    if (st == SQ_OK && oka && okb &&
        (max_turning(out->xy, out->npts, 2) > MERGE_MAX_TURN ||
         leaves_face(tr, out->xy, out->npts))) {
        free(out->xy); /* a kink or a short cut across a hole: refuse
                          (Marcon's blend must stay smooth and in the face) */
        memset(out, 0, sizeof *out);
        oka = 0;
    }
    if (st == SQ_OK && oka && okb) {
        out->start = a->start;
        out->end = b->start;
        out->start_angle = a->start_angle;
        out->end_angle = b->start_angle + M_PI;
        out->merged = 1;
        a->active = b->active = 0;
        *done = 1;
    }
    sq_walker_free(&ca);
    sq_walker_free(&cb);
    return st;
}

static sq_status to_separatrix(sq_walker *w, sq_separatrix *s, sq_error *err)
{
    memset(s, 0, sizeof *s);
    double *xy = realloc(w->xy, 2 * (size_t)w->npts * sizeof *xy);
    if (!xy) return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    s->xy = xy;
    s->npts = w->npts;
    s->start = w->start;
    s->end = w->end;
    s->start_angle = w->start_angle;
    s->end_angle = w->end_angle;
    w->xy = NULL;
    w->npts = w->cap = 0;
    return SQ_OK;
}

typedef struct {
    sq_walker *w;
    int *partner; /* merged with, or -1 */
    char *refused; /* n*n: pairs whose merge failed (not tried again) */
    sq_separatrix *merged;
    int n;
} walk_set;

static void walk_set_free(walk_set *ws)
{
    for (int i = 0; i < ws->n; i++) {
        sq_walker_free(&ws->w[i]);
        free(ws->merged[i].xy);
    }
    free(ws->w);
    free(ws->partner);
    free(ws->refused);
    free(ws->merged);
}

/* Does a face vertex taking `quads` quads start separatrices (quads - 1)?
 * Not a smooth junction or a bend (sq_vertex.bent), nor a vertex taking 2 quads whose angle is within
 * SQ_LAYOUT_BEND_TOL_DEG of 180 deg: the layout counts neither as a patch
 * corner (layout_patches.c, layout_check.c), and the separatrix that would
 * split a 135-180 deg angle in two leaves along one of its edges where the
 * field follows a curved edge beside it, a boundary-hugging sliver of 1-
 * and 2-corner patches (stress corpus 0035: 137.7 and 155.5 deg).  Such a
 * vertex contributes 2 - 2 = 0 to Gauss-Bonnet either way.  Not beside an
 * edge shorter than BEND_MIN_EDGE_REL of the face's size: on a patch side
 * such an edge is one chord's end squeezed to its length, wedges of scaled
 * Jacobian 1e-4-1e-2 (corpus 0103, 0215, 0295: 1e-6-5e-5 edges), and the
 * repairs around it run 5 x longer (0311). */
#define BEND_MIN_EDGE_REL 0.01
/* Room for one more walker (the arrays grown, refused re-laid for n + 1). */
static sq_status walk_set_grow(walk_set *ws, sq_error *err)
{
    const int n = ws->n, m = n + 1;
    sq_walker *w = realloc(ws->w, sizeof *w * (size_t)m);
    if (w) ws->w = w;
    int *partner = w ? realloc(ws->partner, sizeof *partner * (size_t)m) : NULL;
    if (partner) ws->partner = partner;
    sq_separatrix *merged = partner ? realloc(ws->merged, sizeof *merged * (size_t)m) : NULL;
    if (merged) ws->merged = merged;
    char *refused = merged ? calloc((size_t)m * m, 1) : NULL;
    if (!refused) return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory (%d separatrices)", m);
    for (int i = 0; i < n; i++) memcpy(refused + (size_t)i * m, ws->refused + (size_t)i * n, (size_t)n);
    free(ws->refused);
    ws->refused = refused;
    memset(&ws->w[n], 0, sizeof *ws->w);
    memset(&ws->merged[n], 0, sizeof *ws->merged);
    ws->partner[n] = -1;
    return SQ_OK;
}

/* A separatrix that left through an identified edge re-enters through its
 * partner (docs/domains.md): a new line from the image of its end, in the
 * image of its direction (a rigid motion turns it by its angle), started on
 * the partner edge and carrying the length so far (the length bound of the
 * whole chain stops one that winds round the identified domain for ever).
 * The two lines are one separatrix of the identified domain. */
static sq_status reenter(sq_tracer *tr, walk_set *ws, int i, sq_error *err)
{
    const sq_walker *w = &ws->w[i];
    const sq_identification *id = &tr->opt.periodic;
    if (w->end.kind != SQ_END_BOUNDARY) return SQ_OK;
    for (int k = 0; k < id->npairs; k++) {
        const sq_identified_pair *p = &id->pairs[k];
        if (w->end.id != p->a && w->end.id != p->b) continue;
        const int fwd = w->end.id == p->a, to = fwd ? p->b : p->a;
        double T[6], q[2];
        if (fwd) memcpy(T, p->affine, sizeof T);
        else sq_affine_inverse(p->affine, T);
        sq_affine_map(T, &w->xy[2 * (w->npts - 1)], q);
        const double Lf = cad_face_edge_length(tr->face, w->end.id);
        const double Lt = cad_face_edge_length(tr->face, to);
        const double alpha = w->end_angle + atan2(T[3], T[0]), h = w->h, length = w->length;
        const sq_sep_end start = {SQ_END_BOUNDARY, to, Lt * (1.0 - w->end.s / Lf)};
        SQ_TRY(walk_set_grow(ws, err)); /* w moves */
        sq_walker *nw = &ws->w[ws->n++];
        SQ_TRY(sq_walker_init(tr, nw, q, alpha, h, err));
        nw->start = start;
        nw->length = length;
        return SQ_OK;
    }
    return SQ_OK;
}

static int starts_separatrices(const sq_tracer *tr, const sq_vertex *v, int quads)
{
    if (v->smooth || v->bent || quads < 2) return 0;
    double shortest = fmin(cad_face_edge_length(tr->face, v->edge_in),
                           cad_face_edge_length(tr->face, v->edge_out));
    return !(quads == 2 && fabs(v->angle_deg - 180.0) < SQ_LAYOUT_BEND_TOL_DEG &&
             shortest >= BEND_MIN_EDGE_REL * tr->scale);
}

static sq_status run(sq_tracer *tr, const int *vertex_quads, walk_set *ws, sq_error *err)
{
    const sq_face_info *info = tr->info;
    int cap = 0;
    for (int j = 0; j < tr->nsing; j++) {
        if (tr->sing[j].valence < 1 || tr->sing[j].valence > 64)
            return SQ_FAIL(err, SQ_ERR_PATTERN, "singular point %d has valence %d", j,
                           tr->sing[j].valence);
        cap += tr->sing[j].valence;
    }
    for (int k = 0; k < info->nvertices; k++)
        if (vertex_quads && starts_separatrices(tr, &info->vertices[k], vertex_quads[k]))
            cap += vertex_quads[k] - 1;
    ws->w = calloc(cap ? cap : 1, sizeof *ws->w);
    ws->partner = malloc((cap ? cap : 1) * sizeof *ws->partner);
    ws->merged = calloc(cap ? cap : 1, sizeof *ws->merged);
    if (!ws->w || !ws->partner || !ws->merged)
        return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory (%d separatrices)", cap);
    double alpha[64], h0;
    for (int j = 0; j < tr->nsing; j++) {
        SQ_TRY(sq_trace_singular_starts(tr, j, alpha, &h0, err));
        double p0[2] = {tr->sing[j].x, tr->sing[j].y};
        for (int k = 0; k < tr->sing[j].valence; k++) {
            sq_walker *w = &ws->w[ws->n];
            ws->partner[ws->n++] = -1;
            SQ_TRY(sq_walker_init(tr, w, p0, alpha[k], h0, err));
            w->start_sing = j;
            w->start.kind = SQ_END_SINGULAR;
            w->start.id = j;
        }
    }
    for (int k = 0; k < info->nvertices; k++) {
        if (!vertex_quads || !starts_separatrices(tr, &info->vertices[k], vertex_quads[k])) continue;
        int n = vertex_quads[k];
        if (n > 64) return SQ_FAIL(err, SQ_ERR_PATTERN, "vertex %d takes %d quads", k, n);
        SQ_TRY(sq_trace_corner_starts(tr, k, n, alpha, &h0, err));
        double p0[2] = {info->vertices[k].x, info->vertices[k].y};
        for (int q = 0; q < n - 1; q++) {
            sq_walker *w = &ws->w[ws->n];
            ws->partner[ws->n++] = -1;
            SQ_TRY(sq_walker_init(tr, w, p0, alpha[q], h0, err));
            w->start_vertex = k;
            w->start.kind = SQ_END_CORNER;
            w->start.id = k;
        }
    }
    ws->refused = calloc((size_t)ws->n * ws->n + 1, 1);
    if (!ws->refused) return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    /* synchronous advance (§3.3), fronts compared after every round */
    int nactive = ws->n;
    while (nactive > 0) {
        for (int i = 0; i < ws->n; i++) {
            if (!ws->w[i].active) continue;
            SQ_TRY(sq_walker_step(tr, &ws->w[i], err));
            if (!ws->w[i].active && tr->opt.periodic.npairs) SQ_TRY(reenter(tr, ws, i, err));
        }
        for (int i = 0; i < ws->n; i++) {
            if (!ws->w[i].active || ws->partner[i] >= 0) continue;
            for (int q = 0; q < ws->n; q++) {
                if (q == i || ws->partner[q] >= 0 || ws->refused[i * ws->n + q]) continue;
                if (!meet(tr, &ws->w[i], &ws->w[q])) continue;
                int lo = i < q ? i : q, hi = i < q ? q : i, done;
                SQ_TRY(merge(tr, &ws->w[lo], &ws->w[hi], &ws->merged[lo], &done, err));
                if (!done) {
                    ws->refused[i * ws->n + q] = ws->refused[q * ws->n + i] = 1;
                    continue;
                }
                ws->partner[lo] = hi;
                ws->partner[hi] = lo;
                break;
            }
        }
        int was = nactive;
        nactive = 0;
        for (int i = 0; i < ws->n; i++) nactive += ws->w[i].active;
        if (nactive != was) sq_progress_report(&tr->opt.progress, "trace", ws->n - nactive, ws->n);
    }
    return SQ_OK;
}

/* Two lines that both ran to the other's start (the meeting was missed,
 * e.g. one started much later along the other) are one separatrix. */
static int same_link(const sq_walker *a, const sq_walker *b)
{
    if (a->end.kind != b->start.kind || a->end.id != b->start.id) return 0;
    if (b->end.kind != a->start.kind || b->end.id != a->start.id) return 0;
    double d = fmod(fabs(a->end_angle - (b->start_angle + M_PI)), 2.0 * M_PI);
    return fmin(d, 2.0 * M_PI - d) < 0.25 * M_PI;
}

sq_status sq_trace_separatrices_stats(const sq_cross_field *field, const cad_face *face,
                                      const sq_face_info *info, const int *vertex_quads,
                                      int nsing, const sq_singularity *sing,
                                      const sq_trace_options *opt, sq_separatrix_set *out,
                                      sq_trace_stats *stats, sq_error *err)
{
    sq_tracer tr;
    if (!out) return SQ_FAIL(err, SQ_ERR_USAGE, "no output set");
    memset(out, 0, sizeof *out);
    SQ_TRY(sq_tracer_init(&tr, field, face, info, nsing, sing, opt, err));
    walk_set ws = {0};
    sq_status st = run(&tr, vertex_quads, &ws, err);
    int merges = 0;
    for (int i = 0; st == SQ_OK && i < ws.n; i++) {
        if (ws.partner[i] >= 0) continue;
        for (int q = i + 1; q < ws.n; q++) {
            if (ws.partner[q] >= 0 || !same_link(&ws.w[i], &ws.w[q])) continue;
            ws.partner[i] = q;
            ws.partner[q] = i;
            st = blend(ws.w[i].xy, ws.w[i].npts, ws.w[q].xy, ws.w[q].npts, &ws.merged[i], err);
            if (st != SQ_OK) break;
            sq_separatrix *m = &ws.merged[i];
            m->start = ws.w[i].start;
            m->end = ws.w[q].start;
            m->start_angle = ws.w[i].start_angle;
            m->end_angle = ws.w[q].start_angle + M_PI;
            m->merged = 1;
            break;
        }
    }
    for (int i = 0; st == SQ_OK && i < ws.n; i++) {
        sq_separatrix s;
        if (ws.partner[i] < 0) {
            st = to_separatrix(&ws.w[i], &s, err);
        } else if (ws.partner[i] > i) {
            s = ws.merged[i];
            memset(&ws.merged[i], 0, sizeof s);
            merges++;
        } else {
            continue;
        }
        if (st == SQ_OK) st = sq_separatrix_set_append(out, &s, err);
        if (st != SQ_OK) free(s.xy);
    }
    if (stats) {
        stats->traced = ws.n;
        stats->merges = merges;
        stats->steps = tr.steps;
    }
    walk_set_free(&ws);
    if (st != SQ_OK) sq_separatrix_set_free(out);
    return st;
}

sq_status sq_trace_separatrices(const sq_cross_field *field, const cad_face *face,
                                const sq_face_info *info, const int *vertex_quads, int nsing,
                                const sq_singularity *sing, const sq_trace_options *opt,
                                sq_separatrix_set *out, sq_error *err)
{
    return sq_trace_separatrices_stats(field, face, info, vertex_quads, nsing, sing, opt, out,
                                       NULL, err);
}

sq_status sq_trace_streamline(const sq_cross_field *field, const cad_face *face,
                              const sq_face_info *info, int nsing, const sq_singularity *sing,
                              const sq_trace_options *opt, const double p0[2], double alpha0,
                              sq_separatrix *out, long *steps, sq_error *err)
{
    sq_tracer tr;
    sq_walker w;
    SQ_TRY(sq_tracer_init(&tr, field, face, info, nsing, sing, opt, err));
    int elem = -1;
    double th;
    if (field->direction(field->ctx, p0, &elem, &th)) elem = -1;
    /* the order ramp (1 -> 4) starts with steps 1e-3 of the target so the
     * low-order steps' errors (Euler: h^2 κ / 2) stay below 1e-10; the step
     * then grows 1.25 times per step */
    SQ_TRY(sq_walker_init(&tr, &w, p0, alpha0, 1e-3 * sq_tracer_step_at(&tr, elem), err));
    for (int j = 0; j < nsing; j++)
        if (hypot(p0[0] - sing[j].x, p0[1] - sing[j].y) < 1e-12 * tr.scale) w.start_sing = j;
    sq_status st = SQ_OK;
    while (st == SQ_OK && w.active) st = sq_walker_step(&tr, &w, err);
    if (st == SQ_OK) st = to_separatrix(&w, out, err);
    if (steps) *steps = tr.steps;
    sq_walker_free(&w);
    return st;
}

sq_status sq_trace_continue(const sq_cross_field *field, const cad_face *face,
                            const sq_face_info *info, int nsing, const sq_singularity *sing,
                            const sq_trace_options *opt, sq_separatrix_set *set, int k,
                            sq_error *err)
{
    sq_tracer tr;
    if (!set || k < 0 || k >= set->n || set->s[k].npts < 1)
        return SQ_FAIL(err, SQ_ERR_USAGE, "no separatrix %d to continue", k);
    SQ_TRY(sq_tracer_init(&tr, field, face, info, nsing, sing, opt, err));
    tr.obst = set;
    tr.obst_skip = k;
    sq_separatrix *s = &set->s[k];
    int n = s->npts;
    const double *last = &s->xy[2 * (n - 1)];
    /* direction of travel at the end: the last segment, or the start angle */
    double dir = n >= 2 ? atan2(last[1] - s->xy[2 * n - 3], last[0] - s->xy[2 * n - 4])
                        : s->start_angle;
    /* rebuild the AB history from the last (up to) four points, each with
     * the branch nearest to the polyline's direction there */
    sq_walker w;
    double th;
    int elem = -1;
    if (field->direction(field->ctx, last, &elem, &th)) elem = -1;
    double h = sq_tracer_step_at(&tr, elem);
    SQ_TRY(sq_walker_init(&tr, &w, last, dir, h, err));
    if (elem >= 0) {
        w.alpha = th + HALF_PI * nearbyint((dir - th) / HALF_PI);
        w.f[0][0] = cos(w.alpha);
        w.f[0][1] = sin(w.alpha);
        w.elem = elem;
    }
    double tau = 0.0;
    for (int i = n - 2; i >= 0 && i >= n - 4 && w.nh < 4; i--) {
        const double *p = &s->xy[2 * i], *q = &s->xy[2 * i + 2];
        double d = atan2(q[1] - p[1], q[0] - p[0]), a = d;
        int e2 = elem;
        if (field->direction(field->ctx, p, &e2, &th)) break;
        a = th + HALF_PI * nearbyint((d - th) / HALF_PI);
        tau -= hypot(q[0] - p[0], q[1] - p[1]);
        w.f[w.nh][0] = cos(a);
        w.f[w.nh][1] = sin(a);
        w.tau[w.nh] = tau;
        w.nh++;
    }
    if (w.nh > 1) w.h = w.tau[0] - w.tau[1];
    for (int j = 0; j < nsing; j++)
        if (s->start.kind == SQ_END_SINGULAR && s->start.id == j) w.start_sing = j;
    if (s->start.kind == SQ_END_CORNER) w.start_vertex = s->start.id;
    w.length = sq_separatrix_length(s);
    sq_status st = SQ_OK;
    while (st == SQ_OK && w.active) st = sq_walker_step(&tr, &w, err);
    if (st == SQ_OK && w.npts > 1) {
        double *xy = realloc(s->xy, 2 * (size_t)(n + w.npts - 1) * sizeof *xy);
        if (!xy) {
            st = SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
        } else {
            memcpy(xy + 2 * n, w.xy + 2, 2 * (size_t)(w.npts - 1) * sizeof *xy);
            s->xy = xy;
            s->npts = n + w.npts - 1;
            s->end = w.end;
            s->end_angle = w.end_angle;
        }
    }
    sq_walker_free(&w);
    return st;
}
