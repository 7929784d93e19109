/* semquad public API: the curved triangulation of a face (`semquad
 * triangulate`), on which the fields are solved. */
#include "api_private.h"
#include "write_tri.h"

#include <stdlib.h>

sq_status sq_face_triangulate(const sq_model *m, int face, const sq_options *o,
                              sq_triangles **out, sq_error *err)
{
    *out = NULL;
    sq_options def;
    o = sq_api_options(o, &def);
    sq_tri_options to;
    sq_tri_options_default(&to);
    if (o->tri_order) to.order = o->tri_order;
    if (o->tri_size > 0.0) to.size = o->tri_size;
    if (o->tri_min_angle_deg > 0.0) to.min_angle_deg = o->tri_min_angle_deg;
    if (o->tri_max_turn_deg > 0.0) to.max_turn_deg = o->tri_max_turn_deg;
    sq_triangles *t = calloc(1, sizeof *t);
    if (!t) return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    sq_status st = sq_api_face_open(m, face, o, &t->face, err);
    if (st == SQ_OK) st = sq_triangulate(t->face.cad, &to, &t->tri, err);
    if (st != SQ_OK) {
        sq_triangles_free(&t);
        return st;
    }
    *out = t;
    return SQ_OK;
}

void sq_triangles_free(sq_triangles **t)
{
    if (!t || !*t) return;
    sq_triangulation_free(&(*t)->tri);
    sq_api_face_close(&(*t)->face);
    free(*t);
    *t = NULL;
}

int sq_triangles_face(const sq_triangles *t) { return t->face.index; }

int sq_triangles_count(const sq_triangles *t) { return t->tri.mesh->ntris; }

sq_status sq_triangles_describe(const sq_triangles *t, char **text, sq_error *err)
{
    sq_api_text x;
    SQ_TRY(sq_api_text_open(&x, err));
    fprintf(x.fp,
            "%s face %d: %d triangles of order %d, min angle %.2f deg, min scaled Jacobian "
            "%.4f, area %.12g\n",
            t->face.model->path, t->face.index, t->tri.mesh->ntris, t->tri.mesh->order,
            t->tri.min_angle_deg, t->tri.min_scaled_jacobian, t->tri.area);
    return sq_api_text_close(&x, text, err);
}

sq_status sq_triangles_write(const sq_triangles *t, const char *path, sq_error *err)
{
    if (sq_api_ends_with(path, ".svg")) return sq_write_tri_svg(path, &t->tri, err);
    if (sq_api_ends_with(path, ".vtu")) return sq_write_tri_vtu(path, &t->tri, err);
    return SQ_FAIL(err, SQ_ERR_USAGE, "%s: unknown triangulation format (use .vtu or .svg)", path);
}

sq_status sq_triangles_write_report(const sq_triangles *t, const char *path, sq_error *err)
{
    return sq_write_tri_report(path, t->face.model->path, t->face.index, &t->tri, err);
}
