/* semquad — writers for the curved triangulation: VTU (Lagrange triangles),
 * SVG picture, JSON report.  All write atomically (outfile.h). */
#ifndef SQ_WRITE_TRI_H
#define SQ_WRITE_TRI_H

#include "triangulate.h"

/* VTK XML unstructured grid, one VTK_LAGRANGE_TRIANGLE (69) per element
 * with its geometry at the equispaced nodes VTK expects; cell data:
 * scaled_jacobian and boundary-edge count. */
sq_status sq_write_tri_vtu(const char *path, const sq_triangulation *t, sq_error *err);

/* Picture: elements' curved edges as polylines, boundary edges thicker. */
sq_status sq_write_tri_svg(const char *path, const sq_triangulation *t, sq_error *err);

/* {"input", "face", "triangles", "order", "size", "min_angle_deg",
 *  "min_scaled_jacobian", "area", "vertices"} */
sq_status sq_write_tri_report(const char *path, const char *input, int face,
                              const sq_triangulation *t, sq_error *err);

#endif
