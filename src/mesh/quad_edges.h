/* semquad — the edges of a quad mesh: each element side between two
 * corner vertices once, with the quad side that owns it and the CAD edge
 * under it (refinement places an edge's new nodes once, so the quads on
 * both sides share them; the mesh's h is their mean length). */
#ifndef SQ_QUAD_EDGES_H
#define SQ_QUAD_EDGES_H

#include "quad_mesh.h"

typedef struct {
    int nedges;
    int *side_edge; /* 4 nquads: the edge of side k of quad q at 4q + k */
    int *owner;     /* nedges: 4q + k of its first side (least q, then k); the
                       edge runs in that side's walking direction */
    int *tag;       /* nedges: the CAD edge under it (bnd_tag), -1 inside the face */
} sq_quad_edges;

/* Node index of corner k (0..3, counter-clockwise from (0,0)) of quad q. */
int sq_quad_corner_node(const sq_quad_mesh *m, int q, int k);

/* The sides' sort on `threads` threads (sq_parallel_sort: the same edges
 * for every number). */
sq_status sq_quad_edges_build(const sq_quad_mesh *m, int threads, sq_quad_edges *e,
                              sq_error *err);
void sq_quad_edges_free(sq_quad_edges *e); /* NULL-safe, zeroes *e */

/* Mean and largest straight distance between the two vertices of an edge. */
void sq_quad_edges_lengths(const sq_quad_mesh *m, const sq_quad_edges *e, double *mean,
                           double *max);

#endif
