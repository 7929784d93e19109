/* semquad — the faces' meshes merged into one (domain.h, design 4). */
#include "domain.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* interface nodes closer than this part of the size are one node: the
 * faces place them at the same arc lengths of the same curve, to rounding
 * (1e-12 of the size and below), and no two nodes of a valid mesh of that
 * size come within 1e-6 of it */
#define MERGE_TOL 1e-6

static double dot3(const double *a, const double *b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

static void cross3(const double *a, const double *b, double *c)
{
    c[0] = a[1] * b[2] - a[2] * b[1], c[1] = a[2] * b[0] - a[0] * b[2], c[2] = a[0] * b[1] - a[1] * b[0];
}

void sq_domain_frame(const sq_domain *d, int f, double A[6], int *flip)
{
    double O0[3], X0[3], Y0[3], N0[3], O[3], X[3], Y[3], N[3], D[3];
    cad_face_frame(d->faces[0], O0, X0, Y0);
    cad_face_frame(d->faces[f], O, X, Y);
    cross3(X0, Y0, N0);
    cross3(X, Y, N);
    *flip = dot3(N, N0) < 0.0;
    for (int k = 0; k < 3; k++) D[k] = O[k] - O0[k];
    A[0] = dot3(X, X0), A[1] = dot3(Y, X0), A[2] = dot3(D, X0);
    A[3] = dot3(X, Y0), A[4] = dot3(Y, Y0), A[5] = dot3(D, Y0);
}

/* Face f's nodes into out (2 per node) in face 0's frame; *flip when its
 * normal is face 0's reversed.  SQ_ERR_GEOMETRY when it is not in face 0's
 * plane (a 2D domain is one plane). */
static sq_status to_frame0(const sq_domain *d, int f, const sq_quad_mesh *m, double tol, double *out,
                           int *flip, sq_error *err)
{
    double O0[3], X0[3], Y0[3], N0[3], O[3], X[3], Y[3], A[6];
    cad_face_frame(d->faces[0], O0, X0, Y0);
    cad_face_frame(d->faces[f], O, X, Y);
    cross3(X0, Y0, N0);
    sq_domain_frame(d, f, A, flip);
    for (int v = 0; v < m->nnodes; v++) {
        double P[3];
        for (int k = 0; k < 3; k++) P[k] = O[k] + m->xy[2 * v] * X[k] + m->xy[2 * v + 1] * Y[k] - O0[k];
        out[2 * v] = dot3(P, X0), out[2 * v + 1] = dot3(P, Y0);
        if (fabs(dot3(P, N0)) > tol)
            return SQ_FAIL(err, SQ_ERR_GEOMETRY,
                           "face %d is not in the plane of the domain's first face (%.3g off): a "
                           "domain is one plane",
                           f, fabs(dot3(P, N0)));
    }
    return SQ_OK;
}

typedef struct {
    double x, y;
    int id;
} pt;

static int cmp_pt(const void *a, const void *b)
{
    const pt *p = a, *q = b;
    return (p->x > q->x) - (p->x < q->x);
}

static int find(int *rep, int i)
{
    while (rep[i] != i) i = rep[i] = rep[rep[i]];
    return i;
}

/* Union of the candidate nodes within tol of one another; the smaller
 * index represents. */
static sq_status merge_close(const double *xy, const int *cand, int nc, double tol, int *rep,
                             sq_error *err)
{
    pt *p = malloc(sizeof(pt) * ((size_t)nc + 1));
    if (!p) return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    for (int k = 0; k < nc; k++) p[k] = (pt){xy[2 * cand[k]], xy[2 * cand[k] + 1], cand[k]};
    qsort(p, (size_t)nc, sizeof(pt), cmp_pt);
    for (int a = 0; a < nc; a++)
        for (int b = a + 1; b < nc && p[b].x - p[a].x <= tol; b++) {
            if (hypot(p[b].x - p[a].x, p[b].y - p[a].y) > tol) continue;
            int ra = find(rep, p[a].id), rb = find(rep, p[b].id);
            if (ra < rb) rep[rb] = ra;
            else if (rb < ra) rep[ra] = rb;
        }
    free(p);
    return SQ_OK;
}

typedef struct {
    int a, b, side; /* end nodes (a < b), side of the curve (0, 1) */
    int curve;
} iface_side;

static int cmp_side(const void *x, const void *y)
{
    const iface_side *p = x, *q = y;
    if (p->a != q->a) return (p->a > q->a) - (p->a < q->a);
    if (p->b != q->b) return (p->b > q->b) - (p->b < q->b);
    return (p->side > q->side) - (p->side < q->side);
}

/* Every interface side must meet one of the other face's, end to end. */
static sq_status check_conforming(iface_side *s, int n, sq_error *err)
{
    qsort(s, (size_t)n, sizeof *s, cmp_side);
    for (int k = 0; k < n; k += 2)
        if (k + 1 >= n || s[k].a != s[k + 1].a || s[k].b != s[k + 1].b || s[k].side == s[k + 1].side)
            return SQ_FAIL(err, SQ_ERR_LAYOUT,
                           "the faces do not conform on their shared curve %d: a side of one face "
                           "there meets no side of the other",
                           s[k].curve);
    return SQ_OK;
}

/* The faces' nodes in face 0's frame (xy), and every node's representative
 * once interface nodes are merged (rep). */
static sq_status merged_nodes(const sq_domain *d, sq_quad_mesh *const *m, const int *off,
                              double size, double *xy, int *flip, int *rep, sq_error *err)
{
    int nn = off[d->nfaces], nc = 0;
    for (int i = 0; i < nn; i++) rep[i] = i;
    for (int f = 0; f < d->nfaces; f++) {
        SQ_TRY(to_frame0(d, f, m[f], MERGE_TOL * size, &xy[2 * (size_t)off[f]], &flip[f], err));
        nc += m[f]->nbnd * (m[f]->order + 1);
    }
    int *cand = malloc(sizeof(int) * ((size_t)nc + 1));
    if (!cand) return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    nc = 0;
    for (int f = 0; f < d->nfaces; f++) {
        const sq_quad_mesh *q = m[f];
        int Q = q->order, npe = (Q + 1) * (Q + 1);
        for (int s = 0; s < q->nbnd; s++) {
            if (d->curves[d->curve_of[f][q->bnd_tag[s]]].face[1] < 0) continue;
            for (int k = 0; k <= Q; k++)
                cand[nc++] = off[f] + q->conn[(size_t)q->bnd_quad[s] * npe + sq_quad_side_node(Q, q->bnd_side[s], k)];
        }
    }
    sq_status st = merge_close(xy, cand, nc, MERGE_TOL * size, rep, err);
    free(cand);
    return st;
}

/* Quads, regions and boundary sides of the merged mesh r (nodes renumbered
 * by id); the interface sides into is[*nis]. */
static void merged_elements(const sq_domain *d, sq_quad_mesh *const *m, const int *off,
                            const int *flip, const int *id, sq_quad_mesh *r, iface_side *is, int *nis)
{
    static const int flipped_side[4] = {0, 3, 2, 1}; /* (i, j) -> (Q - i, j) */
    int Q = r->order, npe = (Q + 1) * (Q + 1), q0 = 0, nb = 0;
    *nis = 0;
    for (int f = 0; f < d->nfaces; f++) {
        const sq_quad_mesh *q = m[f];
        for (int e = 0; e < q->nquads; e++) {
            const int *c = &q->conn[(size_t)e * npe];
            int *o = &r->conn[(size_t)(q0 + e) * npe];
            for (int j = 0; j <= Q; j++)
                for (int i = 0; i <= Q; i++)
                    o[sq_quad_node(Q, i, j)] = id[off[f] + c[sq_quad_node(Q, flip[f] ? Q - i : i, j)]];
            r->patch[q0 + e] = q->patch[e];
            r->region[q0 + e] = f;
        }
        for (int s = 0; s < q->nbnd; s++) {
            int c = d->curve_of[f][q->bnd_tag[s]], side = q->bnd_side[s];
            const sq_domain_curve *cv = &d->curves[c];
            if (cv->face[1] < 0) {
                r->bnd_quad[nb] = q0 + q->bnd_quad[s];
                r->bnd_side[nb] = flip[f] ? flipped_side[side] : side;
                r->bnd_tag[nb++] = cv->tag;
                continue;
            }
            const int *cq = &q->conn[(size_t)q->bnd_quad[s] * npe];
            int a = id[off[f] + cq[sq_quad_side_node(Q, side, 0)]], b = id[off[f] + cq[sq_quad_side_node(Q, side, Q)]];
            is[(*nis)++] = (iface_side){a < b ? a : b, a < b ? b : a, cv->face[0] != f, c};
        }
        q0 += q->nquads;
    }
}

sq_status sq_domain_merge(const sq_domain *d, sq_quad_mesh *const *m, const int *cad_index,
                          double size, sq_quad_mesh **out, sq_error *err)
{
    *out = NULL;
    int nf = d->nfaces, nq = 0, nbnd = 0, nifc = 0;
    int *off = malloc(sizeof(int) * ((size_t)nf + 1)), *flip = malloc(sizeof(int) * ((size_t)nf + 1));
    if (!off || !flip) {
        free(off), free(flip);
        return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    }
    off[0] = 0;
    for (int f = 0; f < nf; f++) {
        off[f + 1] = off[f] + m[f]->nnodes;
        nq += m[f]->nquads;
        for (int s = 0; s < m[f]->nbnd; s++)
            if (d->curves[d->curve_of[f][m[f]->bnd_tag[s]]].face[1] < 0) nbnd++;
            else nifc++;
    }
    size_t nn = (size_t)off[nf];
    double *xy = malloc(sizeof(double) * 2 * (nn + 1));
    int *rep = malloc(sizeof(int) * (nn + 1)), *id = malloc(sizeof(int) * (nn + 1));
    iface_side *is = malloc(sizeof *is * ((size_t)nifc + 1));
    sq_status st = xy && rep && id && is ? SQ_OK : SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    for (int f = 1; f < nf && st == SQ_OK; f++)
        if (m[f]->order != m[0]->order || m[f]->nodes != m[0]->nodes)
            st = SQ_FAIL(err, SQ_ERR_INTERNAL, "faces meshed at different orders");
    if (st == SQ_OK) st = merged_nodes(d, m, off, size, xy, flip, rep, err);
    int nnew = 0;
    for (size_t i = 0; i < nn && st == SQ_OK; i++) id[i] = find(rep, (int)i) == (int)i ? nnew++ : -1;
    for (size_t i = 0; i < nn && st == SQ_OK; i++) id[i] = id[find(rep, (int)i)];
    sq_quad_mesh *r = NULL;
    if (st == SQ_OK) st = sq_quad_mesh_create(m[0]->order, m[0]->nodes, nnew, nq, nbnd, &r, err);
    if (st == SQ_OK) st = sq_quad_mesh_set_regions(r, nf, err);
    if (st == SQ_OK) {
        for (size_t i = 0; i < nn; i++)
            if (find(rep, (int)i) == (int)i) r->xy[2 * id[i]] = xy[2 * i], r->xy[2 * id[i] + 1] = xy[2 * i + 1];
        for (int f = 0; f < nf; f++) r->region_face[f] = cad_index[f];
        r->ntags = d->ntags;
        int nis = 0;
        merged_elements(d, m, off, flip, id, r, is, &nis);
        st = check_conforming(is, nis, err);
    }
    if (st == SQ_OK) *out = r;
    else sq_quad_mesh_free(&r);
    free(off), free(flip), free(xy), free(rep), free(id), free(is);
    return st;
}
