/* semquad — VTK XML unstructured grid of a high-order quad mesh: cells
 * VTK_LAGRANGE_QUADRILATERAL (70) in VTK's node order (quad_order.h) at
 * equispaced positions (a GLL mesh is resampled), shared points written
 * once (point p = mesh node p), and per-cell data eta (straight corners, as
 * quadstats.py), eta_curved (tangents of the curved sides), scaled_jacobian
 * and patch.  VTK file formats ("VTK XML Formats") and "Modeling Arbitrary-
 * Order Lagrange Finite Elements in VTK" (Kitware blog). */
#ifndef SQ_WRITE_QUAD_VTU_H
#define SQ_WRITE_QUAD_VTU_H

#include "quad_mesh.h"
#include "sq_progress.h"
#include "sq_status.h"

/* Atomic (outfile.h).  Reports "write" to progress (may be NULL): points
 * and cells written of all, at most about 100 events. */
sq_status sq_write_quad_vtu(const char *path, const sq_quad_mesh *m, const sq_progress *progress,
                            sq_error *err);

#endif
