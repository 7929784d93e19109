/* semquad — quads of order Q from the vertex mesh (quad_mesher.h design 4):
 * boundary sides on the CAD curves, layer sides curved like their wall,
 * interiors by transfinite interpolation of the four sides. */
#include "quad_mesher_private.h"

#include "gauss.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Node fractions along one segment: GLL or equispaced, tau[0..Q]. */
static sq_status sub_fractions(int Q, sq_node_kind kind, double *tau, sq_error *err)
{
    if (kind == SQ_NODES_EQUISPACED || Q == 1) {
        for (int i = 0; i <= Q; i++) tau[i] = (double)i / Q;
        return SQ_OK;
    }
    double x[11], w[11];
    SQ_TRY(sem_gauss_lobatto(Q + 1, x, w, err));
    for (int i = 0; i <= Q; i++) tau[i] = 0.5 * (1.0 + x[i]);
    tau[0] = 0.0;
    tau[Q] = 1.0;
    return SQ_OK;
}

sq_status qm_side_arcs(const cad_face *face, int tag, const double A[2], const double B[2],
                       int along, double *s0, double *s1, sq_error *err)
{
    SQ_TRY(cad_face_edge_project(face, tag, A, s0, NULL, NULL, err));
    SQ_TRY(cad_face_edge_project(face, tag, B, s1, NULL, NULL, err));
    /* the quad walks its boundary side along the curve's direction of
     * travel (both keep the face on the left): arc lengths that decrease
     * that way cross a closed curve's closing point.  (Not "the shorter
     * way round": a side may cover half a curve or more, a short edge
     * taken whole by one quad.) */
    double Lc = cad_face_edge_length(face, tag);
    if (along && *s1 < *s0) *s1 += Lc;
    else if (!along && *s0 < *s1) *s0 += Lc;
    return SQ_OK;
}

sq_status qm_curve_point(const cad_face *face, int tag, double s, double xy[2], sq_error *err)
{
    double Lc = cad_face_edge_length(face, tag);
    if (s > Lc) s -= Lc;
    return cad_face_edge_eval(face, tag, s, xy, NULL, NULL, err);
}

/* The Q+1 nodes P of a side from vertex A to vertex B: on CAD edge `tag`
 * (>= 0) between the vertices' arc lengths (`along`: its quad walks it from
 * A), curved like the wall inside a boundary layer (within `thick` of a
 * wall), else straight. */
static sq_status side_nodes(const cad_face *face, const sq_mesher_options *opt, double thick,
                            const double *tau, int Q, const double A[2], const double B[2],
                            int tag, int along, double *P, sq_error *err)
{
    sq_status st = SQ_OK;
    double s0 = 0.0, s1 = 0.0;
    if (tag >= 0) st = qm_side_arcs(face, tag, A, B, along, &s0, &s1, err);
    int lc = -1;
    double ls0 = 0.0, ls1 = 0.0, ld0 = 0.0, ld1 = 0.0;
    int layer = tag < 0 && opt->nbl > 0 &&
                qm_layer_side(face, opt, thick, A, B, &lc, &ls0, &ls1, &ld0, &ld1);
    for (int i = 0; i <= Q && st == SQ_OK; i++) {
        if (layer && i > 0 && i < Q) {
            double s = ls0 + tau[i] * (ls1 - ls0), d = ld0 + tau[i] * (ld1 - ld0);
            double Lc = cad_face_edge_length(face, lc), X[2], t[2];
            if (s > Lc) s -= Lc;
            st = cad_face_edge_eval(face, lc, s, X, t, NULL, err);
            /* the face is on the left of the wall's direction */
            P[2 * i] = X[0] - d * t[1];
            P[2 * i + 1] = X[1] + d * t[0];
        } else if (tag >= 0 && i > 0 && i < Q) {
            st = qm_curve_point(face, tag, s0 + tau[i] * (s1 - s0), &P[2 * i], err);
        } else {
            P[2 * i] = A[0] + tau[i] * (B[0] - A[0]);
            P[2 * i + 1] = A[1] + tau[i] * (B[1] - A[1]);
        }
    }
    if (st == SQ_OK) P[0] = A[0], P[1] = A[1], P[2 * Q] = B[0], P[2 * Q + 1] = B[1];
    return st;
}

