/* semquad — outputs of the layout stage: JSON report (DESIGN.md keys
 * "singularities", "corners", "layout"), SVG (patches in distinct colours,
 * separatrices, singular points by valence, every repair marked) and the
 * patches as STEP (the CAD face split along the separatrices). */
#ifndef SQ_WRITE_LAYOUT_H
#define SQ_WRITE_LAYOUT_H

#include "json_writer.h"
#include "layout_pipeline.h"

/* The keys a layout and a mesh report share, inside the open top-level
 * object: "input", "face", "chi" and the "field" object (kind, method,
 * order, triangles, dofs), the "layout" object and the layout's singular
 * points (with repairs' midpoints) as "singularities", plus "corners". */
void sq_json_layout_head(sq_json *j, const char *input, int face, const sq_layout_result *r);

sq_status sq_write_layout_report(const char *path, const char *input, int face,
                                 const sq_layout_result *r, double t_read, double t_split,
                                 sq_error *err);
sq_status sq_write_layout_svg(const char *path, const sq_layout_result *r, sq_error *err);

/* Split face `face_index` of model along the layout's separatrices and
 * write the patches as STEP; *nfaces (may be NULL) gets the sub-face count.
 * A path that is not a regular file (or "-") is refused before any work. */
sq_status sq_write_layout_step(const char *path, const cad_model *model, int face_index,
                               const cad_face *face, const sq_layout *L, int *nfaces,
                               sq_error *err);

#endif
