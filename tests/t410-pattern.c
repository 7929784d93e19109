/* Pattern files: parsing (line numbers in every error), points outside or
 * on the boundary refused, corner overrides, and the Gauss–Bonnet check
 * with both sides and the smallest fix in the message. */
#include "pattern.h"
#include "test_face.h"

#include <gsl/gsl_errno.h>

static int expect_fail(const char *text, const char *want, const cad_face *f,
                       const sq_face_info *info)
{
    sq_pattern p;
    sq_error err;
    sq_error_clear(&err);
    sq_status st = sq_pattern_parse(text, "pat", &p, &err);
    if (st == SQ_OK) {
        sq_pattern_balance bal;
        st = sq_pattern_check(f, info, &p, &bal, &err);
        if (st == SQ_OK) sq_pattern_balance_free(&bal);
        sq_pattern_free(&p);
    }
    int fails = sq_check_int(text, "status", st, SQ_ERR_PATTERN);
    if (!strstr(err.msg, want)) {
        printf("'%s': message '%s' lacks '%s'\n", text, err.msg, want);
        fails++;
    }
    return fails;
}

int main(void)
{
    gsl_set_error_handler_off();
    sq_error err;
    cad_model *m = NULL;
    cad_face *f = NULL;
    sq_face_info info;
    sq_test_open_face("square.step", &m, &f);
    SQ_TEST_OK(sq_face_info_compute(f, &info, &err), err);
    int fails = 0;

    /* a good file with comments, blank lines and a corner override */
    sq_pattern p;
    const char *good = "# four 3s and four 5s\n\n0.3 0.3 5\n0.7 0.3 5 # c\n0.7 0.7 5\n0.3 0.7 5\n"
                       "0.1 0.1 3\n0.9 0.1 3\n0.9 0.9 3\n0.1 0.9 3\n";
    SQ_TEST_OK(sq_pattern_parse(good, "good", &p, &err), err);
    fails += sq_check_int("good", "points", p.npoints, 8);
    fails += sq_check_int("good", "line of point 2", p.lines[1], 4);
    fails += sq_check_abs("good", "x of point 2", p.points[1].x, 0.7, 0.0);
    fails += sq_check_int("good", "valence of point 5", p.points[4].valence, 3);
    sq_pattern_balance bal;
    SQ_TEST_OK(sq_pattern_check(f, &info, &p, &bal, &err), err);
    fails += sq_check_int("good", "lhs", bal.lhs, 4);
    fails += sq_check_int("good", "rhs", bal.rhs, 4);
    sq_pattern_balance_free(&bal);
    sq_pattern_free(&p);

    /* a 90° corner taking 2 quads: one valence-3 point less is needed */
    SQ_TEST_OK(sq_pattern_parse("corner 1 1 2\n0.5 0.5 3\n0.3 0.5 3\n0.7 0.5 3\n", "corner", &p,
                                &err),
               err);
    fails += sq_check_int("corner", "overrides", p.ncorners, 1);
    sq_status st = sq_pattern_check(f, &info, &p, &bal, &err);
    fails += sq_check_int("corner", "status", st, SQ_ERR_PATTERN);
    if (!strstr(err.msg, "add 2 valence-5 points or remove 2 valence-3 points")) {
        printf("corner: message '%s' lacks the fix\n", err.msg);
        fails++;
    }
    sq_pattern_free(&p);
    SQ_TEST_OK(sq_pattern_parse("corner 1 1 2\n0.5 0.5 3\n", "corner", &p, &err), err);
    SQ_TEST_OK(sq_pattern_check(f, &info, &p, &bal, &err), err);
    fails += sq_check_int("corner", "lhs", bal.lhs, 4);
    int q11 = -1;
    for (int k = 0; k < info.nvertices; k++)
        if (info.vertices[k].x == 1.0 && info.vertices[k].y == 1.0) q11 = bal.quads[k];
    fails += sq_check_int("corner", "quads at (1,1)", q11, 2);
    sq_pattern_balance_free(&bal);
    sq_pattern_free(&p);

    /* malformed lines and bad points name their line */
    fails += expect_fail("0.5 0.5 3\n0.5 x 3\n", "pat:2:", f, &info);
    fails += expect_fail("\n\n0.5 0.5\n", "pat:3:", f, &info);
    fails += expect_fail("0.5 0.5 0\n", "valence 0 out of range", f, &info);
    fails += expect_fail("corner 1 1\n", "pat:1:", f, &info);
    fails += expect_fail("0.2 0.2 3\n1.5 0.5 3\n", "line 2: point (1.5, 0.5) lies outside", f, &info);
    fails += expect_fail("0.2 0.2 3\n0.3 0.3 3\n1.0 0.5 3\n", "line 3: point (1, 0.5) lies on the boundary",
                         f, &info);
    fails += expect_fail("corner 0.5 0.5 2\n", "line 1: no vertex of the face", f, &info);
    /* Gauss–Bonnet: the square with one valence-5 point */
    fails += expect_fail("0.5 0.5 5\n",
                         "4.712389 (3 x pi/2) but 2 pi chi = 6.283185 (4 x pi/2, chi = 1); "
                         "smallest fix: add one valence-3 point or remove one valence-5 point",
                         f, &info);
    fails += expect_fail("0.5 0.5 6\n", "(2 x pi/2) but 2 pi chi = 6.283185 (4 x pi/2, chi = 1); "
                         "smallest fix: add 2 valence-3 points", f, &info);
    fails += expect_fail("0.5 0.5 3\n", "(5 x pi/2) but 2 pi chi = 6.283185 (4 x pi/2, chi = 1); "
                         "smallest fix: add one valence-5 point or remove one valence-3 point",
                         f, &info);
    sq_face_info_free(&info);
    cad_face_free(&f);
    cad_model_free(&m);
    return fails != 0;
}
