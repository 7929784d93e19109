/* semquad — the layout as a planar graph and its faces (design 1–3 of
 * layout.h). */
#include "layout_internal.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* ---- small helpers ------------------------------------------------------ */

static void *grow(void *p, int *cap, int need, size_t size)
{
    if (need <= *cap) return p;
    int c = *cap > 0 ? *cap : 8;
    while (c < need) c *= 2;
    void *q = realloc(p, (size_t)c * size);
    if (q) *cap = c;
    return q;
}

sq_status lay_sep_push(sq_separatrix_set *set, const double *xy, int npts, sq_sep_end start,
                       sq_sep_end end, sq_error *err)
{
    sq_separatrix *s = grow(set->s, &set->cap, set->n + 1, sizeof *s);
    if (!s) return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    set->s = s;
    sq_separatrix *t = &s[set->n];
    memset(t, 0, sizeof *t);
    t->xy = malloc(2 * (size_t)(npts > 0 ? npts : 1) * sizeof *t->xy);
    if (!t->xy) return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    memcpy(t->xy, xy, 2 * (size_t)npts * sizeof *xy);
    t->npts = npts;
    t->start = start;
    t->end = end;
    t->start_angle = npts > 1 ? atan2(xy[3] - xy[1], xy[2] - xy[0]) : 0.0;
    set->n++;
    return SQ_OK;
}

void lay_sep_remove(sq_separatrix_set *set, int k)
{
    free(set->s[k].xy);
    memmove(&set->s[k], &set->s[k + 1], (size_t)(set->n - k - 1) * sizeof *set->s);
    set->n--;
}

void lay_sepset_free(sq_separatrix_set *set)
{
    if (!set) return;
    for (int k = 0; k < set->n; k++) free(set->s[k].xy);
    free(set->s);
    memset(set, 0, sizeof *set);
}

sq_status lay_sing_push(sq_layout *L, double x, double y, int valence, sq_lrole role,
                        sq_error *err)
{
    sq_singularity *s = realloc(L->sing, (size_t)(L->nsing + 1) * sizeof *s);
    if (!s) return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    L->sing = s;
    sq_lrole *r = realloc(L->role, (size_t)(L->nsing + 1) * sizeof *r);
    if (!r) return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    L->role = r;
    s[L->nsing] = (sq_singularity){x, y, valence, SQ_ORIGIN_MIDPOINT};
    r[L->nsing] = role;
    L->nsing++;
    return SQ_OK;
}

double lay_poly_arclen(const double *xy, int npts, double pos)
{
    double len = 0.0;
    for (int j = 0; j + 1 < npts && j < pos; j++) {
        double f = pos - j < 1.0 ? pos - j : 1.0;
        len += f * hypot(xy[2 * j + 2] - xy[2 * j], xy[2 * j + 3] - xy[2 * j + 1]);
    }
    return len;
}

/* ---- intersections ------------------------------------------------------ */

#define CHUNK 16

typedef struct {
    int sep, j0, j1; /* segments j0..j1-1 */
    double bb[4];
} chunk;

static sq_status hit_push(lay_hit **h, int *n, int *cap, lay_hit v, sq_error *err)
{
    lay_hit *q = grow(*h, cap, *n + 1, sizeof **h);
    if (!q) return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    *h = q;
    q[(*n)++] = v;
    return SQ_OK;
}

/* min and max of two finite numbers (fmin and fmax are library calls here) */
static inline double lo(double a, double b) { return a < b ? a : b; }
static inline double hi(double a, double b) { return a > b ? a : b; }

static int end_of(const sq_separatrix *s, double x, double y, double tol)
{
    if (hypot(x - s->xy[0], y - s->xy[1]) <= tol) return 0;
    if (hypot(x - s->xy[2 * s->npts - 2], y - s->xy[2 * s->npts - 1]) <= tol) return 1;
    return -1;
}

