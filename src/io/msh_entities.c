/* semquad — the model entities of a quad mesh's MSH file (msh_entities.h):
 * curves from the boundary sides and the sides between faces, points where
 * curves end or meet, each node on the least entity holding it. */
#include "msh_entities.h"

#include "quad_edges.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static int region_of(const sq_quad_mesh *m, int q) { return m->region ? m->region[q] : 0; }

/* The element sides on curves: side[i] = 4q + k, curve[i] its curve,
 * minus[i] the face on its right (-1: none, a boundary side). */
typedef struct {
    int n;
    int *side, *curve, *minus;
} curve_side_list;

/* Label the interface sides side[from..n) with curves from *ncurves on:
 * a curve goes on through a node of two interface sides between the same
 * two faces that no boundary side touches. */
static sq_status chain_interfaces(const sq_quad_mesh *m, curve_side_list *cs, int from,
                                  int *ncurves, sq_error *err)
{
    int n = cs->n - from, nv = m->nnodes;
    int *deg = calloc((size_t)nv + 1, sizeof *deg), *slot = malloc(sizeof(int) * (2 * (size_t)nv + 1));
    char *on_bnd = calloc((size_t)nv + 1, 1);
    int *stack = malloc(sizeof(int) * ((size_t)n + 1));
    if (!deg || !slot || !on_bnd || !stack) {
        free(deg), free(slot), free(on_bnd), free(stack);
        return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    }
    for (int b = 0; b < m->nbnd; b++)
        for (int j = 0; j < 2; j++) on_bnd[sq_quad_corner_node(m, m->bnd_quad[b], (m->bnd_side[b] + j) % 4)] = 1;
    for (int i = 0; i < n; i++)
        for (int j = 0; j < 2; j++) {
            int s = cs->side[from + i], v = sq_quad_corner_node(m, s / 4, (s % 4 + j) % 4);
            if (deg[v] < 2) slot[2 * v + deg[v]] = i;
            deg[v]++;
        }
    for (int i = 0; i < n; i++) {
        if (cs->curve[from + i] >= 0) continue;
        int top = 0, c = (*ncurves)++;
        cs->curve[from + i] = c, stack[top++] = i;
        while (top > 0) {
            int k = stack[--top], s = cs->side[from + k];
            for (int j = 0; j < 2; j++) {
                int v = sq_quad_corner_node(m, s / 4, (s % 4 + j) % 4);
                if (deg[v] != 2 || on_bnd[v]) continue;
                int o = slot[2 * v] == k ? slot[2 * v + 1] : slot[2 * v];
                if (cs->curve[from + o] >= 0 || cs->minus[from + o] != cs->minus[from + k] ||
                    region_of(m, cs->side[from + o] / 4) != region_of(m, s / 4))
                    continue;
                cs->curve[from + o] = c, stack[top++] = o;
            }
        }
    }
    free(deg), free(slot), free(on_bnd), free(stack);
    return SQ_OK;
}

/* The boundary sides (curve = tag), then one side per edge between two
 * faces (the lower face's), chained into curves. */
static sq_status list_curve_sides(const sq_quad_mesh *m, curve_side_list *cs, int *ncurves,
                                  sq_error *err)
{
    sq_quad_edges ed = {0};
    if (m->nregions > 1) SQ_TRY(sq_quad_edges_build(m, 1, &ed, err));
    size_t cap = (size_t)m->nbnd + (m->nregions > 1 ? 4 * (size_t)m->nquads : 0) + 1;
    cs->side = malloc(sizeof(int) * cap), cs->curve = malloc(sizeof(int) * cap);
    cs->minus = malloc(sizeof(int) * cap);
    if (!cs->side || !cs->curve || !cs->minus) {
        sq_quad_edges_free(&ed);
        return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    }
    for (int b = 0; b < m->nbnd; b++, cs->n++)
        cs->side[cs->n] = 4 * m->bnd_quad[b] + m->bnd_side[b], cs->curve[cs->n] = m->bnd_tag[b], cs->minus[cs->n] = -1;
    int from = cs->n;
    for (int s = 0; m->nregions > 1 && s < 4 * m->nquads; s++) {
        int o = ed.owner[ed.side_edge[s]], ro = region_of(m, o / 4), rs = region_of(m, s / 4);
        if (o == s || ro == rs) continue;
        cs->side[cs->n] = ro < rs ? o : s, cs->curve[cs->n] = -1, cs->minus[cs->n++] = ro < rs ? rs : ro;
    }
    *ncurves = m->ntags;
    sq_status st = chain_interfaces(m, cs, from, ncurves, err);
    sq_quad_edges_free(&ed);
    return st;
}

