/* semquad — drawing curved triangulations into an SVG picture. */
#ifndef SQ_SVG_MESH_H
#define SQ_SVG_MESH_H

#include "svg.h"
#include "tri_lagrange.h"
#include "tri_mesh.h"

/* World bounding box of the mesh's geometry nodes. */
void sq_svg_mesh_bbox(const sem_tri_mesh *m, double bb[4]);

/* Draw the curved element edges: interior edges (once each) if interior,
 * boundary edges on top.  lag: Lagrange basis of the mesh's geometry order. */
void sq_svg_mesh_edges(sq_svg *svg, const sem_tri_mesh *m, const sem_tri_lagrange *lag,
                       int interior, const char *interior_color, double interior_width,
                       const char *boundary_color, double boundary_width);

#endif