sq_status lay_intersections(const sq_separatrix_set *set, double tol, lay_hit **hits, int *nhits,
                            sq_error *err)
{
    *hits = NULL;
    *nhits = 0;
    int nch = 0, cap = 0;
    chunk *ch = NULL;
    for (int i = 0; i < set->n; i++) {
        const sq_separatrix *s = &set->s[i];
        for (int j0 = 0; j0 + 1 < s->npts; j0 += CHUNK) {
            int j1 = j0 + CHUNK < s->npts - 1 ? j0 + CHUNK : s->npts - 1;
            chunk c = {i, j0, j1, {HUGE_VAL, HUGE_VAL, -HUGE_VAL, -HUGE_VAL}};
            for (int j = j0; j <= j1; j++) {
                c.bb[0] = fmin(c.bb[0], s->xy[2 * j] - tol);
                c.bb[1] = fmin(c.bb[1], s->xy[2 * j + 1] - tol);
                c.bb[2] = fmax(c.bb[2], s->xy[2 * j] + tol);
                c.bb[3] = fmax(c.bb[3], s->xy[2 * j + 1] + tol);
            }
            chunk *q = grow(ch, &cap, nch + 1, sizeof *ch);
            if (!q) {
                free(ch);
                return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
            }
            ch = q;
            ch[nch++] = c;
        }
    }
    int hcap = 0;
    sq_status st = SQ_OK;
    const double eps = 1e-12;
    for (int ci = 0; ci < nch && st == SQ_OK; ci++)
        for (int cj = ci; cj < nch && st == SQ_OK; cj++) {
            const chunk *A = &ch[ci], *B = &ch[cj];
            if (A->bb[0] > B->bb[2] || B->bb[0] > A->bb[2] || A->bb[1] > B->bb[3] ||
                B->bb[1] > A->bb[3])
                continue;
            const sq_separatrix *sa = &set->s[A->sep], *sb = &set->s[B->sep];
            for (int a = A->j0; a < A->j1 && st == SQ_OK; a++)
                for (int b = (ci == cj ? a + 1 : B->j0); b < B->j1 && st == SQ_OK; b++) {
                    if (A->sep == B->sep && abs(a - b) <= 1) continue;
                    const double *p = &sa->xy[2 * a], *q = &sb->xy[2 * b];
                    double r[2] = {p[2] - p[0], p[3] - p[1]}, s[2] = {q[2] - q[0], q[3] - q[1]};
                    /* A hit below lies on both segments' lines within tol +
                     * eps x length of each segment, so within their bounding
                     * boxes grown by that much (the 1-norms bound the
                     * lengths): pairs whose grown boxes are apart are skipped
                     * before the hypot calls that dominate the cost. */
                    double g = tol + eps * (fabs(r[0]) + fabs(r[1]) + fabs(s[0]) + fabs(s[1]));
                    if (lo(p[0], p[2]) - g > hi(q[0], q[2]) ||
                        lo(q[0], q[2]) - g > hi(p[0], p[2]) ||
                        lo(p[1], p[3]) - g > hi(q[1], q[3]) || lo(q[1], q[3]) - g > hi(p[1], p[3]))
                        continue;
                    double den = r[0] * s[1] - r[1] * s[0];
                    double lr = hypot(r[0], r[1]), ls = hypot(s[0], s[1]);
                    if (fabs(den) <= 1e-14 * lr * ls || lr == 0.0 || ls == 0.0) continue;
                    double w[2] = {q[0] - p[0], q[1] - p[1]};
                    double t = (w[0] * s[1] - w[1] * s[0]) / den;
                    double u = (w[0] * r[1] - w[1] * r[0]) / den;
                    double et = eps + tol / lr, eu = eps + tol / ls;
                    if (t < -et || t > 1 + et || u < -eu || u > 1 + eu) continue;
                    t = fmin(fmax(t, 0.0), 1.0);
                    u = fmin(fmax(u, 0.0), 1.0);
                    lay_hit h;
                    h.a = A->sep;
                    h.b = B->sep;
                    h.pa = a + t;
                    h.pb = b + u;
                    h.x = p[0] + t * r[0];
                    h.y = p[1] + t * r[1];
                    h.enda = end_of(sa, h.x, h.y, tol);
                    h.endb = end_of(sb, h.x, h.y, tol);
                    h.cosang = fabs(r[0] * s[0] + r[1] * s[1]) / (lr * ls);
                    if (h.enda >= 0 && h.endb >= 0) continue; /* a shared end node */
                    /* a polyline vertex on the other curve is seen by the two
                     * segments beside it: keep one */
                    int dup = 0;
                    for (int k = *nhits - 1; k >= 0 && k >= *nhits - 8; k--) {
                        const lay_hit *o = &(*hits)[k];
                        if (o->a == h.a && o->b == h.b && hypot(o->x - h.x, o->y - h.y) <= tol)
                            dup = 1;
                    }
                    if (!dup) st = hit_push(hits, nhits, &hcap, h, err);
                }
        }
    free(ch);
    if (st != SQ_OK) {
        free(*hits);
        *hits = NULL;
        *nhits = 0;
        return st;
    }
    /* vertices shared by segments of different chunks: drop the remaining
     * duplicates (same pair of curves, same point) */
    int m = 0;
    for (int k = 0; k < *nhits; k++) {
        int dup = 0;
        for (int o = 0; o < m && !dup; o++) {
            const lay_hit *x = &(*hits)[o], *y = &(*hits)[k];
            dup = ((x->a == y->a && x->b == y->b) || (x->a == y->b && x->b == y->a)) &&
                  hypot(x->x - y->x, x->y - y->y) <= tol;
        }
        if (!dup) (*hits)[m++] = (*hits)[k];
    }
    *nhits = m;
    return SQ_OK;
}

/* ---- graph -------------------------------------------------------------- */

void lay_graph_clear(sq_layout *L)
{
    for (int e = 0; e < L->nedges; e++) free(L->edges[e].xy);
    for (int p = 0; p < L->npatches; p++) {
        sq_layout_patch *P = &L->patches[p];
        free(P->cycle_start);
        free(P->half);
        free(P->corners);
        free(P->corner_half);
        free(P->corner_angle);
    }
    free(L->nodes);
    free(L->edges);
    free(L->patches);
    L->nodes = NULL;
    L->edges = NULL;
    L->patches = NULL;
    L->nnodes = L->nedges = L->npatches = 0;
}

typedef struct {
    int sep;
    double pos;
    int node;
} split;

static int cmp_split(const void *a, const void *b)
{
    const split *x = a, *y = b;
    if (x->sep != y->sep) return x->sep - y->sep;
    return (x->pos > y->pos) - (x->pos < y->pos);
}

typedef struct {
    double s;
    int node;
} bpt;

