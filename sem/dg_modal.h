/* semquad sem/ — fast modal (Dubiner) tabulation and modal geometry.
 *
 * sem_tri_dubiner() recomputes its normalisation constants (square roots)
 * and Jacobi recurrence coefficients at every call.  The hot paths (point
 * location, evaluation at a point, DG assembly) tabulate the same order
 * millions of times, so the constants are computed once into a plain table
 * and the evaluation is only the two recurrences (Dubiner 1991; Karniadakis
 * & Sherwin 2005, Appendix A), with the same mode numbering and values as
 * tri_basis.h.
 *
 * The geometry map x(r,s) = sum_n g_n l_n(r,s) (tri_mesh.h) is a polynomial
 * of degree `order`: its Dubiner coefficients ghat_m = int_T x phi_m (exact
 * by a rule of degree 2*order) let x and J be evaluated with the same cheap
 * recurrence instead of the Lagrange basis (an n x n product). */
#ifndef SEM_DG_MODAL_H
#define SEM_DG_MODAL_H

#include "gauss.h"
#include "sq_status.h"
#include "tri_mesh.h"

#define SEM_MAX_MODES ((SEM_MAX_ORDER + 1) * (SEM_MAX_ORDER + 2) / 2)

typedef struct {
    int P;
    int nmodes;
    double c[SEM_MAX_ORDER + 1][SEM_MAX_ORDER + 1];  /* c_pq = sqrt(2(2p+1)(p+q+1)) */
    double ja[SEM_MAX_ORDER + 1][SEM_MAX_ORDER + 1]; /* Jacobi recurrence, alpha = 2p+1: */
    double jb[SEM_MAX_ORDER + 1][SEM_MAX_ORDER + 1]; /* P_{k+1} = (ja + jb b) P_k - jc P_{k-1} */
    double jc[SEM_MAX_ORDER + 1][SEM_MAX_ORDER + 1];
} sem_dubiner_tab;

/* Fill the table for order P (0..SEM_MAX_ORDER; clamped). No allocation. */
void sem_dubiner_tab_init(sem_dubiner_tab *T, int P);

/* Values and reference derivatives of all modes at (r,s), numbered as in
 * tri_basis.h; dr and ds may both be NULL (values only). */
void sem_dubiner_tab_eval(const sem_dubiner_tab *T, double r, double s, double *phi, double *dr,
                          double *ds);

/* Dubiner coefficients of the geometry map of every element:
 * out[((size_t)e * nmodes + m) * 2 + c], nmodes = modes of mesh->order.
 * Caller frees with free(). */
sq_status sem_modal_geometry(const sem_tri_mesh *mesh, double **out, sq_error *err);

/* x (may be NULL) and J = {x_r, x_s, y_r, y_s} (may be NULL) from the
 * modal geometry gm (2*nmodes, interleaved) and tabulated modes of the
 * geometry order (phi, dr, ds of length nmodes).  Returns det J. */
static inline double sem_modal_map(int nmodes, const double *gm, const double *phi,
                                   const double *dr, const double *ds, double x[2], double jac[4])
{
    double px = 0.0, py = 0.0, xr = 0.0, xs = 0.0, yr = 0.0, ys = 0.0;
    for (int m = 0; m < nmodes; ++m) {
        const double gx = gm[2 * m], gy = gm[2 * m + 1];
        px += gx * phi[m];
        py += gy * phi[m];
        xr += gx * dr[m];
        xs += gx * ds[m];
        yr += gy * dr[m];
        ys += gy * ds[m];
    }
    if (x) {
        x[0] = px;
        x[1] = py;
    }
    if (jac) {
        jac[0] = xr;
        jac[1] = xs;
        jac[2] = yr;
        jac[3] = ys;
    }
    return xr * ys - xs * yr;
}

/* x[k], y[k] at npts points of a map with interleaved coefficients g
 * (2 nb) on nb functions tabulated function by function (t[i npts + k]):
 * each point's sums in function order, as a sum per point adds them, for
 * all points at once: independent sums that vectorise, where one point's
 * sum is a chain of dependent additions. */
static inline void sem_map_points(int nb, const double *g, const double *t, int npts,
                                  double *restrict x, double *restrict y)
{
    for (int k = 0; k < npts; ++k) x[k] = y[k] = 0.0;
    for (int i = 0; i < nb; ++i) {
        const double gx = g[2 * i], gy = g[2 * i + 1];
        const double *restrict ti = t + (size_t)i * npts;
        for (int k = 0; k < npts; ++k) {
            x[k] += gx * ti[k];
            y[k] += gy * ti[k];
        }
    }
}

#endif
