/* semquad — drawing curved triangulations into an SVG picture. */
#ifndef SQ_SVG_MESH_H
#define SQ_SVG_MESH_H

#include "outfile.h"
#include "svg.h"
#include "tri_lagrange.h"
#include "tri_mesh.h"

/* A picture of a curved triangulation: the file (written atomically), the
 * SVG fitted to the mesh, the Lagrange basis of its geometry, its box. */
typedef struct {
    sq_outfile file;
    sq_svg svg;
    sem_tri_lagrange *lag;
    double bbox[4];
} sq_svg_mesh_picture;

/* Open path and draw the mesh's curved edges (interior ones in the given
 * colour and width, the boundary dark on top); the caller draws more, then
 * closes.  Nothing is left open on failure. */
sq_status sq_svg_mesh_open(const char *path, const sem_tri_mesh *m, const char *interior_color,
                           double interior_width, sq_svg_mesh_picture *pic, sq_error *err);
/* End the picture and rename the file into place (or remove it when
 * status is not SQ_OK); frees pic.  Returns status or the write error. */
sq_status sq_svg_mesh_close(sq_svg_mesh_picture *pic, sq_status status, sq_error *err);

/* World bounding box of the mesh's geometry nodes. */
void sq_svg_mesh_bbox(const sem_tri_mesh *m, double bb[4]);

/* Draw the curved element edges: interior edges (once each) if interior,
 * boundary edges on top.  lag: Lagrange basis of the mesh's geometry order. */
void sq_svg_mesh_edges(sq_svg *svg, const sem_tri_mesh *m, const sem_tri_lagrange *lag,
                       int interior, const char *interior_color, double interior_width,
                       const char *boundary_color, double boundary_width);

/* A scalar on element e at reference point (r, s). */
typedef double (*sq_svg_scalar_fn)(void *ctx, int e, double r, double s);

/* Isolines f = level0 + k*step (every integer k; step <= 0: the single
 * level level0), as linear pieces on a lattice of order S in every element
 * (skip[e] set: element left out; skip may be NULL), drawn through the
 * curved geometry.  Values within tol of a level count as above it, so a
 * function that is identically the level along an edge draws nothing
 * there. */
void sq_svg_mesh_isolines(sq_svg *svg, const sem_tri_mesh *m, const sem_tri_lagrange *lag, int S,
                          sq_svg_scalar_fn f, void *ctx, double level0, double step, double tol,
                          const unsigned char *skip, const char *color, double width);

#endif
