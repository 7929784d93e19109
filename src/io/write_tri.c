#include "write_tri.h"

#include "json_writer.h"
#include "outfile.h"
#include "svg_mesh.h"
#include "tri_lagrange.h"
#include "write_vtu.h"

#include <stdlib.h>

sq_status sq_write_tri_vtu(const char *path, const sq_triangulation *t, sq_error *err)
{
    const char *const names[] = {"scaled_jacobian"};
    const double *const cells[] = {t->jac};
    sq_vtu_data data = {.ncell_arrays = 1, .cell_names = names, .cell_data = cells};
    return sq_write_vtu(path, t->mesh, 0, &data, err);
}

sq_status sq_write_tri_svg(const char *path, const sq_triangulation *t, sq_error *err)
{
    const sem_tri_mesh *m = t->mesh;
    sq_svg_mesh_picture pic;
    SQ_TRY(sq_svg_mesh_open(path, m, "#3366aa", 0.8, &pic, err));
    for (int v = 0; v < m->nverts; v++)
        sq_svg_circle(&pic.svg, m->vxy[2 * v], m->vxy[2 * v + 1], 1.8, "#3366aa");
    char caption[160];
    snprintf(caption, sizeof caption,
             "%d triangles, order %d, min angle %.1f deg, min scaled Jacobian %.3f", m->ntris,
             m->order, t->min_angle_deg, t->min_scaled_jacobian);
    sq_svg_text(&pic.svg, pic.bbox[0], pic.bbox[1], 0.0, 16.0, 12.0, "#333333", caption);
    return sq_svg_mesh_close(&pic, SQ_OK, err);
}

sq_status sq_write_tri_report(const char *path, const char *input, int face,
                              const sq_triangulation *t, sq_error *err)
{
    sq_outfile f;
    SQ_TRY(sq_outfile_open(path, &f, err));
    sq_json j;
    sq_json_init(&j, f.fp);
    sq_json_begin_object(&j);
    sq_json_key(&j, "input");
    sq_json_string(&j, input);
    sq_json_key(&j, "face");
    sq_json_int(&j, face);
    sq_json_key(&j, "triangles");
    sq_json_int(&j, t->mesh->ntris);
    sq_json_key(&j, "vertices");
    sq_json_int(&j, t->mesh->nverts);
    sq_json_key(&j, "order");
    sq_json_int(&j, t->mesh->order);
    sq_json_key(&j, "size");
    sq_json_number(&j, t->size);
    sq_json_key(&j, "min_angle_deg");
    sq_json_number(&j, t->min_angle_deg);
    sq_json_key(&j, "min_scaled_jacobian");
    sq_json_number(&j, t->min_scaled_jacobian);
    sq_json_key(&j, "area");
    sq_json_number(&j, t->area);
    sq_json_end_object(&j);
    return sq_outfile_commit(&f, err);
}
