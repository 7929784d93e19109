/* semquad — a face's mesh with periodic pairs (periodic.h, designs 2 and
 * 3): the face as a domain for the split road's exchange, the partner
 * nodes linked and set, the identified domain's Gauss–Bonnet count. */
#include "periodic.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

sq_status sq_periodic_domain(const cad_face *const *face, const sq_face_info *info,
                             const sq_periodic *p, sq_domain *d, sq_error *err)
{
    memset(d, 0, sizeof *d);
    int ne = cad_face_num_edges(face[0]);
    d->nfaces = 1, d->faces = face, d->info = info;
    d->curves = calloc((size_t)ne + 1, sizeof *d->curves);
    d->curve_of = calloc(2, sizeof *d->curve_of);
    if (!d->curves || !d->curve_of || !(d->curve_of[0] = malloc(sizeof(int) * ((size_t)ne + 1)))) {
        sq_domain_free(d);
        return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    }
    for (int e = 0; e < ne; e++) d->curve_of[0][e] = -1;
    /* a pair is an interface of the face with itself, its sides b against a */
    for (int k = 0; k < p->npairs; k++) {
        int c = d->ncurves++;
        d->curves[c] = (sq_domain_curve){{0, 0}, {p->pairs[k].a, p->pairs[k].b}, 1, 0, -1};
        d->curve_of[0][p->pairs[k].a] = d->curve_of[0][p->pairs[k].b] = c;
        d->ninterfaces++;
    }
    for (int e = 0; e < ne; e++)
        if (d->curve_of[0][e] < 0) {
            d->curve_of[0][e] = d->ncurves;
            d->curves[d->ncurves++] = (sq_domain_curve){{0, -1}, {e, -1}, 0, 0, d->ntags++};
        }
    return SQ_OK;
}

/* The distinct nodes of m's sides on curve t (*n of them, sorted). */
static sq_status curve_nodes(const sq_quad_mesh *m, int t, int **nodes, int *n, sq_error *err)
{
    int Q = m->order, npe = (Q + 1) * (Q + 1), ns = 0;
    for (int s = 0; s < m->nbnd; s++) ns += m->bnd_tag[s] == t;
    *n = 0;
    *nodes = malloc(sizeof(int) * ((size_t)ns * (size_t)(Q + 1) + 1));
    if (!*nodes) return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    for (int s = 0; s < m->nbnd; s++) {
        if (m->bnd_tag[s] != t) continue;
        const int *c = &m->conn[(size_t)m->bnd_quad[s] * npe];
        for (int k = 0; k <= Q; k++) (*nodes)[(*n)++] = c[sq_quad_side_node(Q, m->bnd_side[s], k)];
    }
    *n = sq_sort_unique(*nodes, *n);
    return SQ_OK;
}

/* The link of pair r: every node of b paired with the node of a whose
 * image is nearest, one to one within tol, or SQ_ERR_LAYOUT; l's arrays
 * are its own (freed by the caller, also on failure). */
static sq_status link_pair(const sq_periodic_pair *r, const sq_quad_mesh *m, double tol,
                           sq_quad_periodic *l, sq_error *err)
{
    int *na = NULL, *nb = NULL, ca = 0, cb = 0;
    sq_status st = curve_nodes(m, r->a, &na, &ca, err);
    if (st == SQ_OK) st = curve_nodes(m, r->b, &nb, &cb, err);
    char *used = st == SQ_OK ? calloc((size_t)ca + 1, 1) : NULL;
    l->master_node = st == SQ_OK ? malloc(sizeof(int) * ((size_t)cb + 1)) : NULL;
    if (st == SQ_OK && (!used || !l->master_node)) st = SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    if (st == SQ_OK && ca != cb)
        st = SQ_FAIL(err, SQ_ERR_LAYOUT, "periodic edges %d and %d carry %d and %d nodes", r->a,
                     r->b, ca, cb);
    const double *T = r->affine;
    for (int j = 0; j < cb && st == SQ_OK; j++) {
        const double *y = &m->xy[2 * (size_t)nb[j]];
        int best = -1;
        double dbest = HUGE_VAL;
        for (int i = 0; i < ca; i++) {
            double x[2];
            sq_affine_map(T, &m->xy[2 * (size_t)na[i]], x);
            const double d = hypot(x[0] - y[0], x[1] - y[1]);
            if (d < dbest) dbest = d, best = i;
        }
        if (dbest > tol || used[best])
            st = SQ_FAIL(err, SQ_ERR_LAYOUT,
                         "node (%.9g, %.9g) of periodic edge %d has no partner on edge %d within %.3g",
                         y[0], y[1], r->b, r->a, tol);
        else
            used[best] = 1, l->master_node[j] = na[best];
    }
    if (st == SQ_OK) {
        l->tag = r->b, l->master = r->a, l->nnodes = cb, l->node = nb, nb = NULL;
        memcpy(l->affine, T, sizeof l->affine);
    }
    free(na), free(nb), free(used);
    return st;
}

sq_status sq_periodic_link(const sq_periodic *p, sq_quad_mesh *m, double size, double rel_tol,
                           sq_error *err)
{
    sq_quad_mesh_free_periodic(m);
    for (int k = 0; k < p->npairs; k++) {
        sq_quad_periodic l = {0};
        sq_status st = link_pair(&p->pairs[k], m, rel_tol * size, &l, err);
        if (st == SQ_OK) st = sq_quad_mesh_add_periodic(m, &l, err);
        if (st != SQ_OK) {
            free(l.node), free(l.master_node);
            sq_quad_mesh_free_periodic(m);
            return st;
        }
    }
    sq_quad_mesh_apply_periodic(m);
    return SQ_OK;
}

