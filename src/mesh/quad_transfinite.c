/* semquad — one quad patch filled by discrete transfinite interpolation of
 * its four sides (quad_mesher.h design 3), the sides read from the edges'
 * shared nodes. */
#include "quad_mesher_private.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Point k of edge e walked in direction `reversed`, and its global id. */
static void edge_point(const sq_layout *L, const qm_edge_nodes *en, int Q, int e, int reversed,
                       int k, double xy[2], long *gid)
{
    int M = en->n[e] * Q + 1, kk = reversed ? M - 1 - k : k;
    xy[0] = en->pts[e][2 * kk];
    xy[1] = en->pts[e][2 * kk + 1];
    if (kk == 0) *gid = L->edges[e].n0;
    else if (kk == M - 1) *gid = L->edges[e].n1;
    else *gid = en->base[e] + kk - 1;
}

/* The points of side k of patch p in walking order: count N (returned),
 * xy[2N], gid[N]; tags[N-1]: CAD edge under each segment (-1 inside). */
static int side_points(const sq_layout *L, const qm_edge_nodes *en, int Q, const sq_layout_patch *p,
                       int k, double *xy, long *gid, int *tags)
{
    int N = 0;
    for (int h = p->side_start[k]; h < p->side_start[k + 1]; h++) {
        int e = p->half[h].edge, M = en->n[e] * Q + 1;
        for (int i = h == p->side_start[k] ? 0 : 1; i < M; i++) {
            edge_point(L, en, Q, e, p->half[h].reversed, i, &xy[2 * N], &gid[N]);
            if (N > 0) tags[N - 1] = L->edges[e].cad_edge;
            N++;
        }
    }
    return N;
}

/* Cumulative chord-length fractions of a point list read with stride. */
static void fractions(const double *xy, int N, double *f)
{
    f[0] = 0.0;
    for (int i = 1; i < N; i++)
        f[i] = f[i - 1] + hypot(xy[2 * i] - xy[2 * i - 2], xy[2 * i + 1] - xy[2 * i - 1]);
    for (int i = 1; i < N; i++) f[i] /= f[N - 1] > 0.0 ? f[N - 1] : 1.0;
}

void qm_patch_grid_free(qm_patch_grid *g)
{
    free(g->xy);
    free(g->gid);
    for (int k = 0; k < 4; k++) free(g->tag[k]);
    memset(g, 0, sizeof *g);
}

