/* semquad — the repair line (Jezdimirović 2021 journal §6.1): a field line
 * traced by Heun steps from a point of the layout to the boundary (exactly
 * on the CAD curve) or to the first separatrix it meets, and added to the set
 * as a separatrix; the boundary sample and the cross branch it steps by. */
#include "repair_private.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

sq_status lay_sample_boundary(lay_repair *r, sq_error *err)
{
    int ne = cad_face_num_edges(r->face), tot = 0;
    for (int e = 0; e < ne; e++) tot += cad_face_edge_type(r->face, e) == CAD_EDGE_LINE ? 1 : 256;
    r->bxy = malloc(4 * (size_t)tot * sizeof *r->bxy);
    r->bs = malloc(2 * (size_t)tot * sizeof *r->bs);
    r->bedge = malloc((size_t)tot * sizeof *r->bedge);
    if (!r->bxy || !r->bs || !r->bedge) return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    r->nb = 0;
    for (int e = 0; e < ne; e++) {
        int m = cad_face_edge_type(r->face, e) == CAD_EDGE_LINE ? 1 : 256;
        double len = cad_face_edge_length(r->face, e), prev[2];
        SQ_TRY(cad_face_edge_eval(r->face, e, 0.0, prev, NULL, NULL, err));
        for (int k = 1; k <= m; k++) {
            double p[2], s = len * k / m;
            SQ_TRY(cad_face_edge_eval(r->face, e, s, p, NULL, NULL, err));
            double *q = &r->bxy[4 * r->nb];
            q[0] = prev[0];
            q[1] = prev[1];
            q[2] = p[0];
            q[3] = p[1];
            r->bs[2 * r->nb] = len * (k - 1) / m;
            r->bs[2 * r->nb + 1] = s;
            r->bedge[r->nb++] = e;
            prev[0] = p[0];
            prev[1] = p[1];
        }
    }
    return SQ_OK;
}

/* Segment p-q against segment a-b: parameters t on p-q and u on a-b. */
int lay_seg_seg(const double p[2], const double q[2], const double a[2], const double b[2],
                double *t, double *u)
{
    double r[2] = {q[0] - p[0], q[1] - p[1]}, s[2] = {b[0] - a[0], b[1] - a[1]};
    double den = r[0] * s[1] - r[1] * s[0];
    if (fabs(den) <= 1e-300) return 0;
    double w[2] = {a[0] - p[0], a[1] - p[1]};
    *t = (w[0] * s[1] - w[1] * s[0]) / den;
    *u = (w[0] * r[1] - w[1] * r[0]) / den;
    return *t >= 0.0 && *t <= 1.0 && *u >= -1e-12 && *u <= 1.0 + 1e-12;
}

/* Exact crossing of the line through p (direction d) with CAD edge e near
 * arc length s (Newton on cross(d, C(s) - p) = 0). */
static sq_status boundary_exact(lay_repair *r, int e, const double p[2], const double d[2],
                                double *s, double xy[2], sq_error *err)
{
    double len = cad_face_edge_length(r->face, e);
    for (int it = 0; it < 30; it++) {
        double c[2], t[2];
        SQ_TRY(cad_face_edge_eval(r->face, e, *s, c, t, NULL, err));
        double f = d[0] * (c[1] - p[1]) - d[1] * (c[0] - p[0]);
        double df = d[0] * t[1] - d[1] * t[0];
        xy[0] = c[0];
        xy[1] = c[1];
        if (fabs(df) < 1e-14) break;
        double ds = -f / df;
        *s = fmin(fmax(*s + ds, 0.0), len);
        if (fabs(ds) < 1e-15 * (len + 1.0)) break;
    }
    return cad_face_edge_eval(r->face, e, *s, xy, NULL, NULL, err);
}

/* A cross branch at x nearest to direction d (unit); 1 if x is outside. */
int lay_branch(const lay_repair *r, const double x[2], int *elem, const double d[2], double out[2])
{
    if (!r->field) {
        out[0] = d[0];
        out[1] = d[1];
        return 0;
    }
    double th;
    if (r->field->direction(r->field->ctx, x, elem, &th)) return 1;
    double best = -2.0;
    for (int k = 0; k < 4; k++) {
        double a = th + k * M_PI / 2, c[2] = {cos(a), sin(a)};
        double dot = c[0] * d[0] + c[1] * d[1];
        if (dot > best) {
            best = dot;
            out[0] = c[0];
            out[1] = c[1];
        }
    }
    return 0;
}

