/* t230: the convergence study (src/converge/converge.h) on CAD faces.
 *  - half_disc (curved boundary, automatic size), u = e^x sin y, CG and DG,
 *    P = 2..12: the L2 error decreases with P up to the round-off plateau
 *    (each step gains a factor >= 3 while that stays above the solve's
 *    worst-case round-off, sq_solve_roundoff with n = sqrt(triangles),
 *    |u| <= e) and is at most 1e-10 or that round-off at P = 12 (geometry
 *    order max(P, 8): the boundary error stays below it);
 *  - square, sizes 0.5 .. 0.0625, P = 1..3, CG and DG: the observed L2
 *    rate (least squares against dofs^-1/2) is within 0.3 of P + 1 and the
 *    H1 rate within 0.3 of P;
 *  - bad options (unknown solution, reversed orders) give SQ_ERR_USAGE. */
#include "converge.h"
#include "sem_roundoff.h"
#include "test_util.h"

static int open_face(const char *file, cad_model **m, cad_face **f)
{
    char path[1024];
    sq_error err = {0};
    sq_test_path(path, sizeof path, 0, file);
    SQ_TEST_OK(cad_model_read(path, m, &err), err);
    SQ_TEST_OK(cad_face_create(*m, 0, f, &err), err);
    return 0;
}

int main(void)
{
    int fails = 0;
    sq_error err = {0};
    cad_model *m = NULL;
    cad_face *f = NULL;
    char where[96];

    /* p-refinement on the half disc */
    open_face("half_disc.step", &m, &f);
    sq_converge_options opt;
    sq_converge_options_default(&opt);
    opt.pmin = 2;
    opt.pmax = 12;
    sq_converge_result r;
    SQ_TEST_OK(sq_converge_study(f, &opt, &r, &err), err);
    fails += sq_check_int("t230 half_disc", "runs", r.nruns, 2 * 11);
    for (int k = 0; k < r.nruns; k++) {
        const sq_converge_run *u = &r.runs[k];
        snprintf(where, sizeof where, "t230 half_disc %s P=%d", u->method == SEM_CG ? "CG" : "DG",
                 u->P);
        fails += sq_check_int(where, "P", u->P, 2 + k % 11);
        fails += sq_check_int(where, "method", u->method, k < 11 ? SEM_CG : SEM_DG);
        const double rf = sq_solve_roundoff(u->P, (int)ceil(sqrt(u->ntris)), exp(1.0));
        if (k % 11 > 0 && r.runs[k - 1].l2 > 3 * rf)
            fails += sq_check_abs(where, "L2 ratio to P-1", u->l2 / r.runs[k - 1].l2, 0.0, 1.0 / 3.0);
        if (u->P == 12) fails += sq_check_abs(where, "L2 error", u->l2, 0.0, fmax(1e-10, rf));
    }
    sq_converge_result_free(&r);
    cad_face_free(&f);
    cad_model_free(&m);

    /* h-refinement on the square */
    open_face("square.step", &m, &f);
    const double sizes[] = {0.5, 0.25, 0.125, 0.0625};
    sq_converge_options_default(&opt);
    opt.pmin = 1;
    opt.pmax = 3;
    opt.nsizes = 4;
    opt.sizes = sizes;
    opt.geom_order = 1; /* straight edges */
    SQ_TEST_OK(sq_converge_study(f, &opt, &r, &err), err);
    fails += sq_check_int("t230 square", "runs", r.nruns, 2 * 3 * 4);
    for (int mth = 0; mth < 2; mth++)
        for (int P = 1; P <= 3; P++) {
            double a = 0.0, b = 0.0;
            snprintf(where, sizeof where, "t230 square %s P=%d", mth ? "DG" : "CG", P);
            fails += sq_check_int(where, "rate available",
                                  sq_converge_rate(&r, (sem_method)mth, P, 0, &a), 0);
            fails += sq_check_int(where, "rate available",
                                  sq_converge_rate(&r, (sem_method)mth, P, 1, &b), 0);
            fails += sq_check_abs(where, "L2 rate", a, P + 1, 0.3);
            fails += sq_check_abs(where, "H1 rate", b, P, 0.3);
        }
    sq_converge_result_free(&r);

    /* usage errors */
    sq_converge_options_default(&opt);
    opt.solution = "no-such";
    fails += sq_check_int("t230 bad solution", "status", sq_converge_study(f, &opt, &r, &err),
                          SQ_ERR_USAGE);
    sq_converge_options_default(&opt);
    opt.pmin = 5;
    opt.pmax = 3;
    fails += sq_check_int("t230 bad orders", "status", sq_converge_study(f, &opt, &r, &err),
                          SQ_ERR_USAGE);
    cad_face_free(&f);
    cad_model_free(&m);
    return fails ? 1 : 0;
}
