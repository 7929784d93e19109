/* semquad tests — face 0 of an example file (SQ_EXAMPLES), through cad/. */
#ifndef SQ_TEST_FACE_H
#define SQ_TEST_FACE_H

#include "cad.h"
#include "field_analysis.h"
#include "htheta_field.h"
#include "pattern.h"
#include "test_util.h"

static inline void sq_test_open_face(const char *file, cad_model **m, cad_face **f)
{
    char path[4096];
    sq_error err;
    sq_test_path(path, sizeof path, 0, file);
    SQ_TEST_OK(cad_model_read(path, m, &err), err);
    SQ_TEST_OK(cad_face_create(*m, 0, f, &err), err);
}

/* The natural pattern of face f: the guiding field's points at the
 * default options (degenerate zeros split). */
static inline void sq_test_natural_pattern(const cad_face *f, sq_pattern *p)
{
    sq_error err;
    sq_field_options fo;
    sq_field_options_default(&fo);
    sq_field_analysis an;
    SQ_TEST_OK(sq_field_analyse(f, &fo, &an, &err), err);
    SQ_TEST_OK(sq_pattern_from_analysis(f, &an, p, &err), err);
    sq_field_analysis_free(&an);
}

/* The H/θ field of example `file`'s natural pattern at the default
 * options (the caller frees ht, p, f and m). */
static inline void sq_test_natural_htheta(const char *file, cad_model **m, cad_face **f,
                                          sq_pattern *p, sq_htheta *ht)
{
    sq_error err;
    sq_test_open_face(file, m, f);
    sq_test_natural_pattern(*f, p);
    sq_htheta_options o;
    sq_htheta_options_default(&o);
    SQ_TEST_OK(sq_htheta_compute(*f, p, &o, ht, &err), err);
}

#endif
