/* semquad — periodic pairs of a face's edges (periodic.h, design 1). */
#include "periodic.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define NCHECK 9 /* points checked per pair: s = 0, L/8, ..., L */

/* Curve c at fraction u of its length, in the common frame and the
 * curve's sense there. */
static sq_status curve_at(const sq_periodic_curve *c, double u, double xy[2], sq_error *err)
{
    double L = cad_face_edge_length(c->face, c->edge), p[2];
    SQ_TRY(cad_face_edge_eval(c->face, c->edge, (c->flip ? 1.0 - u : u) * L, p, NULL, NULL, err));
    sq_affine_map(c->frame, p, xy);
    return SQ_OK;
}

/* The rigid motion taking p0 to q0 and p1 to q1 (|p1 - p0| = |q1 - q0| to
 * tol, else 0): the angle between the chords, a translation below tol of
 * turning over the chord. */
static int fit(const double p0[2], const double p1[2], const double q0[2], const double q1[2],
               double tol, sq_periodic_pair *r)
{
    double dp[2] = {p1[0] - p0[0], p1[1] - p0[1]}, dq[2] = {q1[0] - q0[0], q1[1] - q0[1]};
    double lp = hypot(dp[0], dp[1]), lq = hypot(dq[0], dq[1]);
    if (fabs(lp - lq) > tol || lp <= tol) return 0;
    double phi = atan2(dp[0] * dq[1] - dp[1] * dq[0], dp[0] * dq[0] + dp[1] * dq[1]);
    r->rotation = fabs(phi) * lp > tol;
    double c = r->rotation ? cos(phi) : 1.0, s = r->rotation ? sin(phi) : 0.0;
    /* the mean of both end points' offsets: T(p0) = q0, T(p1) = q1 to rounding */
    double t0 = 0.5 * (q0[0] + q1[0] - c * (p0[0] + p1[0]) + s * (p0[1] + p1[1]));
    double t1 = 0.5 * (q0[1] + q1[1] - s * (p0[0] + p1[0]) - c * (p0[1] + p1[1]));
    double T[6] = {c, -s, t0, s, c, t1};
    memcpy(r->affine, T, sizeof T);
    r->shift[0] = t0, r->shift[1] = t1;
    r->angle_deg = phi * 180.0 / M_PI;
    r->centre[0] = r->centre[1] = 0.0;
    if (r->rotation) { /* (I - R) c = t */
        double a = 1.0 - c, det = a * a + s * s;
        r->centre[0] = (a * t0 - s * t1) / det;
        r->centre[1] = (s * t0 + a * t1) / det;
        r->shift[0] = r->shift[1] = 0.0;
    }
    return 1;
}

/* Largest |T(a at fraction u) - b at fraction 1 - u| over NCHECK points. */
static sq_status pair_gap(const sq_periodic_curve *a, const sq_periodic_curve *b, const double T[6],
                          double *gap, sq_error *err)
{
    *gap = 0.0;
    for (int k = 0; k < NCHECK; k++) {
        double u = (double)k / (NCHECK - 1), pa[2], pb[2], q[2];
        SQ_TRY(curve_at(a, u, pa, err));
        SQ_TRY(curve_at(b, 1.0 - u, pb, err));
        sq_affine_map(T, pa, q);
        *gap = fmax(*gap, hypot(q[0] - pb[0], q[1] - pb[1]));
    }
    return SQ_OK;
}

/* Curve a onto curve b (senses opposite): *ok and the transform in r. */
static sq_status match(const sq_periodic_curve *c, int a, int b, double tol, sq_periodic_pair *r,
                       int *ok, sq_error *err)
{
    *ok = 0;
    const sq_periodic_curve *ca = &c[a], *cb = &c[b];
    if (fabs(cad_face_edge_length(ca->face, ca->edge) - cad_face_edge_length(cb->face, cb->edge)) > tol ||
        ca->closed || cb->closed) /* a closed edge: no chord */
        return SQ_OK;
    r->a = a, r->b = b, r->group = -1;
    if (!fit(&ca->ends[0], &ca->ends[2], &cb->ends[2], &cb->ends[0], tol, r)) return SQ_OK;
    SQ_TRY(pair_gap(ca, cb, r->affine, &r->gap, err));
    *ok = r->gap <= tol;
    return SQ_OK;
}

