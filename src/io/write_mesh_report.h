/* semquad — the JSON report of `semquad mesh` (docs/conventions.md, "The
 * report"): input, field, singularities, corners, layout, mesh, sizes,
 * timings. */
#ifndef SQ_WRITE_MESH_REPORT_H
#define SQ_WRITE_MESH_REPORT_H

#include <stdio.h>

#include "cad.h"
#include "json_writer.h"
#include "layout_pipeline.h"
#include "quad_mesh.h"
#include "size_report.h"

/* seconds per stage; total: from reading the file to the last output
 * written, the whole command after the process has started */
typedef struct {
    double read, triangulate, solve, critical_points, trace, layout, mesh, write, total;
} sq_mesh_timings;

/* The road the mesh took: "layout" (field, layout, patches) or "split"
 * (quad_split.h), and, for a split road the layout road fell back on,
 * why it did. */
typedef struct {
    const char *name;
    char reason[512];
} sq_road_choice;

/* The user's sizes against the mesh, and the far size h was read with
 * (the "sizes" key; report NULL: no sizes, no key); the boundary layers
 * achieved against those asked (the "boundary_layers" key; NULL: none). */
typedef struct {
    const sq_size_report *report;
    double far;
    const sq_bl_report *bl;
} sq_report_sizes;

/* model: the file read, for the face's "healing" key; info: the face; r:
 * the layout road's result (its field and layout keys are written when
 * the road is "layout" and r holds them: a refined mesh's r is zeroed);
 * sz: the user's sizes, or NULL */
sq_status sq_write_mesh_report(const char *path, const char *input, const cad_model *model,
                               int face, const sq_face_info *info, const sq_road_choice *road,
                               const sq_layout_result *r, const sq_quad_mesh *m,
                               const sq_quad_quality *q, const sq_report_sizes *sz,
                               const sq_mesh_timings *t, sq_error *err);
/* The same report on fp (a string, through a memory stream). */
void sq_print_mesh_report(FILE *fp, const char *input, const cad_model *model, int face,
                          const sq_face_info *info, const sq_road_choice *road,
                          const sq_layout_result *r, const sq_quad_mesh *m,
                          const sq_quad_quality *q, const sq_report_sizes *sz,
                          const sq_mesh_timings *t);

/* The "periodic" key (docs/domains.md), when m has periodic links: each
 * pair's edges, its transform and node count; the identified domain's
 * Gauss–Bonnet count and the mesh's. */
void sq_json_periodic(sq_json *j, const sq_quad_mesh *m);

#endif
