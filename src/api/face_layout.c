/* semquad public API: the quad layout of a face (`semquad layout`). */
#include "api_private.h"
#include "write_layout.h"

#include <stdlib.h>

sq_status sq_face_layout(const sq_model *m, int face, const sq_options *o, sq_quad_layout **out,
                         sq_error *err)
{
    *out = NULL;
    sq_options def;
    o = sq_api_options(o, &def);
    sq_layout_options lo;
    SQ_TRY(sq_api_layout_options(o, 0, &lo, err));
    sq_quad_layout *l = calloc(1, sizeof *l);
    if (!l || !(l->t_split = malloc(sizeof *l->t_split))) {
        free(l);
        return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    }
    *l->t_split = -1.0;
    sq_status st = sq_api_face_open(m, face, o, &l->face, err);
    if (st == SQ_OK && o->periodic) {
        sq_face_info info = {0};
        st = sq_face_info_compute(l->face.cad, &info, err);
        if (st == SQ_OK) st = sq_api_periodic_find(l->face.cad, &info, o, &l->per, &lo, err);
        sq_face_info_free(&info);
    }
    if (st == SQ_OK) st = sq_layout_run(l->face.cad, &lo, &l->r, err);
    char split[512];
    if ((st == SQ_OK || st == SQ_ERR_LAYOUT) && sq_layout_note(&l->r, split, sizeof split))
        sq_api_log(o, SQ_LOG_NOTE, "%s", split);
    /* an invalid layout is still handed over, so it can be drawn and reported */
    if (st != SQ_OK && st != SQ_ERR_LAYOUT) {
        sq_quad_layout_free(&l);
        return st;
    }
    *out = l;
    return st;
}

void sq_quad_layout_free(sq_quad_layout **l)
{
    if (!l || !*l) return;
    sq_layout_result_free(&(*l)->r);
    sq_periodic_free(&(*l)->per);
    sq_api_face_close(&(*l)->face);
    free((*l)->t_split);
    free(*l);
    *l = NULL;
}

int sq_quad_layout_face(const sq_quad_layout *l) { return l->face.index; }
int sq_quad_layout_num_patches(const sq_quad_layout *l) { return l->r.layout.stats.quad_patches; }
int sq_quad_layout_num_singular_points(const sq_quad_layout *l) { return l->r.nsing; }

sq_status sq_quad_layout_describe(const sq_quad_layout *l, char **text, sq_error *err)
{
    const sq_layout_stats *s = &l->r.layout.stats;
    sq_api_text x;
    SQ_TRY(sq_api_text_open(&x, err));
    fprintf(x.fp,
            "%s face %d: %d singular points, %d separatrices, %d quad patches; repairs: %d "
            "limit cycles, %d T-junctions, %d triangles, %d valence-2 points, %d annuli, %d "
            "duplicates, %d crossings\n",
            l->face.model->path, l->face.index, l->r.nsing, s->separatrices, s->quad_patches,
            s->limit_cycles_cut, s->t_junctions, s->triangles_repaired, s->valence2_split,
            s->annuli_cut, s->duplicates_removed, s->crossings_split);
    return sq_api_text_close(&x, text, err);
}

sq_status sq_quad_layout_write(const sq_quad_layout *l, const char *path, sq_error *err)
{
    if (sq_api_ends_with(path, ".svg")) return sq_write_layout_svg(path, &l->r, err);
    if (!sq_api_ends_with(path, ".step") && !sq_api_ends_with(path, ".stp"))
        return SQ_FAIL(err, SQ_ERR_USAGE, "%s: unknown layout format (use .svg or .step)", path);
    if (!l->r.valid)
        return SQ_FAIL(err, SQ_ERR_LAYOUT, "%s: the layout is not valid: no patches to write",
                       path);
    double t = sq_now();
    sq_status st = sq_write_layout_step(path, l->face.model->cad, l->face.index, l->face.cad,
                                        &l->r.layout, NULL, err);
    *l->t_split = sq_now() - t;
    return st;
}

sq_status sq_quad_layout_write_report(const sq_quad_layout *l, const char *path, sq_error *err)
{
    return sq_write_layout_report(path, l->face.model->path, l->face.index, &l->r,
                                  l->face.model->t_read, *l->t_split, err);
}
