/* semquad — refinement of a finished quad mesh into sub-maps of its quads
 * (quad_refine.h).  Each parent quad carries a lattice of (N+1)² points,
 * N = nQ, at the parameters U_I = (a + tau_i)/n, I = aQ + i; child (a, b)
 * takes the points aQ..aQ+Q × bQ..bQ+Q.  The lattice's border points
 * belong to the parent's edges (placed once per edge, so neighbours share
 * them), the others to the parent alone. */
#include "quad_refine.h"

#include "quad_edges.h"
#include "quad_mesher_private.h"
#include "sq_parallel.h"

#include <stdlib.h>
#include <string.h>

#define RF_MAXN 2                        /* children per side */
#define RF_MAXL (RF_MAXN * 10 + 1)        /* lattice points per side */

typedef struct {
    const cad_face *face;
    const sq_quad_mesh *m; /* the parent mesh */
    sq_quad_basis pb;      /* its element maps' basis */
    const double *tau;     /* the children's node parameters, [0..Q] */
    int n, Q, N;
    double U[RF_MAXL];     /* lattice parameters in the parent */
    double LU[RF_MAXL][11]; /* the parent's basis at U[I] */
    sq_quad_edges e;
    int *vid;              /* parent node -> vertex of the refined mesh, or -1 */
    int nv;
    int threads;           /* for the edges inside the face and the parents */
    sq_quad_mesh *out;
} refine;

/* The walk along side k of a quad: the p-th of N+1 lattice points (I, J)
 * (of n children: the p-th child (a, b), N = n - 1), and the parameters
 * (u, v) at the fraction t. */
static void side_lattice(int k, int N, int p, int *I, int *J)
{
    static const int dI[4][2] = {{0, 1}, {1, 0}, {1, -1}, {0, 0}}; /* I = c0 N + c1 p */
    static const int dJ[4][2] = {{0, 0}, {0, 1}, {1, 0}, {1, -1}};
    *I = dI[k][0] * N + dI[k][1] * p;
    *J = dJ[k][0] * N + dJ[k][1] * p;
}

static void side_param(int k, double t, double *u, double *v)
{
    *u = k == 0 ? t : k == 1 ? 1.0 : k == 2 ? 1.0 - t : 0.0;
    *v = k == 0 ? 0.0 : k == 1 ? t : k == 2 ? 1.0 : 1.0 - t;
}

/* Global node of lattice point (I, J) of parent q. */
static int lattice_node(const refine *r, int q, int I, int J)
{
    int N = r->N;
    int onI = I == 0 || I == N, onJ = J == 0 || J == N;
    if (onI && onJ) {
        int k = J == 0 ? (I == 0 ? 0 : 1) : (I == N ? 2 : 3);
        return r->vid[sq_quad_corner_node(r->m, q, k)];
    }
    if (onI || onJ) {
        int k = J == 0 ? 0 : I == N ? 1 : J == N ? 2 : 3;
        int p = k == 0 ? I : k == 1 ? J : k == 2 ? N - I : N - J;
        int f = r->e.side_edge[4 * q + k], o = r->e.owner[f];
        /* the edge runs from its owner's corner o%4 */
        if (sq_quad_corner_node(r->m, q, k) != sq_quad_corner_node(r->m, o / 4, o % 4)) p = N - p;
        return r->nv + f * (N - 1) + (p - 1);
    }
    return r->nv + r->e.nedges * (N - 1) + q * (N - 1) * (N - 1) + (J - 1) * (N - 1) + (I - 1);
}

/* The N-1 inner points of edge f, in its owner's walking direction: on the
 * CAD curve at the same arc-length fractions, else the owner's map. */
static sq_status place_edge(refine *r, int f, sq_error *err)
{
    int q = r->e.owner[f] / 4, k = r->e.owner[f] % 4, tag = r->e.tag[f];
    double s0 = 0.0, s1 = 0.0;
    if (tag >= 0) {
        const double *A = &r->m->xy[2 * (size_t)sq_quad_corner_node(r->m, q, k)];
        const double *B = &r->m->xy[2 * (size_t)sq_quad_corner_node(r->m, q, (k + 1) % 4)];
        SQ_TRY(qm_side_arcs(r->face, tag, A, B, 1, &s0, &s1, err));
    }
    for (int p = 1; p < r->N; p++) {
        double *x = &r->out->xy[2 * (size_t)(r->nv + f * (r->N - 1) + (p - 1))];
        if (tag >= 0) {
            SQ_TRY(qm_curve_point(r->face, tag, s0 + r->U[p] * (s1 - s0), x, err));
        } else {
            double u, v;
            side_param(k, r->U[p], &u, &v);
            sq_quad_mesh_map(r->m, &r->pb, q, u, v, x, NULL);
        }
    }
    return SQ_OK;
}