static int cmp_bpt(const void *a, const void *b)
{
    const bpt *x = a, *y = b;
    return (x->s > y->s) - (x->s < y->s);
}

/* graph-building state */
typedef struct {
    sq_layout *L;
    const cad_face *face;
    const sq_face_info *info;
    int cap_nodes, cap_edges;
    double tol;
    int *vstart, *vend; /* per CAD edge: vertex at its start / end */
    double *twice_area; /* per edge: twice the signed area swept n0 -> n1 */
    double *dir;        /* per half-edge: direction angle at its origin */
    double *dir2;       /* per half-edge: chord angle (tie-break) */
} gstate;

static sq_status node_add(gstate *g, sq_layout_node n, int *id, sq_error *err)
{
    sq_layout *L = g->L;
    sq_layout_node *q = grow(L->nodes, &g->cap_nodes, L->nnodes + 1, sizeof *q);
    if (!q) return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    L->nodes = q;
    q[L->nnodes] = n;
    *id = L->nnodes++;
    return SQ_OK;
}

/* The node of a separatrix end (feet found or added). */
static sq_status end_node(gstate *g, const sq_sep_end *e, const double *p, int sep, int *id,
                          sq_error *err)
{
    sq_layout *L = g->L;
    const sq_face_info *info = g->info;
    switch (e->kind) {
    case SQ_END_CORNER:
        if (e->id < 0 || e->id >= info->nvertices)
            return SQ_FAIL(err, SQ_ERR_USAGE, "separatrix %d ends at face vertex %d (of %d)", sep,
                           e->id, info->nvertices);
        *id = e->id;
        return SQ_OK;
    case SQ_END_SINGULAR:
        if (e->id < 0 || e->id >= L->nsing)
            return SQ_FAIL(err, SQ_ERR_USAGE, "separatrix %d ends at singular point %d (of %d)",
                           sep, e->id, L->nsing);
        *id = info->nvertices + e->id;
        return SQ_OK;
    case SQ_END_BOUNDARY: {
        int ne = cad_face_num_edges(g->face);
        if (e->id < 0 || e->id >= ne)
            return SQ_FAIL(err, SQ_ERR_USAGE, "separatrix %d ends on CAD edge %d (of %d)", sep,
                           e->id, ne);
        double len = cad_face_edge_length(g->face, e->id);
        if (e->s <= g->tol && g->vstart[e->id] >= 0) {
            *id = g->vstart[e->id];
            return SQ_OK;
        }
        if (e->s >= len - g->tol && g->vend[e->id] >= 0) {
            *id = g->vend[e->id];
            return SQ_OK;
        }
        for (int k = 0; k < L->nnodes; k++)
            if (L->nodes[k].kind == SQ_LNODE_FOOT && L->nodes[k].id == e->id &&
                fabs(L->nodes[k].s - e->s) <= g->tol) {
                *id = k;
                return SQ_OK;
            }
        double xy[2];
        SQ_TRY(cad_face_edge_eval(g->face, e->id, e->s, xy, NULL, NULL, err));
        sq_layout_node n = {xy[0], xy[1], SQ_LNODE_FOOT, e->id, e->s, 2, 0};
        return node_add(g, n, id, err);
    }
    default: {
        sq_layout_node n = {p[0], p[1], SQ_LNODE_OPEN, sep, 0.0, 0, 0};
        return node_add(g, n, id, err);
    }
    }
}

static sq_status edge_add(gstate *g, sq_layout_edge e, sq_error *err)
{
    sq_layout *L = g->L;
    sq_layout_edge *q = grow(L->edges, &g->cap_edges, L->nedges + 1, sizeof *q);
    if (!q) {
        free(e.xy);
        return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    }
    L->edges = q;
    e.length = 0.0;
    for (int j = 0; j + 1 < e.npts; j++)
        e.length += hypot(e.xy[2 * j + 2] - e.xy[2 * j], e.xy[2 * j + 3] - e.xy[2 * j + 1]);
    q[L->nedges++] = e;
    return SQ_OK;
}

/* Separatrix pieces between consecutive split points. */
static sq_status sep_pieces(gstate *g, int i, const split *sp, int nsp, sq_error *err)
{
    const sq_separatrix *s = &g->L->seps.s[i];
    double *buf = malloc(2 * (size_t)(s->npts + 2) * sizeof *buf);
    if (!buf) return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    sq_status st = SQ_OK;
    for (int k = 0; k + 1 < nsp && st == SQ_OK; k++) {
        const sq_layout_node *A = &g->L->nodes[sp[k].node], *B = &g->L->nodes[sp[k + 1].node];
        int n = 0;
        buf[2 * n] = A->x;
        buf[2 * n + 1] = A->y;
        n++;
        for (int j = (int)floor(sp[k].pos) + 1; j < sp[k + 1].pos; j++) {
            if (j <= sp[k].pos) continue;
            const double *p = &s->xy[2 * j];
            if (hypot(p[0] - buf[2 * n - 2], p[1] - buf[2 * n - 1]) <= g->tol) continue;
            if (hypot(p[0] - B->x, p[1] - B->y) <= g->tol) continue;
            buf[2 * n] = p[0];
            buf[2 * n + 1] = p[1];
            n++;
        }
        buf[2 * n] = B->x;
        buf[2 * n + 1] = B->y;
        n++;
        if (sp[k].node == sp[k + 1].node && n <= 3) continue; /* nothing between */
        if (n == 2 && hypot(B->x - A->x, B->y - A->y) <= g->tol) continue;
        sq_layout_edge e = {sp[k].node, sp[k + 1].node, -1, 0, 0, i, n, NULL, 0};
        e.xy = malloc(2 * (size_t)n * sizeof *e.xy);
        if (!e.xy) {
            st = SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
            break;
        }
        memcpy(e.xy, buf, 2 * (size_t)n * sizeof *buf);
        st = edge_add(g, e, err);
    }
    free(buf);
    return st;
}

