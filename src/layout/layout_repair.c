/* semquad — layout correction (layout.h design 4; Jezdimirović 2021 journal
 * §6, Marcon 2019 §3.4). */
#include "layout_internal.h"

#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct {
    sq_layout *L;
    const cad_face *face;
    const sq_face_info *info;
    const sq_cross_field *field;
    double step, maxlen, tol;
    int nb;        /* boundary sample segments */
    double *bxy;   /* 4*nb: segment ends */
    int *bedge;    /* per segment: CAD edge */
    double *bs;    /* 2*nb: arc lengths of the ends */
    lay_hit *hit;  /* the set's crossings (crossings()), nhit of them, */
    int nhit, hit_ok; /* valid while hit_ok: the set has not changed */
    int trials;    /* patch repairs tried (try_candidate), up to MAX_TRIALS */
    double work;   /* separatrix points the set-level passes visited (WORK_MAX) */
    double lwork;  /* segments the repair lines' steps tested (LINE_WORK_MAX) */
} rctx;

/* The repairs' work bound, in separatrix points visited by the set-level
 * passes (each finds every crossing of the set again): about 10 s of one
 * core for the densest sets (1.5e-5 s a point at 10^4 crossings); the
 * examples' layouts take less than 2.4e5 (T106), 0.02 to 1 s.  (A repair
 * line's steps have their own bound.)  A bound on the work, not on the
 * clock, keeps the answer the same on every machine. */
#define WORK_MAX 1e6
/* The repair lines' work bound, in segments (separatrix and boundary) their
 * steps tested: each step tests every one, and a line in a thin patch (a
 * tiny edge's) steps at MIN_STEP_FRACTION of the default step, so lines
 * within their step budget could still take minutes (stress corpus 0311, a
 * 1.7e-6 edge: over 49 s of CPU, 1e10 tests).  About 10 s of one core, as
 * WORK_MAX (5 ns a test): of the stress corpus's 131 layouts that succeed
 * (2026-11-26), the most took 1.3e8 (0100), the examples' 1.3e5 (annulus),
 * T106's none.  A bound on the work, not on the clock, as WORK_MAX. */
#define LINE_WORK_MAX 2e9

/* Points of the set. */
static long set_points(const sq_separatrix_set *S)
{
    long n = 0;
    for (int i = 0; i < S->n; i++) n += S->s[i].npts;
    return n;
}

/* The crossings of the separatrix set, found once per state of the set
 * (the repairs tried in turn on an unchanged set share them). */
static sq_status crossings(rctx *r, sq_error *err)
{
    if (r->hit_ok) return SQ_OK;
    free(r->hit);
    r->hit = NULL;
    r->nhit = 0;
    SQ_TRY(lay_intersections(&r->L->seps, r->tol, &r->hit, &r->nhit, err));
    r->hit_ok = 1;
    return SQ_OK;
}

/* ---- geometry helpers --------------------------------------------------- */

