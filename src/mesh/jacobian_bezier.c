/* semquad — bounds of det J of a curved quad by its Bézier coefficients and
 * adaptive de Casteljau subdivision (jacobian_bezier.h; Johnen, Remacle &
 * Geuzaine 2013). */
#include "jacobian_bezier.h"

#include "lib_lock.h"

#include <float.h>
#include <lapacke.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#define MAXQ 10
#define MAXN (2 * MAXQ) /* coefficients per direction of det J: 2Q */

/* A sub-patch [u0, u0+h] x [v0, v0+h] and its coefficients pool[slot]. */
typedef struct {
    double u0, v0, h;
    double lo, hi; /* least and largest coefficient */
    int depth, slot;
} patch;

struct sq_jac_bezier {
    int order;
    double to_bern[(MAXQ + 1) * (MAXQ + 1)]; /* Lagrange -> Bernstein, row i: coefficient i */
    double binom[MAXN][MAXN];                /* C(n, k), n < 2Q */
    double lebesgue;                         /* max_i sum_a |to_bern[i][a]| */
    int npatch, cap;                         /* sub-patches made, room for */
    patch *patches;
    double *pool;                /* cap * (2Q)^2 coefficients */
    double half[2][MAXN * MAXN]; /* the two halves of a cut in u */
};

double sq_jac_ratio(const sq_jac_bounds *b)
{
    double den = fmax(b->max_up, -b->min_lo);
    return den > 0.0 ? b->min_lo / den : -1.0;
}

int sq_jac_valid(const sq_jac_bounds *b) { return b->min_lo > b->roundoff; }

/* Bernstein polynomial b_{k,n}(t) = C(n,k) t^k (1-t)^(n-k). */
static double bernstein(const sq_jac_bezier *jb, int n, int k, double t)
{
    return jb->binom[n][k] * pow(t, k) * pow(1.0 - t, n - k);
}

/* to_bern = B^{-1}, B[a][k] = b_{k,Q}(t_a) at the element's node
 * parameters: x_a = sum_k c_k b_k(t_a) for the Bernstein coefficients c. */
static sq_status lagrange_to_bernstein(sq_jac_bezier *jb, const sq_quad_basis *b, sq_error *err)
{
    int n = jb->order + 1;
    lapack_int ipiv[MAXQ + 1];
    for (int a = 0; a < n; a++)
        for (int k = 0; k < n; k++)
            jb->to_bern[a * n + k] = bernstein(jb, n - 1, k, b->t[a]);
    sem_lib_lock();
    lapack_int info = LAPACKE_dgetrf(LAPACK_ROW_MAJOR, n, n, jb->to_bern, n, ipiv);
    if (info == 0) info = LAPACKE_dgetri(LAPACK_ROW_MAJOR, n, jb->to_bern, n, ipiv);
    sem_lib_unlock();
    if (info != 0)
        return SQ_FAIL(err, SQ_ERR_INTERNAL, "Bernstein collocation matrix of order %d singular",
                       jb->order);
    for (int i = 0; i < n; i++) {
        double row = 0.0;
        for (int a = 0; a < n; a++)
            row += fabs(jb->to_bern[i * n + a]);
        jb->lebesgue = fmax(jb->lebesgue, row);
    }
    return SQ_OK;
}

sq_status sq_jac_bezier_create(int order, sq_node_kind nodes, sq_jac_bezier **out, sq_error *err)
{
    *out = NULL;
    if (order < 1 || order > MAXQ)
        return SQ_FAIL(err, SQ_ERR_USAGE, "Jacobian bounds of order %d: expects 1..%d", order,
                       MAXQ);
    sq_quad_basis b;
    SQ_TRY(sq_quad_basis_init(&b, order, nodes, err));
    sq_jac_bezier *jb = calloc(1, sizeof *jb);
    if (!jb) return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    jb->order = order;
    for (int n = 0; n < MAXN; n++) {
        jb->binom[n][0] = 1.0;
        for (int k = 1; k <= n; k++)
            jb->binom[n][k] = jb->binom[n - 1][k - 1] + (k < n ? jb->binom[n - 1][k] : 0.0);
    }
    sq_status st = lagrange_to_bernstein(jb, &b, err);
    if (st != SQ_OK) {
        free(jb);
        return st;
    }
    *out = jb;
    return SQ_OK;
}

