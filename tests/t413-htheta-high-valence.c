/* High valence on the square (one quad per corner, Jezdimirović 2021
 * Fig. 10): (a) four valence-5 and four valence-3 points, (b) two
 * valence-6 and four valence-3, (c) one valence-8 at the centre and four
 * valence-3.  At P = 8 the jump of θ around every point is (π/2)(4 − V)
 * to 1e-8; the branch cut reaches every point; the outer boundary stays
 * aligned. */
#include "htheta_field.h"
#include "test_util.h"

#include <gsl/gsl_errno.h>

int main(void)
{
    gsl_set_error_handler_off();
    const char *files[] = {"square_v5.txt", "square_v6.txt", "square_v8.txt"};
    const int npts[] = {8, 6, 5};
    char path[4096];
    sq_error err;
    cad_model *m = NULL;
    cad_face *f = NULL;
    sq_test_path(path, sizeof path, 0, "square.step");
    SQ_TEST_OK(cad_model_read(path, &m, &err), err);
    SQ_TEST_OK(cad_face_create(m, 0, &f, &err), err);
    int fails = 0;
    for (int c = 0; c < 3; c++) {
        sq_pattern p;
        sq_test_path(path, sizeof path, 0, files[c]);
        SQ_TEST_OK(sq_pattern_read(path, &p, &err), err);
        fails += sq_check_int(files[c], "points", p.npoints, npts[c]);
        sq_htheta_options o;
        sq_htheta_options_default(&o);
        fails += sq_check_int(files[c], "order", o.order, 8);
        sq_htheta ht;
        SQ_TEST_OK(sq_htheta_compute(f, &p, &o, &ht, &err), err);
        for (int k = 0; k < ht.npoints; k++) {
            char what[64];
            snprintf(what, sizeof what, "jump around point %d (valence %d)", k, ht.points[k].valence);
            /* θ differences summed around the point: the solve's round-off,
             * kappa (3n+1) U |θ| ~ 2e-8 at worst (t412) */
            fails += sq_check_abs(files[c], what, ht.points[k].jump,
                                  M_PI_2 * (4 - p.points[k].valence), 1e-8);
            int touches = 0;
            for (int i = 0; i < 2 * ht.theta.cut.nedges; i++)
                touches += ht.theta.cut.edges[i] == ht.points[k].vertex;
            if (!touches) {
                printf("%s: the branch cut misses point %d\n", files[c], k);
                fails++;
            }
        }
        /* L is a forest whose trees each reach the boundary: edges =
         * interior vertices on L */
        int *on = calloc((size_t)ht.tri.mesh->nverts, sizeof(int)), nin = 0;
        for (int i = 0; i < 2 * ht.theta.cut.nedges; i++) on[ht.theta.cut.edges[i]] = 1;
        for (int v = 0; v < ht.tri.mesh->nverts; v++) nin += on[v] && ht.vloops[v] < 0;
        fails += sq_check_int(files[c], "cut edges - interior cut vertices", ht.theta.cut.nedges, nin);
        free(on);
        fails += sq_check_int(files[c], "outer loop aligned", ht.loops[0].aligned, 1);
        /* boundary integrals by GSL's QAG to 1e-13 relative against the
         * corners' and points' exact multiples of pi/2: 1e-9 of a few 2 pi */
        fails += sq_check_abs(files[c], "H data imbalance", ht.h.imbalance, 0.0, 1e-9);
        sq_htheta_free(&ht);
        sq_pattern_free(&p);
    }
    cad_face_free(&f);
    cad_model_free(&m);
    return fails != 0;
}