static sq_status sample_boundary(rctx *r, sq_error *err)
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
static int seg_seg(const double p[2], const double q[2], const double a[2], const double b[2],
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
static sq_status boundary_exact(rctx *r, int e, const double p[2], const double d[2], double *s,
                                double xy[2], sq_error *err)
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
static int branch(const rctx *r, const double x[2], int *elem, const double d[2], double out[2])
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

typedef struct {
    int npts, cap;
    double *xy;
    sq_sep_end end;
    int hit_sep;     /* SQ_END_SEPARATRIX-like end: separatrix and position */
    double hit_pos;
} line;

static sq_status line_push(line *l, const double p[2], sq_error *err)
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

/* Trace a field line from p0 in direction d0 (Heun steps, as Jezdimirović
 * §6.1) until it meets the boundary (end: foot or face vertex) or a
 * separatrix of the layout (hit_sep >= 0 at hit_pos).  Hits within `skip`
 * of p0 are ignored (the line leaves a node there). */
static sq_status trace_line(rctx *r, const double p0[2], const double d0[2], double skip,
                            line *out, sq_error *err)
{
    memset(out, 0, sizeof *out);
    out->hit_sep = -1;
    out->end.kind = SQ_END_OPEN;
    out->end.id = -1;
    SQ_TRY(line_push(out, p0, err));
    double x[2] = {p0[0], p0[1]}, d[2] = {d0[0], d0[1]}, len = 0.0;
    double nd = hypot(d[0], d[1]);
    d[0] /= nd;
    d[1] /= nd;
    int elem = -1;
    const sq_separatrix_set *S = &r->L->seps;
    /* the steps a line of maxlen takes at the default step, four times
     * over: small steps in thin patches may not run it out of time */
    const double budget = r->maxlen / r->step;
    const double per_step = (double)(r->nb + set_points(S));
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
        if (branch(r, x, &elem, d, d1)) {
            d1[0] = d[0];
            d1[1] = d[1];
        }
        double xp[2] = {x[0] + h * d1[0], x[1] + h * d1[1]};
        int e2 = elem;
        if (branch(r, xp, &e2, d1, d2)) {
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
        /* first thing the step meets: boundary or a separatrix */
        double tbest = 2.0;
        int kind = 0, which = -1;
        double where = 0.0;
        for (int b = 0; b < r->nb; b++) {
            const double *q = &r->bxy[4 * b];
            double t, u;
            if (!seg_seg(x, xn, q, q + 2, &t, &u)) continue;
            if (len + t * h <= fmax(skip, 0.5 * r->step)) continue; /* chords: sagitta */
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
                if (!seg_seg(x, xn, &s->xy[2 * j], &s->xy[2 * j + 2], &t, &u)) continue;
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

/* Nearest position (segment + t) on separatrix k to p. */
static double nearest_pos(const sq_separatrix *s, const double p[2], double *dist)
{
    double best = HUGE_VAL, pos = 0.0;
    for (int j = 0; j + 1 < s->npts; j++) {
        const double *a = &s->xy[2 * j], *b = a + 2;
        double v[2] = {b[0] - a[0], b[1] - a[1]}, l2 = v[0] * v[0] + v[1] * v[1];
        double t = l2 > 0 ? ((p[0] - a[0]) * v[0] + (p[1] - a[1]) * v[1]) / l2 : 0.0;
        t = fmin(fmax(t, 0.0), 1.0);
        double d = hypot(a[0] + t * v[0] - p[0], a[1] + t * v[1] - p[1]);
        if (d < best) {
            best = d;
            pos = j + t;
        }
    }
    if (dist) *dist = best;
    return pos;
}

/* Split separatrix k at position pos (point p) into two joined at singular
 * point `node`; the pieces replace k (k: first part, appended: second). */
static sq_status split_sep(sq_layout *L, int k, double pos, const double p[2], int node,
                           sq_error *err)
{
    sq_separatrix *s = &L->seps.s[k];
    int j = (int)floor(pos);
    if (j >= s->npts - 1) j = s->npts - 2;
    if (j < 0) j = 0;
    int n2 = s->npts - j; /* p + points j+1..npts-1 */
    double *b = malloc(2 * (size_t)n2 * sizeof *b);
    if (!b) return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    b[0] = p[0];
    b[1] = p[1];
    memcpy(b + 2, &s->xy[2 * (j + 1)], 2 * (size_t)(n2 - 1) * sizeof *b);
    sq_sep_end mid = {SQ_END_SINGULAR, node, 0.0}, oldend = s->end;
    sq_status st = lay_sep_push(&L->seps, b, n2, mid, oldend, err);
    free(b);
    if (st != SQ_OK) return st;
    s = &L->seps.s[k]; /* the set may have moved */
    s->npts = j + 2;
    s->xy[2 * (j + 1)] = p[0];
    s->xy[2 * (j + 1) + 1] = p[1];
    s->end = mid;
    return SQ_OK;
}

static int same_end(const sq_sep_end *a, const sq_sep_end *b, double tol)
{
    if (a->kind != b->kind || a->id != b->id) return 0;
    if (a->kind == SQ_END_BOUNDARY) return fabs(a->s - b->s) <= tol;
    return a->kind != SQ_END_OPEN;
}

/* ---- repairs on the separatrix set ------------------------------------- */

/* Duplicated separatrices: same ends, every point of one within 2 % of the
 * face size of the other (Jezdimirović §6.1, Fig. 15). */
static sq_status remove_duplicate(rctx *r, int *done, sq_error *err)
{
    (void)err;
    sq_separatrix_set *S = &r->L->seps;
    double close = 0.02 * r->L->scale, tol = 1e-6 * r->L->scale;
    for (int a = 0; a < S->n; a++)
        for (int b = a + 1; b < S->n; b++) {
            const sq_separatrix *A = &S->s[a], *B = &S->s[b];
            int same = (same_end(&A->start, &B->start, tol) && same_end(&A->end, &B->end, tol)) ||
                       (same_end(&A->start, &B->end, tol) && same_end(&A->end, &B->start, tol));
            if (!same) continue;
            /* stop at the first point farther than `close` (most pairs
             * with the same ends are not duplicates) */
            double worst = 0.0, d;
            for (int j = 0; j < A->npts && worst <= close; j++) {
                nearest_pos(B, &A->xy[2 * j], &d);
                worst = fmax(worst, d);
            }
            for (int j = 0; j < B->npts && worst <= close; j++) {
                nearest_pos(A, &B->xy[2 * j], &d);
                worst = fmax(worst, d);
            }
            if (worst > close) continue;
            /* keep a merged one if there is one */
            lay_sep_remove(S, A->merged && !B->merged ? b : a);
            r->L->stats.duplicates_removed++;
            *done = 1;
            return SQ_OK;
        }
    return SQ_OK;
}

/* Ends that stop on another separatrix (open ends the graph finds on a
 * curve, the tracer's SQ_END_SEPARATRIX) become T-junction nodes. */
static sq_status make_tjunction(rctx *r, int *done, sq_error *err)
{
    sq_layout *L = r->L;
    SQ_TRY(crossings(r, err));
    const lay_hit *h = r->hit;
    const int nh = r->nhit;
    sq_status st = SQ_OK;
    for (int k = 0; k < nh && !*done; k++) {
        int stem = -1, other = -1, end = -1;
        double pos = 0;
        if (h[k].enda >= 0 && h[k].endb < 0) {
            stem = h[k].a, other = h[k].b, end = h[k].enda, pos = h[k].pb;
        } else if (h[k].endb >= 0 && h[k].enda < 0) {
            stem = h[k].b, other = h[k].a, end = h[k].endb, pos = h[k].pa;
        } else {
            continue;
        }
        sq_separatrix *s = &L->seps.s[stem];
        sq_sep_end *e = end ? &s->end : &s->start;
        if (e->kind != SQ_END_OPEN && e->kind != SQ_END_SEPARATRIX) continue;
        double p[2] = {h[k].x, h[k].y};
        st = lay_sing_push(L, p[0], p[1], 3, SQ_LROLE_TJUNCTION, err);
        if (st != SQ_OK) break;
        e->kind = SQ_END_SINGULAR;
        e->id = L->nsing - 1;
        st = split_sep(L, other, pos, p, L->nsing - 1, err);
        *done = 1;
    }
    return st;
}

/* Limit cycles: an open separatrix, or one crossing itself or another one
 * twice; cut at its first near-orthogonal crossing (else the most
 * orthogonal one), leaving a T-junction (Jezdimirović §6.1, Fig. 16). */
static sq_status cut_limit_cycle(rctx *r, int *done, sq_error *err)
{
    sq_layout *L = r->L;
    SQ_TRY(crossings(r, err));
    const lay_hit *h = r->hit;
    const int nh = r->nhit;
    sq_status st = SQ_OK;
    int n = L->seps.n;
    /* seen[o] == k + 1: k already crosses o (one pass over the crossings
     * per separatrix, not one per pair of them: faces with many holes have
     * 10^4 crossings before the repairs) */
    int *seen = calloc((size_t)n + 1, sizeof *seen);
    if (!seen) return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    for (int k = 0; k < n && !*done && st == SQ_OK; k++) {
        const sq_separatrix *s = &L->seps.s[k];
        int lc = s->end.kind == SQ_END_OPEN;
        for (int a = 0; a < nh && !lc; a++) {
            if (h[a].enda >= 0 || h[a].endb >= 0 || (h[a].a != k && h[a].b != k)) continue;
            int o = h[a].a == k ? h[a].b : h[a].a;
            lc = o == k || seen[o] == k + 1;
            seen[o] = k + 1;
        }
        if (!lc) continue;
        /* the cut: first crossing along k with |cos| < 0.5, else the most
         * orthogonal; the cut point's position on k and on the other */
        int best = -1, good = -1;
        double bestpos = HUGE_VAL, goodpos = HUGE_VAL, bestcos = 2.0;
        for (int a = 0; a < nh; a++) {
            if (h[a].enda >= 0 || h[a].endb >= 0) continue;
            if (h[a].a != k && h[a].b != k) continue;
            double posk = h[a].a == k ? h[a].pa : h[a].pb;
            if (h[a].a == k && h[a].b == k) posk = fmax(h[a].pa, h[a].pb);
            if (h[a].cosang < 0.5 && posk < goodpos) {
                goodpos = posk;
                good = a;
            }
            if (h[a].cosang < bestcos) {
                bestcos = h[a].cosang;
                best = a;
                bestpos = posk;
            }
        }
        int c = good >= 0 ? good : best;
        double posk = good >= 0 ? goodpos : bestpos;
        if (c < 0) continue; /* open but crossing nothing: left for the report */
        int other = h[c].a == k ? h[c].b : h[c].a;
        double poso = h[c].a == k ? h[c].pb : h[c].pa;
        if (other == k) poso = fmin(h[c].pa, h[c].pb);
        double p[2] = {h[c].x, h[c].y};
        st = lay_sing_push(L, p[0], p[1], 3, SQ_LROLE_TJUNCTION, err);
        if (st != SQ_OK) break;
        int node = L->nsing - 1;
        /* truncate k at posk */
        sq_separatrix *sk = &L->seps.s[k];
        int j = (int)floor(posk);
        if (j >= sk->npts - 1) j = sk->npts - 2;
        sk->npts = j + 2;
        sk->xy[2 * (j + 1)] = p[0];
        sk->xy[2 * (j + 1) + 1] = p[1];
        sk->end = (sq_sep_end){SQ_END_SINGULAR, node, 0.0};
        st = split_sep(L, other, poso, p, node, err);
        L->stats.limit_cycles_cut++;
        *done = 1;
    }
    free(seen);
    return st;
}

/* Two separatrices crossing once: a regular node of valence 4 where both
 * are split (the patches around it are checked by their angles). */
static sq_status split_crossing(rctx *r, int *done, sq_error *err)
{
    sq_layout *L = r->L;
    SQ_TRY(crossings(r, err));
    const lay_hit *h = r->hit;
    const int nh = r->nhit;
    sq_status st = SQ_OK;
    for (int k = 0; k < nh && !*done; k++) {
        if (h[k].enda >= 0 || h[k].endb >= 0 || h[k].a == h[k].b) continue;
        double p[2] = {h[k].x, h[k].y};
        st = lay_sing_push(L, p[0], p[1], 4, SQ_LROLE_CROSSING, err);
        if (st != SQ_OK) break;
        int node = L->nsing - 1;
        int a = h[k].a, b = h[k].b;
        double pa = h[k].pa, pb = h[k].pb;
        st = split_sep(L, a, pa, p, node, err);
        if (st == SQ_OK) st = split_sep(L, b, pb, p, node, err);
        L->stats.crossings_split++;
        *done = 1;
    }
    return st;
}

/* Direction of separatrix s leaving node position p (at its start or end). */
static void leave_dir(const sq_separatrix *s, int at_end, double d[2], double scale)
{
    int n = s->npts;
    const double *p0 = at_end ? &s->xy[2 * n - 2] : s->xy;
    d[0] = d[1] = 0.0;
    for (int j = 1; j < n; j++) {
        const double *q = &s->xy[2 * (at_end ? n - 1 - j : j)];
        d[0] = q[0] - p0[0];
        d[1] = q[1] - p0[1];
        if (hypot(d[0], d[1]) > 1e-6 * scale) break;
    }
    double l = hypot(d[0], d[1]);
    if (l > 0) {
        d[0] /= l;
        d[1] /= l;
    }
}

/* Finish a repair line from node `from`: append it to the set, ending on the
 * boundary, at a nearby inserted node, or at a new T-junction. */
static sq_status add_line(rctx *r, line *ln, sq_sep_end start, sq_error *err)
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
            SQ_TRY(split_sep(L, ln->hit_sep, ln->hit_pos, pp, L->nsing - 1, err));
        }
    }
    st = lay_sep_push(&L->seps, ln->xy, ln->npts, start, end, err);
    return st;
}

/* T-junction repair: continue the stem across the separatrix it ends on,
 * along the field, to the boundary or the next separatrix (Jezdimirović
 * §6.3, Fig. 17); the T becomes a regular valence-4 node. */
static sq_status repair_tjunction(rctx *r, int *done, sq_error *err)
{
    sq_layout *L = r->L;
    for (int t = 0; t < L->nsing && !*done; t++) {
        if (L->role[t] != SQ_LROLE_TJUNCTION) continue;
        /* the three separatrix ends at t; the stem is the one not in the most
         * opposite pair */
        int ids[8], ends[8], m = 0;
        for (int k = 0; k < L->seps.n && m < 8; k++)
            for (int w = 0; w < 2 && m < 8; w++) {
                const sq_sep_end *e = w ? &L->seps.s[k].end : &L->seps.s[k].start;
                if (e->kind == SQ_END_SINGULAR && e->id == t) {
                    ids[m] = k;
                    ends[m++] = w;
                }
            }
        if (m != 3) continue;
        double d[3][2];
        for (int k = 0; k < 3; k++) leave_dir(&L->seps.s[ids[k]], ends[k], d[k], L->scale);
        int stem = 0;
        double best = 2.0;
        for (int k = 0; k < 3; k++) {
            const double *a = d[(k + 1) % 3], *b = d[(k + 2) % 3];
            double dot = a[0] * b[0] + a[1] * b[1];
            if (dot < best) {
                best = dot;
                stem = k;
            }
        }
        double dir[2] = {-d[stem][0], -d[stem][1]}, p[2] = {L->sing[t].x, L->sing[t].y};
        line ln;
        sq_status st = trace_line(r, p, dir, 1e-6 * L->scale, &ln, err);
        if (st == SQ_OK) st = add_line(r, &ln, (sq_sep_end){SQ_END_SINGULAR, t, 0.0}, err);
        free(ln.xy);
        if (st != SQ_OK) return st;
        L->role[t] = SQ_LROLE_CROSSING;
        L->sing[t].valence = 4;
        L->stats.t_junctions++;
        *done = 1;
    }
    return SQ_OK;
}

/* ---- repairs on patches ------------------------------------------------- */

/* Arc-length midpoint of the half-edges half[a..b) of patch P: the edge and
 * the fraction along it (from its n0). */
static void chain_mid(const sq_layout *L, const sq_layout_patch *P, int a, int b, int *edge,
                      double *frac)
{
    double tot = 0.0;
    for (int k = a; k < b; k++) tot += L->edges[P->half[k % P->nhalf].edge].length;
    double acc = 0.0;
    for (int k = a; k < b; k++) {
        const sq_layout_half *h = &P->half[k % P->nhalf];
        double l = L->edges[h->edge].length;
        if (acc + l >= 0.5 * tot || k == b - 1) {
            double f = l > 0 ? (0.5 * tot - acc) / l : 0.5;
            *edge = h->edge;
            *frac = h->reversed ? 1.0 - f : f;
            return;
        }
        acc += l;
    }
}

/* Area centroid of the patch's outer cycle (Green's theorem on its
 * polylines); 0 if the cycle has no area. */
static int patch_centroid(const sq_layout *L, const sq_layout_patch *P, double cen[2])
{
    int end = P->ncycles > 0 ? P->cycle_start[1] : P->nhalf;
    double A = 0.0, cx = 0.0, cy = 0.0;
    for (int k = 0; k < end; k++) {
        const sq_layout_edge *E = &L->edges[P->half[k].edge];
        for (int j = 0; j + 1 < E->npts; j++) {
            int j0 = P->half[k].reversed ? E->npts - 1 - j : j;
            int j1 = P->half[k].reversed ? j0 - 1 : j0 + 1;
            const double *u = &E->xy[2 * j0], *v = &E->xy[2 * j1];
            double c = u[0] * v[1] - v[0] * u[1];
            A += c;
            cx += (u[0] + v[0]) * c;
            cy += (u[1] + v[1]) * c;
        }
    }
    if (!(fabs(A) > 0)) return 0;
    cen[0] = cx / (3.0 * A);
    cen[1] = cy / (3.0 * A);
    return 1;
}

/* Arc-length midpoint of side k of patch P (corner k to corner k+1): the
 * edge, the fraction along it and the point. */
static sq_status side_mid(rctx *r, const sq_layout_patch *P, int k, int *edge, double *frac,
                          double xy[2], sq_error *err)
{
    int a = P->corner_half[k], b = P->corner_half[(k + 1) % P->ncorners];
    if (b <= a) b += P->nhalf;
    chain_mid(r->L, P, a, b, edge, frac);
    return sq_layout_edge_point(r->L, r->face, *edge, *frac, xy, err);
}

/* Separatrix from inserted node M along the path xy[np] (each segment cut
 * into 16 pieces), ending in `end`. */
static sq_status path_sep(sq_layout *L, int M, const double *xy, int np, sq_sep_end end,
                          sq_error *err)
{
    enum { PIECES = 16 };
    int n = (np - 1) * PIECES + 1;
    double *q = malloc(2 * (size_t)n * sizeof *q);
    if (!q) return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    for (int i = 0; i + 1 < np; i++)
        for (int j = 0; j < PIECES + (i + 2 == np); j++) {
            double t = (double)j / PIECES;
            const double *a = &xy[2 * i], *b = a + 2;
            q[2 * (i * PIECES + j)] = a[0] + t * (b[0] - a[0]);
            q[2 * (i * PIECES + j) + 1] = a[1] + t * (b[1] - a[1]);
        }
    sq_status st = lay_sep_push(&L->seps, q, n, (sq_sep_end){SQ_END_SINGULAR, M, 0.0}, end, err);
    free(q);
    return st;
}

/* Straight separatrix from inserted node M (at a) to b, ending in `end`. */
static sq_status straight_sep(sq_layout *L, int M, const double a[2], const double b[2],
                              sq_sep_end end, sq_error *err)
{
    double xy[4] = {a[0], a[1], b[0], b[1]};
    return path_sep(L, M, xy, 2, end, err);
}

/* A spoke from inserted node M along path[np] (from M to point p on layout
 * edge `edge` at fraction frac; NULL: straight from cen): on the boundary it
 * ends in a foot, on a separatrix in a new T-junction, repaired next (the
 * "patches influenced" of Jezdimirović §6.3). */
static sq_status add_spoke(rctx *r, int M, const double cen[2], const double *path, int np,
                           int edge, double frac, const double p[2], sq_error *err)
{
    sq_layout *L = r->L;
    const sq_layout_edge *E = &L->edges[edge];
    sq_sep_end end;
    if (E->cad_edge >= 0) {
        end = (sq_sep_end){SQ_END_BOUNDARY, E->cad_edge, E->s0 + frac * (E->s1 - E->s0)};
    } else {
        double q[2] = {p[0], p[1]}, dist;
        /* the edge's separatrix, unless an earlier spoke split it before q */
        int sep = E->sep;
        double pos = nearest_pos(&L->seps.s[sep], q, &dist);
        for (int k = 0; k < L->seps.n && dist > r->tol; k++) {
            double d, ps = nearest_pos(&L->seps.s[k], q, &d);
            if (d < dist) sep = k, pos = ps, dist = d;
        }
        SQ_TRY(lay_sing_push(L, q[0], q[1], 3, SQ_LROLE_TJUNCTION, err));
        end = (sq_sep_end){SQ_END_SINGULAR, L->nsing - 1, 0.0};
        SQ_TRY(split_sep(L, sep, pos, q, L->nsing - 1, err));
    }
    if (path) return path_sep(L, M, path, np, end, err);
    return straight_sep(L, M, cen, p, end, err);
}

/* ---- the n-quad split: a centre joined to the sides' midpoints ----------- */

/* Distance from p to the closed polygon ring[n]. */
static double ring_dist(const double *ring, int n, const double p[2])
{
    double best = HUGE_VAL;
    for (int i = 0; i < n; i++) {
        const double *a = &ring[2 * i], *b = &ring[2 * ((i + 1) % n)];
        double v[2] = {b[0] - a[0], b[1] - a[1]}, l2 = v[0] * v[0] + v[1] * v[1];
        double t = l2 > 0 ? ((p[0] - a[0]) * v[0] + (p[1] - a[1]) * v[1]) / l2 : 0.0;
        t = fmin(fmax(t, 0.0), 1.0);
        best = fmin(best, hypot(a[0] + t * v[0] - p[0], a[1] + t * v[1] - p[1]));
    }
    return best;
}

/* Does segment a-b meet the closed polygon ring[n] farther than tol from b? */
static int seg_leaves(const double *ring, int n, const double a[2], const double b[2], double tol)
{
    for (int i = 0; i < n; i++) {
        const double *p = &ring[2 * i], *q = &ring[2 * ((i + 1) % n)];
        double t, u;
        if (!seg_seg(a, b, p, q, &t, &u)) continue;
        double x = a[0] + t * (b[0] - a[0]), y = a[1] + t * (b[1] - a[1]);
        if (hypot(x - b[0], y - b[1]) > tol) return 1;
    }
    return 0;
}

/* Polylines a[na] and b[nb] meet other than at their common first point? */
static int paths_cross(const double *a, int na, const double *b, int nb, double tol)
{
    for (int i = 0; i + 1 < na; i++)
        for (int j = 0; j + 1 < nb; j++) {
            double t, u;
            if (!seg_seg(&a[2 * i], &a[2 * i + 2], &b[2 * j], &b[2 * j + 2], &t, &u)) continue;
            double x = a[2 * i] + t * (a[2 * i + 2] - a[2 * i]);
            double y = a[2 * i + 1] + t * (a[2 * i + 3] - a[2 * i + 1]);
            if (hypot(x - a[0], y - a[1]) > tol) return 1;
        }
    return 0;
}

/* The patch's outer ring with the n side points sp[n] inserted (each on the
 * ring segment nearest it, in walking order); at[k]: the index of side
 * point k in *ring. */
static sq_status ring_with_points(const sq_layout *L, const sq_layout_patch *P, const double *sp,
                                  int n, double **ring, int *nring, int *at, sq_error *err)
{
    int m;
    double *poly = lay_cycle_polygon(L, P->half, P->cycle_start[1], &m);
    double *out = malloc(2 * (size_t)(m + n) * sizeof *out);
    int *seg = malloc((size_t)(n > 0 ? n : 1) * sizeof *seg);
    double *par = malloc((size_t)(n > 0 ? n : 1) * sizeof *par);
    if (!poly || !out || !seg || !par) {
        free(poly), free(out), free(seg), free(par);
        return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    }
    for (int k = 0; k < n; k++) {
        double best = HUGE_VAL;
        for (int i = 0; i < m; i++) {
            const double *a = &poly[2 * i], *b = &poly[2 * ((i + 1) % m)];
            double v[2] = {b[0] - a[0], b[1] - a[1]}, l2 = v[0] * v[0] + v[1] * v[1];
            double t = l2 > 0 ? ((sp[2 * k] - a[0]) * v[0] + (sp[2 * k + 1] - a[1]) * v[1]) / l2
                              : 0.0;
            t = fmin(fmax(t, 0.0), 1.0);
            double d = hypot(a[0] + t * v[0] - sp[2 * k], a[1] + t * v[1] - sp[2 * k + 1]);
            if (d < best) best = d, seg[k] = i, par[k] = t;
        }
    }
    int c = 0;
    for (int i = 0; i < m; i++) {
        out[2 * c] = poly[2 * i];
        out[2 * c + 1] = poly[2 * i + 1];
        c++;
        /* the points on segment i, by their parameter (n is small) */
        double last = -1.0;
        for (;;) {
            int pick = -1;
            for (int k = 0; k < n; k++)
                if (seg[k] == i && par[k] > last && (pick < 0 || par[k] < par[pick])) pick = k;
            if (pick < 0) break;
            last = par[pick];
            out[2 * c] = sp[2 * pick];
            out[2 * c + 1] = sp[2 * pick + 1];
            at[pick] = c++;
        }
    }
    free(poly), free(seg), free(par);
    *ring = out;
    *nring = c;
    return SQ_OK;
}

typedef struct {
    long key;
    int e; /* 3 * triangle + edge */
} edge_key;

static int cmp_edge_key(const void *a, const void *b)
{
    const edge_key *x = a, *y = b;
    if (x->key != y->key) return x->key < y->key ? -1 : 1;
    return x->e - y->e;
}

/* nb[3t + j]: the triangle across edge j (vertices j, j+1) of triangle t,
 * -1 on the rim; malloc'ed, NULL when out of memory. */
static int *tri_neighbours(const cad_cdt_output *o)
{
    size_t n3 = 3 * (size_t)(o->ntris > 0 ? o->ntris : 1);
    int *nb = malloc(n3 * sizeof *nb);
    edge_key *k = malloc(n3 * sizeof *k);
    if (!nb || !k) {
        free(nb), free(k);
        return NULL;
    }
    long nv = o->nverts;
    for (int e = 0; e < 3 * o->ntris; e++) {
        long a = o->tri[e], b = o->tri[3 * (e / 3) + (e % 3 + 1) % 3];
        k[e] = (edge_key){a < b ? a * nv + b : b * nv + a, e};
        nb[e] = -1;
    }
    qsort(k, (size_t)(3 * o->ntris), sizeof *k, cmp_edge_key);
    for (int i = 0; i + 1 < 3 * o->ntris; i++)
        if (k[i].key == k[i + 1].key) {
            nb[k[i].e] = k[i + 1].e / 3;
            nb[k[i + 1].e] = k[i].e / 3;
        }
    free(k);
    return nb;
}

/* A path inside the ring from c (in triangle t0) to triangulation vertex
 * v: through the midpoints of the edges the breadth-first triangle walk
 * crosses, then shortened wherever a straight piece stays inside.  *path
 * malloc'ed (*np points, c first, v last). */
static sq_status cdt_path(const cad_cdt_output *o, const int *nb, const double *ring, int nring,
                          const double c[2], int t0, int v, double tol, double **path, int *np,
                          sq_error *err)
{
    int nt = o->ntris;
    int *from = malloc((size_t)nt * sizeof *from), *queue = malloc((size_t)nt * sizeof *queue);
    double *raw = malloc(2 * (size_t)(nt + 2) * sizeof *raw);
    if (!from || !queue || !raw) {
        free(from), free(queue), free(raw);
        return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    }
    for (int t = 0; t < nt; t++) from[t] = -2;
    int head = 0, tail = 0, goal = -1;
    from[t0] = -1;
    queue[tail++] = t0;
    while (head < tail && goal < 0) {
        int t = queue[head++];
        for (int j = 0; j < 3; j++) {
            if (o->tri[3 * t + j] == v) goal = t;
            int u = nb[3 * t + j];
            if (u >= 0 && from[u] == -2) {
                from[u] = t;
                queue[tail++] = u;
            }
        }
    }
    int n = 0;
    if (goal >= 0) { /* v, the crossed edges' midpoints back to t0, c */
        raw[2 * n] = o->xy[2 * v], raw[2 * n + 1] = o->xy[2 * v + 1], n++;
        for (int t = goal; from[t] >= 0; t = from[t]) {
            int s = from[t];
            for (int j = 0; j < 3; j++)
                if (nb[3 * s + j] == t) {
                    int a = o->tri[3 * s + j], b = o->tri[3 * s + (j + 1) % 3];
                    raw[2 * n] = 0.5 * (o->xy[2 * a] + o->xy[2 * b]);
                    raw[2 * n + 1] = 0.5 * (o->xy[2 * a + 1] + o->xy[2 * b + 1]);
                    n++;
                    break;
                }
        }
        raw[2 * n] = c[0], raw[2 * n + 1] = c[1], n++;
    }
    free(from), free(queue);
    if (goal < 0) {
        free(raw);
        return SQ_FAIL(err, SQ_ERR_LAYOUT, "no path inside the patch to a side");
    }
    /* reverse to c ... v, keeping only the points a straight piece needs */
    double *out = malloc(2 * (size_t)n * sizeof *out);
    if (!out) {
        free(raw);
        return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    }
    int m = 0, i = n - 1;
    out[2 * m] = raw[2 * i], out[2 * m + 1] = raw[2 * i + 1], m++;
    while (i > 0) {
        int j = i - 1;
        while (j > 0 && !seg_leaves(ring, nring, &raw[2 * i], &raw[2 * (j - 1)],
                                    j - 1 == 0 ? tol : 0.0))
            j--;
        out[2 * m] = raw[2 * j], out[2 * m + 1] = raw[2 * j + 1], m++;
        i = j;
    }
    free(raw);
    *path = out;
    *np = m;
    return SQ_OK;
}

/* The triangle holding p (the nearest centroid's when none does). */
static int tri_holding(const cad_cdt_output *o, const double p[2])
{
    int best = 0;
    double bd = HUGE_VAL;
    for (int t = 0; t < o->ntris; t++) {
        const double *a = &o->xy[2 * o->tri[3 * t]], *b = &o->xy[2 * o->tri[3 * t + 1]],
                     *c = &o->xy[2 * o->tri[3 * t + 2]];
        double d1 = (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0]);
        double d2 = (c[0] - b[0]) * (p[1] - b[1]) - (c[1] - b[1]) * (p[0] - b[0]);
        double d3 = (a[0] - c[0]) * (p[1] - c[1]) - (a[1] - c[1]) * (p[0] - c[0]);
        if (d1 >= 0 && d2 >= 0 && d3 >= 0) return t;
        double d = hypot((a[0] + b[0] + c[0]) / 3 - p[0], (a[1] + b[1] + c[1]) / 3 - p[1]);
        if (d < bd) bd = d, best = t;
    }
    return best;
}

