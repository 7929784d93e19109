/* semquad public API: the field of a face and its singular points
 * (`semquad field`): the guiding field (Marcon 2019), or the H/θ field of
 * a pattern (Jezdimirović 2021 §4–5), from a file or from the guiding
 * field's own points ("natural"). */
#include "api_private.h"
#include "write_field.h"
#include "write_htheta.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* The pattern from a file or the guiding field, then H, the branch cut
 * and θ. */
static sq_status htheta(sq_field *h, const sq_field_options *fo, const char *sing,
                        const sq_options *o, sq_error *err)
{
    sq_pattern pat;
    sq_status st;
    if (!strcmp(sing, "natural")) {
        sq_field_analysis an;
        SQ_TRY(sq_field_analyse(h->face.cad, fo, &an, err));
        st = sq_pattern_from_analysis(h->face.cad, &an, &pat, err);
        sq_field_analysis_free(&an);
        SQ_TRY(st);
        if (pat.ndegenerate)
            sq_api_log(o, SQ_LOG_NOTE,
                       "%d degenerate singular point%s of the guiding field (|index| > 1) split "
                       "into elementary points",
                       pat.ndegenerate, pat.ndegenerate == 1 ? "" : "s");
    } else {
        SQ_TRY(sq_pattern_read(sing, &pat, err));
    }
    sq_htheta_options ho;
    sq_htheta_options_default(&ho);
    ho.order = fo->order;
    ho.tri.order = fo->tri.order;
    ho.tri.size = fo->tri.size;
    st = sq_htheta_compute(h->face.cad, &pat, &ho, &h->ht, err);
    sq_pattern_free(&pat);
    SQ_TRY(st);
    h->htheta = 1;
    sq_error w;
    if (sq_htheta_check_alignment(&h->ht, 0, &w) != SQ_OK)
        sq_api_log(o, SQ_LOG_WARNING, "%s%s", w.msg,
                   o->allow_misaligned ? " (proceeding: --allow-misaligned)" : "");
    return SQ_OK;
}

/* The singular points as plain arrays. */
static sq_status fill_points(sq_field *h, sq_error *err)
{
    int n = h->htheta ? h->ht.npoints : h->an.npoints;
    h->nsing = n;
    h->xy = malloc(2 * (size_t)(n ? n : 1) * sizeof *h->xy);
    h->valence = malloc((size_t)(n ? n : 1) * sizeof *h->valence);
    if (!h->xy || !h->valence) return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    for (int k = 0; k < n; k++) {
        h->xy[2 * k] = h->htheta ? h->ht.points[k].x : h->an.points[k].x;
        h->xy[2 * k + 1] = h->htheta ? h->ht.points[k].y : h->an.points[k].y;
        h->valence[k] = h->htheta ? h->ht.points[k].valence : h->an.points[k].valence;
    }
    return SQ_OK;
}

sq_status sq_face_field(const sq_model *m, int face, const sq_options *o, sq_field **out,
                        sq_error *err)
{
    *out = NULL;
    sq_options def;
    o = sq_api_options(o, &def);
    sq_field_options fo;
    SQ_TRY(sq_api_field_options(o, &fo, err));
    const char *sing = sq_api_singularities(o);
    sq_field *h = calloc(1, sizeof *h);
    if (!h) return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    sq_status st = sq_api_face_open(m, face, o, &h->face, err);
    if (st == SQ_OK && sing) st = htheta(h, &fo, sing, o, err);
    if (st == SQ_OK && !sing) st = sq_field_analyse(h->face.cad, &fo, &h->an, err);
    if (st == SQ_OK && !sing && h->an.ph_lhs != h->an.ph_rhs)
        sq_api_log(o, SQ_LOG_WARNING,
                   "Poincare-Hopf check fails (%d != %d): a singular point was missed or "
                   "misclassified",
                   h->an.ph_lhs, h->an.ph_rhs);
    if (st == SQ_OK) st = fill_points(h, err);
    if (st != SQ_OK) {
        sq_field_free(&h);
        return st;
    }
    *out = h;
    return SQ_OK;
}

void sq_field_free(sq_field **f)
{
    if (!f || !*f) return;
    sq_field *h = *f;
    free(h->xy);
    free(h->valence);
    if (h->htheta)
        sq_htheta_free(&h->ht);
    else
        sq_field_analysis_free(&h->an);
    sq_api_face_close(&h->face);
    free(h);
    *f = NULL;
}

int sq_field_face(const sq_field *f) { return f->face.index; }
int sq_field_num_singular_points(const sq_field *f) { return f->nsing; }
const double *sq_field_singular_xy(const sq_field *f) { return f->xy; }
const int *sq_field_singular_valence(const sq_field *f) { return f->valence; }

