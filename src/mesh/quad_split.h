/* semquad — the split road: an all-quad mesh of any valid face without a
 * field or a layout, the road `semquad mesh` takes when the layout road
 * finds no valid layout (or `--road split`).
 *
 * design:
 *  1. the face's constrained Delaunay triangulation at order 1
 *     (triangulate.h: boundary vertices on the CAD curves, CGAL's Delaunay
 *     refinement) with edges of about SQ_SPLIT_TRI_SIZE times the target
 *     size: a triangle's quads have sides of about half its edges.
 *     Where CGAL's angle bound cannot be met within the work bound (a sliver
 *     of aspect 1e6, a needle corner) the size bound alone;
 *  2. the triangles paired across interior edges into convex quads of
 *     corner angles within 30-150 deg, greedily, the best shaped first (a
 *     recombination, as Gmsh's before its subdivision); every pair split
 *     into four quads and every triangle left alone into three, at the
 *     centroid and the midpoints of the edges (a convex polygon's quads
 *     about its centroid are convex).  A boundary edge's midpoint goes
 *     onto its CAD curve at the middle arc length;
 *  3. the mesher's design 3 and 4 (quad_mesher.h): untangling, Winslow
 *     relaxation, order Q with the sides on the curves.
 *
 * Valid wherever the triangulation is, at the price of irregular vertices
 * (valence 3 at a lone triangle's centroid, the pairs' and triangles'
 * count at a vertex): the report says which road was taken and why. */
#ifndef SQ_QUAD_SPLIT_H
#define SQ_QUAD_SPLIT_H

#include "quad_mesher.h"

/* Triangle edge bound per target quad size (design 1): a triangle's quads
 * have sides of 1/2 (on its edges) and 1/(2 sqrt 3) (inside) of its edges,
 * and CGAL's edges are about 0.7 of its bound; 3 gave about area / size^2
 * quads at three a triangle, as the layout road; the pairs' two a triangle
 * give about a third fewer. */
#define SQ_SPLIT_TRI_SIZE 3.0

/* opt: order, nodes, size (<= 0: the default), max_quads (the quads are
 * at most three per triangle: SQ_ERR_USAGE beyond it, naming a size that
 * fits). */
sq_status sq_mesh_split(const cad_face *face, const sq_face_info *info,
                        const sq_mesher_options *opt, sq_quad_mesh **out, sq_error *err);

/* sq_mesh_split in two halves, for faces of a domain that exchange their
 * shared edges' points between them (docs/domains.md): design 1 (with
 * opt->edge_points), then designs 2 and 3 on that triangulation. */
sq_status sq_split_triangulate(const cad_face *face, const sq_face_info *info,
                               const sq_mesher_options *opt, sq_triangulation *tri, sq_error *err);
sq_status sq_mesh_split_triangulation(const cad_face *face, const sq_face_info *info,
                                      const sq_triangulation *tri, const sq_mesher_options *opt,
                                      sq_quad_mesh **out, sq_error *err);

#endif