/* The centre of an n-quad split when the centroid will not do: among the
 * triangles' circumcentres (Voronoi vertices of the ring's points, on its
 * medial axis) inside the ring, else their centroids, the one that sees
 * the most side points sp[n] along straight spokes, the farthest from the
 * ring among those (the largest empty circle when it sees them all). */
static void far_point(const cad_cdt_output *o, const double *ring, int nring, const double *sp,
                      int n, double tol, double cen[2])
{
    double best = -1.0;
    int bestseen = -1;
    for (int t = 0; t < o->ntris; t++) {
        const double *a = &o->xy[2 * o->tri[3 * t]], *b = &o->xy[2 * o->tri[3 * t + 1]],
                     *c = &o->xy[2 * o->tri[3 * t + 2]];
        double bx = b[0] - a[0], by = b[1] - a[1], cx = c[0] - a[0], cy = c[1] - a[1];
        double d = 2.0 * (bx * cy - by * cx), q[2];
        q[0] = a[0] + (cy * (bx * bx + by * by) - by * (cx * cx + cy * cy)) / d;
        q[1] = a[1] + (bx * (cx * cx + cy * cy) - cx * (bx * bx + by * by)) / d;
        if (!(fabs(d) > 0) || !lay_poly_contains(ring, nring, q)) {
            q[0] = (a[0] + b[0] + c[0]) / 3.0;
            q[1] = (a[1] + b[1] + c[1]) / 3.0;
        }
        /* straight spokes seen, and all of them when no two consecutive
         * ones are within SQ_LAYOUT_CORNER_TOL_DEG of straight (else the
         * centre is no corner of the quad between them) */
        int seen = 0;
        double ang[16];
        for (int k = 0; k < n; k++) {
            seen += !seg_leaves(ring, nring, q, &sp[2 * k], tol);
            if (k < 16) ang[k] = atan2(sp[2 * k + 1] - q[1], sp[2 * k] - q[0]);
        }
        for (int k = 0; k < n && k < 16 && seen == n; k++) {
            double gap = remainder(ang[(k + 1) % n] - ang[k], 2.0 * M_PI);
            if (gap < 0) gap += 2.0 * M_PI;
            if (gap > M_PI - SQ_LAYOUT_CORNER_TOL_DEG * M_PI / 180.0) seen = n - 1;
        }
        if (seen < bestseen) continue;
        double dist = ring_dist(ring, nring, q);
        if (seen > bestseen || dist > best) {
            best = dist;
            bestseen = seen;
            cen[0] = q[0];
            cen[1] = q[1];
        }
    }
}

