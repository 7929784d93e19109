/* The H/θ field's work, counted where it is done (sem_poisson_work): θ's
 * single-valued part is solved with H's factor (the same operator on the
 * same space, theta_field.h), so the field computes one element matrix per
 * triangle and factors one system, H's: on the unit disc
 * (examples/disc.step) with four valence-3 points at half the radius
 * (examples/disc_v3.txt), with `semquad mesh`'s
 * options (the two-step route's field) and with the field's own defaults.
 * Counts, not tolerances. */
#include "htheta_field.h"
#include "layout_pipeline.h"
#include "test_face.h"

#include <gsl/gsl_errno.h>

static int check(const cad_face *f, const sq_pattern *p, const sq_htheta_options *o,
                 const char *what)
{
    sq_error err;
    sq_htheta ht;
    SQ_TEST_OK(sq_htheta_compute(f, p, o, &ht, &err), err);
    int fails = sq_check_int(what, "element matrices (one per triangle)",
                             ht.work.element_matrices, ht.tri.mesh->ntris);
    fails += sq_check_int(what, "factorizations (H's)", ht.work.factorizations, 1);
    fails += sq_check_int(what, "H's solver released", ht.h.solver == NULL, 1);
    sq_htheta_free(&ht);
    return fails;
}

int main(void)
{
    gsl_set_error_handler_off();
    char path[4096];
    sq_error err;
    cad_model *m = NULL;
    cad_face *f = NULL;
    sq_test_open_face("disc.step", &m, &f);
    sq_pattern p;
    sq_test_path(path, sizeof path, 0, "disc_v3.txt");
    SQ_TEST_OK(sq_pattern_read(path, &p, &err), err);
    int fails = 0;
    sq_layout_options lo;
    sq_layout_options_for_mesh(&lo);
    fails += check(f, &p, &lo.htheta, "mesh options");
    sq_htheta_options o;
    sq_htheta_options_default(&o);
    fails += check(f, &p, &o, "defaults");
    sq_pattern_free(&p);
    cad_face_free(&f);
    cad_model_free(&m);
    if (fails) printf("t419: %d failure(s)\n", fails);
    return fails ? 1 : 0;
}