static void describe_htheta(FILE *fp, const char *path, int face, const sq_htheta *ht)
{
    fprintf(fp,
            "%s face %d: H-theta field CG P=%d on %d triangles (%ld dofs), branch cut of %d "
            "edges\n",
            path, face, ht->h.order, ht->tri.mesh->ntris, ht->h.ndofs, ht->theta.cut.nedges);
    fprintf(fp, "  Gauss-Bonnet: sum(4 - V) + sum(2 - n) = %d = 4 chi\n", ht->balance.lhs);
    fprintf(fp, "  %d singular point%s (jump of theta around each, expected (pi/2)(4 - V)):\n",
            ht->npoints, ht->npoints == 1 ? "" : "s");
    for (int k = 0; k < ht->npoints; k++)
        fprintf(fp, "    (%.9g, %.9g) valence %d %s: jump %.12f (error %.2e)\n", ht->points[k].x,
                ht->points[k].y, ht->points[k].valence, sq_origin_name(ht->points[k].origin),
                ht->points[k].jump, ht->points[k].jump - ht->points[k].c);
    for (int l = 0; l < ht->nloops; l++) {
        const sq_htheta_loop *L = &ht->loops[l];
        fprintf(fp, "  loop %d (%s): misalignment %.6f deg", l, l ? "hole" : "outer",
                L->misalignment * 180.0 / M_PI);
        if (l)
            fprintf(fp, ", jump %.9f (expected %.9f, turning %.9f)", L->jump, L->expected_jump,
                    L->turning);
        fprintf(fp, ": %s\n", L->aligned ? "aligned" : "MISALIGNED");
    }
}

static void describe_guiding(FILE *fp, const char *path, int face, const sq_field_analysis *an)
{
    fprintf(fp, "%s face %d: guiding field %s P=%d on %d triangles (%ld dofs per component)\n",
            path, face, an->field.method == SEM_CG ? "CG" : "DG", an->field.order,
            an->tri.mesh->ntris, an->field.ndofs);
    fprintf(fp, "  %d singular point%s\n", an->npoints, an->npoints == 1 ? "" : "s");
    for (int k = 0; k < an->npoints; k++)
        fprintf(fp, "    (%.9f, %.9f) valence %d%s\n", an->points[k].x, an->points[k].y,
                an->points[k].valence, an->points[k].near_boundary ? " (on the boundary)" : "");
    fprintf(fp, "  corners:\n");
    for (int k = 0; k < an->info.nvertices; k++)
        if (!an->info.vertices[k].smooth)
            fprintf(fp, "    (%.6g, %.6g) %.2f deg: %d quad%s\n", an->info.vertices[k].x,
                    an->info.vertices[k].y, an->info.vertices[k].angle_deg,
                    an->corners[k].valence, an->corners[k].valence == 1 ? "" : "s");
    fprintf(fp, "  Poincare-Hopf: sum(4 - V) + sum(2 - n) = %d, 4 chi = %d: %s\n", an->ph_lhs,
            an->ph_rhs, an->ph_lhs == an->ph_rhs ? "holds" : "VIOLATED");
}

sq_status sq_field_describe(const sq_field *f, char **text, sq_error *err)
{
    sq_api_text x;
    SQ_TRY(sq_api_text_open(&x, err));
    if (f->htheta)
        describe_htheta(x.fp, f->face.model->path, f->face.index, &f->ht);
    else
        describe_guiding(x.fp, f->face.model->path, f->face.index, &f->an);
    return sq_api_text_close(&x, text, err);
}

sq_status sq_field_write(const sq_field *f, const char *path, sq_error *err)
{
    int svg = sq_api_ends_with(path, ".svg");
    if (!svg && !sq_api_ends_with(path, ".vtu"))
        return SQ_FAIL(err, SQ_ERR_USAGE, "%s: unknown field format (use .vtu or .svg)", path);
    if (f->htheta)
        return svg ? sq_write_htheta_svg(path, &f->ht, err) : sq_write_htheta_vtu(path, &f->ht, err);
    return svg ? sq_write_field_svg(path, &f->an, err) : sq_write_field_vtu(path, &f->an, err);
}

sq_status sq_field_write_report(const sq_field *f, const char *path, sq_error *err)
{
    const char *in = f->face.model->path;
    double t_read = f->face.model->t_read;
    if (f->htheta) return sq_write_htheta_report(path, in, f->face.index, &f->ht, t_read, err);
    return sq_write_field_report(path, in, f->face.index, &f->an, t_read, err);
}
