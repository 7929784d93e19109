/* semquad sem/ — nodal point set on the reference triangle.
 *
 * Lattice indexing: node (i,j), i,j >= 0, i+j <= P, has index
 *   sem_tri_node_index(P,i,j) = j*(P+1) - j*(j-1)/2 + i
 * (rows of constant j, i increasing).  Node (0,0) is vertex 0, (P,0) vertex
 * 1, (0,P) vertex 2.  Coordinates follow Blyth & Pozrikidis (2006): built from
 * the 1D Gauss–Lobatto–Legendre points v_0..v_P on [0,1],
 *   r = (1 + 2 v_i - v_j - v_k)/3,  s = (1 + 2 v_j - v_i - v_k)/3,  k = P-i-j,
 * so the nodes on every edge are the GLL points of that edge. */
#ifndef SEM_TRI_NODES_H
#define SEM_TRI_NODES_H

#include "sq_status.h"

static inline int sem_tri_num_nodes(int P) { return (P + 1) * (P + 2) / 2; }
static inline int sem_tri_node_index(int P, int i, int j) { return j * (P + 1) - j * (j - 1) / 2 + i; }

/* rs[2*sem_tri_num_nodes(P)]: (r,s) of every node, lattice order. */
sq_status sem_tri_nodes(int P, double *rs, sq_error *err);

/* Lattice indices of the nodes on local edge k (0: v0->v1, 1: v1->v2,
 * 2: v2->v0), in the direction of the edge, both end vertices included:
 * idx[P+1]. */
void sem_tri_edge_nodes(int P, int k, int *idx);

#endif
