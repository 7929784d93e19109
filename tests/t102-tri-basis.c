/* t102: the Dubiner basis is orthonormal on T (mass matrix = I with a rule
 * of degree 2P, P = 0..16) and its derivatives agree with central finite
 * differences everywhere, including the collapsed vertex (0,1). */
#include "gauss.h"
#include "tri_basis.h"
#include "tri_nodes.h"
#include "tri_quad.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

/* Unit round-off.  No BLAS here: the modes come from P-step recurrences on
 * terms bounded by (P+1)^2 (sampled max |phi| = 99 at P = 16), so each value
 * is off by at most 4 (P+1) U (P+1)^2. */
#define U (DBL_EPSILON / 2)
#define NMAX ((SEM_MAX_ORDER + 1) * (SEM_MAX_ORDER + 2) / 2)

static int failures;

static void check(const char *what, int P, int m, double value, double expected, double tol)
{
    if (!(fabs(value - expected) <= tol)) {
        printf("t102 %s (P=%d, mode %d): value %.17g expected %.17g tolerance %g\n", what, P, m, value,
               expected, tol);
        ++failures;
    }
}

int main(void)
{
    static double phi[NMAX], M[NMAX * NMAX];
    double worst_mass = 0.0;
    for (int P = 0; P <= SEM_MAX_ORDER; ++P) {
        const int n = sem_tri_num_nodes(P);
        sem_tri_quad *q = NULL;
        if (sem_tri_quad_create(2 * P, &q, NULL) != SQ_OK) {
            printf("t102 quad_create(%d) failed\n", 2 * P);
            return 1;
        }
        for (int i = 0; i < n * n; ++i) M[i] = 0.0;
        for (int k = 0; k < q->npts; ++k) {
            sem_tri_dubiner(P, q->rs[2 * k], q->rs[2 * k + 1], phi, NULL, NULL);
            for (int i = 0; i < n; ++i)
                for (int j = 0; j < n; ++j) M[i * n + j] += q->w[k] * phi[i] * phi[j];
        }
        double e = 0.0;
        int ie = 0;
        for (int i = 0; i < n; ++i)
            for (int j = 0; j < n; ++j) {
                const double d = fabs(M[i * n + j] - (i == j));
                if (d > e) {
                    e = d;
                    ie = i;
                }
            }
        if (e > worst_mass) worst_mass = e;
        /* sum of npts terms w phi_i phi_j (2 roundings each): (npts + 2) U
         * sum w |phi_i phi_j| <= (npts + 2) U (Cauchy-Schwarz, M_ii = 1); the
         * values' errors add 2 sum w |phi| 4 (P+1)^3 U <= sqrt(2) 4 (P+1)^3 U
         * (sum w = 1/2). */
        check("mass matrix max |M - I|", P, ie, e, 0.0, (q->npts + 2.0 + 6.0 * pow(P + 1, 3)) * U);
        sem_tri_quad_free(&q);
    }

    /* Derivatives vs 4th-order central differences, relative to the size of
     * the derivatives of that degree. */
    static double dr[NMAX], ds[NMAX], fp[4][NMAX];
    const double pts[][2] = {{0.2, 0.3}, {0.0, 0.0}, {1.0, 0.0}, {0.0, 1.0}, {0.5, 0.5},
                             {0.0, 0.5}, {1e-9, 1.0 - 1e-9}, {0.0, 1.0 - 1e-13}, {0.7, 0.05}, {0.3, 0.69}};
    double worst_fd = 0.0;
    for (int P = 1; P <= 12; ++P) {
        const int n = sem_tri_num_nodes(P);
        const double h = 1e-3;
        for (size_t t = 0; t < sizeof pts / sizeof pts[0]; ++t) {
            const double r = pts[t][0], s = pts[t][1];
            sem_tri_dubiner(P, r, s, phi, dr, ds);
            double scale = 1.0;
            for (int m = 0; m < n; ++m) scale = fmax(scale, fmax(fabs(dr[m]), fabs(ds[m])));
            for (int dir = 0; dir < 2; ++dir) {
                const double off[4] = {-2 * h, -h, h, 2 * h};
                for (int o = 0; o < 4; ++o)
                    sem_tri_dubiner(P, r + (dir == 0) * off[o], s + (dir == 1) * off[o], fp[o], NULL, NULL);
                for (int m = 0; m < n; ++m) {
                    const double fd = (fp[0][m] - 8 * fp[1][m] + 8 * fp[2][m] - fp[3][m]) / (12 * h);
                    const double an = dir == 0 ? dr[m] : ds[m];
                    const double rel = fabs(fd - an) / scale;
                    if (rel > worst_fd) worst_fd = rel;
                    /* truncation h^4 |f^(5)| / 30, by Markov's inequality at most
                     * h^4 P^8 / 30 of the derivatives' size (exact for P <= 4), and
                     * the round-off of the difference, 18 U (P+1)^2 / (12 h) */
                    check(dir == 0 ? "d/dr vs finite difference" : "d/ds vs finite difference", P, m,
                          an / scale, fd / scale,
                          pow(h, 4) * pow(P, 8) / 30 + 1.5 * U * (P + 1) * (P + 1) / h);
                }
            }
            /* a NULL output must not change the others */
            double phi2[NMAX];
            sem_tri_dubiner(P, r, s, phi2, NULL, NULL);
            for (int m = 0; m < n; ++m) check("values with NULL derivatives", P, m, phi2[m], phi[m], 0.0);
        }
    }
    /* phi_00 = sqrt(2) (constant of unit norm on area 1/2) */
    sem_tri_dubiner(0, 0.3, 0.3, phi, dr, ds);
    check("phi_00", 0, 0, phi[0], sqrt(2.0), 2 * U * sqrt(2.0)); /* one or two roundings */
    if (getenv("SQ_VERBOSE"))
        printf("t102 worst |M-I| %.3g, worst relative finite-difference gap %.3g\n", worst_mass, worst_fd);
    return failures ? 1 : 0;
}
