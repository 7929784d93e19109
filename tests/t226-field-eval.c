/* t226: evaluation of a field at physical points (sem/field_eval.h) on the
 * curved disc mesh (geometry order 4), field order P = 8.
 *  - the field is the nodal interpolant of g(x) = sin(2x) e^y on every
 *    element (converted to Dubiner coefficients by exact projection): at
 *    random physical points the evaluator's value equals the Lagrange form
 *    sum_n g(x_n) l_n(r,s) to round-off, and equals g(x) at the nodes;
 *  - value and reference derivatives agree with sem_field_eval_ref; the
 *    physical gradient agrees with J^{-T} of the independent Lagrange-form
 *    Jacobian (tri_geom.h) and with central finite differences;
 *  - two components are evaluated consistently;
 *  - sem_field_eval_modes on sem_tri_dubiner's modes gives
 *    sem_field_eval_ref's values and derivatives bit for bit;
 *  - points outside the disc are reported as outside.
 * Its speed is bench/'s (docs/benchmarks.md): a test asserts no time. */
#include "field.h"
#include "field_eval.h"
#include "tri_basis.h"
#include "test_meshes.h"
#include "test_util.h"

#include <float.h>

#define NMAX ((SEM_MAX_ORDER + 1) * (SEM_MAX_ORDER + 2) / 2)

static double urand(unsigned long *st)
{
    *st = *st * 6364136223846793005UL + 1442695040888963407UL;
    return (double)(*st >> 11) / 9007199254740992.0;
}

static double gfun(const double x[2], int c) { return c == 0 ? sin(2 * x[0]) * exp(x[1]) : x[0] * x[1] - 0.3; }

