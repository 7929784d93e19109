/* semquad sem/ — the C0 boundary/interior modal basis of order P on the
 * reference triangle, in collapsed coordinates (Karniadakis & Sherwin 2005,
 * §3.2.3): with xi = (2r-1, 2s-1), a = 2(1+xi1)/(1-xi2) - 1, b = xi2,
 *   vertex modes  v0: (1-a)/2 (1-b)/2,  v1: (1+a)/2 (1-b)/2,  v2: (1+b)/2;
 *   edge modes p = 1..P-1, restricted to their edge the function
 *     f_p(t) = (1-t)/2 (1+t)/2 P_{p-1}^{(1,1)}(t),
 *     t from -1 at local vertex k to +1 at vertex k+1 (the edge direction):
 *     edge 0: (1-a)/2 (1+a)/2 P_{p-1}^{(1,1)}(a) ((1-b)/2)^{p+1},
 *     edge 1: (1+a)/2 (1-b)/2 (1+b)/2 P_{p-1}^{(1,1)}(b),
 *     edge 2: (1-a)/2 (1-b)/2 (1+b)/2 P_{p-1}^{(1,1)}(-b);
 *   interior modes p, q >= 1, p+q <= P-1:
 *     (1-a)/2 (1+a)/2 P_{p-1}^{(1,1)}(a) ((1-b)/2)^{p+1} (1+b)/2 P_{q-1}^{(2p+1,1)}(b).
 * Vertex and edge modes vanish on the other edges, interior modes on the
 * whole boundary, so the basis is C0-conforming once the odd edge modes
 * (f_p(-t) = (-1)^(p-1) f_p(t)) are signed by the edge's global direction.
 *
 * Local numbering: vertex k -> k; edge k mode p -> 3 + k(P-1) + p-1
 * (nb = 3P boundary modes first); interior modes after (pairs (p,q),
 * p outer, q inner).  nloc = (P+1)(P+2)/2.
 *
 * Every mode is a polynomial of degree <= P, so it is also a combination of
 * the orthonormal Dubiner modes (tri_basis.h): psi_i = sum_m C[i][m] phi_m,
 * C[i][m] = ∫_T psi_i phi_m (exact quadrature).  Derivatives and the
 * conversion of a CG solution to the Dubiner storage of sem_field go
 * through C. */
#ifndef SEM_CG_BASIS_H
#define SEM_CG_BASIS_H

#include "sq_status.h"

typedef struct {
    int P;
    int nloc; /* (P+1)(P+2)/2 */
    int nb;   /* 3P boundary modes */
    int ni;   /* (P-1)(P-2)/2 interior modes */
    double *C; /* nloc x nloc, row-major: C[i*nloc + m] */
} sem_cg_basis;

sq_status sem_cg_basis_create(int P, sem_cg_basis **out, sq_error *err);
void sem_cg_basis_free(sem_cg_basis **b); /* NULL-safe, NULLs *b */

/* Values of all nloc modes at (r,s), from the collapsed-coordinate formulas
 * (no derivatives; exact at the collapsed vertex s = 1 too). */
void sem_cg_basis_eval_collapsed(int P, double r, double s, double *psi);

/* Values and reference derivatives (any may be NULL) of all modes at (r,s)
 * through C.  No allocation. */
void sem_cg_basis_eval(const sem_cg_basis *b, double r, double s, double *psi, double *dr,
                       double *ds);

/* Local index of edge mode p (1..P-1) of local edge k, and the sign that
 * makes it match the neighbour's: +1 if the edge is walked from its lower
 * to its higher global vertex, else (-1)^(p-1). */
static inline int sem_cg_edge_mode(int P, int k, int p) { return 3 + k * (P - 1) + p - 1; }
static inline int sem_cg_edge_sign(int p, int forward) { return forward || (p & 1) ? 1 : -1; }

#endif