void sq_jac_bezier_free(sq_jac_bezier **jb)
{
    if (!jb || !*jb) return;
    free((*jb)->patches);
    free((*jb)->pool);
    free(*jb);
    *jb = NULL;
}

/* Bernstein coefficients X[j (Q+1) + i] of one coordinate (comp 0: x, 1: y)
 * of the quad relative to its first node: X = T (x - x_0) T^t, T =
 * to_bern, x the nodal values.  The Bernstein functions sum to one, so the
 * shift changes no derivative; it keeps the round-off of the sums, whose
 * terms T grows (sum_a |T_ia| up to 3.6e3 at Q = 10 equispaced, 7.7e2
 * GLL), relative to the element's size rather than to its distance from
 * the origin. */
static void bernstein_of(const sq_jac_bezier *jb, const double *xy, const int *node, int comp,
                         double *X, double *dist)
{
    int n = jb->order + 1;
    double t[(MAXQ + 1) * (MAXQ + 1)], x0 = xy[2 * (size_t)node[0] + comp];
    for (int b = 0; b < n; b++) /* t[b][i] = sum_a T[i][a] x[a][b], along u */
        for (int i = 0; i < n; i++) {
            double s = 0.0;
            for (int a = 0; a < n; a++) {
                double x = xy[2 * (size_t)node[b * n + a] + comp] - x0;
                *dist = fmax(*dist, fabs(x));
                s += jb->to_bern[i * n + a] * x;
            }
            t[b * n + i] = s;
        }
    for (int j = 0; j < n; j++) /* along v */
        for (int i = 0; i < n; i++) {
            double s = 0.0;
            for (int b = 0; b < n; b++)
                s += jb->to_bern[j * n + b] * t[b * n + i];
            X[j * n + i] = s;
        }
}

/* Scaled Bernstein coefficients of a first derivative of X (degree Q in
 * both directions): along u (du = 1) the derivative has degree (Q-1, Q)
 * and coefficients Q (X_{i+1,j} - X_{ij}); along v, (Q, Q-1).  Each is
 * multiplied by C(mu, i) C(mv, j), its degrees' binomials, for the product
 * rule of scaled_product.  F is (mu+1) x (mv+1), i fastest. */
static void scaled_derivative(const sq_jac_bezier *jb, const double *X, int du, double *F,
                              double *fmax_abs)
{
    int Q = jb->order, n = Q + 1, mu = Q - du, mv = Q - (1 - du);
    for (int j = 0; j <= mv; j++)
        for (int i = 0; i <= mu; i++) {
            double d = Q * (X[(j + 1 - du) * n + i + du] - X[j * n + i]);
            *fmax_abs = fmax(*fmax_abs, fabs(d));
            F[j * (mu + 1) + i] = d * jb->binom[mu][i] * jb->binom[mv][j];
        }
}

/* H += sign * F G for scaled coefficients F (degrees fu, fv) and G (gu,
 * gv): the product of two Bernstein polynomials has the coefficients
 * sum_{i+k=p, j+l=q} C(fu,i) C(fv,j) f_ij C(gu,k) C(gv,l) g_kl
 *   / (C(fu+gu,p) C(fv+gv,q))
 * (Johnen 2013 §3; Farin, "Curves and surfaces for CAGD", §5.7); the
 * binomials of F and G are in the scaled values, the division is done
 * once by the caller.  H has N = fu+gu+1 columns. */
static void scaled_product(const double *F, int fu, int fv, const double *G, int gu, int gv,
                           double sign, double *H)
{
    int N = fu + gu + 1;
    for (int j = 0; j <= fv; j++)
        for (int i = 0; i <= fu; i++) {
            double f = sign * F[j * (fu + 1) + i];
            for (int l = 0; l <= gv; l++)
                for (int k = 0; k <= gu; k++)
                    H[(j + l) * N + i + k] += f * G[l * (gu + 1) + k];
        }
}

