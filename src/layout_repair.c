/* semquad — layout correction (layout.h design 4; Jezdimirović 2021 journal
 * §6, Marcon 2019 §3.4). */
#include "layout_internal.h"

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
} rctx;

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
    while (len < r->maxlen) {
        double h = r->step, d1[2], d2[2], xn[2];
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
            double worst = 0.0, d;
            for (int j = 0; j < A->npts; j++) {
                nearest_pos(B, &A->xy[2 * j], &d);
                worst = fmax(worst, d);
            }
            for (int j = 0; j < B->npts; j++) {
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
    for (int k = 0; k < n && !*done && st == SQ_OK; k++) {
        const sq_separatrix *s = &L->seps.s[k];
        int lc = s->end.kind == SQ_END_OPEN;
        for (int a = 0; a < nh && !lc; a++) {
            if (h[a].enda >= 0 || h[a].endb >= 0) continue;
            if (h[a].a == k && h[a].b == k) lc = 1;
            for (int b = a + 1; b < nh && !lc; b++) {
                if (h[b].enda >= 0 || h[b].endb >= 0) continue;
                int pa = (h[a].a == k) ? h[a].b : (h[a].b == k ? h[a].a : -2);
                int pb = (h[b].a == k) ? h[b].b : (h[b].b == k ? h[b].a : -2);
                if (pa >= 0 && pa == pb) lc = 1;
            }
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

/* Straight separatrix from inserted node M (at a) to b, ending in `end`. */
static sq_status straight_sep(sq_layout *L, int M, const double a[2], const double b[2],
                              sq_sep_end end, sq_error *err)
{
    enum { NP = 17 };
    double xy[2 * NP];
    for (int j = 0; j < NP; j++) {
        double t = (double)j / (NP - 1);
        xy[2 * j] = a[0] + t * (b[0] - a[0]);
        xy[2 * j + 1] = a[1] + t * (b[1] - a[1]);
    }
    return lay_sep_push(&L->seps, xy, NP, (sq_sep_end){SQ_END_SINGULAR, M, 0.0}, end, err);
}

/* A straight spoke from inserted node M (at cen) to point p on layout edge
 * `edge` at fraction frac: on the boundary it ends in a foot, on a
 * separatrix in a new T-junction, repaired next (the "patches influenced"
 * of Jezdimirović §6.3). */
static sq_status add_spoke(rctx *r, int M, const double cen[2], int edge, double frac,
                           const double p[2], sq_error *err)
{
    sq_layout *L = r->L;
    const sq_layout_edge *E = &L->edges[edge];
    sq_sep_end end;
    if (E->cad_edge >= 0) {
        end = (sq_sep_end){SQ_END_BOUNDARY, E->cad_edge, E->s0 + frac * (E->s1 - E->s0)};
    } else {
        int sep = E->sep;
        double q[2] = {p[0], p[1]};
        SQ_TRY(lay_sing_push(L, q[0], q[1], 3, SQ_LROLE_TJUNCTION, err));
        end = (sq_sep_end){SQ_END_SINGULAR, L->nsing - 1, 0.0};
        double pos = nearest_pos(&L->seps.s[sep], q, NULL);
        SQ_TRY(split_sep(L, sep, pos, q, L->nsing - 1, err));
    }
    return straight_sep(L, M, cen, p, end, err);
}

/* Triangular patch: midpoint division (Marcon §3.4, Fig. 13): a valence-3
 * node at the centroid, straight spokes to the three side midpoints; a
 * midpoint on a separatrix is a T-junction repaired next. */
static sq_status split_triangle(rctx *r, int *done, sq_error *err)
{
    sq_layout *L = r->L;
    for (int p = 0; p < L->npatches && !*done; p++) {
        const sq_layout_patch *P = &L->patches[p];
        if (P->ncorners != 3 || P->ncycles != 1) continue;
        double mid[3][2], cen[2];
        int medge[3];
        double mfrac[3];
        for (int k = 0; k < 3; k++) SQ_TRY(side_mid(r, P, k, &medge[k], &mfrac[k], mid[k], err));
        if (!patch_centroid(L, P, cen)) {
            cen[0] = (mid[0][0] + mid[1][0] + mid[2][0]) / 3.0;
            cen[1] = (mid[0][1] + mid[1][1] + mid[2][1]) / 3.0;
        }
        SQ_TRY(lay_sing_push(L, cen[0], cen[1], 3, SQ_LROLE_MIDPOINT, err));
        int M = L->nsing - 1;
        for (int k = 0; k < 3; k++) SQ_TRY(add_spoke(r, M, cen, medge[k], mfrac[k], mid[k], err));
        /* a valence-0 face vertex of the triangle now takes one quad */
        for (int k = 0; k < 3; k++) {
            const sq_layout_node *n = &L->nodes[P->corners[k]];
            if (n->kind == SQ_LNODE_CORNER && L->vertex_quads[n->id] == 0)
                L->vertex_quads[n->id] = 1;
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
        for (int j = 0; j < 2; j++) SQ_TRY(add_spoke(r, M, cen, medge[j], mfrac[j], mid[j], err));
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
    for (it = 0; it < 400 && st == SQ_OK; it++) {
        /* set-level repairs first, the graph rebuilt after them; each
         * iteration follows a change of the set */
        int done = 0;
        r.hit_ok = 0;
        st = remove_duplicate(&r, &done, err);
        if (st == SQ_OK && !done) st = make_tjunction(&r, &done, err);
        if (st == SQ_OK && !done) st = cut_limit_cycle(&r, &done, err);
        if (st == SQ_OK && !done) st = split_crossing(&r, &done, err);
        if (st == SQ_OK && !done) st = repair_tjunction(&r, &done, err);
        if (st != SQ_OK) break;
        if (done) continue;
        st = lay_graph_build(L, face, info, err);
        if (st != SQ_OK) break;
        sq_layout_defects_free(&d);
        if (sq_layout_check(L, &d) == 0) break;
        st = cut_annulus(&r, &done, err);
        if (st == SQ_OK && !done) st = split_valence2(&r, &done, err);
        if (st == SQ_OK && !done) st = split_triangle(&r, &done, err);
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
            st = SQ_FAIL(err, SQ_ERR_LAYOUT, "no valid layout: %s", buf);
        }
    } else if (st != SQ_ERR_LAYOUT) {
        sq_layout_free(L);
    }
    sq_layout_defects_free(&d);
    return st;
}
