/* semquad — node orders of high-order quadrilaterals and lines in the file
 * formats, as lattice indices (i, j) of quad_mesh.h (node (i, j) at
 * (i/Q, j/Q) when equispaced).
 *
 * Gmsh (MSH element types 3, 10, 36, 37, 38, 47..51; Gmsh reference manual,
 * "Node ordering"): the 4 corners counter-clockwise, then the interior nodes
 * of edges 0-1, 1-2, 2-3, 3-0 each in the direction of the edge, then the
 * interior nodes as a quad of order Q-2 in the same order, recursively.
 *
 * VTK (VTK_LAGRANGE_QUADRILATERAL = 70; VTK's vtkHigherOrderQuadrilateral,
 * "Lagrange cells" on the VTK blog): the 4 corners counter-clockwise, then
 * the edge interiors of (j=0), (i=Q), (j=Q), (i=0) each with its lattice
 * coordinate increasing (so edges 2 and 3 run against the counter-clockwise
 * direction), then the interior in lattice order, i fastest. */
#ifndef SQ_QUAD_ORDER_H
#define SQ_QUAD_ORDER_H

/* ij[2*(Q+1)^2]: lattice (i, j) of the k-th node of the format's order. */
void sq_quad_gmsh_order(int Q, int *ij);
void sq_quad_vtk_order(int Q, int *ij);

/* Gmsh element type of a quad / a line of order Q (1..10), 0 otherwise. */
int sq_gmsh_quad_type(int Q);
int sq_gmsh_line_type(int Q);

/* Node order of a line of order Q in Gmsh and VTK: the two ends, then the
 * interior from the first end: k-th node at lattice position idx[k]. */
void sq_line_order(int Q, int *idx);

#endif
