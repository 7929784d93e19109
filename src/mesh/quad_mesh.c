/* semquad — the high-order quad mesh container, its element maps and the
 * resampling between GLL and equispaced node placements (quad_mesh.h). */
#include "quad_mesh.h"

#include "gauss.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

sq_status sq_quad_mesh_create(int order, sq_node_kind nodes, int nnodes, int nquads, int nbnd,
                              sq_quad_mesh **out, sq_error *err)
{
    *out = NULL;
    if (order < 1 || order > 10)
        return SQ_FAIL(err, SQ_ERR_USAGE, "quad order %d outside 1..10", order);
    if (nodes != SQ_NODES_GLL && nodes != SQ_NODES_EQUISPACED)
        return SQ_FAIL(err, SQ_ERR_USAGE, "unknown node placement %d", (int)nodes);
    if (nnodes < 0 || nquads < 0 || nbnd < 0)
        return SQ_FAIL(err, SQ_ERR_USAGE, "negative mesh size");
    size_t npe = (size_t)(order + 1) * (order + 1);
    sq_quad_mesh *m = calloc(1, sizeof *m);
    if (!m) return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    m->order = order;
    m->nodes = nodes;
    m->nnodes = nnodes;
    m->nquads = nquads;
    m->nbnd = nbnd;
    m->xy = calloc(2 * (size_t)nnodes + 1, sizeof *m->xy);
    m->conn = calloc(npe * (size_t)nquads + 1, sizeof *m->conn);
    m->patch = malloc(((size_t)nquads + 1) * sizeof *m->patch);
    m->bnd_quad = calloc((size_t)nbnd + 1, sizeof *m->bnd_quad);
    m->bnd_side = calloc((size_t)nbnd + 1, sizeof *m->bnd_side);
    m->bnd_tag = calloc((size_t)nbnd + 1, sizeof *m->bnd_tag);
    if (!m->xy || !m->conn || !m->patch || !m->bnd_quad || !m->bnd_side || !m->bnd_tag) {
        sq_quad_mesh_free(&m);
        return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory for a mesh of %d quads", nquads);
    }
    for (int q = 0; q < nquads; q++) m->patch[q] = -1;
    *out = m;
    return SQ_OK;
}

/* The regions' names freed (region_name NULL: every face face_<number>). */
static void free_region_names(sq_quad_mesh *m)
{
    for (int r = 0; m->region_name && r < m->nregions; r++) free(m->region_name[r]);
    free(m->region_name);
    m->region_name = NULL;
}

void sq_quad_mesh_free(sq_quad_mesh **mp)
{
    if (!mp || !*mp) return;
    sq_quad_mesh *m = *mp;
    free(m->xy);
    free(m->conn);
    free(m->patch);
    free(m->bnd_quad);
    free(m->bnd_side);
    free(m->bnd_tag);
    for (int t = 0; m->tag_name && t < m->ntags; t++) free(m->tag_name[t]);
    free(m->tag_name);
    free_region_names(m);
    free(m->region);
    free(m->region_face);
    sq_quad_mesh_free_periodic(m);
    free(m);
    *mp = NULL;
}

sq_status sq_quad_mesh_set_regions(sq_quad_mesh *m, int nregions, sq_error *err)
{
    free_region_names(m);
    free(m->region);
    free(m->region_face);
    m->nregions = nregions;
    m->region = calloc((size_t)m->nquads + 1, sizeof *m->region);
    m->region_face = calloc((size_t)nregions + 1, sizeof *m->region_face);
    if (!m->region || !m->region_face) return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    return SQ_OK;
}

/* A copy of n names (NULL entries kept), or NULL with *ok 0. */
static char **copy_names(char *const *src, int n, int *ok)
{
    char **d = calloc((size_t)n + 1, sizeof *d);
    *ok = d != NULL;
    for (int k = 0; d && k < n; k++)
        if (src[k] && !(d[k] = strdup(src[k]))) *ok = 0;
    return d;
}

sq_status sq_quad_mesh_copy_names(sq_quad_mesh *dst, const sq_quad_mesh *src, sq_error *err)
{
    int ok = 1, ok2 = 1;
    if (dst->tag_name || (dst->nregions && dst->region_name))
        return SQ_FAIL(err, SQ_ERR_INTERNAL, "names copied onto a mesh with names");
    if (src->tag_name && src->ntags == dst->ntags)
        dst->tag_name = copy_names(src->tag_name, src->ntags, &ok);
    if (src->region_name && src->nregions == dst->nregions)
        dst->region_name = copy_names(src->region_name, src->nregions, &ok2);
    if (ok && ok2) return SQ_OK;
    return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
}