static sq_status boundary_pieces(gstate *g, sq_error *err)
{
    sq_layout *L = g->L;
    int ne = cad_face_num_edges(g->face);
    bpt *pt = malloc((size_t)(L->nnodes + 2) * sizeof *pt);
    if (!pt) return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    sq_status st = SQ_OK;
    for (int e = 0; e < ne && st == SQ_OK; e++) {
        double len = cad_face_edge_length(g->face, e);
        int n = 0;
        pt[n++] = (bpt){0.0, g->vstart[e]};
        for (int k = 0; k < L->nnodes; k++)
            if (L->nodes[k].kind == SQ_LNODE_FOOT && L->nodes[k].id == e)
                pt[n++] = (bpt){L->nodes[k].s, k};
        qsort(pt + 1, (size_t)(n - 1), sizeof *pt, cmp_bpt);
        pt[n++] = (bpt){len, g->vend[e]};
        int ns = cad_face_edge_type(g->face, e) == CAD_EDGE_LINE ? 2 : 33;
        for (int k = 0; k + 1 < n && st == SQ_OK; k++) {
            sq_layout_edge E = {pt[k].node, pt[k + 1].node, e, pt[k].s, pt[k + 1].s, -1, ns, NULL,
                                0};
            E.xy = malloc(2 * (size_t)ns * sizeof *E.xy);
            if (!E.xy) {
                st = SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
                break;
            }
            for (int j = 0; j < ns && st == SQ_OK; j++)
                st = cad_face_edge_eval(g->face, e, E.s0 + (E.s1 - E.s0) * j / (ns - 1),
                                        &E.xy[2 * j], NULL, NULL, err);
            if (st == SQ_OK) { /* ends exactly at the nodes */
                E.xy[0] = L->nodes[E.n0].x;
                E.xy[1] = L->nodes[E.n0].y;
                E.xy[2 * ns - 2] = L->nodes[E.n1].x;
                E.xy[2 * ns - 1] = L->nodes[E.n1].y;
                st = edge_add(g, E, err);
            } else {
                free(E.xy);
            }
        }
    }
    free(pt);
    return st;
}

/* Direction of half-edge h (2e + reversed) at its origin, and a chord
 * direction a little further along (to order half-edges with one tangent). */
static sq_status half_dirs(gstate *g, int h, sq_error *err)
{
    const sq_layout_edge *E = &g->L->edges[h / 2];
    int rev = h & 1, n = E->npts;
    double d[2];
    if (E->cad_edge >= 0) {
        double t[2];
        SQ_TRY(cad_face_edge_eval(g->face, E->cad_edge, rev ? E->s1 : E->s0, NULL, t, NULL, err));
        d[0] = rev ? -t[0] : t[0];
        d[1] = rev ? -t[1] : t[1];
    } else {
        const double *p0 = rev ? &E->xy[2 * n - 2] : E->xy;
        d[0] = d[1] = 0.0;
        for (int j = 1; j < n; j++) {
            const double *p = &E->xy[2 * (rev ? n - 1 - j : j)];
            d[0] = p[0] - p0[0];
            d[1] = p[1] - p0[1];
            if (hypot(d[0], d[1]) > 1e-12 * g->L->scale) break;
        }
    }
    g->dir[h] = atan2(d[1], d[0]);
    /* chord to the point at arc length min(2 % of the scale, half the edge) */
    double target = fmin(0.02 * g->L->scale, 0.5 * E->length), acc = 0.0;
    const double *p0 = rev ? &E->xy[2 * n - 2] : E->xy, *p = p0;
    for (int j = 1; j < n && acc < target; j++) {
        const double *q = &E->xy[2 * (rev ? n - 1 - j : j)];
        acc += hypot(q[0] - p[0], q[1] - p[1]);
        p = q;
    }
    g->dir2[h] = atan2(p[1] - p0[1], p[0] - p0[0]);
    return SQ_OK;
}

static double wrap2pi(double a)
{
    a = fmod(a, 2.0 * M_PI);
    return a < 0 ? a + 2.0 * M_PI : a;
}

/* Is half-edge a before b counter-clockwise from angle 0? */
static int half_less(const gstate *g, int a, int b)
{
    double ta = wrap2pi(g->dir[a]), tb = wrap2pi(g->dir[b]);
    if (fabs(ta - tb) > 1e-9) return ta < tb;
    /* same tangent: the chord turned further counter-clockwise comes later */
    double ca = remainder(g->dir2[a] - g->dir[a], 2 * M_PI),
           cb = remainder(g->dir2[b] - g->dir[b], 2 * M_PI);
    return ca < cb;
}

static int uf_find(int *p, int x)
{
    while (p[x] != x) x = p[x] = p[p[x]];
    return x;
}