/* D: the lattice's displacement from the parent's map, known on its
 * border; along the children's sides inside the parent, linear between
 * their ends (zero at an inner child corner). */
static void inner_lines(const refine *r, double (*D)[RF_MAXL][2])
{
    int N = r->N, Q = r->Q;
    for (int c = 1; c < r->n; c++)
        for (int K = 1; K < N; K++) {
            int a = K / Q < r->n ? K / Q : r->n - 1, i = K - a * Q;
            double t = r->tau[i];
            for (int d = 0; d < 2; d++) {
                D[c * Q][K][d] = (1 - t) * D[c * Q][a * Q][d] + t * D[c * Q][a * Q + Q][d];
                D[K][c * Q][d] = (1 - t) * D[a * Q][c * Q][d] + t * D[a * Q + Q][c * Q][d];
            }
        }
}

/* Inside child (a, b): the displacement of its four sides, blended
 * (transfinite interpolation of D; D is indexed [J][I]). */
static void child_blend(const refine *r, int a, int b, double (*D)[RF_MAXL][2])
{
    int Q = r->Q, I0 = a * Q, J0 = b * Q;
    for (int j = 1; j < Q; j++)
        for (int i = 1; i < Q; i++) {
            double t = r->tau[i], s = r->tau[j];
            for (int d = 0; d < 2; d++)
                D[J0 + j][I0 + i][d] =
                    (1 - s) * D[J0][I0 + i][d] + s * D[J0 + Q][I0 + i][d] +
                    (1 - t) * D[J0 + j][I0][d] + t * D[J0 + j][I0 + Q][d] -
                    ((1 - t) * (1 - s) * D[J0][I0][d] + t * (1 - s) * D[J0][I0 + Q][d] +
                     t * s * D[J0 + Q][I0 + Q][d] + (1 - t) * s * D[J0 + Q][I0][d]);
        }
}

/* Parent q's inner lattice points, its children's nodes and patches. */
static void fill_parent(refine *r, int q)
{
    int N = r->N, Q = r->Q, n = r->n;
    double D[RF_MAXL][RF_MAXL][2], base[RF_MAXL][RF_MAXL][2]; /* [J][I] */
    for (int J = 0; J <= N; J++)
        for (int I = 0; I <= N; I++) {
            sq_quad_mesh_point(r->m, q, r->LU[I], r->LU[J], base[J][I]);
            int border = I == 0 || I == N || J == 0 || J == N;
            const double *x = &r->out->xy[2 * (size_t)lattice_node(r, q, I, J)];
            D[J][I][0] = border ? x[0] - base[J][I][0] : 0.0;
            D[J][I][1] = border ? x[1] - base[J][I][1] : 0.0;
        }
    inner_lines(r, D);
    for (int b = 0; b < n; b++)
        for (int a = 0; a < n; a++) child_blend(r, a, b, D);
    for (int J = 1; J < N; J++)
        for (int I = 1; I < N; I++) {
            double *x = &r->out->xy[2 * (size_t)lattice_node(r, q, I, J)];
            x[0] = base[J][I][0] + D[J][I][0];
            x[1] = base[J][I][1] + D[J][I][1];
        }
    for (int b = 0; b < n; b++)
        for (int a = 0; a < n; a++) {
            int c = q * n * n + b * n + a;
            int *cn = &r->out->conn[(size_t)c * (Q + 1) * (Q + 1)];
            for (int j = 0; j <= Q; j++)
                for (int i = 0; i <= Q; i++)
                    cn[sq_quad_node(Q, i, j)] = lattice_node(r, q, a * Q + i, b * Q + j);
            r->out->patch[c] = r->m->patch[q];
        }
}

/* Each parent boundary side becomes n child sides, in its walking order. */
static void boundary_sides(refine *r)
{
    int n = r->n;
    for (int s = 0; s < r->m->nbnd; s++) {
        int q = r->m->bnd_quad[s], k = r->m->bnd_side[s];
        for (int c = 0; c < n; c++) {
            int I, J;
            side_lattice(k, n - 1, c, &I, &J); /* the child (a, b) = (I, J) */
            int o = n * s + c;
            r->out->bnd_quad[o] = q * n * n + J * n + I;
            r->out->bnd_side[o] = k;
            r->out->bnd_tag[o] = r->m->bnd_tag[s];
        }
    }
    r->out->ntags = r->m->ntags;
}