static sq_status line_push(lay_line *l, const double p[2], sq_error *err)
{
    if (l->npts == l->cap) {
        int c = l->cap ? 2 * l->cap : 64;
        double *q = realloc(l->xy, 2 * (size_t)c * sizeof *q);
        if (!q) return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
        l->xy = q;
        l->cap = c;
    }
    l->xy[2 * l->npts] = p[0];
    l->xy[2 * l->npts + 1] = p[1];
    l->npts++;
    return SQ_OK;
}

/* Distance from x to the nearest separatrix of S, or `cap` if farther. */
static double sep_clearance(const sq_separatrix_set *S, const double x[2], double cap)
{
    double best = cap;
    for (int i = 0; i < S->n; i++) {
        const sq_separatrix *s = &S->s[i];
        for (int j = 0; j + 1 < s->npts; j++) {
            const double *a = &s->xy[2 * j], *b = a + 2;
            /* cheap reject: both ends farther than best along an axis */
            if ((a[0] - x[0] > best && b[0] - x[0] > best) ||
                (x[0] - a[0] > best && x[0] - b[0] > best) ||
                (a[1] - x[1] > best && b[1] - x[1] > best) ||
                (x[1] - a[1] > best && x[1] - b[1] > best))
                continue;
            double v[2] = {b[0] - a[0], b[1] - a[1]}, l2 = v[0] * v[0] + v[1] * v[1];
            double t = l2 > 0 ? ((x[0] - a[0]) * v[0] + (x[1] - a[1]) * v[1]) / l2 : 0.0;
            t = fmin(fmax(t, 0.0), 1.0);
            best = fmin(best, hypot(a[0] + t * v[0] - x[0], a[1] + t * v[1] - x[1]));
        }
    }
    return best;
}

/* The smallest repair step, as a fraction of the default one: a line
 * leaving a separatrix grows its step from this by 1.5 per step. */
#define MIN_STEP_FRACTION 0.02

/* An empty line (open end, no separatrix hit) at p0. */
static sq_status line_start(lay_line *out, const double p0[2], sq_error *err)
{
    memset(out, 0, sizeof *out);
    out->hit_sep = -1;
    out->end.kind = SQ_END_OPEN;
    out->end.id = -1;
    return line_push(out, p0, err);
}

/* The first thing segment x-xn (the step of length h after `len` along
 * the line) meets, boundary or separatrix (hits within `skip` of the
 * line's start ignored, on the boundary within `bskip`): if any (*hit), its point is appended to out and
 * out's end or hit_sep/hit_pos set. */
