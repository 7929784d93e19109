/* semquad — the branch cut L that makes θ single-valued (Jezdimirović
 * 2021 §5.2.1): a spanning tree of the triangulation's edges grown from
 * the outer boundary in order of distance (Dijkstra with edge lengths: the
 * priority-ordered breadth-first search of the paper, so paths are short
 * and straight), each boundary loop taken as one node, then hanging edges
 * pruned until every leaf is a singular point or a hole.  What is left
 * joins every singular point to the boundary and every hole to the outer
 * boundary, without closed loops: the face minus L is simply connected
 * and contains no singular point. */
#ifndef SQ_BRANCH_CUT_H
#define SQ_BRANCH_CUT_H

#include "cad.h"
#include "tri_mesh.h"

typedef struct {
    int nedges;
    int *edges;         /* 2*nedges mesh vertex indices: the edges of L */
    int *half;          /* nedges: one half-edge 3*t + k of each edge */
    unsigned char *cut; /* 3*ntris: 1 on both half-edges of every edge of L */
} sq_branch_cut;

/* Boundary loop of every vertex of the triangulation (btag = CAD edge),
 * -1 for interior vertices: *loops gets nverts entries (caller frees). */
sq_status sq_mesh_vertex_loops(const cad_face *face, const sem_tri_mesh *mesh, int **loops,
                               sq_error *err);

/* Build L.  loops: from sq_mesh_vertex_loops; sing[nsing]: mesh vertices
 * of the singular points (interior).  SQ_ERR_INTERNAL if the mesh is not
 * connected. */
sq_status sq_branch_cut_build(const sem_tri_mesh *mesh, const int *loops, int nloops, int nsing,
                              const int *sing, sq_branch_cut *out, sq_error *err);
void sq_branch_cut_free(sq_branch_cut *c); /* frees, zeroes the struct */

#endif