/* the n-quad split's triangulation: at most this many points per point of
 * the patch's ring (its own points and CGAL's splits of encroached sides) */
#define SPLIT_CDT_POINTS_PER_RING_POINT 8

/* n-quad split of patch p (one cycle, n corners; Marcon §3.4's midpoint
 * division for n = 3): a node of valence n joined to the arc-length
 * midpoints of the n sides, so that the patch becomes n quads.  The node
 * is the area centroid when straight spokes from it stay inside the
 * patch, else a point of the patch's medial axis (far_point); a spoke that
 * cannot be straight follows the patch's constrained Delaunay
 * triangulation (only if `bent`: else SQ_ERR_LAYOUT, as when the spokes
 * would cross). */
static sq_status split_centre(rctx *r, int p, int bent, sq_error *err)
{
    sq_layout *L = r->L;
    const sq_layout_patch *P = &L->patches[p];
    const int n = P->ncorners;
    if (n < 2 || P->ncycles != 1) return SQ_FAIL(err, SQ_ERR_LAYOUT, "patch %d: no sides", p);
    double *mid = malloc(2 * (size_t)n * sizeof *mid), *mfrac = malloc((size_t)n * sizeof *mfrac);
    int *medge = malloc((size_t)n * sizeof *medge), *at = malloc((size_t)n * sizeof *at);
    double **path = calloc((size_t)n, sizeof *path), *ring = NULL;
    int *np = calloc((size_t)n, sizeof *np), *nb = NULL, nring = 0;
    cad_cdt_output o = {0};
    sq_status st = SQ_OK;
    if (!mid || !mfrac || !medge || !at || !path || !np)
        st = SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    for (int k = 0; k < n && st == SQ_OK; k++)
        st = side_mid(r, P, k, &medge[k], &mfrac[k], &mid[2 * k], err);
    if (st == SQ_OK) st = ring_with_points(L, P, mid, n, &ring, &nring, at, err);
    double cen[2] = {0, 0};
    int straight = st == SQ_OK && patch_centroid(L, P, cen) &&
                   lay_poly_contains(ring, nring, cen);
    for (int k = 0; k < n && straight; k++)
        straight = !seg_leaves(ring, nring, cen, &mid[2 * k], r->tol);
    if (st == SQ_OK && !straight && !bent)
        st = SQ_FAIL(err, SQ_ERR_LAYOUT, "patch %d: straight spokes would leave it", p);
    if (st == SQ_OK && !straight) {
        int *seg = malloc(2 * (size_t)nring * sizeof *seg);
        if (!seg) st = SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
        for (int i = 0; i < nring && st == SQ_OK; i++) seg[2 * i] = i, seg[2 * i + 1] = (i + 1) % nring;
        cad_cdt_input in = {0};
        in.npoints = nring, in.xy = ring, in.nsegments = nring, in.seg = seg;
        /* spokes need a triangulation, not a fine one: CGAL's conforming
         * splits of encroached sides multiply without end near tiny sides,
         * so a split that needs more than a few points per ring point is
         * given up (the trial is undone) */
        in.max_vertices = SPLIT_CDT_POINTS_PER_RING_POINT * nring;
        if (st == SQ_OK) st = cad_cdt_mesh(&in, &o, err);
        free(seg);
        if (st == SQ_OK && !(nb = tri_neighbours(&o)))
            st = SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
        if (st == SQ_OK) far_point(&o, ring, nring, mid, n, r->tol, cen);
        int t0 = st == SQ_OK ? tri_holding(&o, cen) : 0;
        for (int k = 0; k < n && st == SQ_OK; k++) {
            if (!seg_leaves(ring, nring, cen, &mid[2 * k], r->tol)) continue;
            int v = 0; /* the triangulation's vertex at side point k */
            for (int i = 1; i < o.nverts; i++)
                if (hypot(o.xy[2 * i] - mid[2 * k], o.xy[2 * i + 1] - mid[2 * k + 1]) <
                    hypot(o.xy[2 * v] - mid[2 * k], o.xy[2 * v + 1] - mid[2 * k + 1]))
                    v = i;
            st = cdt_path(&o, nb, ring, nring, cen, t0, v, r->tol, &path[k], &np[k], err);
            if (st == SQ_OK) { /* end exactly on the side point */
                path[k][2 * np[k] - 2] = mid[2 * k];
                path[k][2 * np[k] - 1] = mid[2 * k + 1];
            }
        }
    }
    /* spokes must not meet but at the centre */
    for (int a = 0; a < n && st == SQ_OK; a++)
        for (int b = a + 1; b < n && st == SQ_OK; b++) {
            double sa[4] = {cen[0], cen[1], mid[2 * a], mid[2 * a + 1]};
            double sb[4] = {cen[0], cen[1], mid[2 * b], mid[2 * b + 1]};
            const double *pa = path[a] ? path[a] : sa, *pb = path[b] ? path[b] : sb;
            if (paths_cross(pa, path[a] ? np[a] : 2, pb, path[b] ? np[b] : 2, r->tol))
                st = SQ_FAIL(err, SQ_ERR_LAYOUT, "patch %d: spokes from (%g, %g) cross", p,
                             cen[0], cen[1]);
        }
    if (st == SQ_OK) st = lay_sing_push(L, cen[0], cen[1], n, SQ_LROLE_MIDPOINT, err);
    int M = L->nsing - 1;
    for (int k = 0; k < n && st == SQ_OK; k++)
        st = add_spoke(r, M, cen, path[k], np[k], medge[k], mfrac[k], &mid[2 * k], err);
    /* a valence-0 face vertex of the patch now takes one quad */
    for (int k = 0; k < n && st == SQ_OK; k++) {
        const sq_layout_node *v = &L->nodes[P->corners[k]];
        if (v->kind == SQ_LNODE_CORNER && L->vertex_quads[v->id] == 0) L->vertex_quads[v->id] = 1;
    }
    for (int k = 0; path && k < n; k++) free(path[k]);
    free(path), free(np), free(mid), free(mfrac), free(medge), free(at), free(ring), free(nb);
    cad_cdt_output_free(&o);
    return st;
}