/* Winding number test of p against a closed polygon. */
int lay_poly_contains(const double *xy, int n, const double p[2])
{
    int wn = 0;
    for (int i = 0; i < n; i++) {
        const double *a = &xy[2 * i], *b = &xy[2 * ((i + 1) % n)];
        double c = (b[0] - a[0]) * (p[1] - a[1]) - (p[0] - a[0]) * (b[1] - a[1]);
        if (a[1] <= p[1]) {
            if (b[1] > p[1] && c > 0) wn++;
        } else if (b[1] <= p[1] && c < 0) {
            wn--;
        }
    }
    return wn != 0;
}

double *lay_cycle_polygon(const sq_layout *L, const sq_layout_half *h, int n, int *np)
{
    int tot = 0;
    for (int k = 0; k < n; k++) tot += L->edges[h[k].edge].npts - 1;
    double *xy = malloc(2 * (size_t)(tot > 0 ? tot : 1) * sizeof *xy);
    if (!xy) return NULL;
    int m = 0;
    for (int k = 0; k < n; k++) {
        const sq_layout_edge *E = &L->edges[h[k].edge];
        for (int j = 0; j + 1 < E->npts; j++) {
            int jj = h[k].reversed ? E->npts - 1 - j : j;
            xy[2 * m] = E->xy[2 * jj];
            xy[2 * m + 1] = E->xy[2 * jj + 1];
            m++;
        }
    }
    *np = m;
    return xy;
}

typedef struct {
    int start, n;   /* into the cycle half-edge array */
    double area;    /* signed */
    int comp;
    int outside;    /* uses a boundary edge backwards */
    int patch;
} cycinfo;

