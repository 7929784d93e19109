/* t103: the nodal Lagrange basis on sem_tri_nodes(): l_n(x_m) = delta_nm,
 * partition of unity, derivatives summing to zero, and exact reproduction
 * (values and derivatives) of polynomials of degree P, for P = 1..16. */
#include "gauss.h"
#include "sem_roundoff.h"
#include "tri_lagrange.h"
#include "tri_nodes.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#define NMAX ((SEM_MAX_ORDER + 1) * (SEM_MAX_ORDER + 2) / 2)

static int failures;

static void check(const char *what, int P, int k, double value, double expected, double tol)
{
    if (!(fabs(value - expected) <= tol)) {
        printf("t103 %s (P=%d, #%d): value %.17g expected %.17g tolerance %g\n", what, P, k, value,
               expected, tol);
        ++failures;
    }
}

/* Tolerances: n kappa_1(V) U times the absolute sums (sem_roundoff.h). */
#define U SQ_U

/* A polynomial of total degree exactly P with all monomials present. */
static double poly(int P, double r, double s, double *fr, double *fs)
{
    const double u = 0.3 + 0.8 * r - 0.6 * s, v = -0.2 + 0.5 * r + 0.9 * s;
    const double c = P >= 2 ? 0.5 : 0.0; /* an r*s term when the degree allows */
    *fr = P * pow(u, P - 1) * 0.8 + P * pow(v, P - 1) * 0.5 + 1.0 + c * s;
    *fs = P * pow(u, P - 1) * -0.6 + P * pow(v, P - 1) * 0.9 - 2.0 + c * r;
    return pow(u, P) + pow(v, P) + 0.25 + r - 2.0 * s + c * r * s;
}

int main(void)
{
    static double l[NMAX], lr[NMAX], ls[NMAX], l2[NMAX];
    const double pts[][2] = {{0.1, 0.2}, {1.0 / 3, 1.0 / 3}, {0.0, 1.0}, {0.9, 0.05}, {0.0, 0.0},
                             {0.45, 0.55}, {0.02, 0.7}};
    double worst_delta = 0.0, worst_poly = 0.0, worst_dpoly = 0.0;
    for (int P = 1; P <= SEM_MAX_ORDER; ++P) {
        sem_tri_lagrange *L = NULL;
        sq_error err;
        if (sem_tri_lagrange_create(P, &L, &err) != SQ_OK) {
            printf("t103 lagrange_create(%d) failed: %s\n", P, err.msg);
            return 1;
        }
        const int n = sem_tri_lagrange_num_nodes(L);
        check("num_nodes", P, 0, n, sem_tri_num_nodes(P), 0);
        check("order", P, 0, sem_tri_lagrange_order(L), P, 0);
        const double *rs = sem_tri_lagrange_nodes(L);
        const double nk = sq_lagrange_roundoff(L); /* n kappa_1(V) U */
        for (int m = 0; m < n; ++m) {
            sem_tri_lagrange_eval(L, rs[2 * m], rs[2 * m + 1], l, NULL, NULL);
            for (int k = 0; k < n; ++k) {
                const double d = fabs(l[k] - (k == m));
                if (d > worst_delta) worst_delta = d;
                check("l_k(x_m) = delta", P, k * 1000 + m, l[k], k == m, nk); /* sum |l| = 1 */
            }
        }
        for (size_t t = 0; t < sizeof pts / sizeof pts[0]; ++t) {
            const double r = pts[t][0], s = pts[t][1];
            sem_tri_lagrange_eval(L, r, s, l, lr, ls);
            double sum = 0, sr = 0, ss = 0, scale = 1.0, al = 0, alr = 0, als = 0;
            for (int k = 0; k < n; ++k) {
                sum += l[k];
                sr += lr[k];
                ss += ls[k];
                scale = fmax(scale, fmax(fabs(lr[k]), fabs(ls[k])));
                al += fabs(l[k]);
                alr += fabs(lr[k]);
                als += fabs(ls[k]);
            }
            check("partition of unity", P, (int)t, sum, 1.0, nk * al);
            check("sum dl/dr", P, (int)t, sr / scale, 0.0, nk * alr / scale);
            check("sum dl/ds", P, (int)t, ss / scale, 0.0, nk * als / scale);
            /* polynomial reproduction */
            double f = 0, fr = 0, fs = 0, er, es, af = 0, afr = 0, afs = 0;
            for (int k = 0; k < n; ++k) {
                double gr, gs;
                const double g = poly(P, rs[2 * k], rs[2 * k + 1], &gr, &gs);
                f += g * l[k];
                fr += g * lr[k];
                fs += g * ls[k];
                af += fabs(g * l[k]);
                afr += fabs(g * lr[k]);
                afs += fabs(g * ls[k]);
            }
            const double e = poly(P, r, s, &er, &es);
            worst_poly = fmax(worst_poly, fabs(f - e));
            worst_dpoly = fmax(worst_dpoly, fmax(fabs(fr - er), fabs(fs - es)) / (1.0 + fabs(er) + fabs(es)));
            /* the g_k themselves (pow of degree P) add P U sum |g l| */
            check("reproduces degree-P polynomial", P, (int)t, f, e, (nk + P * U) * af);
            check("reproduces its r derivative", P, (int)t, fr, er, (nk + P * U) * afr);
            check("reproduces its s derivative", P, (int)t, fs, es, (nk + P * U) * afs);
            /* partial outputs agree with the full evaluation: the same axpy's
             * in the same order (sem/tri_lagrange.c), equal but for one
             * rounding if a compiler contracts one loop and not the other */
            sem_tri_lagrange_eval(L, r, s, NULL, l2, NULL);
            for (int k = 0; k < n; ++k) check("dr alone", P, k, l2[k], lr[k], 1e-15 * (1 + fabs(lr[k])));
            sem_tri_lagrange_eval(L, r, s, l2, NULL, NULL);
            for (int k = 0; k < n; ++k) check("l alone", P, k, l2[k], l[k], 1e-15 * (1 + fabs(l[k])));
        }
        sem_tri_lagrange_free(&L);
        if (L) {
            printf("t103 free did not NULL the pointer\n");
            ++failures;
        }
    }
    sem_tri_lagrange_free(NULL);
    sem_tri_lagrange *bad = NULL;
    if (sem_tri_lagrange_create(0, &bad, NULL) != SQ_ERR_USAGE || bad ||
        sem_tri_lagrange_create(SEM_MAX_ORDER + 1, &bad, NULL) != SQ_ERR_USAGE || bad) {
        printf("t103 bad order accepted\n");
        ++failures;
    }
    if (getenv("SQ_VERBOSE"))
        printf("t103 worst |l_k(x_m)-delta| %.3g, polynomial %.3g, derivative (rel) %.3g\n", worst_delta,
               worst_poly, worst_dpoly);
    return failures ? 1 : 0;
}