sq_status sq_quad_basis_init(sq_quad_basis *b, int order, sq_node_kind nodes, sq_error *err)
{
    if (order < 1 || order > 10)
        return SQ_FAIL(err, SQ_ERR_USAGE, "quad order %d outside 1..10", order);
    memset(b, 0, sizeof *b);
    b->order = order;
    if (nodes == SQ_NODES_GLL) {
        double x[11], w[11];
        SQ_TRY(sem_gauss_lobatto(order + 1, x, w, err));
        for (int i = 0; i <= order; i++) b->t[i] = 0.5 * (x[i] + 1.0);
        b->t[0] = 0.0; /* exact ends, so corners and sides interpolate exactly */
        b->t[order] = 1.0;
    } else {
        for (int i = 0; i <= order; i++) b->t[i] = (double)i / order;
    }
    for (int i = 0; i <= order; i++) {
        double p = 1.0;
        for (int j = 0; j <= order; j++)
            if (j != i) p *= b->t[i] - b->t[j];
        b->w[i] = 1.0 / p;
    }
    return SQ_OK;
}

void sq_quad_basis_eval(const sq_quad_basis *b, double u, double *l, double *dl)
{
    int Q = b->order;
    for (int i = 0; i <= Q; i++) {
        /* products with a factor left out: exact at the nodes too */
        double p = b->w[i], dp = 0.0;
        for (int j = 0; j <= Q; j++) {
            if (j == i) continue;
            dp = dp * (u - b->t[j]) + p;
            p *= u - b->t[j];
        }
        l[i] = p;
        if (dl) dl[i] = dp;
    }
}

void sq_quad_mesh_point(const sq_quad_mesh *m, int q, const double *lu, const double *lv,
                        double x[2])
{
    int Q = m->order;
    const int *c = &m->conn[(size_t)q * (Q + 1) * (Q + 1)];
    double X[2] = {0, 0};
    for (int j = 0; j <= Q; j++)
        for (int i = 0; i <= Q; i++) {
            const double *p = &m->xy[2 * (size_t)c[sq_quad_node(Q, i, j)]];
            double f = lu[i] * lv[j];
            X[0] += f * p[0];
            X[1] += f * p[1];
        }
    x[0] = X[0];
    x[1] = X[1];
}

void sq_quad_mesh_map(const sq_quad_mesh *m, const sq_quad_basis *b, int q, double u, double v,
                      double x[2], double d[4])
{
    int Q = m->order;
    double lu[11], dlu[11], lv[11], dlv[11];
    sq_quad_basis_eval(b, u, lu, dlu);
    sq_quad_basis_eval(b, v, lv, dlv);
    sq_quad_mesh_point(m, q, lu, lv, x);
    if (!d) return;
    const int *c = &m->conn[(size_t)q * (Q + 1) * (Q + 1)];
    double D[4] = {0, 0, 0, 0};
    for (int j = 0; j <= Q; j++)
        for (int i = 0; i <= Q; i++) {
            const double *p = &m->xy[2 * (size_t)c[sq_quad_node(Q, i, j)]];
            double fu = dlu[i] * lv[j], fv = lu[i] * dlv[j];
            D[0] += fu * p[0];
            D[1] += fv * p[0];
            D[2] += fu * p[1];
            D[3] += fv * p[1];
        }
    memcpy(d, D, sizeof D);
}