/* A pair joining group g takes g's transform (first's): a node at the
 * junction of two edges of a chain is then one image under both. */
static void take_transform(sq_periodic_pair *r, const sq_periodic_pair *g)
{
    r->group = g->group, r->rotation = g->rotation;
    memcpy(r->affine, g->affine, sizeof r->affine);
    memcpy(r->shift, g->shift, sizeof r->shift);
    memcpy(r->centre, g->centre, sizeof r->centre);
    r->angle_deg = g->angle_deg;
}

/* Two transforms are one when they move the face's box corners alike. */
static int same_transform(const double S[6], const double T[6], const double bbox[4], double tol)
{
    for (int k = 0; k < 4; k++) {
        double p[2] = {bbox[2 * (k & 1)], bbox[1 + 2 * (k >> 1)]}, u[2], v[2];
        sq_affine_map(S, p, u), sq_affine_map(T, p, v);
        if (hypot(u[0] - v[0], u[1] - v[1]) > tol) return 0;
    }
    return 1;
}

static sq_status parse_spec(const char *spec, int ne, sq_periodic *p, sq_error *err)
{
    const char *s = spec;
    while (*s) {
        char *end;
        long a = strtol(s, &end, 10), b;
        if (end == s || *end != ':') goto bad;
        s = end + 1;
        b = strtol(s, &end, 10);
        if (end == s || (*end && *end != ',')) goto bad;
        s = *end ? end + 1 : end;
        if (a < 0 || b < 0 || a >= ne || b >= ne || a == b)
            return SQ_FAIL(err, SQ_ERR_USAGE, "--periodic %ld:%ld: edges are 0..%d and distinct", a,
                           b, ne - 1);
        for (int k = 0; k < p->npairs; k++)
            if (p->pairs[k].a == a || p->pairs[k].b == a || p->pairs[k].a == b || p->pairs[k].b == b)
                return SQ_FAIL(err, SQ_ERR_USAGE, "--periodic: an edge of %ld:%ld is in another pair",
                               a, b);
        sq_periodic_pair *q = realloc(p->pairs, sizeof *q * (size_t)(p->npairs + 1));
        if (!q) return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
        p->pairs = q;
        p->pairs[p->npairs++] = (sq_periodic_pair){.a = (int)a, .b = (int)b};
    }
    if (p->npairs > 0) return SQ_OK;
bad:
    return SQ_FAIL(err, SQ_ERR_USAGE, "--periodic expects auto or A:B[,C:D...] (edge indices), got '%s'",
                   spec);
}

static double curve_length(const sq_periodic_curve *c)
{
    return cad_face_edge_length(c->face, c->edge);
}

/* Named pairs: each must match (its own transform); groups by transform. */
static sq_status check_named(const sq_periodic_curve *c, const double bbox[4], sq_periodic *p,
                             sq_error *err)
{
    for (int k = 0; k < p->npairs; k++) {
        sq_periodic_pair *r = &p->pairs[k];
        int a = r->a, b = r->b, ok;
        SQ_TRY(match(c, a, b, p->tol, r, &ok, err));
        if (!ok)
            return SQ_FAIL(err, SQ_ERR_PERIODIC,
                           "--periodic %d:%d: edges %d (length %.9g) and %d (length %.9g) do not "
                           "match under a translation or a rotation within %.3g",
                           a, b, a, curve_length(&c[a]), b, curve_length(&c[b]), p->tol);
        r->group = k;
        for (int j = 0; j < k; j++)
            if (same_transform(p->pairs[j].affine, r->affine, bbox, p->tol)) {
                take_transform(r, &p->pairs[j]);
                break;
            }
    }
    return SQ_OK;
}

