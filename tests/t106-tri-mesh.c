/* t106: mesh create/free and neighbours: two triangles splitting the unit
 * square share exactly one edge; a strip of many triangles; an edge shared
 * by three triangles and a vertex index out of range are rejected. */
#include "tri_mesh.h"

#include <stdio.h>

static int failures;

static void check(const char *what, int k, int value, int expected)
{
    if (value != expected) {
        printf("t106 %s (#%d): value %d expected %d tolerance 0\n", what, k, value, expected);
        ++failures;
    }
}

int main(void)
{
    sem_tri_mesh *m = NULL;
    sq_error err;
    if (sem_tri_mesh_create(3, 4, 2, &m, &err) != SQ_OK) {
        printf("t106 create failed: %s\n", err.msg);
        return 1;
    }
    check("nodes_per_tri", 0, m->nodes_per_tri, 10);
    for (int k = 0; k < 6; ++k) {
        check("neigh initialised to -1", k, m->neigh[k], -1);
        check("btag initialised to -1", k, m->btag[k], -1);
        check("tri zeroed", k, m->tri[k], 0);
    }
    for (int k = 0; k < 2 * 10 * 2; ++k) check("gxy zeroed", k, m->gxy[k] != 0.0, 0);
    const double v[8] = {0, 0, 1, 0, 1, 1, 0, 1};
    for (int k = 0; k < 8; ++k) m->vxy[k] = v[k];
    const int t[6] = {0, 1, 2, 0, 2, 3}; /* counter-clockwise, diagonal 0-2 */
    for (int k = 0; k < 6; ++k) m->tri[k] = t[k];
    if (sem_tri_mesh_build_neighbours(m, &err) != SQ_OK) {
        printf("t106 build_neighbours failed: %s\n", err.msg);
        return 1;
    }
    /* triangle 0: edge 2 joins 2 -> 0; triangle 1: edge 0 joins 0 -> 2 */
    const int expect[6] = {-1, -1, 1, 0, -1, -1};
    for (int k = 0; k < 6; ++k) check("square neighbours", k, m->neigh[k], expect[k]);
    sem_tri_mesh_free(&m);
    check("free NULLs the pointer", 0, m != NULL, 0);
    sem_tri_mesh_free(&m);
    sem_tri_mesh_free(NULL);

    /* a strip of 2N triangles over N unit squares */
    enum { N = 50 };
    if (sem_tri_mesh_create(1, 2 * (N + 1), 2 * N, &m, NULL) != SQ_OK) return 1;
    for (int i = 0; i < N; ++i) { /* bottom vertex i, top vertex N+1+i */
        const int a = i, b = i + 1, c = N + 2 + i, d = N + 1 + i;
        const int tt[6] = {a, b, c, a, c, d};
        for (int k = 0; k < 6; ++k) m->tri[6 * i + k] = tt[k];
    }
    if (sem_tri_mesh_build_neighbours(m, NULL) != SQ_OK) return 1;
    for (int i = 0; i < N; ++i) {
        /* lower (a,b,c): edge 1 b->c is edge 2 (d'->a') of the next
         * square's upper triangle (a',c',d'), since a' = b and d' = c */
        check("strip lower edge 0 boundary", i, m->neigh[6 * i + 0], -1);
        check("strip lower edge 1", i, m->neigh[6 * i + 1], i + 1 < N ? 2 * (i + 1) + 1 : -1);
        check("strip lower edge 2 (diagonal)", i, m->neigh[6 * i + 2], 2 * i + 1);
        check("strip upper edge 0 (diagonal)", i, m->neigh[6 * i + 3], 2 * i);
        check("strip upper edge 1 boundary", i, m->neigh[6 * i + 4], -1);
        check("strip upper edge 2", i, m->neigh[6 * i + 5], i > 0 ? 2 * (i - 1) : -1);
    }
    sem_tri_mesh_free(&m);

    /* three triangles on edge 0-1 */
    if (sem_tri_mesh_create(1, 5, 3, &m, NULL) != SQ_OK) return 1;
    const int t3[9] = {0, 1, 2, 1, 0, 3, 0, 1, 4};
    for (int k = 0; k < 9; ++k) m->tri[k] = t3[k];
    check("edge shared by three triangles", 0, sem_tri_mesh_build_neighbours(m, &err), SQ_ERR_INTERNAL);
    m->tri[8] = 7;
    check("vertex out of range", 0, sem_tri_mesh_build_neighbours(m, &err), SQ_ERR_USAGE);
    sem_tri_mesh_free(&m);

    check("bad order", 0, sem_tri_mesh_create(0, 3, 1, &m, NULL), SQ_ERR_USAGE);
    check("out stays NULL", 0, m != NULL, 0);
    check("negative count", 0, sem_tri_mesh_create(2, -1, 1, &m, NULL), SQ_ERR_USAGE);
    /* an empty mesh is valid */
    check("empty mesh", 0, sem_tri_mesh_create(2, 0, 0, &m, NULL), SQ_OK);
    check("empty neighbours", 0, sem_tri_mesh_build_neighbours(m, NULL), SQ_OK);
    sem_tri_mesh_free(&m);
    return failures ? 1 : 0;
}
