/* semquad sem/ — gluing a mesh along pairs of its boundary edges. */
#include "tri_mesh_glue.h"

#include <stdlib.h>
#include <string.h>

static int uf_find(int *parent, int i)
{
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
}

sq_status sem_tri_mesh_glue(const sem_tri_mesh *m, int npairs, const int *pairs,
                            sem_tri_mesh **out, sq_error *err)
{
    if (!out || !m || (npairs > 0 && !pairs))
        return SQ_FAIL(err, SQ_ERR_USAGE, "tri_mesh_glue: NULL argument");
    *out = NULL;
    const int nt = m->ntris, nv = m->nverts;
    int *parent = malloc(((size_t)nv + 1) * sizeof *parent);
    int *newid = malloc(((size_t)nv + 1) * sizeof *newid);
    int *mate = malloc((3 * (size_t)nt + 1) * sizeof *mate);
    if (!parent || !newid || !mate) {
        free(parent);
        free(newid);
        free(mate);
        return SQ_FAIL(err, SQ_ERR_INTERNAL, "tri_mesh_glue: out of memory");
    }
    sq_status st = SQ_OK;
    for (int v = 0; v < nv; ++v) parent[v] = v;
    for (size_t h = 0; h < 3 * (size_t)nt; ++h) mate[h] = -1;
    for (int p = 0; p < npairs && st == SQ_OK; ++p) {
        const int h0 = pairs[2 * p], h1 = pairs[2 * p + 1];
        if (h0 < 0 || h1 < 0 || h0 >= 3 * nt || h1 >= 3 * nt || h0 == h1 || m->neigh[h0] >= 0 ||
            m->neigh[h1] >= 0 || mate[h0] >= 0 || mate[h1] >= 0) {
            st = SQ_FAIL(err, SQ_ERR_USAGE,
                         "tri_mesh_glue: pair %d (edges %d, %d) is not two free boundary edges", p,
                         h0, h1);
            break;
        }
        mate[h0] = h1;
        mate[h1] = h0;
        const int t0 = h0 / 3, k0 = h0 % 3, t1 = h1 / 3, k1 = h1 % 3;
        const int a[2] = {m->tri[h0], m->tri[3 * t0 + (k0 + 1) % 3]};
        const int b[2] = {m->tri[3 * t1 + (k1 + 1) % 3], m->tri[h1]};
        for (int e = 0; e < 2; ++e) {
            const int x = uf_find(parent, a[e]), y = uf_find(parent, b[e]);
            if (x != y) parent[x < y ? y : x] = x < y ? x : y; /* the lower keeps its place */
        }
    }
    int n = 0;
    for (int v = 0; v < nv && st == SQ_OK; ++v) newid[v] = uf_find(parent, v) == v ? n++ : -1;
    for (int t = 0; t < nt && st == SQ_OK; ++t) {
        const int *c = m->tri + 3 * t;
        const int r0 = uf_find(parent, c[0]), r1 = uf_find(parent, c[1]), r2 = uf_find(parent, c[2]);
        if (r0 == r1 || r1 == r2 || r2 == r0)
            st = SQ_FAIL(err, SQ_ERR_USAGE, "tri_mesh_glue: element %d would have two vertices "
                                            "glued into one",
                         t);
    }
    sem_tri_mesh *g = NULL;
    if (st == SQ_OK) st = sem_tri_mesh_create(m->order, n, nt, &g, err);
    if (st == SQ_OK) {
        for (int v = 0; v < nv; ++v) {
            const int id = newid[uf_find(parent, v)];
            if (newid[v] >= 0) g->vxy[2 * id] = m->vxy[2 * v], g->vxy[2 * id + 1] = m->vxy[2 * v + 1];
        }
        for (size_t h = 0; h < 3 * (size_t)nt; ++h) {
            g->tri[h] = newid[uf_find(parent, m->tri[h])];
            g->neigh[h] = mate[h] >= 0 ? mate[h] / 3 : m->neigh[h];
            g->btag[h] = mate[h] >= 0 ? -1 : m->btag[h];
        }
        memcpy(g->gxy, m->gxy, sizeof(double) * 2 * (size_t)m->nodes_per_tri * (size_t)nt);
    }
    free(parent);
    free(newid);
    free(mate);
    if (st != SQ_OK) {
        sem_tri_mesh_free(&g);
        return st;
    }
    *out = g;
    return SQ_OK;
}
