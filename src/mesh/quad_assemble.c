/* semquad — the conforming vertex mesh of a layout (quad_mesher.h design 2):
 * every edge's nodes placed once, by arc length, so that the patches sharing
 * it share them; the patch grids glued into one mesh. */
#include "quad_mesher_private.h"

#include <stdlib.h>
#include <string.h>

static void edge_nodes_free(qm_edge_nodes *en, int nedges)
{
    for (int e = 0; en->pts && e < nedges; e++) free(en->pts[e]);
    free(en->pts);
    free(en->base);
}

void qm_vmesh_free(qm_vmesh *v)
{
    free(v->xy);
    free(v->foot);
    free(v->quad);
    free(v->patch);
    free(v->side_tag);
    memset(v, 0, sizeof *v);
}

/* Glue the patch grids into the vertex mesh. */
static sq_status build_vmesh(const sq_layout *L, qm_patch_grid *grids, long nids, qm_vmesh *v,
                             sq_error *err)
{
    long *map = malloc(sizeof(long) * (size_t)(nids + 1));
    double *gxy = malloc(sizeof(double) * 2 * (size_t)(nids + 1));
    int nq = 0;
    for (int q = 0; q < L->npatches; q++) nq += grids[q].NU * grids[q].NV;
    v->quad = malloc(sizeof(int) * 4 * (size_t)(nq + 1));
    v->patch = malloc(sizeof(int) * (size_t)(nq + 1));
    v->side_tag = malloc(sizeof(int) * 4 * (size_t)(nq + 1));
    if (!map || !gxy || !v->quad || !v->patch || !v->side_tag) {
        free(map);
        free(gxy);
        return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    }
    for (long i = 0; i < nids; i++) map[i] = -1;
    for (int q = 0; q < L->npatches; q++) {
        const qm_patch_grid *g = &grids[q];
        for (size_t k = 0; k < (size_t)(g->NU + 1) * (g->NV + 1); k++) {
            map[g->gid[k]] = 0;
            gxy[2 * g->gid[k]] = g->xy[2 * k];
            gxy[2 * g->gid[k] + 1] = g->xy[2 * k + 1];
        }
    }
    int nv = 0;
    for (long i = 0; i < nids; i++)
        if (map[i] == 0) map[i] = nv++;
    v->nv = nv;
    v->xy = malloc(sizeof(double) * 2 * (size_t)(nv + 1));
    v->foot = calloc((size_t)nv + 1, sizeof(int));
    if (!v->xy || !v->foot) {
        free(map);
        free(gxy);
        return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    }
    for (long i = 0; i < nids; i++)
        if (map[i] >= 0) {
            v->xy[2 * map[i]] = gxy[2 * i];
            v->xy[2 * map[i] + 1] = gxy[2 * i + 1];
            /* the layout's nodes come first in the id space */
            if (i < L->nnodes) v->foot[map[i]] = L->nodes[i].kind == SQ_LNODE_FOOT;
        }
    int qq = 0;
    for (int q = 0; q < L->npatches; q++) {
        const qm_patch_grid *g = &grids[q];
        for (int b = 0; b < g->NV; b++)
            for (int a = 0; a < g->NU; a++, qq++) {
                int *c = &v->quad[4 * qq];
#define GID(i, j) (int)map[g->gid[(size_t)(j) * (g->NU + 1) + (i)]]
                c[0] = GID(a, b);
                c[1] = GID(a + 1, b);
                c[2] = GID(a + 1, b + 1);
                c[3] = GID(a, b + 1);
#undef GID
                int *t = &v->side_tag[4 * qq];
                t[0] = b == 0 ? g->tag[0][a] : -1;
                t[1] = a == g->NU - 1 ? g->tag[1][b] : -1;
                t[2] = b == g->NV - 1 ? g->tag[2][g->NU - 1 - a] : -1;
                t[3] = a == 0 ? g->tag[3][g->NV - 1 - b] : -1;
                v->patch[qq] = q;
            }
    }
    v->nq = qq;
    free(map);
    free(gxy);
    return SQ_OK;
}

sq_status qm_assemble(const sq_layout *L, const cad_face *face, const sq_mesher_options *opt,
                      const int *nseg, const double *cum, qm_vmesh *v, sq_error *err)
{
    int S = qm_size_samples(opt);
    qm_edge_nodes en = {0};
    qm_patch_grid *grids = calloc((size_t)L->npatches + 1, sizeof *grids);
    en.n = nseg;
    en.base = malloc(sizeof(long) * ((size_t)L->nedges + 1));
    en.pts = calloc((size_t)L->nedges + 1, sizeof(double *));
    sq_status st = grids && en.base && en.pts ? SQ_OK
                                              : SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    /* Design 2: the vertices of every edge, once, by arc length; ids: the
     * layout's nodes first */
    long next_id = L->nnodes;
    for (int e = 0; e < L->nedges && st == SQ_OK; e++) {
        int n = en.n[e];
        en.pts[e] = malloc(sizeof(double) * 2 * (size_t)(n + 1));
        if (!en.pts[e]) {
            st = SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
            break;
        }
        double *f = malloc(sizeof(double) * (size_t)(n + 1));
        if (!f) {
            st = SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
            break;
        }
        for (int k = 1; k < n; k++)
            f[k] = qm_measure_fraction(&cum[(size_t)e * (S + 1)], S, (double)k / n);
        for (int k = 1; k < n && st == SQ_OK; k++)
            st = sq_layout_edge_point(L, face, e, f[k], &en.pts[e][2 * k], err);
        free(f);
        /* the ends are the layout's nodes, exactly */
        en.pts[e][0] = L->nodes[L->edges[e].n0].x;
        en.pts[e][1] = L->nodes[L->edges[e].n0].y;
        en.pts[e][2 * n] = L->nodes[L->edges[e].n1].x;
        en.pts[e][2 * n + 1] = L->nodes[L->edges[e].n1].y;
        en.base[e] = next_id;
        next_id += n - 1;
    }
    if (st == SQ_OK) st = qm_fill_patches(L, &en, &opt->progress, &next_id, grids, err);
    if (st == SQ_OK) st = build_vmesh(L, grids, next_id, v, err);
    for (int q = 0; grids && q < L->npatches; q++) qm_patch_grid_free(&grids[q]);
    free(grids);
    edge_nodes_free(&en, L->nedges);
    return st;
}
