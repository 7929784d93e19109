/* semquad — outputs of the guiding-field stage: JSON report (keys of
 * docs/conventions.md), VTU (u, v, ψ on Lagrange triangles) and SVG
 * (crosses, u = 0 and v = 0 contours, singular points by valence, corner
 * valences). */
#ifndef SQ_WRITE_FIELD_H
#define SQ_WRITE_FIELD_H

#include "field_analysis.h"
#include "json_writer.h"

sq_status sq_write_field_report(const char *path, const char *input, int face,
                                const sq_field_analysis *a, double t_read, sq_error *err);
sq_status sq_write_field_vtu(const char *path, const sq_field_analysis *a, sq_error *err);
sq_status sq_write_field_svg(const char *path, const sq_field_analysis *a, sq_error *err);

/* The "singularities" and "corners" keys, for reports of later stages. */
void sq_json_field_keys(sq_json *j, const sq_field_analysis *a);

#endif