sq_status qm_raise_order(const cad_face *face, const qm_vmesh *v, int Q, sq_node_kind kind,
                         const sq_mesher_options *opt, sq_quad_mesh **out, sq_error *err)
{
    double thick = opt->nbl > 0 ? 1.5 * qm_bl_thickness(opt, opt->bl_layers) : 0.0;
    double tau[11];
    SQ_TRY(sub_fractions(Q, kind, tau, err));
    /* unique sides: key (min, max) vertex, found through a per-vertex list */
    int ns = 0, *side_of = malloc(sizeof(int) * 4 * (size_t)v->nq);
    int *head = malloc(sizeof(int) * (size_t)v->nv), *next = malloc(sizeof(int) * 4 * (size_t)v->nq);
    int *sa = malloc(sizeof(int) * 4 * (size_t)v->nq), *sb = malloc(sizeof(int) * 4 * (size_t)v->nq);
    if (!side_of || !head || !next || !sa || !sb) {
        free(side_of);
        free(head);
        free(next);
        free(sa);
        free(sb);
        return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    }
    for (int i = 0; i < v->nv; i++) head[i] = -1;
    int nbnd = 0;
    for (int q = 0; q < v->nq; q++)
        for (int k = 0; k < 4; k++) {
            int a = v->quad[4 * q + k], b = v->quad[4 * q + (k + 1) % 4];
            int lo = a < b ? a : b, hi = a < b ? b : a, f = head[lo];
            while (f >= 0 && sb[f] != hi) f = next[f];
            if (f < 0) {
                f = ns++;
                sa[f] = lo;
                sb[f] = hi;
                next[f] = head[lo];
                head[lo] = f;
            }
            side_of[4 * q + k] = f;
            nbnd += v->side_tag[4 * q + k] >= 0;
        }
    long nn = (long)v->nv + (long)ns * (Q - 1) + (long)v->nq * (Q - 1) * (Q - 1);
    sq_quad_mesh *m = NULL;
    sq_status st = sq_quad_mesh_create(Q, kind, (int)nn, v->nq, nbnd, &m, err);
    double *sidexy = st == SQ_OK ? malloc(sizeof(double) * 2 * ((size_t)ns * (Q + 1) + 1)) : NULL;
    int *done = st == SQ_OK ? calloc((size_t)ns + 1, sizeof(int)) : NULL;
    if (st == SQ_OK && (!sidexy || !done)) st = SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    if (st == SQ_OK) memcpy(m->xy, v->xy, sizeof(double) * 2 * (size_t)v->nv);
    int b = 0;
    for (int q = 0; q < v->nq && st == SQ_OK; q++) {
        double S[4][11][2]; /* side k nodes in the element's walking direction */
        for (int k = 0; k < 4 && st == SQ_OK; k++) {
            int a = v->quad[4 * q + k], f = side_of[4 * q + k];
            int tag = v->side_tag[4 * q + k];
            if (!done[f]) { /* nodes from sa[f] to sb[f] */
                const double *A = &v->xy[2 * sa[f]], *B = &v->xy[2 * sb[f]];
                double *P = &sidexy[2 * (size_t)f * (Q + 1)];
                st = side_nodes(face, opt, thick, tau, Q, A, B, tag, a == sa[f], P, err);
                if (st == SQ_OK) {
                    for (int i = 1; i < Q; i++) {
                        long id = v->nv + (long)f * (Q - 1) + (i - 1);
                        m->xy[2 * id] = P[2 * i];
                        m->xy[2 * id + 1] = P[2 * i + 1];
                    }
                }
                done[f] = 1;
            }
            const double *P = &sidexy[2 * (size_t)f * (Q + 1)];
            int fwd = sa[f] == a;
            for (int i = 0; i <= Q; i++) {
                int ii = fwd ? i : Q - i;
                S[k][i][0] = P[2 * ii];
                S[k][i][1] = P[2 * ii + 1];
            }
            if (tag >= 0) {
                m->bnd_quad[b] = q;
                m->bnd_side[b] = k;
                m->bnd_tag[b] = tag;
                b++;
            }
        }
        if (st != SQ_OK) break;
        int *cn = &m->conn[(size_t)q * (Q + 1) * (Q + 1)];
        for (int j = 0; j <= Q; j++)
            for (int i = 0; i <= Q; i++) {
                int id;
                if ((i == 0 || i == Q) && (j == 0 || j == Q)) {
                    int corner = j == 0 ? (i == 0 ? 0 : 1) : (i == Q ? 2 : 3);
                    id = v->quad[4 * q + corner];
                } else if (j == 0 || i == Q || j == Q || i == 0) {
                    /* side node: side k at its own index t */
                    int k = j == 0 ? 0 : i == Q ? 1 : j == Q ? 2 : 3;
                    int t = k == 0 ? i : k == 1 ? j : k == 2 ? Q - i : Q - j;
                    int f = side_of[4 * q + k], fwd = sa[f] == v->quad[4 * q + k];
                    id = v->nv + f * (Q - 1) + ((fwd ? t : Q - t) - 1);
                } else {
                    id = v->nv + ns * (Q - 1) + q * (Q - 1) * (Q - 1) + (j - 1) * (Q - 1) + (i - 1);
                    /* transfinite interpolation of the four sides at (tau_i, tau_j) */
                    double u = tau[i], w = tau[j];
                    const double *B0 = S[0][i], *T0 = S[2][Q - i], *L0 = S[3][Q - j], *R0 = S[1][j];
                    const double *c00 = S[0][0], *c10 = S[1][0], *c11 = S[2][0], *c01 = S[3][0];
                    for (int d = 0; d < 2; d++)
                        m->xy[2 * id + d] = (1 - w) * B0[d] + w * T0[d] + (1 - u) * L0[d] +
                                            u * R0[d] -
                                            ((1 - u) * (1 - w) * c00[d] + u * (1 - w) * c10[d] +
                                             u * w * c11[d] + (1 - u) * w * c01[d]);
                }
                cn[sq_quad_node(Q, i, j)] = id;
            }
        m->patch[q] = v->patch[q];
    }
    free(side_of);
    free(head);
    free(next);
    free(sa);
    free(sb);
    free(sidexy);
    free(done);
    if (st != SQ_OK) {
        sq_quad_mesh_free(&m);
        return st;
    }
    int ntags = cad_face_num_edges(face);
    for (int k = 0; k < m->nbnd; k++)
        if (m->bnd_tag[k] + 1 > ntags) ntags = m->bnd_tag[k] + 1;
    m->ntags = ntags;
    *out = m;
    return SQ_OK;
}