/* Design 3: discrete transfinite interpolation of the four sides. */
static sq_status fill_patch(const sq_layout *L, const qm_edge_nodes *en, int Q, int q,
                            long *next_id, qm_patch_grid *g, sq_error *err)
{
    const sq_layout_patch *p = &L->patches[q];
    int NU = (int)qm_side_count(p, 0, en->n) * Q, NV = (int)qm_side_count(p, 1, en->n) * Q;
    int maxN = (NU > NV ? NU : NV) + 1;
    size_t np = (size_t)(NU + 1) * (NV + 1);
    g->NU = NU;
    g->NV = NV;
    g->xy = malloc(sizeof(double) * 2 * np);
    g->gid = malloc(sizeof(long) * np);
    double *sxy = malloc(sizeof(double) * 2 * 4 * (size_t)maxN);
    long *sid = malloc(sizeof(long) * 4 * (size_t)maxN);
    double *f = malloc(sizeof(double) * 4 * (size_t)maxN);
    int ok = g->xy && g->gid && sxy && sid && f;
    for (int k = 0; k < 4 && ok; k++) ok = (g->tag[k] = malloc(sizeof(int) * (size_t)maxN)) != NULL;
    if (!ok) {
        free(sxy);
        free(sid);
        free(f);
        return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    }
    double *S[4];
    long *I[4];
    int *T[4];
    for (int k = 0; k < 4; k++) {
        S[k] = sxy + 2 * (size_t)k * maxN;
        I[k] = sid + (size_t)k * maxN;
        T[k] = g->tag[k];
        side_points(L, en, Q, p, k, S[k], I[k], T[k]);
    }
#define G(i, j) ((size_t)(j) * (NU + 1) + (i))
    /* boundary of the grid: bottom left->right, right bottom->top, top and
     * left walked backwards (the patch's cycle runs counter-clockwise) */
    for (int i = 0; i <= NU; i++) {
        memcpy(&g->xy[2 * G(i, 0)], &S[0][2 * i], 2 * sizeof(double));
        g->gid[G(i, 0)] = I[0][i];
        memcpy(&g->xy[2 * G(i, NV)], &S[2][2 * (NU - i)], 2 * sizeof(double));
        g->gid[G(i, NV)] = I[2][NU - i];
    }
    for (int j = 0; j <= NV; j++) {
        memcpy(&g->xy[2 * G(NU, j)], &S[1][2 * j], 2 * sizeof(double));
        g->gid[G(NU, j)] = I[1][j];
        memcpy(&g->xy[2 * G(0, j)], &S[3][2 * (NV - j)], 2 * sizeof(double));
        g->gid[G(0, j)] = I[3][NV - j];
    }
    /* blending parameters from the sides' arc-length fractions */
    double *fb = f, *ft = f + maxN, *fl = f + 2 * maxN, *fr = f + 3 * maxN;
    double *tmp = malloc(sizeof(double) * 2 * (size_t)maxN);
    if (!tmp) {
        free(sxy);
        free(sid);
        free(f);
        return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    }
    for (int i = 0; i <= NU; i++) memcpy(&tmp[2 * i], &g->xy[2 * G(i, 0)], 2 * sizeof(double));
    fractions(tmp, NU + 1, fb);
    for (int i = 0; i <= NU; i++) memcpy(&tmp[2 * i], &g->xy[2 * G(i, NV)], 2 * sizeof(double));
    fractions(tmp, NU + 1, ft);
    for (int j = 0; j <= NV; j++) memcpy(&tmp[2 * j], &g->xy[2 * G(0, j)], 2 * sizeof(double));
    fractions(tmp, NV + 1, fl);
    for (int j = 0; j <= NV; j++) memcpy(&tmp[2 * j], &g->xy[2 * G(NU, j)], 2 * sizeof(double));
    fractions(tmp, NV + 1, fr);
    free(tmp);
    const double *P00 = &g->xy[2 * G(0, 0)], *P10 = &g->xy[2 * G(NU, 0)],
                 *P11 = &g->xy[2 * G(NU, NV)], *P01 = &g->xy[2 * G(0, NV)];
    for (int j = 1; j < NV; j++)
        for (int i = 1; i < NU; i++) {
            /* (xi, eta): where the lines joining matching side fractions meet */
            double du = ft[i] - fb[i], dv = fr[j] - fl[j];
            double xi = (fb[i] + du * fl[j]) / (1.0 - du * dv), eta = fl[j] + dv * xi;
            const double *B = &g->xy[2 * G(i, 0)], *T = &g->xy[2 * G(i, NV)];
            const double *Lf = &g->xy[2 * G(0, j)], *R = &g->xy[2 * G(NU, j)];
            qm_coons(B, T, Lf, R, P00, P10, P11, P01, xi, eta, &g->xy[2 * G(i, j)]);
            g->gid[G(i, j)] = (*next_id)++;
        }
#undef G
    free(sxy);
    free(sid);
    free(f);
    return SQ_OK;
}

sq_status qm_fill_patches(const sq_layout *L, const qm_edge_nodes *en, const sq_progress *progress,
                          long *next_id, qm_patch_grid *grids, sq_error *err)
{
    sq_status st = SQ_OK;
    for (int q = 0; q < L->npatches && st == SQ_OK; q++) {
        st = fill_patch(L, en, 1, q, next_id, &grids[q], err);
        sq_progress_report(progress, "mesh", q + 1, L->npatches);
    }
    return st;
}