sq_status sq_quad_mesh_resample(const sq_quad_mesh *m, sq_node_kind nodes, sq_quad_mesh **out,
                                sq_error *err)
{
    *out = NULL;
    sq_quad_basis from, to;
    SQ_TRY(sq_quad_basis_init(&from, m->order, m->nodes, err));
    SQ_TRY(sq_quad_basis_init(&to, m->order, nodes, err));
    sq_quad_mesh *r = NULL;
    SQ_TRY(sq_quad_mesh_create(m->order, nodes, m->nnodes, m->nquads, m->nbnd, &r, err));
    int Q = m->order;
    size_t npe = (size_t)(Q + 1) * (Q + 1);
    memcpy(r->conn, m->conn, npe * (size_t)m->nquads * sizeof *r->conn);
    memcpy(r->patch, m->patch, (size_t)m->nquads * sizeof *r->patch);
    memcpy(r->bnd_quad, m->bnd_quad, (size_t)m->nbnd * sizeof *r->bnd_quad);
    memcpy(r->bnd_side, m->bnd_side, (size_t)m->nbnd * sizeof *r->bnd_side);
    memcpy(r->bnd_tag, m->bnd_tag, (size_t)m->nbnd * sizeof *r->bnd_tag);
    r->ntags = m->ntags;
    if (m->nregions > 0) {
        sq_status st = sq_quad_mesh_set_regions(r, m->nregions, err);
        if (st != SQ_OK) {
            sq_quad_mesh_free(&r);
            return st;
        }
        memcpy(r->region, m->region, (size_t)m->nquads * sizeof *r->region);
        memcpy(r->region_face, m->region_face, (size_t)m->nregions * sizeof *r->region_face);
    }
    sq_status st = sq_quad_mesh_copy_periodic(r, m, err);
    if (st != SQ_OK) {
        sq_quad_mesh_free(&r);
        return st;
    }
    /* Unused nodes keep their position. */
    memcpy(r->xy, m->xy, 2 * (size_t)m->nnodes * sizeof *r->xy);
    if (nodes == m->nodes) {
        *out = r;
        return SQ_OK;
    }
    /* Node (i, j) of an element moves to the new parameter (s_i, s_j).  A
     * side's nodes depend only on that side's old nodes (tensor product), and
     * both parameter sets are symmetric, so the two elements sharing a side
     * give the same new positions (to rounding): each shared node gets the
     * value of the last element that writes it.  The old basis at the new
     * parameters is the same for every element: evaluated once. */
    double L[11][11];
    for (int i = 0; i <= Q; i++) sq_quad_basis_eval(&from, to.t[i], L[i], NULL);
    for (int q = 0; q < m->nquads; q++) {
        const int *c = &m->conn[(size_t)q * npe];
        for (int j = 0; j <= Q; j++)
            for (int i = 0; i <= Q; i++) {
                int g = c[sq_quad_node(Q, i, j)];
                if ((i == 0 || i == Q) && (j == 0 || j == Q)) continue; /* corners stay */
                sq_quad_mesh_point(m, q, L[i], L[j], &r->xy[2 * (size_t)g]);
            }
    }
    /* a periodic curve's nodes: its master's images again, not its own
     * interpolant's (equal to rounding) */
    sq_quad_mesh_apply_periodic(r);
    *out = r;
    return SQ_OK;
}

void sq_quad_quality_line(const sq_quad_mesh *m, const sq_quad_quality *q, char *buf, size_t n)
{
    snprintf(buf, n,
             "%d quads, order %d (%s), %d interior irregular vertices, eta mean %.3f, "
             "worst %.3f, tau %.1f %%, min scaled Jacobian %.3f",
             m->nquads, m->order, m->nodes == SQ_NODES_GLL ? "GLL" : "equispaced",
             q->irregular_interior, q->eta_mean, q->eta_min, q->tau_percent,
             q->min_scaled_jacobian);
}

typedef struct {
    unsigned long long key; /* lower vertex << 32 | higher vertex */
    int side;               /* 4*quad + local side */
} coarse_side;

static int cmp_coarse(const void *a, const void *b)
{
    const coarse_side *x = a, *y = b;
    if (x->key != y->key) return x->key < y->key ? -1 : 1;
    return (x->side > y->side) - (x->side < y->side);
}