static int find(int *up, int x)
{
    while (up[x] != x) x = up[x] = up[up[x]];
    return x;
}

static int pair_of(const sq_periodic *p, int e)
{
    for (int k = 0; k < p->npairs; k++)
        if (p->pairs[k].a == e || p->pairs[k].b == e) return k;
    return -1;
}

/* Design 3, the domain: its vertices are classes of the face's vertices
 * (a pair joins a's start with b's end and a's end with b's start), its
 * edges the face's less one per pair, its inside the face's: chi = the
 * face's chi - (vertices - classes) + pairs (a passage glued: -1; a square
 * glued both ways: a torus, 0; a sector with its centre: a cone, 1).  A
 * class whose every edge is periodic is interior (index 4 - round(sum of
 * angles / 90)), else a corner (2 - round(sum / 90)). */
static sq_status identified_index(const sq_face_info *info, const sq_periodic *p, int *chi,
                                  int *index, sq_error *err)
{
    int nv = info->nvertices, *up = malloc(sizeof(int) * ((size_t)nv + 1));
    double *angle = calloc((size_t)nv + 1, sizeof *angle);
    int *open = calloc((size_t)nv + 1, sizeof *open);
    if (!up || !angle || !open) {
        free(up), free(angle), free(open);
        return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    }
    for (int v = 0; v < nv; v++) up[v] = v;
    for (int k = 0; k < p->npairs; k++)
        for (int v = 0; v < nv; v++)
            for (int w = 0; w < nv; w++) {
                const sq_vertex *x = &info->vertices[v], *y = &info->vertices[w];
                if ((x->edge_out == p->pairs[k].a && y->edge_in == p->pairs[k].b) ||
                    (x->edge_in == p->pairs[k].a && y->edge_out == p->pairs[k].b))
                    up[find(up, v)] = find(up, w);
            }
    for (int v = 0; v < nv; v++) {
        const sq_vertex *x = &info->vertices[v];
        angle[find(up, v)] += x->angle_deg;
        open[find(up, v)] |= pair_of(p, x->edge_in) < 0 || pair_of(p, x->edge_out) < 0;
    }
    int sum = 0, classes = 0;
    for (int v = 0; v < nv; v++)
        if (find(up, v) == v) classes++, sum += (open[v] ? 2 : 4) - (int)lround(angle[v] / 90.0);
    *chi = info->chi - (nv - classes) + p->npairs;
    *index = 4 * *chi - sum;
    free(up), free(angle), free(open);
    return SQ_OK;
}

sq_status sq_periodic_node_classes(const sq_quad_mesh *m, int **cls, sq_error *err)
{
    int nn = m->nnodes, *up = malloc(sizeof(int) * ((size_t)nn + 1));
    if (!(*cls = up)) return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    for (int v = 0; v < nn; v++) up[v] = v;
    for (int l = 0; l < m->nperiodic; l++)
        for (int k = 0; k < m->periodic[l].nnodes; k++)
            up[find(up, m->periodic[l].node[k])] = find(up, m->periodic[l].master_node[k]);
    for (int v = 0; v < nn; v++) up[v] = find(up, v);
    return SQ_OK;
}

sq_status sq_periodic_irregular(const sq_periodic *p, const sq_quad_mesh *m, int *irregular,
                                int *mesh_index, sq_error *err)
{
    /* the mesh: vertices joined by the links; quads around each class; a
     * class on a boundary side of no pair is on the boundary */
    int nn = m->nnodes, Q = m->order, npe = (Q + 1) * (Q + 1), *up = NULL;
    SQ_TRY(sq_periodic_node_classes(m, &up, err));
    int *quads = calloc((size_t)nn + 1, sizeof(int));
    char *corner = calloc((size_t)nn + 1, 1), *bnd = calloc((size_t)nn + 1, 1);
    if (!quads || !corner || !bnd) {
        free(up), free(quads), free(corner), free(bnd);
        return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    }
    for (int q = 0; q < m->nquads; q++)
        for (int c = 0; c < 4; c++) {
            int v = m->conn[(size_t)q * npe + sq_quad_side_node(Q, c, 0)];
            corner[v] = 1, quads[up[v]]++;
        }
    for (int s = 0; s < m->nbnd; s++) {
        if (pair_of(p, m->bnd_tag[s]) >= 0) continue;
        const int *c = &m->conn[(size_t)m->bnd_quad[s] * npe];
        bnd[up[c[sq_quad_side_node(Q, m->bnd_side[s], 0)]]] = 1;
        bnd[up[c[sq_quad_side_node(Q, m->bnd_side[s], Q)]]] = 1;
    }
    *irregular = *mesh_index = 0;
    for (int v = 0; v < nn; v++) {
        if (!corner[v] || up[v] != v || bnd[v]) continue;
        *irregular += quads[v] != 4;
        *mesh_index += 4 - quads[v];
    }
    free(up), free(quads), free(corner), free(bnd);
    return SQ_OK;
}

sq_status sq_periodic_identified(const sq_face_info *info, const sq_periodic *p,
                                 const sq_quad_mesh *m, int *chi, int *index, int *irregular,
                                 int *mesh_index, sq_error *err)
{
    SQ_TRY(identified_index(info, p, chi, index, err));
    return sq_periodic_irregular(p, m, irregular, mesh_index, err);
}