static sq_status first_hit(lay_repair *r, const double x[2], const double xn[2], double len,
                           double h, double skip, double bskip, lay_line *out, int *hit,
                           sq_error *err)
{
    const sq_separatrix_set *S = &r->L->seps;
    *hit = 1;
    /* first thing the step meets: boundary or a separatrix */
    double tbest = 2.0;
    int kind = 0, which = -1;
    double where = 0.0;
    for (int b = 0; b < r->nb; b++) {
        const double *q = &r->bxy[4 * b];
        double t, u;
        if (!lay_seg_seg(x, xn, q, q + 2, &t, &u)) continue;
        if (len + t * h <= bskip) continue;
        if (t < tbest) {
            tbest = t;
            kind = 1;
            which = b;
            where = u;
        }
    }
    for (int i = 0; i < S->n; i++) {
        const sq_separatrix *s = &S->s[i];
        for (int j = 0; j + 1 < s->npts; j++) {
            double t, u;
            if (!lay_seg_seg(x, xn, &s->xy[2 * j], &s->xy[2 * j + 2], &t, &u)) continue;
            if (len + t * h <= skip) continue;
            if (t < tbest) {
                tbest = t;
                kind = 2;
                which = i;
                where = j + fmin(fmax(u, 0.0), 1.0);
            }
        }
    }
    if (kind == 1) {
        int e = r->bedge[which];
        double s = r->bs[2 * which] + where * (r->bs[2 * which + 1] - r->bs[2 * which]);
        double dir[2] = {xn[0] - x[0], xn[1] - x[1]}, p[2];
        SQ_TRY(boundary_exact(r, e, x, dir, &s, p, err));
        double L = cad_face_edge_length(r->face, e), snap = 1e-6 * r->L->scale;
        out->end.kind = SQ_END_BOUNDARY;
        out->end.id = e;
        out->end.s = s;
        for (int v = 0; v < r->info->nvertices; v++) {
            const sq_vertex *V = &r->info->vertices[v];
            if ((V->edge_out == e && s <= snap) || (V->edge_in == e && s >= L - snap)) {
                out->end.kind = SQ_END_CORNER;
                out->end.id = v;
                p[0] = V->x;
                p[1] = V->y;
            }
        }
        return line_push(out, p, err);
    }
    if (kind == 2) {
        const sq_separatrix *s = &S->s[which];
        int j = (int)floor(where);
        if (j >= s->npts - 1) j = s->npts - 2;
        double u = where - j, p[2];
        p[0] = s->xy[2 * j] + u * (s->xy[2 * j + 2] - s->xy[2 * j]);
        p[1] = s->xy[2 * j + 1] + u * (s->xy[2 * j + 3] - s->xy[2 * j + 1]);
        out->hit_sep = which;
        out->hit_pos = where;
        return line_push(out, p, err);
    }
    *hit = 0;
    return SQ_OK;
}

/* Trace a field line from p0 in direction d0 (Heun steps, as Jezdimirović
 * §6.1) until it meets the boundary (end: foot or face vertex) or a
 * separatrix of the layout (hit_sep >= 0 at hit_pos).  Hits within `skip`
 * of p0 are ignored (the line leaves a node there). */
sq_status lay_trace_line(lay_repair *r, const double p0[2], const double d0[2], double skip,
                         lay_line *out, sq_error *err)
{
    SQ_TRY(line_start(out, p0, err));
    double x[2] = {p0[0], p0[1]}, d[2] = {d0[0], d0[1]}, len = 0.0;
    double nd = hypot(d[0], d[1]);
    d[0] /= nd;
    d[1] /= nd;
    int elem = -1;
    const sq_separatrix_set *S = &r->L->seps;
    /* the steps a line of maxlen takes at the default step, four times
     * over: small steps in thin patches may not run it out of time */
    const double budget = r->maxlen / r->step;
    const double per_step = (double)(r->nb + lay_set_points(S)) + LINE_STEP_WORK;
    for (long nstep = 0; len < r->maxlen && nstep < budget; nstep++) {
        if ((r->lwork += per_step) > LINE_WORK_MAX)
            return SQ_FAIL(err, SQ_ERR_LAYOUT,
                           "repair line from (%g, %g) stopped at the repair lines' work bound "
                           "(%g segment tests)",
                           p0[0], p0[1], LINE_WORK_MAX);
        /* a line that runs between separatrices closer than the step (a
         * thin patch along the boundary) steps at half its clearance, so
         * that it follows the field there instead of jumping across */
        double h = r->step, d1[2], d2[2], xn[2], clear = sep_clearance(S, x, r->step);
        if (clear < r->step) h = fmax(0.5 * clear, MIN_STEP_FRACTION * r->step);
        if (lay_branch(r, x, &elem, d, d1)) {
            d1[0] = d[0];
            d1[1] = d[1];
        }
        double xp[2] = {x[0] + h * d1[0], x[1] + h * d1[1]};
        int e2 = elem;
        if (lay_branch(r, xp, &e2, d1, d2)) {
            d2[0] = d1[0];
            d2[1] = d1[1];
        }
        double dd[2] = {0.5 * (d1[0] + d2[0]), 0.5 * (d1[1] + d2[1])};
        double n2 = hypot(dd[0], dd[1]);
        if (n2 < 1e-12) {
            dd[0] = d1[0];
            dd[1] = d1[1];
            n2 = 1.0;
        }
        xn[0] = x[0] + h * dd[0] / n2;
        xn[1] = x[1] + h * dd[1] / n2;
        int hit;
        /* near the start, boundary chords within a sagitta are no hit */
        SQ_TRY(first_hit(r, x, xn, len, h, skip, fmax(skip, 0.5 * r->step), out, &hit, err));
        if (hit) return SQ_OK;
        SQ_TRY(line_push(out, xn, err));
        d[0] = dd[0] / n2;
        d[1] = dd[1] / n2;
        x[0] = xn[0];
        x[1] = xn[1];
        len += h;
    }
    return SQ_FAIL(err, SQ_ERR_LAYOUT, "repair line from (%g, %g) longer than %g", p0[0], p0[1],
                   r->maxlen);
}