int main(void)
{
    int fail = 0;
    const int P = 8, nc = 2;
    sq_error err;
    sem_tri_mesh *m = tm_disc(1.0, 3, 4);
    if (!m) return 1;
    sem_tri_lagrange *LG = NULL, *LP = NULL;
    sem_tri_quad *q = NULL;
    sem_field *f = NULL;
    SQ_TEST_OK(sem_tri_lagrange_create(m->order, &LG, &err), err);
    SQ_TEST_OK(sem_tri_lagrange_create(P, &LP, &err), err);
    SQ_TEST_OK(sem_tri_quad_create(2 * P, &q, &err), err);
    SQ_TEST_OK(sem_field_create(m, P, nc, &f, &err), err);
    const int nn = sem_tri_lagrange_num_nodes(LP);
    const double *nodes = sem_tri_lagrange_nodes(LP);
    double *gv = malloc(sizeof(double) * (size_t)nn * nc * m->ntris);
    /* nodal values, then Dubiner coefficients c_m = int_T I(g) phi_m */
    for (int e = 0; e < m->ntris; ++e) {
        const double *g = m->gxy + 2 * (size_t)m->nodes_per_tri * e;
        for (int n = 0; n < nn; ++n) {
            double x[2];
            sem_tri_geom_map(LG, g, nodes[2 * n], nodes[2 * n + 1], x, NULL);
            for (int c = 0; c < nc; ++c) gv[((size_t)e * nn + n) * nc + c] = gfun(x, c);
        }
        for (int k = 0; k < q->npts; ++k) {
            double l[NMAX], phi[NMAX];
            sem_tri_lagrange_eval(LP, q->rs[2 * k], q->rs[2 * k + 1], l, NULL, NULL);
            sem_tri_dubiner(P, q->rs[2 * k], q->rs[2 * k + 1], phi, NULL, NULL);
            for (int c = 0; c < nc; ++c) {
                double I = 0;
                for (int n = 0; n < nn; ++n) I += gv[((size_t)e * nn + n) * nc + c] * l[n];
                for (int mm = 0; mm < nn; ++mm) f->coef[((size_t)e * nn + mm) * nc + c] += q->w[k] * I * phi[mm];
            }
        }
    }
    sem_field_evaluator *ev = NULL;
    SQ_TEST_OK(sem_field_evaluator_create(f, NULL, &ev, &err), err);

    unsigned long st = 777;
    int nin = 0, nout = 0, hint = -1;
    for (int k = 0; k < 5000; ++k) {
        const double xy[2] = {-1.1 + 2.2 * urand(&st), -1.1 + 2.2 * urand(&st)};
        double val[2], grad[4];
        int e = hint;
        const int rc = sem_field_evaluator_eval(ev, xy, &e, val, grad);
        char what[96];
        snprintf(what, sizeof what, "point %d (%.5f, %.5f)", k, xy[0], xy[1]);
        const double rad = hypot(xy[0], xy[1]);
        if (rad < 0.99) fail += sq_check_int(what, "found (0)", rc, 0);
        if (rad > 1.01) fail += sq_check_int(what, "outside (1)", rc, 1);
        if (rc) {
            ++nout;
            continue;
        }
        ++nin;
        hint = e;
        /* (r,s) from the locator, then the Lagrange form of the interpolant */
        int e2;
        double r, s;
        if (sem_locator_find(sem_field_evaluator_locator(ev), xy, e, &e2, &r, &s) != 0 || e2 != e) {
            printf("%s: locator disagrees with the evaluator\n", what);
            ++fail;
            continue;
        }
        double l[NMAX], lr[NMAX], ls[NMAX];
        sem_tri_lagrange_eval(LP, r, s, l, lr, ls);
        double J[4];
        const double det = sem_tri_geom_map(LG, m->gxy + 2 * (size_t)m->nodes_per_tri * e, r, s, NULL, J);
        double v2[2], dr2[2], ds2[2];
        sem_field_eval_ref(f, e, r, s, v2, dr2, ds2);
        for (int c = 0; c < nc; ++c) {
            double I = 0, Ir = 0, Is = 0, aI = 0, aD = 0;
            for (int n = 0; n < nn; ++n) {
                const double gn = gv[((size_t)e * nn + n) * nc + c];
                I += gn * l[n];
                Ir += gn * lr[n];
                Is += gn * ls[n];
                aI += fabs(gn * l[n]);
                aD += fabs(gn) * (fabs(lr[n]) + fabs(ls[n]));
            }
            const double gx = (J[3] * Ir - J[2] * Is) / det, gy = (-J[1] * Ir + J[0] * Is) / det;
            /* The computed l_n are exact polynomials of degree P (Dubiner
             * modes times computed coefficients), so the projection gives
             * them back whatever V^{-1}'s round-off: only sums are left,
             * the projection's npts and the evaluation's nn terms, on each
             * side: 2 (npts + nn) U sum |g_n l_n|; for the gradient the same
             * with sum |g_n| |dl_n| times |J^{-1}| <= sum |J| / |det J|.
             * sem_field_eval_ref runs the evaluator's sums: nn U. */
            const double ev = 2.0 * (q->npts + nn) * (DBL_EPSILON / 2);
            const double jinv = (fabs(J[0]) + fabs(J[1]) + fabs(J[2]) + fabs(J[3])) / fabs(det);
            fail += sq_check_abs(what, "value vs nodal interpolant", val[c], I, ev * aI);
            fail += sq_check_abs(what, "value vs sem_field_eval_ref", val[c], v2[c], nn * (DBL_EPSILON / 2) * aI);
            fail += sq_check_abs(what, "d/dx vs Lagrange form", grad[2 * c], gx, ev * aD * jinv);
            fail += sq_check_abs(what, "d/dy vs Lagrange form", grad[2 * c + 1], gy, ev * aD * jinv);
            if (c == 0 && k < 50) { /* g itself is close to its interpolant */
                /* interpolation error of sin(2x) e^y at P = 8 (CPU-independent) */
                fail += sq_check_abs(what, "value vs g(x)", val[0], gfun(xy, 0), 1e-4);
            }
        }
        /* central differences (points well inside one element) */
        const double h = 1e-6;
        if (r > 1e-3 && s > 1e-3 && r + s < 1 - 1e-3 && rad < 0.98) {
            double vp[2], vm[2];
            int ee = e;
            for (int d = 0; d < 2; ++d) {
                double xp[2] = {xy[0], xy[1]}, xm[2] = {xy[0], xy[1]};
                xp[d] += h;
                xm[d] -= h;
                ee = e;
                if (sem_field_evaluator_eval(ev, xp, &ee, vp, NULL) || ee != e) continue;
                ee = e;
                if (sem_field_evaluator_eval(ev, xm, &ee, vm, NULL) || ee != e) continue;
                for (int c = 0; c < nc; ++c)
                    /* truncation h^2 |g^(3)| / 6 ~ 1e-11, round-off U |g| / h ~ 3e-10 */
                    fail += sq_check_abs(what, "gradient vs central difference", grad[2 * c + d],
                                         (vp[c] - vm[c]) / (2 * h), 1e-6 * (1 + fabs(grad[2 * c + d])));
            }
        }
    }
    if (nin < 3000 || nout < 500) {
        printf("sample: %d inside, %d outside\n", nin, nout);
        ++fail;
    }
    /* interpolation at the nodes */
    for (int e = 0; e < m->ntris; e += 7)
        for (int n = 0; n < nn; ++n) {
            double val[2], x[2];
            sem_field_evaluator_eval_ref(ev, e, nodes[2 * n], nodes[2 * n + 1], val, NULL, x);
            /* l_k(x_n) = delta to n kappa_1 U (1.9e-13 at P = 8, t103) times
             * |g| <= e, plus the sums' (npts + nn) U |g| */
            fail += sq_check_abs("node value", "g(x_n)", val[0], gfun(x, 0), 1e-12);
        }

    /* sem_field_eval_modes from sem_tri_dubiner's modes runs
     * sem_field_eval_ref's sums in the same order: the same bits, with and
     * without derivatives (the critical points' lattice scan relies on it) */
    for (int k = 0; k < 200; ++k) {
        const int e = (int)(urand(&st) * m->ntris) % m->ntris;
        const double r = urand(&st), s = (1.0 - r) * urand(&st);
        double phi[NMAX], pr[NMAX], ps[NMAX], v[2], dr[2], ds[2], v2[2], dr2[2], ds2[2];
        sem_tri_dubiner(P, r, s, phi, pr, ps);
        sem_field_eval_modes(f, e, phi, pr, ps, v, dr, ds);
        sem_field_eval_ref(f, e, r, s, v2, dr2, ds2);
        for (int c = 0; c < nc; ++c) {
            fail += sq_check_int("eval_modes", "value bits", v[c] == v2[c], 1);
            fail += sq_check_int("eval_modes", "d/dr bits", dr[c] == dr2[c], 1);
            fail += sq_check_int("eval_modes", "d/ds bits", ds[c] == ds2[c], 1);
        }
        sem_tri_dubiner(P, r, s, phi, NULL, NULL);
        sem_field_eval_modes(f, e, phi, NULL, NULL, v, NULL, NULL);
        sem_field_eval_ref(f, e, r, s, v2, NULL, NULL);
        for (int c = 0; c < nc; ++c) fail += sq_check_int("eval_modes", "value bits, no derivatives", v[c] == v2[c], 1);
    }

    sem_field_evaluator_free(&ev);
    free(gv);
    sem_field_free(&f);
    sem_tri_quad_free(&q);
    sem_tri_lagrange_free(&LG);
    sem_tri_lagrange_free(&LP);
    sem_tri_mesh_free(&m);
    return fail ? 1 : 0;
}