/* A first-order bound of the round-off of every coefficient of det J and
 * of its sub-patches (Higham, "Accuracy and stability of numerical
 * algorithms", §3.1, γ_k ≈ kU): the Bernstein coefficients of x, y are
 * nested sums of Q+1 terms each, |δX| <= (2Q+3) U Λ^2 d, Λ = max_i
 * sum_a |T_ia|, d the largest |x - x_0|; a derivative's coefficients
 * Q (X_{i+1} - X_i) then err by 2Q (2Q+3) U Λ^2 d; the products are
 * convex combinations (their weights sum to one) of at most Q^2 (Q+1)^2
 * products of coefficients bounded by F, so det J's coefficients err by
 * 4 F times that, plus (4 Q (Q+1) + 28) U F^2 for the sums, scalings and
 * divisions, plus 2 (2Q) U F^2 per de Casteljau level (convex
 * combinations of coefficients <= 2 F^2). */
static double roundoff(const sq_jac_bezier *jb, double d, double F)
{
    const double U = 0.5 * DBL_EPSILON;
    int Q = jb->order;
    double lam2 = jb->lebesgue * jb->lebesgue;
    return U * F *
           (8.0 * Q * (2 * Q + 3) * lam2 * d +
            (4.0 * Q * (Q + 1) + 28 + 4.0 * Q * SQ_JAC_MAX_DEPTH) * F);
}

double sq_jac_bezier_coefficients(const sq_jac_bezier *jb, const double *xy, const int *node,
                                  double *c)
{
    int Q = jb->order, N = 2 * Q;
    double X[(MAXQ + 1) * (MAXQ + 1)], Y[(MAXQ + 1) * (MAXQ + 1)];
    double xu[MAXQ * (MAXQ + 1)], xv[MAXQ * (MAXQ + 1)], yu[MAXQ * (MAXQ + 1)],
        yv[MAXQ * (MAXQ + 1)];
    double d = 0.0, F = 0.0;
    bernstein_of(jb, xy, node, 0, X, &d);
    bernstein_of(jb, xy, node, 1, Y, &d);
    scaled_derivative(jb, X, 1, xu, &F);
    scaled_derivative(jb, X, 0, xv, &F);
    scaled_derivative(jb, Y, 1, yu, &F);
    scaled_derivative(jb, Y, 0, yv, &F);
    memset(c, 0, sizeof(double) * (size_t)(N * N));
    /* det J = x_u y_v - x_v y_u: (Q-1, Q) times (Q, Q-1), and (Q, Q-1)
     * times (Q-1, Q), both of degree (2Q-1, 2Q-1) */
    scaled_product(xu, Q - 1, Q, yv, Q, Q - 1, 1.0, c);
    scaled_product(xv, Q, Q - 1, yu, Q - 1, Q, -1.0, c);
    for (int q = 0; q < N; q++)
        for (int p = 0; p < N; p++)
            c[q * N + p] /= jb->binom[N - 1][p] * jb->binom[N - 1][q];
    return roundoff(jb, d, F);
}

/* de Casteljau at t = 1/2 of the n+1 coefficients c[k * s]: the halves'
 * coefficients into lo[k * s] and hi[k * s] (Johnen 2013 §4). */
static void split_half(const double *c, int n, int s, double *lo, double *hi)
{
    double w[MAXN] = {0};
    for (int k = 0; k <= n; k++)
        w[k] = c[k * s];
    lo[0] = w[0];
    hi[n * s] = w[n];
    for (int r = 1; r <= n; r++) {
        for (int k = 0; k <= n - r; k++)
            w[k] = 0.5 * (w[k] + w[k + 1]);
        lo[r * s] = w[0];
        hi[(n - r) * s] = w[n - r];
    }
}

static double *coeffs(sq_jac_bezier *jb, int slot)
{
    size_t N = 2 * (size_t)jb->order;
    return &jb->pool[(size_t)slot * N * N];
}

/* A new sub-patch (its coefficients already in pool[slot]): its bounds, and
 * its corner coefficients, the values of det J there, into the sampled
 * extremes of b. */
static void add_patch(sq_jac_bezier *jb, int slot, double u0, double v0, double h, int depth,
                      sq_jac_bounds *b)
{
    int N = 2 * jb->order, n = N - 1;
    const double *c = coeffs(jb, slot);
    patch *p = &jb->patches[slot];
    p->u0 = u0, p->v0 = v0, p->h = h, p->depth = depth, p->slot = slot;
    p->lo = p->hi = c[0];
    for (int k = 1; k < N * N; k++)
        p->lo = fmin(p->lo, c[k]), p->hi = fmax(p->hi, c[k]);
    const int corner[4][2] = {{0, 0}, {1, 0}, {0, 1}, {1, 1}};
    for (int k = 0; k < 4; k++) {
        double v = c[corner[k][1] * n * N + corner[k][0] * n];
        if (v < b->min_up)
            b->min_up = v, b->u_min = u0 + corner[k][0] * h, b->v_min = v0 + corner[k][1] * h;
        b->max_lo = fmax(b->max_lo, v);
    }
}