/* a ray is cut into pieces of a step, at most this many */
#define RAY_PIECES_MAX 4096

sq_status lay_ray_line(lay_repair *r, const double p0[2], const double d0[2], double skip,
                       lay_line *out, sq_error *err)
{
    SQ_TRY(line_start(out, p0, err));
    /* longer than the face's bounding box: a ray from inside meets its
     * boundary within it */
    double nd = hypot(d0[0], d0[1]), h = 2.0 * r->L->scale;
    double xn[2] = {p0[0] + h * d0[0] / nd, p0[1] + h * d0[1] / nd};
    r->lwork += (double)(r->nb + lay_set_points(&r->L->seps));
    int found;
    SQ_TRY(first_hit(r, p0, xn, 0.0, h, skip, skip, out, &found, err));
    if (!found)
        return SQ_FAIL(err, SQ_ERR_LAYOUT, "ray from (%g, %g) meets no boundary", p0[0], p0[1]);
    /* points a step apart, as a traced line's */
    double e[2] = {out->xy[2], out->xy[3]}, len = hypot(e[0] - p0[0], e[1] - p0[1]);
    int m = (int)fmin(ceil(len / r->step), RAY_PIECES_MAX);
    out->npts = 1;
    for (int k = 1; k < m; k++) {
        double q[2] = {p0[0] + (e[0] - p0[0]) * k / m, p0[1] + (e[1] - p0[1]) * k / m};
        SQ_TRY(line_push(out, q, err));
    }
    return line_push(out, e, err);
}

/* Finish a repair line from node `from`: append it to the set, ending on the
 * boundary, at a nearby inserted node, or at a new T-junction. */
sq_status lay_add_line(lay_repair *r, lay_line *ln, sq_sep_end start, sq_error *err)
{
    sq_layout *L = r->L;
    sq_sep_end end = ln->end;
    sq_status st = SQ_OK;
    if (ln->hit_sep >= 0) {
        const double *p = &ln->xy[2 * ln->npts - 2];
        /* an inserted node close by along that separatrix: end there */
        const sq_separatrix *s = &L->seps.s[ln->hit_sep];
        int snapped = 0;
        for (int w = 0; w < 2 && !snapped; w++) {
            const sq_sep_end *e = w ? &s->end : &s->start;
            if (e->kind != SQ_END_SINGULAR || L->role[e->id] == SQ_LROLE_INPUT) continue;
            const sq_singularity *q = &L->sing[e->id];
            if (hypot(q->x - p[0], q->y - p[1]) > 3.0 * r->step) continue;
            ln->xy[2 * ln->npts - 2] = q->x;
            ln->xy[2 * ln->npts - 1] = q->y;
            end = *e;
            L->sing[e->id].valence++;
            if (L->role[e->id] == SQ_LROLE_TJUNCTION) L->role[e->id] = SQ_LROLE_CROSSING;
            snapped = 1;
        }
        if (!snapped) {
            double pp[2] = {p[0], p[1]};
            SQ_TRY(lay_sing_push(L, pp[0], pp[1], 3, SQ_LROLE_TJUNCTION, err));
            end = (sq_sep_end){SQ_END_SINGULAR, L->nsing - 1, 0.0};
            SQ_TRY(lay_split_sep(L, ln->hit_sep, ln->hit_pos, pp, L->nsing - 1, err));
        }
    }
    st = lay_sep_push(&L->seps, ln->xy, ln->npts, start, end, err);
    return st;
}
