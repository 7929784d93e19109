/* semquad public API: what a CAD file holds (`semquad info`), every face
 * with its status (ok, healed, not planar, broken: reason); a broken face
 * does not stop the listing. */
#include "api_private.h"
#include "face_info.h"
#include "json_writer.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct {
    int index;
    const char *surface;
    cad_face_status status;
    const char *reason; /* broken: why (points into the model or into msg) */
    char msg[512];      /* the reason when cad_face_create refused the face */
    cad_face *face;     /* NULL unless ok or healed */
    sq_face_info info;
} face_entry;

static void print_text(FILE *fp, const char *path, const cad_model *m, const face_entry *f,
                       int nf)
{
    int total = cad_model_num_faces(m);
    fprintf(fp, "%s: %d face%s, unit %s\n", path, total, total == 1 ? "" : "s", cad_model_unit(m));
    for (int k = 0; k < nf; k++) {
        const char *fname = cad_model_face_name(m, f[k].index);
        fprintf(fp, "face %d%s%s%s: %s, %s", f[k].index, fname ? " \"" : "", fname ? fname : "",
                fname ? "\"" : "", f[k].surface, sq_face_status_name(f[k].status));
        if (!f[k].face) {
            if (f[k].status == CAD_FACE_BROKEN) fprintf(fp, ": %s", f[k].reason);
            fprintf(fp, "\n");
            continue;
        }
        const sq_face_info *in = &f[k].info;
        fprintf(fp, ", area %.10g, chi %d, bbox [%g, %g] x [%g, %g]\n", in->area, in->chi, in->bbox[0],
               in->bbox[2], in->bbox[1], in->bbox[3]);
        cad_heal h;
        for (int r = 0; cad_model_face_heal(m, f[k].index, r, &h) == 0; r++) {
            char line[256];
            sq_heal_text(&h, cad_model_unit(m), line, sizeof line);
            fprintf(fp, "  %s: %s\n", f[k].status == CAD_FACE_HEALED ? "healed" : "heal", line);
        }
        for (int l = 0; l < in->nloops; l++) {
            int first = cad_face_loop_first_edge(f[k].face, l);
            int n = cad_face_loop_num_edges(f[k].face, l);
            fprintf(fp, "  loop %d (%s): %d edge%s\n", l, l ? "hole" : "outer", n, n == 1 ? "" : "s");
            for (int e = first; e < first + n; e++) {
                const char *ename = cad_face_edge_name(f[k].face, e);
                fprintf(fp, "    edge %d%s%s%s: %s, length %.10g\n", e, ename ? " \"" : "",
                        ename ? ename : "", ename ? "\"" : "",
                        cad_edge_type_name(cad_face_edge_type(f[k].face, e)),
                        cad_face_edge_length(f[k].face, e));
            }
        }
        fprintf(fp, "  corners: %d\n", in->ncorners);
        for (int v = 0; v < in->nvertices; v++) {
            const sq_vertex *x = &in->vertices[v];
            fprintf(fp, "    (%.10g, %.10g) loop %d: %s%.4f deg\n", x->x, x->y, x->loop,
                   x->smooth ? "smooth junction, " : "", x->angle_deg);
        }
    }
}