typedef struct {
    int node, curve, sign; /* +1: a side of the curve begins at the node, -1: ends */
} side_end;

static int end_cmp(const void *pa, const void *pb)
{
    const side_end *a = pa, *b = pb;
    if (a->node != b->node) return a->node < b->node ? -1 : 1;
    if (a->curve != b->curve) return a->curve < b->curve ? -1 : 1;
    return (a->sign > b->sign) - (a->sign < b->sign);
}

/* Points: nodes where sides of a curve begin more often than they end (its
 * first point) or end more often (its last), or on sides of two curves. */
static sq_status find_points(const sq_quad_mesh *m, const curve_side_list *cs, sq_msh_entities *e,
                             sq_error *err)
{
    side_end *r = malloc(sizeof *r * (2 * (size_t)cs->n + 1));
    e->point_node = malloc(sizeof(int) * (2 * (size_t)cs->n + 1));
    if (!r || !e->point_node) {
        free(r);
        return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    }
    for (int i = 0; i < cs->n; i++)
        for (int j = 0; j < 2; j++)
            r[2 * i + j] = (side_end){sq_quad_corner_node(m, cs->side[i] / 4, (cs->side[i] % 4 + j) % 4),
                                      cs->curve[i], j ? -1 : 1};
    qsort(r, 2 * (size_t)cs->n, sizeof *r, end_cmp);
    for (size_t a = 0, b; a < 2 * (size_t)cs->n; a = b) { /* one node: r[a..b) */
        int curves = 0;
        for (b = a; b < 2 * (size_t)cs->n && r[b].node == r[a].node; b++)
            curves += b == a || r[b].curve != r[b - 1].curve;
        int p = e->npoints, point = curves > 1;
        for (size_t c = a, d; c < b; c = d) { /* one curve: r[c..d) */
            int net = 0;
            for (d = c; d < b && r[d].curve == r[c].curve; d++) net += r[d].sign;
            int *slot = &e->curve_ends[2 * r[c].curve + (net < 0)];
            if (net != 0 && *slot < 0) *slot = p;
            point |= net != 0;
        }
        if (point) e->point_node[e->npoints++] = r[a].node;
    }
    free(r);
    return SQ_OK;
}

static void grow_box(double *b, const double *x)
{
    b[0] = fmin(b[0], x[0]), b[1] = fmin(b[1], x[1]);
    b[2] = fmax(b[2], x[0]), b[3] = fmax(b[3], x[1]);
}

/* Each node's entity (a point, else the first curve with a side through
 * it, else its quad's face), the boxes, the curves' faces and side counts. */