/* `auto`: every matching ordered pair into all[] with its group. */
static sq_status all_matches(const sq_periodic_curve *c, int nc, const double bbox[4], double tol,
                             sq_periodic_pair **all, int *n, int *ngroups, sq_error *err)
{
    *all = malloc(sizeof **all * ((size_t)nc * (size_t)nc + 1));
    if (!*all) return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    *n = *ngroups = 0;
    for (int a = 0; a < nc; a++)
        for (int b = 0; b < nc; b++) {
            sq_periodic_pair r;
            int ok;
            if (a == b) continue;
            SQ_TRY(match(c, a, b, tol, &r, &ok, err));
            if (!ok) continue;
            for (int k = 0; k < *n && r.group < 0; k++)
                if (same_transform((*all)[k].affine, r.affine, bbox, tol)) take_transform(&r, &(*all)[k]);
            if (r.group < 0) r.group = (*ngroups)++;
            (*all)[(*n)++] = r;
        }
    return SQ_OK;
}

/* The groups `auto` takes: the most matched length first; then any group
 * as long (to tol), disjoint from those taken (a doubly periodic box); at
 * a tie a translation before a rotation (a square's sides also match by a
 * quarter turn about a corner). */
static sq_status take_groups(const sq_periodic_curve *c, int nc, sq_periodic_pair *all, int n,
                             int ngroups, sq_periodic *p, sq_error *err)
{
    double *len = calloc((size_t)ngroups + 1, sizeof *len);
    int *used = calloc((size_t)nc + 1, sizeof *used), *taken = calloc((size_t)ngroups + 1, sizeof *taken);
    int *rot = calloc((size_t)ngroups + 1, sizeof *rot);
    p->pairs = malloc(sizeof *p->pairs * ((size_t)n + 1));
    p->candidates = malloc(sizeof *p->candidates * ((size_t)n + 1));
    if (!len || !used || !taken || !rot || !p->pairs || !p->candidates) {
        free(len), free(used), free(taken), free(rot);
        return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    }
    /* a half turn's group holds (a, b) and (b, a): its length counted once */
    for (int k = 0; k < n; k++) {
        int again = 0;
        for (int j = 0; j < k; j++)
            again |= all[j].group == all[k].group && all[j].a == all[k].b && all[j].b == all[k].a;
        if (!again) len[all[k].group] += curve_length(&c[all[k].a]);
        rot[all[k].group] = all[k].rotation;
    }
    double best = -1.0;
    for (int pass = 0; pass < ngroups; pass++) {
        int g = -1;
        for (int h = 0; h < ngroups; h++)
            if (!taken[h] && (g < 0 || len[h] > len[g] + p->tol ||
                              (len[h] > len[g] - p->tol && rot[g] && !rot[h])))
                g = h;
        if (g < 0 || (best >= 0.0 && len[g] < best - p->tol)) break;
        int clash = 0;
        for (int k = 0; k < n; k++)
            if (all[k].group == g) clash |= used[all[k].a] | used[all[k].b];
        taken[g] = clash ? -1 : 1;
        if (clash) continue;
        best = len[g];
        /* a half turn is its own inverse: its group holds (a, b) and (b, a) */
        for (int k = 0; k < n; k++)
            if (all[k].group == g && !used[all[k].a] && !used[all[k].b])
                used[all[k].a] = used[all[k].b] = 1, p->pairs[p->npairs++] = all[k];
    }
    /* one of each two mutually inverse candidates; none of a pair taken */
    for (int k = 0; k < n; k++)
        if (taken[all[k].group] != 1 && all[k].a < all[k].b && !(used[all[k].a] && used[all[k].b]))
            p->candidates[p->ncandidates++] = all[k];
    free(len), free(used), free(taken), free(rot);
    return SQ_OK;
}

