/* semquad — SVG picture of a high-order quad mesh: each quad filled with the
 * colour of its eta (straight corners, quadstats.py's definition) on a ramp
 * from red (eta <= 0.5) through yellow (0.75) to green (1), with a legend;
 * element sides drawn as polylines through the curved element map, the
 * boundary sides thicker; a caption with the quality summary line. */
#ifndef SQ_WRITE_QUAD_SVG_H
#define SQ_WRITE_QUAD_SVG_H

#include "quad_mesh.h"
#include "sq_progress.h"
#include "sq_status.h"

/* Atomic (outfile.h).  Reports "write" to progress (may be NULL): quads and
 * boundary sides drawn of all, at most about 100 events. */
sq_status sq_write_quad_svg(const char *path, const sq_quad_mesh *m, const sq_progress *progress,
                            sq_error *err);

/* "#rrggbb" of eta on the ramp (clamped to [0.5, 1]). */
void sq_quad_eta_color(double eta, char out[8]);

#endif