static sq_status build_patches(gstate *g, sq_error *err)
{
    sq_layout *L = g->L;
    int nh = 2 * L->nedges, nn = L->nnodes;
    sq_status st = SQ_OK;
    int *deg = calloc((size_t)nn + 1, sizeof *deg), *off = calloc((size_t)nn + 1, sizeof *off);
    int *out = malloc((size_t)(nh > 0 ? nh : 1) * sizeof *out);
    int *pos = malloc((size_t)(nh > 0 ? nh : 1) * sizeof *pos);
    int *next = malloc((size_t)(nh > 0 ? nh : 1) * sizeof *next);
    int *seen = calloc((size_t)(nh > 0 ? nh : 1), sizeof *seen);
    int *cyc = malloc((size_t)(nh > 0 ? nh : 1) * sizeof *cyc);
    int *uf = malloc((size_t)(nn > 0 ? nn : 1) * sizeof *uf);
    cycinfo *ci = malloc((size_t)(nh > 0 ? nh : 1) * sizeof *ci);
    if (!deg || !off || !out || !pos || !next || !seen || !cyc || !uf || !ci) {
        st = SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
        goto done;
    }
    /* half-edges leaving each node, sorted counter-clockwise */
    for (int h = 0; h < nh; h++) {
        int o = (h & 1) ? L->edges[h / 2].n1 : L->edges[h / 2].n0;
        deg[o]++;
    }
    for (int v = 0; v < nn; v++) {
        off[v + 1] = off[v] + deg[v];
        L->nodes[v].degree = deg[v];
        deg[v] = 0;
    }
    for (int h = 0; h < nh; h++) {
        int o = (h & 1) ? L->edges[h / 2].n1 : L->edges[h / 2].n0;
        out[off[o] + deg[o]++] = h;
    }
    for (int v = 0; v < nn; v++) {
        int *a = &out[off[v]];
        for (int i = 1; i < deg[v]; i++) { /* insertion sort */
            int x = a[i], j = i - 1;
            while (j >= 0 && half_less(g, x, a[j])) {
                a[j + 1] = a[j];
                j--;
            }
            a[j + 1] = x;
        }
        for (int i = 0; i < deg[v]; i++) pos[a[i]] = i;
    }
    /* next half-edge around the face on the left: the clockwise neighbour
     * of the twin at the destination */
    for (int h = 0; h < nh; h++) {
        int t = h ^ 1, v = (t & 1) ? L->edges[t / 2].n1 : L->edges[t / 2].n0;
        next[h] = out[off[v] + (pos[t] + deg[v] - 1) % deg[v]];
    }
    for (int v = 0; v < nn; v++) uf[v] = v;
    for (int e = 0; e < L->nedges; e++) {
        int a = uf_find(uf, L->edges[e].n0), b = uf_find(uf, L->edges[e].n1);
        uf[a] = b;
    }
    int ncyc = 0, m = 0;
    for (int h0 = 0; h0 < nh; h0++) {
        if (seen[h0]) continue;
        cycinfo c = {m, 0, 0.0, 0, 0, -1};
        for (int h = h0; !seen[h]; h = next[h]) {
            seen[h] = 1;
            cyc[m++] = h;
            c.n++;
            const sq_layout_edge *E = &L->edges[h / 2];
            c.area += 0.5 * ((h & 1) ? -g->twice_area[h / 2] : g->twice_area[h / 2]);
            if (E->cad_edge >= 0 && (h & 1)) c.outside = 1;
        }
        c.comp = uf_find(uf, L->edges[h0 / 2].n0);
        ci[ncyc++] = c;
    }
    /* patches: counter-clockwise inside cycles, then holes assigned */
    int np = 0;
    for (int c = 0; c < ncyc; c++)
        if (!ci[c].outside && ci[c].area > 0) ci[c].patch = np++;
    L->patches = calloc((size_t)(np > 0 ? np : 1), sizeof *L->patches);
    if (!L->patches) {
        st = SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
        goto done;
    }
    L->npatches = np;
    int *owner = malloc((size_t)(ncyc > 0 ? ncyc : 1) * sizeof *owner);
    if (!owner) {
        st = SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
        goto done;
    }
    for (int c = 0; c < ncyc; c++) owner[c] = ci[c].patch;
    for (int c = 0; c < ncyc && st == SQ_OK; c++) {
        if (ci[c].outside || ci[c].area > 0) continue;
        int h = cyc[ci[c].start];
        int v = (h & 1) ? L->edges[h / 2].n1 : L->edges[h / 2].n0;
        double p[2] = {L->nodes[v].x, L->nodes[v].y}, best = HUGE_VAL;
        for (int o = 0; o < ncyc; o++) {
            if (owner[o] < 0 || ci[o].patch < 0 || ci[o].comp == ci[c].comp) continue;
            if (ci[o].area >= best) continue;
            sq_layout_half *hh = malloc((size_t)ci[o].n * sizeof *hh);
            if (!hh) {
                st = SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
                break;
            }
            for (int k = 0; k < ci[o].n; k++)
                hh[k] = (sq_layout_half){cyc[ci[o].start + k] / 2, cyc[ci[o].start + k] & 1};
            int npoly;
            double *poly = lay_cycle_polygon(L, hh, ci[o].n, &npoly);
            free(hh);
            if (!poly) {
                st = SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
                break;
            }
            if (lay_poly_contains(poly, npoly, p)) {
                best = ci[o].area;
                owner[c] = ci[o].patch;
            }
            free(poly);
        }
    }
    /* fill the patches */
    for (int p = 0; p < np && st == SQ_OK; p++) {
        sq_layout_patch *P = &L->patches[p];
        int ncy = 0, nhalf = 0;
        for (int c = 0; c < ncyc; c++)
            if (owner[c] == p && !ci[c].outside) {
                ncy++;
                nhalf += ci[c].n;
            }
        P->cycle_start = malloc((size_t)(ncy + 1) * sizeof *P->cycle_start);
        P->half = malloc((size_t)nhalf * sizeof *P->half);
        P->corners = malloc((size_t)nhalf * sizeof *P->corners);
        P->corner_half = malloc((size_t)nhalf * sizeof *P->corner_half);
        P->corner_angle = malloc((size_t)nhalf * sizeof *P->corner_angle);
        if (!P->cycle_start || !P->half || !P->corners || !P->corner_half || !P->corner_angle) {
            st = SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
            break;
        }
        P->ncycles = 0;
        P->nhalf = 0;
        P->area = 0.0;
        /* the outer (positive) cycle first */
        for (int pass = 0; pass < 2; pass++)
            for (int c = 0; c < ncyc; c++) {
                if (owner[c] != p || ci[c].outside || (pass == 0) != (ci[c].patch == p)) continue;
                P->cycle_start[P->ncycles++] = P->nhalf;
                for (int k = 0; k < ci[c].n; k++) {
                    int h = cyc[ci[c].start + k];
                    P->half[P->nhalf++] = (sq_layout_half){h / 2, h & 1};
                }
                P->area += ci[c].area;
            }
        P->cycle_start[P->ncycles] = P->nhalf;
        /* corners: interior angle between the twin of the incoming and the
         * outgoing half-edge */
        double tol = SQ_LAYOUT_CORNER_TOL_DEG * M_PI / 180.0;
        P->ncorners = 0;
        for (int c = 0; c < P->ncycles; c++) {
            int a = P->cycle_start[c], b = P->cycle_start[c + 1];
            for (int k = a; k < b; k++) {
                int kn = k + 1 < b ? k + 1 : a;
                int hin = 2 * P->half[k].edge + P->half[k].reversed;
                int hout = 2 * P->half[kn].edge + P->half[kn].reversed;
                double ang = (hin ^ 1) == hout ? 2.0 * M_PI
                                               : wrap2pi(g->dir[hin ^ 1] - g->dir[hout]);
                if (fabs(ang - M_PI) > tol) {
                    int v = (hout & 1) ? L->edges[hout / 2].n1 : L->edges[hout / 2].n0;
                    P->corners[P->ncorners] = v;
                    P->corner_half[P->ncorners] = kn;
                    P->corner_angle[P->ncorners] = ang;
                    P->ncorners++;
                }
            }
        }
        for (int k = 0; k < 5; k++) P->side_start[k] = -1;
        if (P->ncorners == 4 && P->ncycles == 1) {
            /* rotate so that half[0] leaves corner 0; sort corners by position */
            int r = P->corner_half[0], n = P->nhalf;
            sq_layout_half *tmp = malloc((size_t)n * sizeof *tmp);
            if (!tmp) {
                st = SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
                break;
            }
            for (int k = 0; k < n; k++) tmp[k] = P->half[(k + r) % n];
            memcpy(P->half, tmp, (size_t)n * sizeof *tmp);
            free(tmp);
            for (int k = 0; k < 4; k++) P->corner_half[k] = (P->corner_half[k] - r + n) % n;
            /* corner_half increases along the cycle from corner 0 */
            for (int k = 0; k < 4; k++) P->side_start[k] = P->corner_half[k];
            P->side_start[4] = n;
        }
    }
    free(owner);
done:
    free(deg);
    free(off);
    free(out);
    free(pos);
    free(next);
    free(seen);
    free(cyc);
    free(uf);
    free(ci);
    return st;
}