/* sq_periodic.identified: the translations, if an edge keeps its data. */
static sq_status identified(const cad_face *face, sq_periodic *p, sq_error *err)
{
    int ntrans = 0;
    for (int k = 0; k < p->npairs; k++) ntrans += !p->pairs[k].rotation;
    if (2 * ntrans >= cad_face_num_edges(face)) return SQ_OK;
    p->identified = malloc(sizeof *p->identified * ((size_t)ntrans + 1));
    if (!p->identified) return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    for (int k = 0; k < p->npairs; k++) {
        const sq_periodic_pair *r = &p->pairs[k];
        if (r->rotation) continue;
        sq_identified_pair *q = &p->identified[p->nidentified++];
        q->a = r->a, q->b = r->b;
        memcpy(q->affine, r->affine, sizeof q->affine);
    }
    return SQ_OK;
}

sq_status sq_periodic_find_curves(const sq_periodic_curve *c, int nc, const double bbox[4],
                                  const char *spec, sq_periodic *p, sq_error *err)
{
    memset(p, 0, sizeof *p);
    p->tol = SQ_PERIODIC_REL_TOL * hypot(bbox[2] - bbox[0], bbox[3] - bbox[1]);
    sq_status st;
    if (strcmp(spec, "auto") != 0) {
        st = parse_spec(spec, nc, p, err);
        if (st == SQ_OK) st = check_named(c, bbox, p, err);
    } else {
        sq_periodic_pair *all = NULL;
        int n = 0, ngroups = 0;
        st = all_matches(c, nc, bbox, p->tol, &all, &n, &ngroups, err);
        if (st == SQ_OK) st = take_groups(c, nc, all, n, ngroups, p, err);
        free(all);
        if (st == SQ_OK && p->npairs == 0)
            st = SQ_FAIL(err, SQ_ERR_PERIODIC,
                         "--periodic auto: no two edges match under a translation or a rotation "
                         "within %.3g",
                         p->tol);
    }
    if (st != SQ_OK) sq_periodic_free(p);
    return st;
}

/* The vertex where edge e starts (end 0) or ends (end 1): the CAD
 * vertices themselves, not an arc length's inversion (which rounds to the
 * integration's tolerance). */
static int vertex_of(const sq_face_info *info, int e, int end, double xy[2])
{
    for (int v = 0; v < info->nvertices; v++)
        if ((end ? info->vertices[v].edge_in : info->vertices[v].edge_out) == e) {
            xy[0] = info->vertices[v].x, xy[1] = info->vertices[v].y;
            return 1;
        }
    return 0;
}

void sq_periodic_curve_of(const cad_face *face, const sq_face_info *info, int e, const double frame[6],
                          int flip, sq_periodic_curve *c)
{
    double p[2][2];
    *c = (sq_periodic_curve){.face = face, .edge = e, .flip = flip};
    memcpy(c->frame, frame, sizeof c->frame);
    c->closed = !vertex_of(info, e, 0, p[0]) || !vertex_of(info, e, 1, p[1]);
    if (c->closed) return;
    sq_affine_map(frame, p[flip], &c->ends[0]);
    sq_affine_map(frame, p[!flip], &c->ends[2]);
}

sq_status sq_periodic_find(const cad_face *face, const sq_face_info *info, const char *spec,
                           sq_periodic *p, sq_error *err)
{
    static const double identity[6] = {1, 0, 0, 0, 1, 0};
    int ne = cad_face_num_edges(face);
    sq_periodic_curve *c = malloc(sizeof *c * ((size_t)ne + 1));
    if (!c) return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    for (int e = 0; e < ne; e++) sq_periodic_curve_of(face, info, e, identity, 0, &c[e]);
    sq_status st = sq_periodic_find_curves(c, ne, info->bbox, spec, p, err);
    free(c);
    if (st == SQ_OK) st = identified(face, p, err);
    if (st != SQ_OK) sq_periodic_free(p);
    return st;
}

void sq_periodic_free(sq_periodic *p)
{
    free(p->identified);
    free(p->pairs);
    free(p->candidates);
    memset(p, 0, sizeof *p);
}

void sq_periodic_held(const sq_periodic *p, int *held, int ne)
{
    memset(held, 0, sizeof(int) * (size_t)ne);
    for (int k = 0; k < p->npairs; k++) held[p->pairs[k].a] = held[p->pairs[k].b] = 1;
}