/* Triangular patch: midpoint division (Marcon §3.4, Fig. 13), the n-quad
 * split with n = 3; a midpoint on a separatrix is a T-junction repaired
 * next. */
static sq_status split_triangle(rctx *r, int *done, sq_error *err)
{
    sq_layout *L = r->L;
    for (int p = 0; p < L->npatches && !*done; p++) {
        const sq_layout_patch *P = &L->patches[p];
        if (P->ncorners != 3 || P->ncycles != 1) continue;
        sq_error e2;
        sq_status st = split_centre(r, p, 0, &e2);
        if (st == SQ_ERR_LAYOUT) continue; /* left to repair_polygon */
        if (st != SQ_OK) {
            if (err) *err = e2;
            return st;
        }
        L->stats.triangles_repaired++;
        *done = 1;
    }
    return SQ_OK;
}

/* The half-edge (index into P->half) leaving a boundary valence-2 point on
 * P's cycle that is not a corner of P, or -1: a face vertex taking one quad
 * with no separatrix at it. */
static int valence2_half(const sq_layout *L, const sq_layout_patch *P)
{
    for (int h = 0; h < P->nhalf; h++) {
        const sq_layout_edge *E = &L->edges[P->half[h].edge];
        int v = P->half[h].reversed ? E->n1 : E->n0;
        const sq_layout_node *n = &L->nodes[v];
        if (n->kind != SQ_LNODE_CORNER || L->vertex_quads[n->id] != 1 || n->degree != 2) continue;
        int corner = 0;
        for (int k = 0; k < P->ncorners; k++) corner |= P->corners[k] == v;
        if (!corner) return h;
    }
    return -1;
}

