/* t202: a field set to the Dubiner expansion of known polynomials (two
 * components, order P = 1..16) evaluates to the polynomials' values and
 * reference derivatives at random points of the triangle to round-off. */
#include "field.h"
#include "gauss.h"
#include "test_meshes.h"
#include "test_util.h"

#include <float.h>

#define SQ_T202_MAXCOMP 8 /* components the test uses, at most */
#include "tri_basis.h"

#define NM ((SEM_MAX_ORDER + 1) * (SEM_MAX_ORDER + 2) / 2)

/* component c: q(r,s) = (1 + r - 2 s)^P + c r s^(P-1), and its gradient */
static void q(int P, int c, double r, double s, double *v, double *dr, double *ds)
{
    const double l = 1 + r - 2 * s;
    const double lp = pow(l, P), lp1 = P ? P * pow(l, P - 1) : 0.0;
    const double sp = P >= 1 ? pow(s, P - 1) : 0.0, sp1 = P >= 2 ? (P - 1) * pow(s, P - 2) : 0.0;
    *v = lp + c * r * sp;
    *dr = lp1 + c * sp;
    *ds = -2 * lp1 + c * r * sp1;
}

int main(void)
{
    int fails = 0;
    sq_error err = {0};
    sem_tri_mesh *m = tm_square(1, 1);
    if (!m) return printf("t202: mesh\n"), 1;
    srand(202);
    for (int P = 1; P <= SEM_MAX_ORDER; ++P) {
        sem_field *f = NULL;
        SQ_TEST_OK(sem_field_create(m, P, 2, &f, &err), err);
        sem_tri_quad *quad = NULL;
        SQ_TEST_OK(sem_tri_quad_create(2 * P, &quad, &err), err);
        /* orthonormal basis: coefficient = ∫ q phi_m (exact rule) */
        const int e = 1;
        for (int k = 0; k < quad->npts; ++k) {
            double phi[NM], v, a, b;
            const double r = quad->rs[2 * k], s = quad->rs[2 * k + 1];
            sem_tri_dubiner(P, r, s, phi, NULL, NULL);
            for (int c = 0; c < 2; ++c) {
                q(P, c, r, s, &v, &a, &b);
                for (int mm = 0; mm < f->nmodes; ++mm)
                    f->coef[((size_t)e * f->nmodes + mm) * 2 + c] += quad->w[k] * v * phi[mm];
            }
        }
        sem_tri_quad_free(&quad);
        for (int t = 0; t < 20; ++t) {
            double r = (double)rand() / RAND_MAX, s = (double)rand() / RAND_MAX;
            if (r + s > 1) r = 1 - r, s = 1 - s;
            double val[2], dr[2], ds[2];
            sem_field_eval_ref(f, e, r, s, val, dr, ds);
            for (int c = 0; c < 2; ++c) {
                double v, a, b;
                char where[64];
                snprintf(where, sizeof where, "t202 P=%d comp %d (%.3f,%.3f)", P, c, r, s);
                q(P, c, r, s, &v, &a, &b);
                /* round-off relative to the size of q on T (2^P): the
                 * coefficients are sums of npts = (P+1)^2 terms, the value a
                 * sum of n modes (orthonormal, no BLAS): (npts + n) U 2^P.
                 * The error is a polynomial of degree P, so its derivatives
                 * are at most 2 P^2 times that (Markov on T). */
                const double sz = ldexp(1.0, P);
                const double tv = ((P + 1) * (P + 1) + f->nmodes) * (DBL_EPSILON / 2) * sz;
                fails += sq_check_abs(where, "value", val[c], v, tv);
                fails += sq_check_abs(where, "d/dr", dr[c], a, 2 * P * P * tv);
                fails += sq_check_abs(where, "d/ds", ds[c], b, 2 * P * P * tv);
            }
            double v0[SQ_T202_MAXCOMP];
            sem_field_eval_ref(f, 0, r, s, v0, NULL, NULL); /* element 0 is zero */
            for (int c = 0; c < f->ncomp; c++)
                fails += sq_check_abs("t202 other element", "value", v0[c], 0.0, 0.0);
        }
        sem_field_free(&f);
    }
    sem_field *f = NULL;
    fails += sq_check_int("t202 bad order", "status",
                          sem_field_create(m, SEM_MAX_ORDER + 1, 1, &f, &err), SQ_ERR_USAGE);
    sem_tri_mesh_free(&m);
    return fails ? 1 : 0;
}
