/* semquad — the faces of the layout's planar graph, its patches (layout.h
 * design 2 and 3): half-edges sorted at every node, cycles walked with the
 * face on the left, holes given to the patch around them, corners by the
 * interior angle, a quad patch's sides. */
#include "layout_internal.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* patch-building state */
typedef struct {
    sq_layout *L;
    const cad_face *face;
    double *twice_area; /* per edge: twice the signed area swept n0 -> n1 */
    double *dir;        /* per half-edge: direction angle at its origin */
    double *dir2;       /* per half-edge: chord angle (tie-break) */
} pstate;

/* Direction of half-edge h (2e + reversed) at its origin, and a chord
 * direction a little further along (to order half-edges with one tangent). */
static sq_status half_dirs(pstate *g, int h, sq_error *err)
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
static int half_less(const pstate *g, int a, int b)
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

/* next[h]: the half-edge after h around the face on its left, the
 * clockwise neighbour of its twin at its destination among the half-edges
 * leaving that node, sorted counter-clockwise; sets the nodes' degrees. */
static sq_status successors(pstate *g, int *next, sq_error *err)
{
    sq_layout *L = g->L;
    int nh = 2 * L->nedges, nn = L->nnodes;
    int *deg = calloc((size_t)nn + 1, sizeof *deg), *off = calloc((size_t)nn + 1, sizeof *off);
    int *out = malloc((size_t)(nh > 0 ? nh : 1) * sizeof *out);
    int *pos = malloc((size_t)(nh > 0 ? nh : 1) * sizeof *pos);
    if (!deg || !off || !out || !pos) {
        free(deg);
        free(off);
        free(out);
        free(pos);
        return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
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
    free(deg);
    free(off);
    free(out);
    free(pos);
    return SQ_OK;
}

/* The cycles of next: their half-edges in cyc, in ci each one's start,
 * length, signed area, connected component and whether it bounds the
 * outside; returns how many, or -1 when out of memory. */
static int walk_cycles(const pstate *g, const int *next, int *cyc, cycinfo *ci)
{
    const sq_layout *L = g->L;
    int nh = 2 * L->nedges, nn = L->nnodes;
    int *seen = calloc((size_t)(nh > 0 ? nh : 1), sizeof *seen);
    int *uf = malloc((size_t)(nn > 0 ? nn : 1) * sizeof *uf);
    if (!seen || !uf) {
        free(seen);
        free(uf);
        return -1;
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
    free(seen);
    free(uf);
    return ncyc;
}

/* owner[c]: the patch cycle c bounds, its own for a counter-clockwise
 * inside cycle, for a clockwise one (a hole) the smallest such cycle of
 * another component that contains it. */
static sq_status assign_holes(const pstate *g, const int *cyc, const cycinfo *ci, int ncyc,
                              int *owner, sq_error *err)
{
    const sq_layout *L = g->L;
    sq_status st = SQ_OK;
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
    return st;
}

/* Is every sector at node v a patch corner, whatever its angle?  At a
 * singular point, a face vertex or a foot where separatrices meet (degree
 * >= 3) the sectors are the patches' corners by construction: a singular
 * point of valence V is a corner of V patches, a vertex taking q quads of q,
 * a foot of n separatrices of n + 1 (layout_check.c).  Read by angle, a
 * sector within SQ_LAYOUT_CORNER_TOL_DEG of 180 deg there (a separatrix
 * leaving a singular point or meeting the boundary at a shallow angle) made
 * a patch of 3 corners and a node of the wrong corner count that no repair
 * could mend: it is a quad corner of a wide angle, its Jacobian positive.
 * The nodes the repairs insert keep the angle rule: a T-junction is a
 * defect, and a midpoint whose spoke leaves at 180 deg a failed split (a
 * needle's centroid: its quads would be wedges). */
static int sector_is_corner(const sq_layout *L, int v)
{
    const sq_layout_node *n = &L->nodes[v];
    if (n->degree < 3) return 0;
    switch (n->kind) {
    case SQ_LNODE_SINGULAR:
        return L->role[n->id] == SQ_LROLE_INPUT;
    case SQ_LNODE_CORNER:
    case SQ_LNODE_FOOT:
        return 1;
    default:
        return 0;
    }
}

/* Is node v one the repairs inserted (a crossing made a node, a
 * T-junction, a split's centre)? */
static int is_inserted(const sq_layout *L, int v)
{
    const sq_layout_node *n = &L->nodes[v];
    return n->kind == SQ_LNODE_CROSSING ||
           (n->kind == SQ_LNODE_SINGULAR && L->role[n->id] != SQ_LROLE_INPUT);
}

/* Is node v a bend of a patch side: a face vertex taking 2 quads with no
 * separatrix at it, its angle within SQ_LAYOUT_BEND_TOL_DEG of π or a
 * periodic bend (sq_layout_node.bend) (trace.c starts none there;
 * layout_check.c wants it a corner of no patch)? */
static int is_bend(const sq_layout *L, int v, double ang)
{
    const sq_layout_node *n = &L->nodes[v];
    return n->kind == SQ_LNODE_CORNER && n->degree == 2 && L->vertex_quads[n->id] == 2 &&
           (n->bend || fabs(ang - M_PI) < SQ_LAYOUT_BEND_TOL_DEG * M_PI / 180.0);
}

/* Patch p from the cycles it owns: its half-edges (the outer cycle first),
 * area and corners; a quad patch's sides. */
static sq_status fill_patch(const pstate *g, int p, const int *cyc, const cycinfo *ci, int ncyc,
                            const int *owner, sq_error *err)
{
    sq_layout *L = g->L;
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
    if (!P->cycle_start || !P->half || !P->corners || !P->corner_half || !P->corner_angle)
        return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
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
            int v = (hout & 1) ? L->edges[hout / 2].n1 : L->edges[hout / 2].n0;
            double tv = L->inserted_corner_tol > 0.0 && is_inserted(L, v) ? L->inserted_corner_tol
                                                                        : tol;
            if ((fabs(ang - M_PI) > tv && !is_bend(L, v, ang)) || sector_is_corner(L, v)) {
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
        if (!tmp) return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
        for (int k = 0; k < n; k++) tmp[k] = P->half[(k + r) % n];
        memcpy(P->half, tmp, (size_t)n * sizeof *tmp);
        free(tmp);
        for (int k = 0; k < 4; k++) P->corner_half[k] = (P->corner_half[k] - r + n) % n;
        /* corner_half increases along the cycle from corner 0 */
        for (int k = 0; k < 4; k++) P->side_start[k] = P->corner_half[k];
        P->side_start[4] = n;
    }
    return SQ_OK;
}

static sq_status build_patches(pstate *g, sq_error *err)
{
    sq_layout *L = g->L;
    int nh = 2 * L->nedges;
    sq_status st = SQ_OK;
    int *next = malloc((size_t)(nh > 0 ? nh : 1) * sizeof *next);
    int *cyc = malloc((size_t)(nh > 0 ? nh : 1) * sizeof *cyc);
    cycinfo *ci = malloc((size_t)(nh > 0 ? nh : 1) * sizeof *ci);
    int *owner = NULL;
    if (!next || !cyc || !ci) {
        st = SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
        goto done;
    }
    st = successors(g, next, err);
    if (st != SQ_OK) goto done;
    int ncyc = walk_cycles(g, next, cyc, ci);
    if (ncyc < 0) {
        st = SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
        goto done;
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
    owner = malloc((size_t)(ncyc > 0 ? ncyc : 1) * sizeof *owner);
    if (!owner) {
        st = SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
        goto done;
    }
    st = assign_holes(g, cyc, ci, ncyc, owner, err);
    for (int p = 0; p < np && st == SQ_OK; p++) st = fill_patch(g, p, cyc, ci, ncyc, owner, err);
done:
    free(next);
    free(cyc);
    free(ci);
    free(owner);
    return st;
}

sq_status lay_patches_build(sq_layout *L, const cad_face *face, sq_error *err)
{
    pstate g = {L, face, NULL, NULL, NULL};
    sq_status st = SQ_OK;
    /* per-edge Green integrals and half-edge directions */
    g.twice_area = malloc((size_t)(L->nedges > 0 ? L->nedges : 1) * sizeof *g.twice_area);
    g.dir = malloc(2 * (size_t)(L->nedges > 0 ? L->nedges : 1) * sizeof *g.dir);
    g.dir2 = malloc(2 * (size_t)(L->nedges > 0 ? L->nedges : 1) * sizeof *g.dir2);
    if (!g.twice_area || !g.dir || !g.dir2) st = SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
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
    free(g.twice_area);
    free(g.dir);
    free(g.dir2);
    return st;
}