static void print_json(FILE *fp, const char *path, const cad_model *m, const face_entry *f,
                       int nf)
{
    sq_json j;
    sq_json_init(&j, fp);
    sq_json_begin_object(&j);
    sq_json_key(&j, "input");
    sq_json_string(&j, path);
    sq_json_key(&j, "unit");
    sq_json_string(&j, cad_model_unit(m));
    sq_json_key_number(&j, "heal_tolerance", cad_model_heal_tolerance(m));
    sq_json_key(&j, "faces");
    sq_json_begin_array(&j);
    for (int k = 0; k < nf; k++) {
        sq_json_begin_object(&j);
        sq_json_key(&j, "index");
        sq_json_int(&j, f[k].index);
        if (cad_model_face_name(m, f[k].index))
            sq_json_key_string(&j, "name", cad_model_face_name(m, f[k].index));
        sq_json_key(&j, "surface");
        sq_json_string(&j, f[k].surface);
        sq_json_key_string(&j, "status", sq_face_status_name(f[k].status));
        if (f[k].status == CAD_FACE_BROKEN) sq_json_key_string(&j, "reason", f[k].reason);
        if (f[k].face) {
            sq_json_healing(&j, m, f[k].index);
            const sq_face_info *in = &f[k].info;
            sq_json_key(&j, "chi");
            sq_json_int(&j, in->chi);
            sq_json_key(&j, "area");
            sq_json_number(&j, in->area);
            sq_json_key(&j, "bbox");
            sq_json_begin_array(&j);
            for (int c = 0; c < 4; c++)
                sq_json_number(&j, in->bbox[c]);
            sq_json_end_array(&j);
            sq_json_key(&j, "loops");
            sq_json_begin_array(&j);
            for (int l = 0; l < in->nloops; l++) {
                int first = cad_face_loop_first_edge(f[k].face, l);
                int n = cad_face_loop_num_edges(f[k].face, l);
                sq_json_begin_object(&j);
                sq_json_key(&j, "hole");
                sq_json_bool(&j, l > 0);
                sq_json_key(&j, "edges");
                sq_json_begin_array(&j);
                for (int e = first; e < first + n; e++) {
                    sq_json_begin_object(&j);
                    if (cad_face_edge_name(f[k].face, e))
                        sq_json_key_string(&j, "name", cad_face_edge_name(f[k].face, e));
                    sq_json_key(&j, "type");
                    sq_json_string(&j, cad_edge_type_name(cad_face_edge_type(f[k].face, e)));
                    sq_json_key(&j, "length");
                    sq_json_number(&j, cad_face_edge_length(f[k].face, e));
                    sq_json_end_object(&j);
                }
                sq_json_end_array(&j);
                sq_json_end_object(&j);
            }
            sq_json_end_array(&j);
            for (int pass = 0; pass < 2; pass++) {
                sq_json_key(&j, pass ? "smooth_junctions" : "corners");
                sq_json_begin_array(&j);
                for (int v = 0; v < in->nvertices; v++) {
                    const sq_vertex *x = &in->vertices[v];
                    if (x->smooth != pass) continue;
                    sq_json_begin_object(&j);
                    sq_json_key(&j, "x");
                    sq_json_number(&j, x->x);
                    sq_json_key(&j, "y");
                    sq_json_number(&j, x->y);
                    sq_json_key(&j, "angle_deg");
                    sq_json_number(&j, x->angle_deg);
                    sq_json_key(&j, "loop");
                    sq_json_int(&j, x->loop);
                    sq_json_end_object(&j);
                }
                sq_json_end_array(&j);
            }
        }
        sq_json_end_object(&j);
    }
    sq_json_end_array(&j);
    sq_json_end_object(&j);
}

/* Status of face f->index, its cad_face and info when it is planar and
 * usable; a face that cannot be opened becomes broken with the reason. */
static sq_status open_entry(const cad_model *m, face_entry *f, sq_error *err)
{
    f->surface = cad_model_face_surface(m, f->index);
    f->status = cad_model_face_status(m, f->index, &f->reason);
    if (f->status != CAD_FACE_OK && f->status != CAD_FACE_HEALED) return SQ_OK;
    sq_error ferr;
    sq_error_clear(&ferr);
    sq_status st = cad_face_create(m, f->index, &f->face, &ferr);
    if (st == SQ_OK) st = sq_face_info_compute(f->face, &f->info, &ferr);
    if (st == SQ_ERR_INTERNAL && !strcmp(ferr.msg, "out of memory"))
        return SQ_FAIL(err, st, "%s", ferr.msg);
    if (st != SQ_OK) {
        cad_face_free(&f->face);
        f->status = CAD_FACE_BROKEN;
        snprintf(f->msg, sizeof f->msg, "%s", ferr.msg);
        f->reason = f->msg;
    }
    return SQ_OK;
}

/* One line on stderr: how many faces healing touched and how many are broken. */
static void summary(const sq_model *model, const face_entry *f, int nf)
{
    const cad_model *m = model->cad;
    int healed = 0, broken = 0;
    for (int k = 0; k < nf; k++) {
        healed += f[k].status == CAD_FACE_HEALED;
        broken += f[k].status == CAD_FACE_BROKEN;
    }
    if (healed || broken)
        sq_api_log(&model->opt, SQ_LOG_NOTE, "%d face%s healed within %.3g %s, %d broken", healed,
                healed == 1 ? "" : "s", cad_model_heal_tolerance(m), cad_model_unit(m), broken);
}

sq_status sq_model_info(const sq_model *model, int face, int json, char **text, sq_error *err)
{
    *text = NULL;
    const cad_model *m = model->cad;
    int total = cad_model_num_faces(m);
    if (face >= total)
        return SQ_FAIL(err, SQ_ERR_USAGE, "--face %d: %s has %d face%s", face, model->path, total,
                       total == 1 ? "" : "s");
    int first = face < 0 ? 0 : face, nf = face < 0 ? total : 1;
    face_entry *f = calloc((size_t)nf, sizeof *f);
    sq_status st = f ? SQ_OK : SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    for (int k = 0; k < nf && st == SQ_OK; k++) {
        f[k].index = first + k;
        st = open_entry(m, &f[k], err);
    }
    sq_api_text t;
    if (st == SQ_OK) st = sq_api_text_open(&t, err);
    if (st == SQ_OK) {
        summary(model, f, nf);
        if (json)
            print_json(t.fp, model->path, m, f, nf);
        else
            print_text(t.fp, model->path, m, f, nf);
        st = sq_api_text_close(&t, text, err);
    }
    for (int k = 0; f && k < nf; k++) {
        sq_face_info_free(&f[k].info);
        cad_face_free(&f[k].face);
    }
    free(f);
    return st;
}
