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

sq_status sq_periodic_relink(const sq_quad_mesh *from, sq_quad_mesh *dst, double size,
                             double rel_tol, sq_error *err)
{
    if (from->nperiodic == 0) return SQ_OK;
    sq_periodic p = {.npairs = from->nperiodic,
                     .pairs = calloc((size_t)from->nperiodic, sizeof(sq_periodic_pair))};
    if (!p.pairs) return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    for (int l = 0; l < p.npairs; l++) {
        p.pairs[l].a = from->periodic[l].master, p.pairs[l].b = from->periodic[l].tag;
        memcpy(p.pairs[l].affine, from->periodic[l].affine, sizeof p.pairs[l].affine);
    }
    sq_status st = sq_periodic_link(&p, dst, size, rel_tol, err);
    free(p.pairs);
    if (st != SQ_OK) return st;
    dst->periodic_chi = from->periodic_chi, dst->periodic_index = from->periodic_index;
    dst->periodic_irregular = from->periodic_irregular;
    dst->periodic_mesh_index = from->periodic_mesh_index;
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

/* up[v]: the class of face vertex v in the identified domain, its
 * representative (a pair joins a's start with b's end and a's end with b's
 * start); open[c]: class c has an edge of no pair (a boundary point). */
static void vertex_classes(const sq_face_info *info, const sq_periodic *p, int *up, int *open)
{
    int nv = info->nvertices;
    for (int v = 0; v < nv; v++) up[v] = v, open[v] = 0;
    for (int k = 0; k < p->npairs; k++)
        for (int v = 0; v < nv; v++)
            for (int w = 0; w < nv; w++) {
                const sq_vertex *x = &info->vertices[v], *y = &info->vertices[w];
                if ((x->edge_out == p->pairs[k].a && y->edge_in == p->pairs[k].b) ||
                    (x->edge_in == p->pairs[k].a && y->edge_out == p->pairs[k].b))
                    up[find(up, v)] = find(up, w);
            }
    for (int v = 0; v < nv; v++) up[v] = find(up, v);
    for (int v = 0; v < nv; v++) {
        const sq_vertex *x = &info->vertices[v];
        open[up[v]] |= pair_of(p, x->edge_in) < 0 || pair_of(p, x->edge_out) < 0;
    }
}

/* Design 3, the domain: its vertices are classes of the face's vertices,
 * its edges the face's less one per pair, its inside the face's: chi = the
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
    vertex_classes(info, p, up, open);
    for (int v = 0; v < nv; v++) angle[up[v]] += info->vertices[v].angle_deg;
    int sum = 0, classes = 0;
    for (int v = 0; v < nv; v++)
        if (up[v] == v) classes++, sum += (open[v] ? 2 : 4) - (int)lround(angle[v] / 90.0);
    *chi = info->chi - (nv - classes) + p->npairs;
    *index = 4 * *chi - sum;
    free(up), free(angle), free(open);
    return SQ_OK;
}

/* The bend of kink v whose partner (the other vertex of its class) is w. */
/* The kink's local feature size: its distance to the nearest point of
 * the face's boundary off its own two edges (projection onto each other
 * CAD edge; one that fails to project counts as far). */
static double kink_reach(const cad_face *face, const sq_vertex *x)
{
    const double p[2] = {x->x, x->y};
    double reach = HUGE_VAL;
    for (int k = 0; k < cad_face_num_edges(face); k++) {
        sq_error ignored = {0};
        double d;
        if (k != x->edge_in && k != x->edge_out &&
            cad_face_edge_project(face, k, p, NULL, NULL, &d, &ignored) == SQ_OK)
            reach = fmin(reach, d);
    }
    return reach;
}

/* The bend of kink v: the data turns over its local feature size on each
 * edge, at most half the edge (its other end may bend too).  Why that
 * length: the field's data along the two edges is the kink's own only as
 * far as no other boundary is nearer; a ramp reaching further turns the
 * data where another wall's data governs the field (a wake running beside
 * the pitch line then ends on it), and a much shorter one is seen from
 * that distance as a jump, which the field takes the short way (a 3/5 pair
 * of zeros about a ramp's length from the kink, guiding_field.h).  Neither
 * reflex nor convex kinks need a factor of their own: a reflex kink (the
 * inner corner of a bend) has the wall across the bend near, so its turn
 * is concentrated by that rule, a convex one (the outer corner) sees the
 * wall across further off, so its turn spreads. */
static sq_bend bend_of(const cad_face *face, const sq_face_info *info, int v)
{
    const sq_vertex *x = &info->vertices[v];
    const double reach = kink_reach(face, x);
    return (sq_bend){v, x->edge_in, x->edge_out, (180.0 - x->angle_deg) * M_PI / 180.0,
                     fmin(reach, 0.5 * cad_face_edge_length(face, x->edge_in)),
                     fmin(reach, 0.5 * cad_face_edge_length(face, x->edge_out))};
}

sq_status sq_periodic_bends(const cad_face *face, const sq_face_info *info, const sq_periodic *p,
                            sq_bend **bends, int *nbends, sq_error *err)
{
    int nv = info->nvertices, *up = malloc(sizeof(int) * ((size_t)nv + 1));
    int *open = malloc(sizeof(int) * ((size_t)nv + 1));
    *nbends = 0;
    *bends = malloc(sizeof **bends * ((size_t)nv + 1));
    if (!up || !open || !*bends) {
        free(up), free(open), free(*bends), *bends = NULL;
        return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    }
    vertex_classes(info, p, up, open);
    for (int v = 0; v < nv; v++)
        for (int w = 0; w < nv; w++) {
            if (w == v || up[w] != up[v] || open[up[v]]) continue;
            int members = 0;
            for (int u = 0; u < nv; u++) members += up[u] == up[v];
            const double a = info->vertices[v].angle_deg, b = info->vertices[w].angle_deg;
            if (members == 2 && fabs(a + b - 360.0) < SQ_PERIODIC_BEND_TOL_DEG &&
                (lround(a / 90.0) != 2 || lround(b / 90.0) != 2))
                (*bends)[(*nbends)++] = bend_of(face, info, v);
        }
    free(up), free(open);
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
