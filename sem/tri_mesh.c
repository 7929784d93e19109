/* semquad sem/ — a curved high-order triangle mesh (plain data). */
#include "tri_mesh.h"

#include "gauss.h"

#include <stdint.h>
#include <stdlib.h>

sq_status sem_tri_mesh_create(int order, int nverts, int ntris, sem_tri_mesh **out, sq_error *err)
{
    if (!out) return SQ_FAIL(err, SQ_ERR_USAGE, "tri_mesh_create: NULL output");
    *out = NULL;
    if (order < 1 || order > SEM_MAX_ORDER || nverts < 0 || ntris < 0)
        return SQ_FAIL(err, SQ_ERR_USAGE, "tri_mesh_create: bad sizes order=%d nverts=%d ntris=%d",
                       order, nverts, ntris);
    const int npt = (order + 1) * (order + 2) / 2;
    /* Overflow guard before the size-derived allocations (the int fields
     * must also index 3*ntris and 2*npt*ntris entries). */
    if ((size_t)ntris > (size_t)INT32_MAX / (size_t)(2 * npt) || (size_t)nverts > (size_t)INT32_MAX / 2)
        return SQ_FAIL(err, SQ_ERR_USAGE, "tri_mesh_create: mesh too large (%d vertices, %d triangles)",
                       nverts, ntris);
    sem_tri_mesh *m = calloc(1, sizeof *m);
    if (!m) return SQ_FAIL(err, SQ_ERR_INTERNAL, "tri_mesh_create: out of memory");
    m->order = order;
    m->nverts = nverts;
    m->ntris = ntris;
    m->nodes_per_tri = npt;
    /* calloc(0) may return NULL: allocate at least one element. */
    m->vxy = calloc(2 * (size_t)nverts + 1, sizeof(double));
    m->tri = calloc(3 * (size_t)ntris + 1, sizeof(int));
    m->neigh = malloc((3 * (size_t)ntris + 1) * sizeof(int));
    m->btag = malloc((3 * (size_t)ntris + 1) * sizeof(int));
    m->gxy = calloc(2 * (size_t)npt * (size_t)ntris + 1, sizeof(double));
    if (!m->vxy || !m->tri || !m->neigh || !m->btag || !m->gxy) {
        sem_tri_mesh_free(&m);
        return SQ_FAIL(err, SQ_ERR_INTERNAL, "tri_mesh_create: out of memory (%d triangles)", ntris);
    }
    for (size_t k = 0; k < 3 * (size_t)ntris; ++k) m->neigh[k] = m->btag[k] = -1;
    *out = m;
    return SQ_OK;
}

void sem_tri_mesh_free(sem_tri_mesh **mesh)
{
    if (!mesh || !*mesh) return;
    sem_tri_mesh *m = *mesh;
    free(m->vxy);
    free(m->tri);
    free(m->neigh);
    free(m->btag);
    free(m->gxy);
    free(m);
    *mesh = NULL;
}

typedef struct {
    int a, b; /* vertex indices, a < b */
    int he;   /* half-edge 3*t + k */
} edge_key;

static int cmp_edge(const void *p, const void *q)
{
    const edge_key *x = p, *y = q;
    if (x->a != y->a) return (x->a > y->a) - (x->a < y->a);
    if (x->b != y->b) return (x->b > y->b) - (x->b < y->b);
    return (x->he > y->he) - (x->he < y->he);
}

sq_status sem_tri_mesh_build_neighbours(sem_tri_mesh *mesh, sq_error *err)
{
    if (!mesh) return SQ_FAIL(err, SQ_ERR_USAGE, "tri_mesh_build_neighbours: NULL mesh");
    const size_t ne = 3 * (size_t)mesh->ntris;
    for (size_t h = 0; h < ne; ++h) {
        const int v = mesh->tri[h];
        if (v < 0 || v >= mesh->nverts)
            return SQ_FAIL(err, SQ_ERR_USAGE,
                           "tri_mesh_build_neighbours: triangle %zu has vertex %d outside 0..%d",
                           h / 3, v, mesh->nverts - 1);
    }
    edge_key *e = malloc((ne + 1) * sizeof *e);
    if (!e) return SQ_FAIL(err, SQ_ERR_INTERNAL, "tri_mesh_build_neighbours: out of memory");
    for (size_t h = 0; h < ne; ++h) {
        const size_t t = h / 3, k = h % 3;
        const int v0 = mesh->tri[3 * t + k], v1 = mesh->tri[3 * t + (k + 1) % 3];
        e[h].a = v0 < v1 ? v0 : v1;
        e[h].b = v0 < v1 ? v1 : v0;
        e[h].he = (int)h;
    }
    /* Sorting the edge keys groups the half-edges of each edge: O(n log n). */
    qsort(e, ne, sizeof *e, cmp_edge);
    sq_status st = SQ_OK;
    for (size_t i = 0; i < ne;) {
        size_t j = i + 1;
        while (j < ne && e[j].a == e[i].a && e[j].b == e[i].b) ++j;
        if (e[i].a == e[i].b) {
            st = SQ_FAIL(err, SQ_ERR_INTERNAL,
                         "tri_mesh_build_neighbours: triangle %d has a degenerate edge (vertex %d twice)",
                         e[i].he / 3, e[i].a);
            break;
        }
        if (j - i > 2) {
            st = SQ_FAIL(err, SQ_ERR_INTERNAL,
                         "tri_mesh_build_neighbours: edge (%d,%d) shared by %zu triangles (%d, %d, %d...)",
                         e[i].a, e[i].b, j - i, e[i].he / 3, e[i + 1].he / 3, e[i + 2].he / 3);
            break;
        }
        if (j - i == 2) {
            mesh->neigh[e[i].he] = e[i + 1].he / 3;
            mesh->neigh[e[i + 1].he] = e[i].he / 3;
        } else {
            mesh->neigh[e[i].he] = -1;
        }
        i = j;
    }
    free(e);
    return st;
}