/* Boundary valence-2 point (Jezdimirović 2021 §6.2–6.3, Fig. 18): a face
 * vertex taking one quad (two mesh edges) where the boundary is nearly
 * straight, so that its patch, a quadrilateral in topology, has only three
 * geometric corners.  It is split into two valence-3 points: a valence-3
 * node imposed at the barycentre of the patch, joined by a spoke to the
 * vertex (which then has three edges and takes two quads, a regular
 * boundary point) and by spokes to the midpoints of the two sides away from
 * it, so that the triangle becomes three quads; the index is kept (1/4 at
 * the vertex before, 1/4 at the node after).  Marcon's midpoint division
 * would put a foot beside the vertex instead and leave it a corner of no
 * patch. */
static sq_status split_valence2(rctx *r, int *done, sq_error *err)
{
    sq_layout *L = r->L;
    for (int p = 0; p < L->npatches && !*done; p++) {
        const sq_layout_patch *P = &L->patches[p];
        if (P->ncorners != 3 || P->ncycles != 1) continue;
        int h = valence2_half(L, P);
        if (h < 0) continue;
        /* side k (corner k to corner k+1) holding the vertex */
        int side = 0;
        for (int k = 0; k < 3; k++) {
            int a = P->corner_half[k], b = P->corner_half[(k + 1) % 3];
            if (b <= a) b += P->nhalf;
            if ((h > a && h < b) || (h + P->nhalf > a && h + P->nhalf < b)) side = k;
        }
        const sq_layout_edge *E = &L->edges[P->half[h].edge];
        const sq_layout_node *V = &L->nodes[P->half[h].reversed ? E->n1 : E->n0];
        int vid = V->id;
        double vxy[2] = {V->x, V->y}, mid[2][2], cen[2];
        int medge[2];
        double mfrac[2];
        for (int j = 0; j < 2; j++)
            SQ_TRY(side_mid(r, P, (side + 1 + j) % 3, &medge[j], &mfrac[j], mid[j], err));
        if (!patch_centroid(L, P, cen)) {
            cen[0] = (vxy[0] + mid[0][0] + mid[1][0]) / 3.0;
            cen[1] = (vxy[1] + mid[0][1] + mid[1][1]) / 3.0;
        }
        SQ_TRY(lay_sing_push(L, cen[0], cen[1], 3, SQ_LROLE_VALENCE2, err));
        int M = L->nsing - 1;
        SQ_TRY(straight_sep(L, M, cen, vxy, (sq_sep_end){SQ_END_CORNER, vid, 0.0}, err));
        for (int j = 0; j < 2; j++) SQ_TRY(add_spoke(r, M, cen, NULL, 0, medge[j], mfrac[j], mid[j], err));
        L->vertex_quads[vid] = 2;
        L->stats.valence2_split++;
        *done = 1;
    }
    return SQ_OK;
}

/* Annular patch (several cycles, no corner): cut along field lines from its
 * outer cycle, at four points (one per quarter of its length) where the
 * field is best aligned with the inward normal. */
