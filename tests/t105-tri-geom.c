/* t105: geometric map and scaled Jacobian.
 *  - straight triangles: x(r,s) affine, det J = 2*area everywhere, scaled
 *    Jacobian 1; a clockwise triangle is reported invalid;
 *  - a quarter-disc sector (radius R) with its nodes placed by the exact
 *    polar map, so the curved edge interpolates the arc: the area
 *    sum w det J converges spectrally to pi R^2 / 4 as P grows;
 *  - the curved edge pushed inward beyond the opposite vertex: scaled
 *    Jacobian <= 0. */
#include "gauss.h"
#include "sem_roundoff.h"
#include "tri_geom.h"
#include "tri_lagrange.h"
#include "tri_nodes.h"
#include "tri_quad.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#define NMAX ((SEM_MAX_ORDER + 1) * (SEM_MAX_ORDER + 2) / 2)
#define PI 3.14159265358979323846

/* Tolerances: the map and its Jacobian are interpolated through the nodal
 * basis, off by e = n kappa_1(V) U (sem_roundoff.h) times the coordinates'
 * size (|g| <= 2.1 here) times sum |l_k|, the Jacobian by e 2.1 sum |dl_k|
 * (at most D = sq_lagrange_dsum); det J = J00 J11 - J01 J10 doubles that
 * times |J| <= 2.1. */

static int failures;

static void check(const char *what, int P, int k, double value, double expected, double tol)
{
    if (!(fabs(value - expected) <= tol)) {
        printf("t105 %s (P=%d, #%d): value %.17g expected %.17g tolerance %g\n", what, P, k, value,
               expected, tol);
        ++failures;
    }
}

static double area(const sem_tri_lagrange *L, const double *g, int P)
{
    sem_tri_quad *q = NULL;
    if (sem_tri_quad_create(2 * P, &q, NULL) != SQ_OK) return NAN;
    double a = 0.0;
    for (int k = 0; k < q->npts; ++k)
        a += q->w[k] * sem_tri_geom_map(L, g, q->rs[2 * k], q->rs[2 * k + 1], NULL, NULL);
    sem_tri_quad_free(&q);
    return a;
}