/* Edges [begin, end) inside the face (their owner's map only: the CAD
 * curves' evaluators are not shared between threads). */
static sq_status inner_edges(void *ctx, long begin, long end, sq_error *err)
{
    refine *r = ctx;
    for (long f = begin; f < end; f++)
        if (r->e.tag[f] < 0) SQ_TRY(place_edge(r, (int)f, err));
    return SQ_OK;
}

/* Parents [begin, end): each writes its own inner points and children. */
static sq_status parents(void *ctx, long begin, long end, sq_error *err)
{
    (void)err;
    for (long q = begin; q < end; q++) fill_parent(ctx, (int)q);
    return SQ_OK;
}

/* items per range of the threads */
#define RF_GRAIN 64

static sq_status vertices(refine *r, sq_error *err)
{
    r->vid = malloc((size_t)(r->m->nnodes ? r->m->nnodes : 1) * sizeof *r->vid);
    if (!r->vid) return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    for (int k = 0; k < r->m->nnodes; k++) r->vid[k] = -1;
    for (int q = 0; q < r->m->nquads; q++)
        for (int k = 0; k < 4; k++) r->vid[sq_quad_corner_node(r->m, q, k)] = 0;
    r->nv = 0;
    for (int k = 0; k < r->m->nnodes; k++)
        if (r->vid[k] == 0) r->vid[k] = r->nv++;
        else r->vid[k] = -1;
    return SQ_OK;
}

static sq_status run(refine *r, sq_error *err)
{
    const sq_quad_mesh *m = r->m;
    SQ_TRY(sq_quad_edges_build(m, r->threads, &r->e, err));
    SQ_TRY(vertices(r, err));
    int N = r->N;
    long nn = r->nv + (long)r->e.nedges * (N - 1) + (long)m->nquads * (N - 1) * (N - 1);
    long nq = (long)m->nquads * r->n * r->n, nb = (long)m->nbnd * r->n;
    if (nn > 2000000000L || nq > 2000000000L / ((r->Q + 1) * (r->Q + 1)))
        return SQ_FAIL(err, SQ_ERR_USAGE, "refining %d quads gives %ld nodes: too many",
                       m->nquads, nn);
    SQ_TRY(sq_quad_mesh_create(r->Q, m->nodes, (int)nn, (int)nq, (int)nb, &r->out, err));
    for (int k = 0; k < m->nnodes; k++)
        if (r->vid[k] >= 0) memcpy(&r->out->xy[2 * (size_t)r->vid[k]], &m->xy[2 * (size_t)k],
                                   2 * sizeof(double));
    for (int f = 0; f < r->e.nedges; f++)
        if (r->e.tag[f] >= 0) SQ_TRY(place_edge(r, f, err));
    SQ_TRY(sq_parallel_for(r->threads, r->e.nedges, RF_GRAIN, inner_edges, r, err));
    SQ_TRY(sq_parallel_for(r->threads, m->nquads, RF_GRAIN, parents, r, err));
    boundary_sides(r);
    return SQ_OK;
}

sq_status sq_quad_mesh_refine(const cad_face *face, const sq_quad_mesh *m, int n, int order,
                              int threads, sq_quad_mesh **out, sq_error *err)
{
    *out = NULL;
    if (n < 1 || n > RF_MAXN || order < 1 || order > 10)
        return SQ_FAIL(err, SQ_ERR_USAGE, "refinement: %d children per side (1..%d), order %d "
                       "(1..10)", n, RF_MAXN, order);
    refine r = {.face = face, .m = m, .n = n, .Q = order, .N = n * order, .threads = threads};
    sq_quad_basis cb;
    SQ_TRY(sq_quad_basis_init(&r.pb, m->order, m->nodes, err));
    SQ_TRY(sq_quad_basis_init(&cb, order, m->nodes, err));
    r.tau = cb.t;
    for (int I = 0; I <= r.N; I++) {
        int a = I / order < n ? I / order : n - 1;
        r.U[I] = (a + cb.t[I - a * order]) / n;
        sq_quad_basis_eval(&r.pb, r.U[I], r.LU[I], NULL);
    }
    sq_status st = run(&r, err);
    sq_quad_edges_free(&r.e);
    free(r.vid);
    if (st != SQ_OK) sq_quad_mesh_free(&r.out);
    *out = r.out;
    return st;
}