static sq_status cut_annulus(rctx *r, int *done, sq_error *err)
{
    sq_layout *L = r->L;
    for (int p = 0; p < L->npatches && !*done; p++) {
        const sq_layout_patch *P = &L->patches[p];
        if (P->ncycles < 2 || P->ncorners != 0) continue;
        int nh = P->cycle_start[1];
        double tot = 0.0;
        for (int k = 0; k < nh; k++) tot += L->edges[P->half[k].edge].length;
        enum { NCUT = 4, NS = 64 };
        int ncut = 0;
        for (int q = 0; q < NCUT; q++) {
            double bestal = -2.0, bp[2] = {0, 0}, bd[2] = {0, 0};
            sq_sep_end bstart = {SQ_END_OPEN, -1, 0.0};
            for (int i = 0; i < NS; i++) {
                double target = tot * (q + (i + 0.5) / NS) / NCUT, acc = 0.0;
                for (int k = 0; k < nh; k++) {
                    const sq_layout_edge *E = &L->edges[P->half[k].edge];
                    if (acc + E->length < target && k < nh - 1) {
                        acc += E->length;
                        continue;
                    }
                    if (E->cad_edge < 0) break; /* only boundary starts */
                    double f = (target - acc) / E->length;
                    if (P->half[k].reversed) f = 1.0 - f;
                    double s = E->s0 + f * (E->s1 - E->s0), x[2], t[2];
                    SQ_TRY(cad_face_edge_eval(r->face, E->cad_edge, s, x, t, NULL, err));
                    double nrm[2] = {-t[1], t[0]}, b[2]; /* the face is on the left */
                    if (P->half[k].reversed) nrm[0] = -nrm[0], nrm[1] = -nrm[1];
                    double xin[2] = {x[0] + 1e-3 * r->step * nrm[0],
                                     x[1] + 1e-3 * r->step * nrm[1]};
                    int el = -1;
                    if (branch(r, xin, &el, nrm, b)) break;
                    /* alignment, ties going to the middle of the quarter */
                    double al = b[0] * nrm[0] + b[1] * nrm[1] -
                                1e-3 * fabs(i + 0.5 - 0.5 * NS) / NS;
                    if (al > bestal) {
                        bestal = al;
                        bp[0] = x[0];
                        bp[1] = x[1];
                        bd[0] = nrm[0];
                        bd[1] = nrm[1];
                        bstart = (sq_sep_end){SQ_END_BOUNDARY, E->cad_edge, s};
                    }
                    break;
                }
            }
            if (bstart.kind != SQ_END_BOUNDARY) continue;
            line ln;
            sq_status st = trace_line(r, bp, bd, 1e-6 * L->scale, &ln, err);
            if (st == SQ_OK) st = add_line(r, &ln, bstart, err);
            free(ln.xy);
            if (st != SQ_OK) return st;
            ncut++;
        }
        if (ncut > 0) {
            L->stats.annuli_cut++;
            *done = 1;
        }
    }
    return SQ_OK;
}

/* ---- polygons: an extra separatrix from a corner --------------------------- */

/* Unit direction of half-edge h of patch P at its start. */
static void half_start_dir(const sq_layout *L, const sq_layout_half *h, double d[2])
{
    const sq_layout_edge *E = &L->edges[h->edge];
    sq_separatrix s = {.npts = E->npts, .xy = E->xy};
    leave_dir(&s, h->reversed, d, L->scale);
}

/* The cross branches at corner k of patch P that point into the patch at
 * least EXTRA_MARGIN_DEG away from both its sides there (dir[2 * j]);
 * returns how many (at most 4). */
#define EXTRA_MARGIN_DEG 20.0
static int wedge_branches(const rctx *r, const sq_layout_patch *P, int k, double *dir)
{
    const sq_layout *L = r->L;
    const sq_layout_node *c = &L->nodes[P->corners[k]];
    double out[2], ang = P->corner_angle[k], margin = EXTRA_MARGIN_DEG * M_PI / 180.0;
    half_start_dir(L, &P->half[P->corner_half[k]], out);
    if (!r->field || ang < 2.0 * margin) return 0;
    /* the field a little inside, along the bisector (the corner may be a
     * singular point) */
    double a0 = atan2(out[1], out[0]), bis = a0 + 0.5 * ang, th;
    double q[2] = {c->x + 1e-3 * r->step * cos(bis), c->y + 1e-3 * r->step * sin(bis)};
    int elem = -1, n = 0;
    if (r->field->direction(r->field->ctx, q, &elem, &th)) return 0;
    for (int j = 0; j < 4; j++) {
        double phi = remainder(th + j * M_PI / 2 - a0, 2.0 * M_PI);
        if (phi < 0) phi += 2.0 * M_PI;
        if (phi > margin && phi < ang - margin) {
            dir[2 * n] = cos(a0 + phi);
            dir[2 * n + 1] = sin(a0 + phi);
            n++;
        }
    }
    return n;
}

/* An extra separatrix from corner k of patch p along direction dir, traced
 * in the field to the patch's other side (Marcon's streamlines from the
 * offending corner): a pentagon with a corner whose angle holds a cross
 * branch becomes a quad and a triangle or two quads; where the line ends
 * on a separatrix it leaves a T-junction, continued next.  The step is
 * bounded by a tenth of the patch's shortest side so that thin patches
 * are crossed, not jumped. */
static sq_status extra_separatrix(rctx *r, int p, int k, const double dir[2], sq_error *err)
{
    sq_layout *L = r->L;
    const sq_layout_patch *P = &L->patches[p];
    const sq_layout_node *c = &L->nodes[P->corners[k]];
    sq_sep_end start;
    switch (c->kind) {
    case SQ_LNODE_CORNER:
        start = (sq_sep_end){SQ_END_CORNER, c->id, 0.0};
        break;
    case SQ_LNODE_FOOT:
        start = (sq_sep_end){SQ_END_BOUNDARY, c->id, c->s};
        break;
    case SQ_LNODE_SINGULAR:
        if (L->role[c->id] == SQ_LROLE_TJUNCTION)
            return SQ_FAIL(err, SQ_ERR_LAYOUT, "corner is a T-junction");
        start = (sq_sep_end){SQ_END_SINGULAR, c->id, 0.0};
        break;
    default:
        return SQ_FAIL(err, SQ_ERR_LAYOUT, "corner is not a node of the set");
    }
    double shortest = HUGE_VAL;
    for (int j = 0; j < P->ncorners; j++) {
        int a = P->corner_half[j], b = P->corner_half[(j + 1) % P->ncorners];
        if (b <= a) b += P->nhalf;
        double len = 0.0;
        for (int h = a; h < b; h++) len += L->edges[P->half[h % P->nhalf].edge].length;
        shortest = fmin(shortest, len);
    }
    double step = r->step, xy[2] = {c->x, c->y};
    r->step = fmin(step, 0.1 * shortest);
    line ln;
    sq_status st = trace_line(r, xy, dir, 1e-6 * L->scale, &ln, err);
    r->step = step;
    if (st == SQ_OK) st = add_line(r, &ln, start, err);
    free(ln.xy);
    if (st != SQ_OK) return st;
    if (c->kind == SQ_LNODE_CORNER) L->vertex_quads[c->id]++;
    if (c->kind == SQ_LNODE_SINGULAR) L->sing[c->id].valence++;
    return SQ_OK;
}

/* ---- repairs tried and undone when they do not help --------------------- */

typedef struct {
    sq_separatrix_set seps;
    int nsing;
    sq_singularity *sing;
    sq_lrole *role;
    int *vertex_quads;
    sq_layout_stats stats;
} snapshot;

static void snapshot_free(snapshot *s)
{
    lay_sepset_free(&s->seps);
    free(s->sing), free(s->role), free(s->vertex_quads);
    memset(s, 0, sizeof *s);
}

static sq_status snapshot_take(const sq_layout *L, snapshot *s, sq_error *err)
{
    memset(s, 0, sizeof *s);
    size_t ns = (size_t)(L->nsing > 0 ? L->nsing : 1), nv = (size_t)(L->nvertices > 0 ? L->nvertices : 1);
    s->sing = malloc(ns * sizeof *s->sing);
    s->role = malloc(ns * sizeof *s->role);
    s->vertex_quads = malloc(nv * sizeof *s->vertex_quads);
    if (!s->sing || !s->role || !s->vertex_quads) {
        snapshot_free(s);
        return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    }
    if (L->nsing > 0) { /* a layout without singular points has no arrays */
        memcpy(s->sing, L->sing, (size_t)L->nsing * sizeof *s->sing);
        memcpy(s->role, L->role, (size_t)L->nsing * sizeof *s->role);
    }
    if (L->nvertices > 0)
        memcpy(s->vertex_quads, L->vertex_quads, (size_t)L->nvertices * sizeof *s->vertex_quads);
    s->nsing = L->nsing;
    s->stats = L->stats;
    for (int k = 0; k < L->seps.n; k++) {
        const sq_separatrix *a = &L->seps.s[k];
        sq_status st = lay_sep_push(&s->seps, a->xy, a->npts, a->start, a->end, err);
        if (st != SQ_OK) {
            snapshot_free(s);
            return st;
        }
        sq_separatrix *b = &s->seps.s[k];
        b->start_angle = a->start_angle;
        b->end_angle = a->end_angle;
        b->merged = a->merged;
    }
    return SQ_OK;
}

