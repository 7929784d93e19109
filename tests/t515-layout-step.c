/* The half disc's layout as STEP (Marcon Fig. 8): the exported patches
 * re-import as 4 planar faces, each with four corners, whose areas sum to
 * π/2 to 1e-9 relative. */
#include "face_info.h"
#include "layout_pipeline.h"
#include "test_util.h"
#include "write_layout.h"

#include <gsl/gsl_errno.h>
#include <unistd.h>

int main(void)
{
    gsl_set_error_handler_off();
    char path[4096], out[64];
    sq_test_path(path, sizeof path, 0, "half_disc.step");
    snprintf(out, sizeof out, "t515-%ld.step", (long)getpid());
    cad_model *m = NULL;
    cad_face *f = NULL;
    sq_error err;
    SQ_TEST_OK(cad_model_read(path, &m, &err), err);
    SQ_TEST_OK(cad_face_create(m, 0, &f, &err), err);
    sq_layout_options lo;
    sq_layout_options_default(&lo);
    sq_layout_result r;
    SQ_TEST_OK(sq_layout_run(f, &lo, &r, &err), err);
    int nfaces = 0, fails = 0;
    SQ_TEST_OK(sq_write_layout_step(out, m, 0, f, &r.layout, &nfaces, &err), err);
    fails += sq_check_int("half_disc layout", "sub-faces split", nfaces, 4);
    cad_model *back = NULL;
    SQ_TEST_OK(cad_model_read(out, &back, &err), err);
    remove(out);
    fails += sq_check_int("patches STEP", "faces read back", cad_model_num_faces(back), 4);
    double sum = 0.0;
    for (int k = 0; k < cad_model_num_faces(back); k++) {
        cad_face *pf = NULL;
        sq_face_info info;
        SQ_TEST_OK(cad_face_create(back, k, &pf, &err), err);
        SQ_TEST_OK(sq_face_info_compute(pf, &info, &err), err);
        sum += info.area;
        fails += sq_check_int("patches STEP", "corners of a patch", info.ncorners, 4);
        sq_face_info_free(&info);
        cad_face_free(&pf);
    }
    /* patch areas by cad_split's adaptive Green rule: 1e-9 (t320) */
    fails += sq_check_rel("patches STEP", "area sum", sum, M_PI / 2, 1e-9);
    cad_model_free(&back);
    sq_layout_result_free(&r);
    cad_face_free(&f);
    cad_model_free(&m);
    return fails ? 1 : 0;
}