sq_status lay_graph_build(sq_layout *L, const cad_face *face, const sq_face_info *info,
                          sq_error *err)
{
    lay_graph_clear(L);
    gstate g;
    memset(&g, 0, sizeof g);
    g.L = L;
    g.face = face;
    g.info = info;
    g.tol = 1e-9 * L->scale;
    int ne = cad_face_num_edges(face);
    sq_status st = SQ_OK;
    lay_hit *hits = NULL;
    int nhits = 0;
    split *sp = NULL;
    g.vstart = malloc((size_t)(ne > 0 ? ne : 1) * sizeof *g.vstart);
    g.vend = malloc((size_t)(ne > 0 ? ne : 1) * sizeof *g.vend);
    if (!g.vstart || !g.vend) {
        st = SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
        goto done;
    }
    for (int e = 0; e < ne; e++) g.vstart[e] = g.vend[e] = -1;
    /* nodes: face vertices, then singular points */
    for (int k = 0; k < info->nvertices && st == SQ_OK; k++) {
        const sq_vertex *v = &info->vertices[k];
        sq_layout_node n = {v->x, v->y, SQ_LNODE_CORNER, k, 0.0, L->vertex_quads[k], 0};
        int id;
        st = node_add(&g, n, &id, err);
        g.vstart[v->edge_out] = k;
        g.vend[v->edge_in] = k;
    }
    for (int k = 0; k < L->nsing && st == SQ_OK; k++) {
        sq_layout_node n = {L->sing[k].x, L->sing[k].y, SQ_LNODE_SINGULAR, k, 0.0,
                            L->sing[k].valence, 0};
        int id;
        st = node_add(&g, n, &id, err);
    }
    if (st != SQ_OK) goto done;
    /* separatrix ends; the polylines' ends are put exactly on their nodes */
    int nsep = L->seps.n;
    int *ends = malloc(2 * (size_t)(nsep > 0 ? nsep : 1) * sizeof *ends);
    if (!ends) {
        st = SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
        goto done;
    }
    for (int i = 0; i < nsep && st == SQ_OK; i++) {
        sq_separatrix *s = &L->seps.s[i];
        if (s->npts < 2) {
            st = SQ_FAIL(err, SQ_ERR_USAGE, "separatrix %d has %d points", i, s->npts);
            break;
        }
        st = end_node(&g, &s->start, s->xy, i, &ends[2 * i], err);
        if (st == SQ_OK) st = end_node(&g, &s->end, &s->xy[2 * s->npts - 2], i, &ends[2 * i + 1], err);
        if (st != SQ_OK) break;
        const sq_layout_node *a = &L->nodes[ends[2 * i]], *b = &L->nodes[ends[2 * i + 1]];
        s->xy[0] = a->x;
        s->xy[1] = a->y;
        s->xy[2 * s->npts - 2] = b->x;
        s->xy[2 * s->npts - 1] = b->y;
    }
    /* intersections: crossings become nodes, ends on another curve split it */
    if (st == SQ_OK) st = lay_intersections(&L->seps, g.tol, &hits, &nhits, err);
    int nsp = 0;
    if (st == SQ_OK) {
        sp = malloc((size_t)(2 * nhits + 2 * nsep + 1) * sizeof *sp);
        if (!sp) st = SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    }
    for (int i = 0; i < nsep && st == SQ_OK; i++) {
        sp[nsp++] = (split){i, 0.0, ends[2 * i]};
        sp[nsp++] = (split){i, (double)(L->seps.s[i].npts - 1), ends[2 * i + 1]};
    }
    for (int k = 0; k < nhits && st == SQ_OK; k++) {
        const lay_hit *h = &hits[k];
        if (h->enda >= 0) {
            sp[nsp++] = (split){h->b, h->pb, ends[2 * h->a + h->enda]};
        } else if (h->endb >= 0) {
            sp[nsp++] = (split){h->a, h->pa, ends[2 * h->b + h->endb]};
        } else {
            int id = -1;
            for (int v = 0; v < L->nnodes && id < 0; v++)
                if (L->nodes[v].kind == SQ_LNODE_CROSSING &&
                    hypot(L->nodes[v].x - h->x, L->nodes[v].y - h->y) <= g.tol)
                    id = v;
            if (id < 0) {
                sq_layout_node n = {h->x, h->y, SQ_LNODE_CROSSING, -1, 0.0, 4, 0};
                st = node_add(&g, n, &id, err);
            }
            sp[nsp++] = (split){h->a, h->pa, id};
            sp[nsp++] = (split){h->b, h->pb, id};
        }
    }
    free(ends);
    if (st != SQ_OK) goto done;
    qsort(sp, (size_t)nsp, sizeof *sp, cmp_split);
    /* boundary pieces first (edges 0..), then separatrix pieces */
    st = boundary_pieces(&g, err);
    for (int a = 0; a < nsp && st == SQ_OK;) {
        int b = a;
        while (b < nsp && sp[b].sep == sp[a].sep) b++;
        st = sep_pieces(&g, sp[a].sep, &sp[a], b - a, err);
        a = b;
    }
    if (st != SQ_OK) goto done;
    /* per-edge Green integrals and half-edge directions */
    g.twice_area = malloc((size_t)(L->nedges > 0 ? L->nedges : 1) * sizeof *g.twice_area);
    g.dir = malloc(2 * (size_t)(L->nedges > 0 ? L->nedges : 1) * sizeof *g.dir);
    g.dir2 = malloc(2 * (size_t)(L->nedges > 0 ? L->nedges : 1) * sizeof *g.dir2);
    if (!g.twice_area || !g.dir || !g.dir2) {
        st = SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
        goto done;
    }
    for (int e = 0; e < L->nedges && st == SQ_OK; e++) {
        const sq_layout_edge *E = &L->edges[e];
        if (E->cad_edge >= 0) {
            st = cad_face_edge_green(face, E->cad_edge, E->s0, E->s1, &g.twice_area[e], err);
        } else {
            double a = 0.0;
            for (int j = 0; j + 1 < E->npts; j++)
                a += E->xy[2 * j] * E->xy[2 * j + 3] - E->xy[2 * j + 2] * E->xy[2 * j + 1];
            g.twice_area[e] = a;
        }
        if (st == SQ_OK) st = half_dirs(&g, 2 * e, err);
        if (st == SQ_OK) st = half_dirs(&g, 2 * e + 1, err);
    }
    if (st == SQ_OK) st = build_patches(&g, err);
done:
    free(hits);
    free(sp);
    free(g.vstart);
    free(g.vend);
    free(g.twice_area);
    free(g.dir);
    free(g.dir2);
    if (st != SQ_OK) lay_graph_clear(L);
    return st;
}