int main(void)
{
    static double g[2 * NMAX];
    const double X[3][2] = {{0.3, -0.2}, {2.1, 0.4}, {0.9, 1.7}}; /* counter-clockwise */
    const double area2 = (X[1][0] - X[0][0]) * (X[2][1] - X[0][1]) - (X[2][0] - X[0][0]) * (X[1][1] - X[0][1]);
    const double R = 1.5;
    double prev_err = HUGE_VAL;
    for (int P = 1; P <= SEM_MAX_ORDER; ++P) {
        sem_tri_lagrange *L = NULL;
        if (sem_tri_lagrange_create(P, &L, NULL) != SQ_OK) return 1;
        const int n = sem_tri_lagrange_num_nodes(L);
        const double *rs = sem_tri_lagrange_nodes(L);
        const double e = sq_lagrange_roundoff(L), D = sq_lagrange_dsum(L);
        static double l[NMAX], lr[NMAX], ls[NMAX];

        /* straight triangle */
        for (int k = 0; k < n; ++k)
            for (int c = 0; c < 2; ++c)
                g[2 * k + c] = X[0][c] + rs[2 * k] * (X[1][c] - X[0][c]) + rs[2 * k + 1] * (X[2][c] - X[0][c]);
        const double pts[][2] = {{0.1, 0.1}, {0.6, 0.2}, {0.0, 1.0}, {0.25, 0.7}};
        for (int t = 0; t < 4; ++t) {
            double x[2], jac[4];
            const double r = pts[t][0], s = pts[t][1];
            const double d = sem_tri_geom_map(L, g, r, s, x, jac);
            sem_tri_lagrange_eval(L, r, s, l, lr, ls);
            double sl = 0.0, sd = 0.0; /* sum |l_k|, sum |dl_k| at (r, s) */
            for (int k = 0; k < n; ++k) {
                sl += fabs(l[k]);
                sd += fabs(lr[k]) + fabs(ls[k]);
            }
            const double ex = e * sl * 2.1, ej = e * sd * 2.1; /* see the top */
            check("straight det J = 2 area", P, t, d, area2, 2 * 2.1 * ej);
            check("straight x", P, t, x[0], X[0][0] + r * (X[1][0] - X[0][0]) + s * (X[2][0] - X[0][0]), ex);
            check("straight y", P, t, x[1], X[0][1] + r * (X[1][1] - X[0][1]) + s * (X[2][1] - X[0][1]), ex);
            check("straight x_r", P, t, jac[0], X[1][0] - X[0][0], ej);
            check("straight y_s", P, t, jac[3], X[2][1] - X[0][1], ej);
            /* the same two products and a difference: 3 U of |J|^2 <= 2.1^2 */
            check("det J return = from jac", P, t, d, jac[0] * jac[3] - jac[1] * jac[2], 3 * SQ_U * 2.1 * 2.1);
        }
        /* min det J / max det J: twice det J's error relative to 2 area */
        check("straight scaled Jacobian", P, 0, sem_tri_geom_scaled_jacobian(L, g), 1.0,
              2 * 2 * 2.1 * e * D * 2.1 / area2);
        /* the same triangle clockwise (swap vertices 1 and 2: r <-> s) */
        for (int k = 0; k < n; ++k)
            for (int c = 0; c < 2; ++c)
                g[2 * k + c] = X[0][c] + rs[2 * k + 1] * (X[1][c] - X[0][c]) + rs[2 * k] * (X[2][c] - X[0][c]);
        const double cw = sem_tri_geom_scaled_jacobian(L, g);
        if (!(cw <= 0)) check("clockwise triangle invalid", P, 0, cw, -1.0, 1e-11);

        /* quarter-disc sector: polar map (r+s) R (cos t, sin t), t = (pi/2) s/(r+s) */
        for (int k = 0; k < n; ++k) {
            const double r = rs[2 * k], s = rs[2 * k + 1], rho = r + s;
            const double th = rho > 0 ? 0.5 * PI * s / rho : 0.0;
            g[2 * k] = rho * R * cos(th);
            g[2 * k + 1] = rho * R * sin(th);
        }
        const double err = fabs(area(L, g, P) - 0.25 * PI * R * R);
        const double sj = sem_tri_geom_scaled_jacobian(L, g);
        if (getenv("SQ_VERBOSE"))
            printf("t105 sector P=%2d area error %.3e scaled Jacobian %.4f\n", P, err, sj);
        if (!(sj > 0)) check("sector scaled Jacobian > 0", P, 0, sj, 1.0, 1.0);
        /* spectral convergence until round-off: the area sums npts w det J,
         * each det J off by 2 |J| e sum |dl| (see the top); below that floor
         * the error is round-off and need not decrease (from P = 6 here:
         * a worst case, the measured errors reach 1e-15) */
        const double floor = 4 * e * D * 0.25 * PI * R * R;
        if (err > floor) {
            if (!(err < prev_err)) check("sector area error decreases", P, 0, err, prev_err, 0);
        }
        if (P == 4) check("sector area error at P=4", P, 0, err, 0.0, 1e-4);
        if (P == 8) check("sector area error at P=8", P, 0, err, 0.0, 1e-9 + floor);
        if (P >= 12) check("sector area error at P>=12", P, 0, err, 0.0, floor);
        prev_err = err;

        /* sampler variant agrees with the documented function */
        sem_tri_geom_sampler *S = NULL;
        if (sem_tri_geom_sampler_create(L, &S, NULL) != SQ_OK) return 1;
        /* the sampler tabulates the same basis values: the same sums up to
         * their order, npts U of the sums' sizes (|det J| <= 4 R^2) */
        check("sampler = scaled_jacobian", P, 0, sem_tri_geom_sampler_scaled_jacobian(S, g), sj,
              2 * n * SQ_U);
        double sa = 0.0;
        const double sm = sem_tri_geom_sampler_measure(S, g, &sa);
        check("sampler measure = scaled_jacobian", P, 0, sm, sj, 2 * n * SQ_U);
        check("sampler area = rule on the map", P, 0, sa, area(L, g, P),
              (n + 4 * P * P) * SQ_U * 4 * R * R);
        sem_tri_geom_sampler_free(&S);
        sem_tri_geom_sampler_free(&S);

        /* inverted: the curved edge (v1 -> v2) bulges inward past vertex 0 */
        if (P >= 2) {
            for (int k = 0; k < n; ++k) {
                const double r = rs[2 * k], s = rs[2 * k + 1];
                /* straight unit right triangle plus a bump vanishing at the
                 * vertices, maximal mid-edge 1 (bump 4rs pulls toward and past the origin) */
                const double bump = 4.0 * r * s * 1.2;
                g[2 * k] = r - bump;
                g[2 * k + 1] = s - bump;
            }
            const double bad = sem_tri_geom_scaled_jacobian(L, g);
            if (!(bad <= 0)) check("inverted element scaled Jacobian <= 0", P, 0, bad, 0.0, 0.0);
        }
        sem_tri_lagrange_free(&L);
    }
    return failures ? 1 : 0;
}
