/* semquad sem/ — a curved high-order triangle mesh (plain data).
 *
 * Reference triangle T = {(r,s): r >= 0, s >= 0, r + s <= 1}, vertices
 * (0,0), (1,0), (0,1).  Element edge k joins local vertex k to (k+1)%3.
 * Each element carries the nodes of its isoparametric geometry map of order
 * `order` on the lattice node set of sem_tri_nodes() (lattice order, see
 * tri_nodes.h); x(r,s) = sum_n node_n * l_n(r,s) with l_n the Lagrange basis
 * of tri_lagrange.h.
 *
 * sem/ knows nothing about CAD: an edge's boundary tag is an integer the
 * caller chose (semquad uses the CAD edge index). */
#ifndef SEM_TRI_MESH_H
#define SEM_TRI_MESH_H

#include "sq_status.h"

typedef struct {
    int order;     /* geometry order, 1..SEM_MAX_ORDER */
    int nverts;
    double *vxy;   /* 2*nverts: corner vertices */
    int ntris;
    int *tri;      /* 3*ntris: corner vertex indices, counter-clockwise */
    int *neigh;    /* 3*ntris: element across edge k, or -1 on the boundary */
    int *btag;     /* 3*ntris: boundary tag of edge k (>= 0), or -1 inside */
    int nodes_per_tri; /* (order+1)(order+2)/2 */
    double *gxy;   /* 2*nodes_per_tri*ntris: geometry nodes, element by element */
} sem_tri_mesh;

/* Allocate a mesh with the given sizes (arrays zeroed; neigh and btag set
 * to -1).  *out stays NULL on failure. */
sq_status sem_tri_mesh_create(int order, int nverts, int ntris, sem_tri_mesh **out, sq_error *err);
void sem_tri_mesh_free(sem_tri_mesh **mesh); /* NULL-safe, NULLs *mesh */

/* Fill neigh[] from tri[] (edges shared by two elements). SQ_ERR_INTERNAL
 * if an edge is shared by more than two elements. */
sq_status sem_tri_mesh_build_neighbours(sem_tri_mesh *mesh, sq_error *err);

#endif