/* Room for `more` sub-patches. */
static sq_status reserve(sq_jac_bezier *jb, int more, sq_error *err)
{
    if (jb->npatch + more <= jb->cap) return SQ_OK;
    int cap = jb->cap ? 2 * jb->cap : 16;
    while (cap < jb->npatch + more)
        cap *= 2;
    size_t N = 2 * (size_t)jb->order;
    patch *p = realloc(jb->patches, (size_t)cap * sizeof *p);
    if (p) jb->patches = p;
    double *pool = p ? realloc(jb->pool, (size_t)cap * N * N * sizeof *pool) : NULL;
    if (!pool) return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    jb->pool = pool;
    jb->cap = cap;
    return SQ_OK;
}

/* Cut sub-patch k in four: its slot takes the lower left quarter, three new
 * slots the others. */
static sq_status cut(sq_jac_bezier *jb, int k, sq_jac_bounds *b, sq_error *err)
{
    SQ_TRY(reserve(jb, 3, err));
    int N = 2 * jb->order, n = N - 1;
    patch p = jb->patches[k];
    const double *c = coeffs(jb, k);
    double *L = jb->half[0], *R = jb->half[1];
    for (int j = 0; j < N; j++)
        split_half(&c[j * N], n, 1, &L[j * N], &R[j * N]);
    int slot[4] = {k, jb->npatch, jb->npatch + 1,
                   jb->npatch + 2}; /* (u, v): lo-lo, hi-lo, lo-hi, hi-hi */
    jb->npatch += 3;
    for (int i = 0; i < N; i++) {
        split_half(&L[i], n, N, &coeffs(jb, slot[0])[i], &coeffs(jb, slot[2])[i]);
        split_half(&R[i], n, N, &coeffs(jb, slot[1])[i], &coeffs(jb, slot[3])[i]);
    }
    double h = 0.5 * p.h;
    for (int s = 0; s < 4; s++)
        add_patch(jb, slot[s], p.u0 + (s & 1) * h, p.v0 + (s >> 1) * h, h, p.depth + 1, b);
    return SQ_OK;
}

sq_status sq_jac_bezier_bounds(sq_jac_bezier *jb, const double *xy, const int *node,
                               sq_jac_bounds *b, sq_error *err)
{
    jb->npatch = 0;
    SQ_TRY(reserve(jb, 1, err));
    jb->npatch = 1;
    b->roundoff = sq_jac_bezier_coefficients(jb, xy, node, coeffs(jb, 0));
    b->min_up = HUGE_VAL;
    b->max_lo = -HUGE_VAL;
    b->splits = b->capped = 0;
    add_patch(jb, 0, 0.0, 0.0, 1.0, 0, b);
    for (;;) {
        int a = 0, z = 0; /* the sub-patches with the least and the largest coefficient */
        for (int k = 1; k < jb->npatch; k++) {
            if (jb->patches[k].lo < jb->patches[a].lo) a = k;
            if (jb->patches[k].hi > jb->patches[z].hi) z = k;
        }
        b->min_lo = jb->patches[a].lo;
        b->max_up = jb->patches[z].hi;
        /* no sharper than the round-off of the coefficients */
        double tol = fmax(SQ_JAC_TOL * fmax(fabs(b->min_up), fabs(b->max_lo)), 2.0 * b->roundoff);
        int min_ok =
            (b->min_lo > b->roundoff || b->min_up <= b->roundoff) && b->min_up - b->min_lo <= tol;
        int max_ok = b->max_up - b->max_lo <= tol;
        if (min_ok && max_ok) break;
        int k = min_ok ? z : a;
        if (jb->patches[k].depth >= SQ_JAC_MAX_DEPTH || b->splits >= SQ_JAC_MAX_SPLITS) {
            b->capped = 1;
            break;
        }
        SQ_TRY(cut(jb, k, b, err));
        b->splits++;
    }
    return SQ_OK;
}