sq_status sq_quad_mesh_elevate(int nverts, const double *vxy, int nquads, const int *quads,
                               const int *side_tag, int ntags, int order, sq_node_kind nodes,
                               sq_quad_warp_fn warp, void *ctx, sq_quad_mesh **out,
                               sq_error *err)
{
    *out = NULL;
    sq_quad_basis b;
    SQ_TRY(sq_quad_basis_init(&b, order, nodes, err));
    for (int k = 0; k < 4 * nquads; k++)
        if (quads[k] < 0 || quads[k] >= nverts)
            return SQ_FAIL(err, SQ_ERR_USAGE, "coarse quad %d refers to vertex %d of %d", k / 4,
                           quads[k], nverts);
    int Q = order, ns = 4 * nquads;
    coarse_side *cs = malloc(sizeof *cs * ((size_t)ns + 1));
    int *edge = malloc(sizeof(int) * ((size_t)ns + 1)), *mult = malloc(sizeof(int) * ((size_t)ns + 1));
    if (!cs || !edge || !mult) {
        free(cs), free(edge), free(mult);
        return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    }
    for (int q = 0; q < nquads; q++)
        for (int k = 0; k < 4; k++) {
            unsigned a = (unsigned)quads[4 * q + k], c = (unsigned)quads[4 * q + (k + 1) % 4];
            cs[4 * q + k].key = (unsigned long long)(a < c ? a : c) << 32 | (a < c ? c : a);
            cs[4 * q + k].side = 4 * q + k;
        }
    qsort(cs, (size_t)ns, sizeof *cs, cmp_coarse);
    int ne = 0, nbnd = 0;
    for (int i = 0; i < ns;) {
        int k = i;
        while (k < ns && cs[k].key == cs[i].key) k++;
        for (int s = i; s < k; s++) edge[cs[s].side] = ne, mult[cs[s].side] = k - i;
        nbnd += k - i == 1;
        ne++;
        i = k;
    }
    free(cs);
    size_t nn = (size_t)nverts + (size_t)ne * (Q - 1) + (size_t)nquads * (Q - 1) * (Q - 1);
    sq_quad_mesh *m = NULL;
    sq_status st = nn > 2147483647u ? SQ_FAIL(err, SQ_ERR_USAGE, "mesh too large")
                                    : sq_quad_mesh_create(Q, nodes, (int)nn, nquads, nbnd, &m, err);
    if (st != SQ_OK) {
        free(edge), free(mult);
        return st;
    }
    m->ntags = side_tag ? ntags : 1;
    int nb = 0;
    size_t npe = (size_t)(Q + 1) * (Q + 1);
    for (int q = 0; q < nquads && st == SQ_OK; q++) {
        const int *v = &quads[4 * q];
        const double *p0 = &vxy[2 * v[0]], *p1 = &vxy[2 * v[1]], *p2 = &vxy[2 * v[2]],
                     *p3 = &vxy[2 * v[3]];
        int *c = &m->conn[(size_t)q * npe];
        for (int j = 0; j <= Q; j++)
            for (int i = 0; i <= Q; i++) {
                int g, bi = i == 0 || i == Q, bj = j == 0 || j == Q;
                if (bi && bj) {
                    g = v[i ? (j ? 2 : 1) : (j ? 3 : 0)];
                } else if (bi || bj) {
                    /* side k and the step s along it from corner k */
                    int k = j == 0 ? 0 : i == Q ? 1 : j == Q ? 2 : 3;
                    int s = k == 0 ? i : k == 1 ? j : k == 2 ? Q - i : Q - j;
                    int from_low = v[k] < v[(k + 1) % 4];
                    g = nverts + edge[4 * q + k] * (Q - 1) + (from_low ? s : Q - s) - 1;
                } else {
                    g = nverts + ne * (Q - 1) + q * (Q - 1) * (Q - 1) + (j - 1) * (Q - 1) + (i - 1);
                }
                c[sq_quad_node(Q, i, j)] = g;
                double u = b.t[i], w = b.t[j], x[2];
                for (int d = 0; d < 2; d++)
                    x[d] = (1 - u) * (1 - w) * p0[d] + u * (1 - w) * p1[d] + u * w * p2[d] +
                           (1 - u) * w * p3[d];
                if (warp) {
                    double y[2];
                    warp(ctx, x, y);
                    x[0] = y[0], x[1] = y[1];
                }
                m->xy[2 * (size_t)g] = x[0];
                m->xy[2 * (size_t)g + 1] = x[1];
            }
        for (int k = 0; k < 4; k++) {
            if (mult[4 * q + k] > 2) {
                st = SQ_FAIL(err, SQ_ERR_USAGE, "coarse side shared by %d quads", mult[4 * q + k]);
                break;
            }
            if (mult[4 * q + k] != 1) continue;
            int t = side_tag ? side_tag[4 * q + k] : 0;
            if (t < 0 || t >= m->ntags) {
                st = SQ_FAIL(err, SQ_ERR_USAGE, "boundary side %d of quad %d has tag %d of %d", k,
                             q, t, m->ntags);
                break;
            }
            m->bnd_quad[nb] = q;
            m->bnd_side[nb] = k;
            m->bnd_tag[nb] = t;
            nb++;
        }
    }
    free(edge);
    free(mult);
    if (st != SQ_OK) {
        sq_quad_mesh_free(&m);
        return st;
    }
    *out = m;
    return SQ_OK;
}

int sq_quad_mesh_tag_group(const sq_quad_mesh *m, int t)
{
    for (int u = 0; m->tag_name && m->tag_name[t] && u < t; u++)
        if (m->tag_name[u] && !strcmp(m->tag_name[u], m->tag_name[t])) return u;
    return t;
}

const char *sq_quad_mesh_region_name(const sq_quad_mesh *m, int r, char *buf, size_t n)
{
    if (m->region_name && m->region_name[r]) return m->region_name[r];
    snprintf(buf, n, "face_%d", m->region_face[r]);
    return buf;
}

const char *sq_quad_mesh_tag_name(const sq_quad_mesh *m, int t, char *buf, size_t n)
{
    if (m->tag_name && m->tag_name[t]) return m->tag_name[t];
    snprintf(buf, n, "boundary_%d", t);
    return buf;
}

static int cmp_int(const void *a, const void *b)
{
    int x = *(const int *)a, y = *(const int *)b;
    return (x > y) - (x < y);
}

int sq_sort_unique(int *a, int n)
{
    qsort(a, (size_t)n, sizeof *a, cmp_int);
    int u = 0;
    for (int k = 0; k < n; k++)
        if (u == 0 || a[k] != a[u - 1]) a[u++] = a[k];
    return u;
}