static void classify_nodes(const sq_quad_mesh *m, const curve_side_list *cs, sq_msh_entities *e,
                           int *ent)
{
    int Q = m->order, npe = (Q + 1) * (Q + 1), P = e->npoints, C = e->ncurves;
    for (int v = 0; v < m->nnodes; v++) ent[v] = -1;
    for (int p = 0; p < P; p++) ent[e->point_node[p]] = p;
    for (int k = 0; k < 4 * (C + e->nsurfaces); k++) e->curve_bb[k] = k % 4 < 2 ? HUGE_VAL : -HUGE_VAL;
    for (int i = 0; i < cs->n; i++) {
        int q = cs->side[i] / 4, k = cs->side[i] % 4, c = cs->curve[i];
        const int *conn = &m->conn[(size_t)q * npe];
        for (int s = 0; s <= Q; s++) {
            int v = conn[sq_quad_side_node(Q, k, s)];
            if (ent[v] < 0) ent[v] = P + c;
            grow_box(&e->curve_bb[4 * c], &m->xy[2 * (size_t)v]);
        }
        e->curve_sides[c]++;
        if (e->curve_faces[2 * c] < 0) e->curve_faces[2 * c] = region_of(m, q), e->curve_faces[2 * c + 1] = cs->minus[i];
    }
    for (int q = 0; q < m->nquads; q++)
        for (int k = 0; k < npe; k++) {
            int v = m->conn[(size_t)q * npe + k], r = region_of(m, q);
            if (ent[v] < 0) ent[v] = P + C + r;
            grow_box(&e->surface_bb[4 * r], &m->xy[2 * (size_t)v]);
        }
    for (int k = 0; k < C + e->nsurfaces; k++)
        if (e->curve_bb[4 * k] > e->curve_bb[4 * k + 2])
            for (int j = 0; j < 4; j++) e->curve_bb[4 * k + j] = 0.0;
}

sq_status sq_msh_entities_build(const sq_quad_mesh *m, sq_msh_entities *e, sq_error *err)
{
    memset(e, 0, sizeof *e);
    e->nsurfaces = m->nregions > 0 ? m->nregions : 1;
    curve_side_list cs = {0};
    int *ent = NULL;
    sq_status st = list_curve_sides(m, &cs, &e->ncurves, err);
    int C = e->ncurves, S = e->nsurfaces;
    if (st == SQ_OK) {
        e->curve_ends = malloc(sizeof(int) * (2 * (size_t)C + 1));
        e->curve_faces = malloc(sizeof(int) * (2 * (size_t)C + 1));
        e->curve_sides = calloc((size_t)C + 1, sizeof(int));
        /* one array: the curves' boxes, then the surfaces' */
        e->curve_bb = malloc(sizeof(double) * 4 * ((size_t)C + S));
        e->node = malloc(sizeof(int) * ((size_t)m->nnodes + 1));
        ent = malloc(sizeof(int) * ((size_t)m->nnodes + 1));
        if (!e->curve_ends || !e->curve_faces || !e->curve_sides || !e->curve_bb || !e->node || !ent)
            st = SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    }
    if (st == SQ_OK) {
        e->surface_bb = &e->curve_bb[4 * (size_t)C];
        for (int k = 0; k < 2 * C; k++) e->curve_ends[k] = e->curve_faces[k] = -1;
        st = find_points(m, &cs, e, err);
    }
    if (st == SQ_OK) {
        classify_nodes(m, &cs, e, ent);
        int nent = e->npoints + C + S;
        e->first = calloc((size_t)nent + 2, sizeof(int));
        if (!e->first) st = SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
        for (int v = 0; st == SQ_OK && v < m->nnodes; v++) e->first[ent[v] + 2]++;
        for (int k = 0; st == SQ_OK && k < nent; k++) e->first[k + 2] += e->first[k + 1];
        for (int v = 0; st == SQ_OK && v < m->nnodes; v++) e->node[e->first[ent[v] + 1]++] = v;
    }
    free(ent), free(cs.side), free(cs.curve), free(cs.minus);
    if (st != SQ_OK) sq_msh_entities_free(e);
    return st;
}

void sq_msh_entities_free(sq_msh_entities *e)
{
    if (!e) return;
    free(e->point_node), free(e->curve_ends), free(e->curve_faces), free(e->curve_sides);
    free(e->curve_bb), free(e->node), free(e->first);
    memset(e, 0, sizeof *e);
}
