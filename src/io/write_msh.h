/* semquad — Gmsh MSH 4.1 ASCII output of a high-order quad mesh.
 *
 * Quads of order Q as Gmsh element types 3, 10, 36, 37, 38, 47..51 and the
 * boundary sides as lines of the same order (1, 8, 26, 27, 28, 62..66), in
 * Gmsh's node order (quad_order.h) at equispaced positions (a GLL mesh is
 * resampled with its elements' Lagrange interpolants).  One curve entity and
 * physical group "boundary_<tag>" (physical tag tag+1) per boundary curve
 * (curves named alike share one group, named so, the physical tag of the
 * least of them),
 * one surface entity with physical group "domain" (physical tag ntags+1),
 * or one per face of a domain; point entities at the corners and the
 * interfaces between faces as curves (msh_entities.h), one node block per
 * entity.  Node tag = mesh node index + 1, quad element tag = quad index + 1.
 * Format: Gmsh reference manual, "MSH file format version 4.1"; the binary
 * form ("4.1 1 8") has the same sections with the numbers of $Entities,
 * $Nodes and $Elements as native ints, size_t and doubles. */
#ifndef SQ_WRITE_MSH_H
#define SQ_WRITE_MSH_H

#include "quad_mesh.h"
#include "sq_progress.h"
#include "sq_status.h"

/* Atomic (outfile.h): SQ_ERR_OUTPUT if the file cannot be written,
 * SQ_ERR_USAGE for an inconsistent mesh (node index or tag out of range).
 * Reports "write" to progress (may be NULL): nodes and elements (quads,
 * boundary lines) written of all, at most about 100 events. */
sq_status sq_write_msh(const char *path, const sq_quad_mesh *m, const sq_progress *progress,
                       sq_error *err);
/* The same file with its node and element lines formatted on `threads`
 * threads (0: the processors online; write_lines.h): the same bytes for
 * every count. */
sq_status sq_write_msh_threads(const char *path, const sq_quad_mesh *m, int threads,
                               const sq_progress *progress, sq_error *err);
/* The same file in binary MSH 4.1: the same nodes, elements, tags and
 * groups, coordinates bit for bit. */
sq_status sq_write_msh_binary(const char *path, const sq_quad_mesh *m,
                              const sq_progress *progress, sq_error *err);

/* Checks shared by the writers: every node index, boundary quad, side and
 * tag in range. */
sq_status sq_quad_mesh_check(const sq_quad_mesh *m, sq_error *err);

#endif