void sq_layout_free(sq_layout *L)
{
    if (!L) return;
    lay_graph_clear(L);
    free(L->sing);
    free(L->role);
    free(L->vertex_quads);
    lay_sepset_free(&L->seps);
    memset(L, 0, sizeof *L);
}

sq_status sq_layout_graph(const cad_face *face, const sq_face_info *info, const int *vertex_quads,
                          int nsing, const sq_singularity *sing, const sq_separatrix_set *seps,
                          sq_layout *out, sq_error *err)
{
    memset(out, 0, sizeof *out);
    if (!face || !info || !vertex_quads || (nsing > 0 && !sing) || nsing < 0)
        return SQ_FAIL(err, SQ_ERR_USAGE, "sq_layout_graph: missing argument");
    sq_layout *L = out;
    sq_status st = SQ_OK;
    L->face_area = info->area;
    L->scale = hypot(info->bbox[2] - info->bbox[0], info->bbox[3] - info->bbox[1]);
    L->nvertices = info->nvertices;
    L->vertex_quads = malloc((size_t)(info->nvertices > 0 ? info->nvertices : 1) *
                             sizeof *L->vertex_quads);
    if (!L->vertex_quads) return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    memcpy(L->vertex_quads, vertex_quads, (size_t)info->nvertices * sizeof *vertex_quads);
    for (int k = 0; k < nsing && st == SQ_OK; k++) {
        st = lay_sing_push(L, sing[k].x, sing[k].y, sing[k].valence, SQ_LROLE_INPUT, err);
        if (st == SQ_OK) L->sing[k].origin = sing[k].origin;
    }
    for (int k = 0; seps && k < seps->n && st == SQ_OK; k++) {
        const sq_separatrix *s = &seps->s[k];
        st = lay_sep_push(&L->seps, s->xy, s->npts, s->start, s->end, err);
        if (st == SQ_OK) {
            L->seps.s[L->seps.n - 1].start_angle = s->start_angle;
            L->seps.s[L->seps.n - 1].merged = s->merged;
        }
    }
    if (st == SQ_OK) st = lay_graph_build(L, face, info, err);
    if (st != SQ_OK) sq_layout_free(L);
    return st;
}

sq_status sq_layout_edge_point(const sq_layout *L, const cad_face *face, int e, double t,
                               double xy[2], sq_error *err)
{
    if (e < 0 || e >= L->nedges) return SQ_FAIL(err, SQ_ERR_USAGE, "edge %d of %d", e, L->nedges);
    const sq_layout_edge *E = &L->edges[e];
    t = fmin(fmax(t, 0.0), 1.0);
    if (E->cad_edge >= 0)
        return cad_face_edge_eval(face, E->cad_edge, E->s0 + t * (E->s1 - E->s0), xy, NULL, NULL,
                                  err);
    double target = t * E->length, acc = 0.0;
    for (int j = 0; j + 1 < E->npts; j++) {
        double l = hypot(E->xy[2 * j + 2] - E->xy[2 * j], E->xy[2 * j + 3] - E->xy[2 * j + 1]);
        if (acc + l >= target || j + 2 == E->npts) {
            double f = l > 0 ? fmin(fmax((target - acc) / l, 0.0), 1.0) : 0.0;
            xy[0] = E->xy[2 * j] + f * (E->xy[2 * j + 2] - E->xy[2 * j]);
            xy[1] = E->xy[2 * j + 1] + f * (E->xy[2 * j + 3] - E->xy[2 * j + 1]);
            return SQ_OK;
        }
        acc += l;
    }
    xy[0] = E->xy[0];
    xy[1] = E->xy[1];
    return SQ_OK;
}
