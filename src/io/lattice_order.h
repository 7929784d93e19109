/* semquad — the vertex/edge/interior node order of high-order triangles
 * used by VTK's Lagrange triangle (type 69) and Gmsh's MSH triangles:
 * the three vertices, the interior nodes of edges 0-1, 1-2, 2-0 in the
 * direction of the edge, then the interior nodes as a triangle of order
 * P-3 in the same order, recursively. */
#ifndef SQ_LATTICE_ORDER_H
#define SQ_LATTICE_ORDER_H

/* ij[2*(P+1)(P+2)/2]: lattice indices (i along r, j along s; node at
 * (i/P, j/P) when equispaced) in that order. */
void sq_tri_lattice_order(int P, int *ij);

#endif
