/* semquad — the layout as a planar graph (layout.h design 1): nodes at the
 * face vertices, singular points, feet, open ends and crossings; edges the
 * pieces of the boundary and of the separatrices between them; its faces
 * (layout_patches.c) made the patches. */
#include "layout_internal.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* The graph's nodes, edges and patches freed. */
static void graph_clear(sq_layout *L)
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
} gstate;

static sq_status node_add(gstate *g, sq_layout_node n, int *id, sq_error *err)
{
    sq_layout *L = g->L;
    sq_layout_node *q = lay_grow(L->nodes, &g->cap_nodes, L->nnodes + 1, sizeof *q);
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
        sq_layout_node n = {xy[0], xy[1], SQ_LNODE_FOOT, e->id, e->s, 2, 0, 0};
        return node_add(g, n, id, err);
    }
    default: {
        sq_layout_node n = {p[0], p[1], SQ_LNODE_OPEN, sep, 0.0, 0, 0, 0};
        return node_add(g, n, id, err);
    }
    }
}

static sq_status edge_add(gstate *g, sq_layout_edge e, sq_error *err)
{
    sq_layout *L = g->L;
    sq_layout_edge *q = lay_grow(L->edges, &g->cap_edges, L->nedges + 1, sizeof *q);
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

sq_status lay_graph_build(sq_layout *L, const cad_face *face, const sq_face_info *info,
                          sq_error *err)
{
    graph_clear(L);
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
        sq_layout_node n = {v->x, v->y, SQ_LNODE_CORNER, k, 0.0, L->vertex_quads[k], 0, v->bent};
        int id;
        st = node_add(&g, n, &id, err);
        g.vstart[v->edge_out] = k;
        g.vend[v->edge_in] = k;
    }
    for (int k = 0; k < L->nsing && st == SQ_OK; k++) {
        sq_layout_node n = {L->sing[k].x, L->sing[k].y, SQ_LNODE_SINGULAR, k, 0.0,
                            L->sing[k].valence, 0, 0};
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
                sq_layout_node n = {h->x, h->y, SQ_LNODE_CROSSING, -1, 0.0, 4, 0, 0};
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
    st = lay_patches_build(L, face, err);
done:
    free(hits);
    free(sp);
    free(g.vstart);
    free(g.vend);
    if (st != SQ_OK) graph_clear(L);
    return st;
}

void sq_layout_free(sq_layout *L)
{
    if (!L) return;
    graph_clear(L);
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
