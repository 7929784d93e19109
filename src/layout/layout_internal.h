/* semquad — internals shared by the layout's files: the graph
 * (layout_graph.c, layout_patches.c, layout_intersect.c, layout_seps.c),
 * its checks and its repairs (not part of the public contract). */
#ifndef SQ_LAYOUT_INTERNAL_H
#define SQ_LAYOUT_INTERNAL_H

#include "layout.h"

/* An intersection of two separatrix polylines (a may equal b: a self
 * crossing).  Positions along a polyline are "segment index + t". */
typedef struct {
    int a, b;
    double pa, pb;     /* positions on a and b */
    double x, y;
    int enda, endb;    /* -1: interior; 0: at the start; 1: at the end */
    double cosang;     /* |cos| of the angle between the two segments */
} lay_hit;

/* All intersections between the separatrices of set (adjacent segments of
 * one polyline excluded); tol: coincidence distance.  *hits malloc'ed. */
sq_status lay_intersections(const sq_separatrix_set *set, double tol, lay_hit **hits, int *nhits,
                            sq_error *err);

/* (Re)build nodes, edges and patches of layout from its sing, seps and
 * vertex_quads; frees the previous graph. */
sq_status lay_graph_build(sq_layout *L, const cad_face *face, const sq_face_info *info,
                          sq_error *err);

/* The patches of L's nodes and edges: the faces of the planar graph
 * (layout_patches.c). */
sq_status lay_patches_build(sq_layout *L, const cad_face *face, sq_error *err);

/* p grown to hold `need` elements of `size` bytes (capacity *cap doubled);
 * NULL when out of memory (p is still valid then). */
void *lay_grow(void *p, int *cap, int need, size_t size);

/* separatrix-set helpers (the layout owns deep copies) */
sq_status lay_sep_push(sq_separatrix_set *set, const double *xy, int npts, sq_sep_end start,
                       sq_sep_end end, sq_error *err);
void lay_sep_remove(sq_separatrix_set *set, int k);
void lay_sepset_free(sq_separatrix_set *set);
sq_status lay_sing_push(sq_layout *L, double x, double y, int valence, sq_lrole role,
                        sq_error *err);

/* Winding-number test of p against the closed polygon xy[n]. */
int lay_poly_contains(const double *xy, int n, const double p[2]);

/* The closed polygon (*np points: each edge's polyline but its last point)
 * of the cycle of half-edges h[n], walked in order; malloc'ed, NULL when out
 * of memory. */
double *lay_cycle_polygon(const sq_layout *L, const sq_layout_half *h, int n, int *np);

#endif
