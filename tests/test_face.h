/* semquad tests — face 0 of an example file (SQ_EXAMPLES), through cad/. */
#ifndef SQ_TEST_FACE_H
#define SQ_TEST_FACE_H

#include "cad.h"
#include "test_util.h"

static inline void sq_test_open_face(const char *file, cad_model **m, cad_face **f)
{
    char path[4096];
    sq_error err;
    sq_test_path(path, sizeof path, 0, file);
    SQ_TEST_OK(cad_model_read(path, m, &err), err);
    SQ_TEST_OK(cad_face_create(*m, 0, f, &err), err);
}

#endif
