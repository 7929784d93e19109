/* semquad — outputs of the H/θ stage: JSON report (field.kind "H-theta",
 * keys of docs/conventions.md plus the θ jumps and the holonomy check),
 * VTU (point data H and theta, θ on the branch continuous off the cut) and
 * SVG (H isolines red, θ isolines blue as in Jezdimirović 2021 Fig. 10,
 * the branch cut black, the points by valence, quads per corner). */
#ifndef SQ_WRITE_HTHETA_H
#define SQ_WRITE_HTHETA_H

#include "htheta_field.h"
#include "json_writer.h"

/* The "singularities", "corners", "consistency", "theta_jumps" and
 * "holonomy" keys (for reports of later stages too). */
void sq_json_htheta_keys(sq_json *j, const sq_htheta *f);

sq_status sq_write_htheta_report(const char *path, const char *input, int face,
                                 const sq_htheta *f, double t_read, sq_error *err);
sq_status sq_write_htheta_vtu(const char *path, const sq_htheta *f, sq_error *err);
sq_status sq_write_htheta_svg(const char *path, const sq_htheta *f, sq_error *err);

#endif
