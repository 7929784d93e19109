/* semquad public API: a CAD model and its faces. */
#include "api_private.h"
#include "face_info.h"

#include <gsl/gsl_errno.h>
#include <stdlib.h>
#include <string.h>

sq_status sq_model_open(const char *path, const sq_options *opt, sq_model **out, sq_error *err)
{
    *out = NULL;
    if (!path) return SQ_FAIL(err, SQ_ERR_USAGE, "sq_model_open: no path");
    /* GSL failures must come back as status codes, not abort the caller;
     * OpenCASCADE's access violations on hostile files become exceptions
     * (cad.h).  Both are process-wide and idempotent. */
    gsl_set_error_handler_off();
    cad_catch_signals();
    sq_options def;
    opt = sq_api_options(opt, &def);
    cad_read_options ro;
    cad_read_options_default(&ro);
    ro.heal = opt->heal;
    if (opt->heal_tolerance > 0.0) ro.heal_tolerance = opt->heal_tolerance;
    sq_model *m = calloc(1, sizeof *m);
    if (!m || !(m->path = strdup(path))) {
        free(m);
        return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    }
    m->opt = *opt;
    double t0 = sq_now();
    sq_status st = cad_model_read_with(path, &ro, &m->cad, err);
    m->t_read = sq_now() - t0;
    if (st != SQ_OK) {
        sq_model_free(&m);
        return st;
    }
    *out = m;
    return SQ_OK;
}

void sq_model_free(sq_model **m)
{
    if (!m || !*m) return;
    cad_model_free(&(*m)->cad);
    free((*m)->path);
    free(*m);
    *m = NULL;
}

int sq_model_num_faces(const sq_model *m) { return cad_model_num_faces(m->cad); }

int sq_model_default_face(const sq_model *m, const char **why)
{
    const char *note = NULL;
    int face = cad_model_default_face(m->cad, &note);
    if (why) *why = note;
    return face;
}

const char *sq_model_unit(const sq_model *m) { return cad_model_unit(m->cad); }

double sq_model_heal_tolerance(const sq_model *m) { return cad_model_heal_tolerance(m->cad); }

const char *sq_model_face_status(const sq_model *m, int face, const char **reason)
{
    if (reason) *reason = NULL;
    if (face < 0 || face >= cad_model_num_faces(m->cad)) return NULL;
    const char *why = NULL;
    cad_face_status s = cad_model_face_status(m->cad, face, &why);
    if (reason && s == CAD_FACE_BROKEN) *reason = why;
    return sq_face_status_name(s);
}

sq_status sq_model_heal_summary(const sq_model *m, int face, char **text, sq_error *err)
{
    *text = NULL;
    cad_heal h;
    if (cad_model_face_heal(m->cad, face, 0, &h) != 0) return SQ_OK;
    sq_api_text t;
    SQ_TRY(sq_api_text_open(&t, err));
    const char *unit = cad_model_unit(m->cad);
    const char *what = cad_model_face_status(m->cad, face, NULL) == CAD_FACE_HEALED ? "healed" : "checked";
    fprintf(t.fp, "face %d %s within %.3g %s: ", face, what, cad_model_heal_tolerance(m->cad), unit);
    for (int k = 0; cad_model_face_heal(m->cad, face, k, &h) == 0; k++) {
        char one[256];
        sq_heal_text(&h, unit, one, sizeof one);
        fprintf(t.fp, "%s%s", k ? "; " : "", one);
    }
    return sq_api_text_close(&t, text, err);
}

sq_status sq_api_face_open(const sq_model *m, int face, const sq_options *o, sq_api_face *f,
                           sq_error *err)
{
    memset(f, 0, sizeof *f);
    int n = cad_model_num_faces(m->cad);
    const char *note = NULL;
    if (face < 0) face = cad_model_default_face(m->cad, &note);
    if (face >= n)
        return SQ_FAIL(err, SQ_ERR_USAGE, "--face %d: %s has %d face%s (0..%d)", face, m->path, n,
                       n == 1 ? "" : "s", n - 1);
    f->model = m;
    f->index = face;
    SQ_TRY(cad_face_create(m->cad, face, &f->cad, err));
    /* said once the face is known to open: a refusal stays one line */
    if (note) sq_api_log(o, SQ_LOG_NOTE, "%s", note);
    return SQ_OK;
}

void sq_api_face_close(sq_api_face *f) { cad_face_free(&f->cad); }
