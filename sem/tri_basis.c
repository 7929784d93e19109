/* semquad sem/ — orthonormal Dubiner basis on the reference triangle.
 *
 * phi_pq(r,s) = c_pq P_p(a) ((1-b)/2)^p P_q^{(2p+1,0)}(b),
 *   a = 2r/(1-s) - 1,  b = 2s - 1
 * (Dubiner 1991; Karniadakis & Sherwin 2005, §3.2 for the collapsed
 * coordinates).  With t = 1 - s = (1-b)/2 the factor Q_p = t^p P_p(a) is a
 * polynomial in (r,s): multiplying Bonnet's Legendre recurrence by t^{p+1}
 * with u = t a = 2r - 1 + s gives
 *   (p+1) Q_{p+1} = (2p+1) u Q_p - p t^2 Q_{p-1},   Q_0 = 1, Q_1 = u,
 * which has no division by 1 - s, so values and derivatives are exact up to
 * and including the collapsed vertex s = 1.
 * Normalisation: int_T phi_pq^2 = 1/((2p+1)(2p+2q+2)) / c_pq^2 = 1 on T of
 * area 1/2, hence c_pq = sqrt(2 (2p+1)(p+q+1)). */
#include "tri_basis.h"

#include "tri_nodes.h"

#include <math.h>

void sem_tri_dubiner(int P, double r, double s, double *phi, double *dr, double *ds)
{
    if (P < 0) return;
    const double u = 2.0 * r - 1.0 + s; /* du/dr = 2, du/ds = 1 */
    const double t = 1.0 - s;           /* dt/ds = -1 */
    const double b = 2.0 * s - 1.0;     /* db/ds = 2 */

    /* Q_{p-1} and Q_p with their r and s derivatives. */
    double qm = 0.0, qmr = 0.0, qms = 0.0;
    double q = 1.0, qr = 0.0, qs = 0.0;
    for (int p = 0; p <= P; ++p) {
        if (p > 0) {
            /* Advance Q_{p-1} -> Q_p with k = p-1 in the recurrence. */
            const int k = p - 1;
            const double A = (2.0 * k + 1.0) / (k + 1.0), C = (double)k / (k + 1.0);
            const double qn = A * u * q - C * t * t * qm;
            const double qnr = A * (2.0 * q + u * qr) - C * t * t * qmr;
            const double qns = A * (q + u * qs) - C * (t * t * qms - 2.0 * t * qm);
            qm = q;
            qmr = qr;
            qms = qs;
            q = qn;
            qr = qnr;
            qs = qns;
        }
        /* Jacobi P_n^{(alpha,0)}(b), alpha = 2p+1, by the three-term
         * recurrence (Karniadakis & Sherwin 2005, Appendix A), and d/db. */
        const double al = 2.0 * p + 1.0;
        double j0 = 1.0, jd0 = 0.0;
        double j1 = 0.5 * (al + (al + 2.0) * b), jd1 = 0.5 * (al + 2.0);
        for (int n = 0; n + p <= P; ++n) {
            double jv, jd;
            if (n == 0) {
                jv = j0;
                jd = jd0;
            } else if (n == 1) {
                jv = j1;
                jd = jd1;
            } else {
                const int k = n - 1; /* P_{k+1} from P_k, P_{k-1} */
                const double k2a = 2.0 * k + al;
                const double a1 = 2.0 * (k + 1) * (k + al + 1.0) * k2a;
                const double a2 = (k2a + 1.0) * al * al;
                const double a3 = (k2a + 1.0) * (k2a + 2.0) * k2a;
                const double a4 = 2.0 * (k + al) * k * (k2a + 2.0);
                jv = ((a2 + a3 * b) * j1 - a4 * j0) / a1;
                jd = (a3 * j1 + (a2 + a3 * b) * jd1 - a4 * jd0) / a1;
                j0 = j1;
                jd0 = jd1;
                j1 = jv;
                jd1 = jd;
            }
            const double c = sqrt(2.0 * al * (p + n + 1.0));
            const int m = sem_tri_node_index(P, p, n);
            if (phi) phi[m] = c * q * jv;
            if (dr) dr[m] = c * qr * jv;
            if (ds) ds[m] = c * (qs * jv + q * 2.0 * jd);
        }
    }
}