/* Put the snapshot back into L (whose own state is freed); s is emptied. */
static void snapshot_restore(sq_layout *L, snapshot *s)
{
    lay_sepset_free(&L->seps);
    free(L->sing), free(L->role), free(L->vertex_quads);
    L->seps = s->seps;
    L->sing = s->sing;
    L->role = s->role;
    L->nsing = s->nsing;
    L->vertex_quads = s->vertex_quads;
    L->stats = s->stats;
    memset(s, 0, sizeof *s);
}

/* One set-level repair, the first that applies (*done). */
static sq_status set_repair(rctx *r, int *done, sq_error *err)
{
    *done = 0;
    r->hit_ok = 0;
    r->work += (double)set_points(&r->L->seps);
    SQ_TRY(remove_duplicate(r, done, err));
    if (!*done) SQ_TRY(make_tjunction(r, done, err));
    if (!*done) SQ_TRY(cut_limit_cycle(r, done, err));
    if (!*done) SQ_TRY(split_crossing(r, done, err));
    if (!*done) SQ_TRY(repair_tjunction(r, done, err));
    return SQ_OK;
}

/* After a patch repair: the set-level repairs until none applies, the
 * graph rebuilt and its defects counted (*ndef; INT_MAX when the repairs
 * do not settle within SETTLE_MAX). */
#define SETTLE_MAX 200
static sq_status settle(rctx *r, int *ndef, sq_error *err)
{
    int done = 1, it = 0;
    *ndef = INT_MAX;
    while (done && it++ < SETTLE_MAX && r->work <= WORK_MAX) SQ_TRY(set_repair(r, &done, err));
    if (done) return SQ_OK;
    SQ_TRY(lay_graph_build(r->L, r->face, r->info, err));
    sq_layout_defects d;
    *ndef = sq_layout_check(r->L, &d);
    sq_layout_defects_free(&d);
    return SQ_OK;
}

/* Each trial settles the whole set: a bound on them bounds the time a face
 * with many non-quad patches takes to be declared invalid. */
#define MAX_TRIALS 16

typedef struct {
    int patch, corner; /* corner < 0: the n-quad split */
    double dir[2];
} candidate;

/* Apply candidate c and settle; keep it (*kept) when fewer than `before`
 * defects are left, else restore the set and its graph. */
static sq_status try_candidate(rctx *r, const candidate *c, int before, int *kept, sq_error *err)
{
    *kept = 0;
    if (r->trials++ >= MAX_TRIALS) return SQ_OK;
    snapshot s;
    SQ_TRY(snapshot_take(r->L, &s, err));
    sq_error e2;
    int ndef = INT_MAX;
    sq_status st = c->corner >= 0 ? extra_separatrix(r, c->patch, c->corner, c->dir, &e2)
                                  : split_centre(r, c->patch, 1, &e2);
    if (st == SQ_OK) st = settle(r, &ndef, &e2);
    if (st == SQ_ERR_INTERNAL) {
        snapshot_free(&s);
        if (err) *err = e2;
        return st;
    }
    *kept = st == SQ_OK && ndef < before;
    if (*kept) {
        snapshot_free(&s);
        return SQ_OK;
    }
    snapshot_restore(r->L, &s);
    r->hit_ok = 0;
    return lay_graph_build(r->L, r->face, r->info, err);
}

/* A patch with n != 4 corners that the triangle repairs leave (a pentagon,
 * a hexagon, a triangle they could not mend): first an extra separatrix
 * from a corner whose angle holds a cross branch, else the n-quad split;
 * the first that leaves fewer defects than `before` is kept. */
static sq_status repair_polygon(rctx *r, int before, int *done, sq_error *err)
{
    sq_layout *L = r->L;
    for (int p = 0; p < L->npatches && !*done; p++) {
        if (L->patches[p].ncycles != 1 || L->patches[p].ncorners == 4) continue;
        for (int k = 0; k < L->patches[p].ncorners && !*done; k++) {
            double dir[8];
            int nd = wedge_branches(r, &L->patches[p], k, dir);
            for (int j = 0; j < nd && !*done; j++) {
                candidate c = {p, k, {dir[2 * j], dir[2 * j + 1]}};
                SQ_TRY(try_candidate(r, &c, before, done, err));
                if (*done) L->stats.extra_separatrices++;
            }
        }
        if (*done || L->patches[p].ncorners < 2) continue;
        candidate c = {p, -1, {0.0, 0.0}};
        SQ_TRY(try_candidate(r, &c, before, done, err));
        if (*done) L->stats.polygons_split++;
    }
    return SQ_OK;
}

/* ---- the correction loop ------------------------------------------------ */

sq_status sq_layout_build(const cad_face *face, const sq_face_info *info, const int *vertex_quads,
                          int nsing, const sq_singularity *sing, const sq_separatrix_set *seps,
                          const sq_cross_field *field, const sq_trace_options *opt,
                          sq_layout *out, sq_error *err)
{
    SQ_TRY(sq_layout_graph(face, info, vertex_quads, nsing, sing, seps, out, err));
    sq_layout *L = out;
    rctx r;
    memset(&r, 0, sizeof r);
    r.L = L;
    r.face = face;
    r.info = info;
    r.field = field;
    r.tol = 1e-9 * L->scale;
    r.step = 0.004 * L->scale;
    double perim = 0.0;
    for (int e = 0; e < cad_face_num_edges(face); e++) perim += cad_face_edge_length(face, e);
    r.maxlen = opt && opt->max_length > 0 ? opt->max_length : 4.0 * perim;
    sq_status st = sample_boundary(&r, err);
    sq_layout_defects d;
    memset(&d, 0, sizeof d);
    int it;
    for (it = 0; it < 400 && st == SQ_OK && r.work <= WORK_MAX && r.lwork <= LINE_WORK_MAX; it++) {
        /* set-level repairs first, the graph rebuilt after them; each
         * iteration follows a change of the set */
        int done = 0;
        st = set_repair(&r, &done, err);
        if (st != SQ_OK) break;
        if (done) continue;
        st = lay_graph_build(L, face, info, err);
        if (st != SQ_OK) break;
        sq_layout_defects_free(&d);
        if (sq_layout_check(L, &d) == 0) break;
        st = cut_annulus(&r, &done, err);
        if (st == SQ_OK && !done) st = split_valence2(&r, &done, err);
        if (st == SQ_OK && !done) st = split_triangle(&r, &done, err);
        if (st == SQ_OK && !done) st = repair_polygon(&r, d.n, &done, err);
        if (st == SQ_OK && !done) break; /* stuck */
    }
    L->stats.iterations = it;
    if (st == SQ_OK || st == SQ_ERR_LAYOUT) { /* the graph of the final set */
        sq_error e2;
        sq_status s2 = lay_graph_build(L, face, info, &e2);
        if (s2 != SQ_OK) {
            st = s2;
            if (err) *err = e2;
        }
    }
    free(r.bxy);
    free(r.bs);
    free(r.bedge);
    free(r.hit);
    if (st == SQ_OK || st == SQ_ERR_LAYOUT) {
        L->stats.separatrices = L->seps.n;
        L->stats.patches = L->npatches;
        L->stats.quad_patches = 0;
        for (int p = 0; p < L->npatches; p++)
            L->stats.quad_patches += L->patches[p].ncorners == 4 && L->patches[p].ncycles == 1;
        sq_layout_defects_free(&d);
        if (sq_layout_check(L, &d) > 0 && st == SQ_OK) {
            char buf[400];
            sq_layout_defects_summary(&d, buf, sizeof buf);
            st = SQ_FAIL(err, SQ_ERR_LAYOUT, "%s%s", buf,
                         r.work > WORK_MAX || r.lwork > LINE_WORK_MAX
                             ? " (repairs stopped at their work bound)"
                             : "");
        }
    } else if (st != SQ_ERR_LAYOUT) {
        sq_layout_free(L);
    }
    sq_layout_defects_free(&d);
    return st;
}
