/* semquad — start directions of the separatrices (Marcon 2019 §3.3,
 * Algorithm 1): at singular points (V rays, guesses 2π/V apart) and at face
 * vertices taking n >= 2 quads (n - 1 rays into the face, guesses Δθ/n
 * apart from the outgoing edge). */
#include "trace_private.h"

#include "critical_points.h"

#include <math.h>
#include <stddef.h>

#define HALF_PI 1.57079632679489661923

sq_status sq_trace_start_direction(const sq_cross_field *field, const double p0[2], double c,
                                   double alpha0, double gain, double tol, double *alpha,
                                   sq_error *err)
{
    if (!(c > 0.0)) return SQ_FAIL(err, SQ_ERR_USAGE, "Algorithm 1 radius %g must be > 0", c);
    double a = alpha0, d = HUGE_VAL, dprev[2] = {HUGE_VAL, HUGE_VAL};
    int elem = -1;
    /* fixed-point iteration: at the ray's point at distance c, take the
     * branch psi' nearest to the ray's direction and turn the ray towards
     * it.  Near a valence-V point psi turns k = (4 - V)/4 as fast as the
     * ray, so the paper's full turn (gain 1) shrinks the error by |k| per
     * pass: fourfold at V = 3 and 5, not at all at V = 8 (a two-cycle
     * around the answer); turned by gain = 1/(1 - k) = 4/V, a pass lands
     * on the answer where psi is linear in the angle */
    for (int it = 0; it < 500; it++) {
        double p1[2] = {p0[0] + c * cos(a), p0[1] + c * sin(a)}, th;
        if (sq_trace_eval(field, p1, 1e3 * c, &elem, &th))
            return SQ_FAIL(err, SQ_ERR_INTERNAL,
                           "Algorithm 1 at (%.9g, %.9g): the ray at angle %.6f, radius %g leaves "
                           "the face",
                           p0[0], p0[1], a, c);
        double ap = th + HALF_PI * nearbyint((a - th) / HALF_PI);
        d = ap - a;
        a += gain * d;
        if (fabs(d) <= tol) {
            *alpha = a;
            return SQ_OK;
        }
        /* far from converged and no smaller than two passes ago (where the
         * iteration converges it has contracted well before pass 20): it
         * does not contract (a corner with a jump of the data, where it
         * settles on a two-cycle); stop rather than run out the passes */
        if (it >= 20 && fabs(d) > 1e3 * tol && fabs(d) >= fabs(dprev[1])) break;
        dprev[1] = dprev[0];
        dprev[0] = d;
    }
    return SQ_FAIL(err, SQ_ERR_INTERNAL,
                   "Algorithm 1 at (%.9g, %.9g) did not converge from %.6f (last change %.3g)",
                   p0[0], p0[1], alpha0, d);
}

static double mod2pi(double a)
{
    return a - 2.0 * M_PI * floor(a / (2.0 * M_PI));
}

/* smallest angular distance between two directions */
static double angdist(double a, double b)
{
    double d = mod2pi(a - b);
    return d > M_PI ? 2.0 * M_PI - d : d;
}

/* Mismatch between the ray at angle a and the cross at its point at
 * distance c, in (-π/4, π/4]. */
static int mismatch(const sq_cross_field *field, const double p0[2], double c, double a, int *elem,
                    double *m)
{
    double p1[2] = {p0[0] + c * cos(a), p0[1] + c * sin(a)}, th;
    if (sq_trace_eval(field, p1, 1e3 * c, elem, &th)) return 1;
    double d = th - a;
    *m = d - HALF_PI * nearbyint(d / HALF_PI);
    return 0;
}

/* Fallback to Algorithm 1 where its fixed-point iteration does not
 * contract (corners with a jump of the data): the rays in (a0, a1) along
 * which the mismatch falls through zero, each bisected to tol.  Returns
 * the count (at most maxn) in *n. */
static sq_status scan_roots(const sq_cross_field *field, const double p0[2], double c, double a0,
                            double a1, int nsamp, double tol, double *roots, int maxn, int *n,
                            sq_error *err)
{
    int elem = -1;
    double prev = 0.0, pa = 0.0;
    *n = 0;
    for (int i = 0; i <= nsamp; i++) {
        double a = a0 + (a1 - a0) * (i + 0.5) / (nsamp + 1), m;
        if (mismatch(field, p0, c, a, &elem, &m))
            return SQ_FAIL(err, SQ_ERR_INTERNAL,
                           "start directions at (%.9g, %.9g): the ray at angle %.6f, radius %g "
                           "leaves the face",
                           p0[0], p0[1], a, c);
        /* a fall through zero (not a wrap of the branch, which jumps up) */
        if (i > 0 && prev > 0.0 && m <= 0.0 && prev - m < 0.25 * M_PI) {
            double lo = pa, hi = a;
            for (int it = 0; it < 200 && hi - lo > tol; it++) {
                double mid = 0.5 * (lo + hi), mm;
                if (mismatch(field, p0, c, mid, &elem, &mm))
                    return SQ_FAIL(err, SQ_ERR_INTERNAL, "ray leaves the face at (%.9g, %.9g)",
                                   p0[0], p0[1]);
                if (mm > 0.0)
                    lo = mid;
                else
                    hi = mid;
            }
            if (*n < maxn) roots[*n] = 0.5 * (lo + hi);
            (*n)++;
        }
        prev = m;
        pa = a;
    }
    return SQ_OK;
}

/* The V start directions at a singular point by Algorithm 1 at radius c
 * (guesses 2π/V apart from the first); 0 if an iteration fails. */
static int singular_iterate(const sq_tracer *tr, const double p0[2], int V, double c,
                            double *alpha)
{
    const double gain = V > 0 ? 4.0 / V : 1.0;
    sq_error e2;
    if (sq_trace_start_direction(tr->field, p0, c, 0.0, gain, tr->opt.tol, &alpha[0], &e2))
        return 0;
    for (int k = 1; k < V; k++)
        if (sq_trace_start_direction(tr->field, p0, c, alpha[0] + 2.0 * M_PI * k / V, gain,
                                     tr->opt.tol, &alpha[k], &e2))
            return 0;
    return 1;
}

/* Fallback: the rays around the point along which the mismatch falls
 * through zero (near a valence-V point it falls by V/4 per radian, V times
 * around), the V most nearly 2π/V apart from the first. */
static sq_status singular_scan(const sq_tracer *tr, int j, const double p0[2], int V, double c,
                               double *alpha, sq_error *err)
{
    double roots[64];
    int nr;
    SQ_TRY(scan_roots(tr->field, p0, c, 0.0, 2.0 * M_PI, 64 * V, tr->opt.tol, roots, 64, &nr,
                      err));
    if (nr > 64) nr = 64;
    if (nr < V)
        return SQ_FAIL(err, SQ_ERR_INTERNAL,
                       "singular point %d (valence %d) at (%.9g, %.9g): Algorithm 1 does not "
                       "converge and the field has %d separatrix directions around it",
                       j, V, p0[0], p0[1], nr);
    alpha[0] = roots[0];
    roots[0] = NAN;
    for (int k = 1; k < V; k++) {
        int best = -1;
        double bd = HUGE_VAL;
        for (int r = 0; r < nr; r++) {
            double d = angdist(roots[r], alpha[0] + 2.0 * M_PI * k / V);
            if (roots[r] == roots[r] && d < bd) bd = d, best = r;
        }
        alpha[k] = roots[best];
        roots[best] = NAN;
    }
    return SQ_OK;
}

sq_status sq_trace_singular_starts(const sq_tracer *tr, int j, double *alpha, double *h0,
                                   sq_error *err)
{
    const sq_singularity *s = &tr->sing[j];
    int V = s->valence;
    double p0[2] = {s->x, s->y}, th;
    int elem = -1;
    if (tr->field->direction(tr->field->ctx, p0, &elem, &th))
        return SQ_FAIL(err, SQ_ERR_INTERNAL, "singular point %d at (%.9g, %.9g) is outside the face",
                       j, p0[0], p0[1]);
    /* Algorithm 1's radius c: the first step, so the first point lands where
     * the ray and the cross agree (§3.3: "based on the size of the elements"),
     * and at most half the way to the boundary (naca0012's natural pattern on
     * the H/θ field: valence-5 points 0.015 from the leading edge in
     * elements 0.02 across) */
    double c = sq_tracer_step_at(tr, elem), dist;
    SQ_TRY(sq_face_boundary_distance(tr->face, p0, &dist, err));
    if (c > 0.5 * dist) c = 0.5 * dist;
    *h0 = c;
    /* Algorithm 1 at c, then at c/2 and c/4 (another singular point or a
     * curved boundary within c bends the field off linear in the angle,
     * where the iteration may not contract), then the root scan around
     * the point */
    int ok = 0;
    for (int pass = 0; pass < 3 && !ok; pass++, c *= 0.5)
        ok = singular_iterate(tr, p0, V, c, alpha);
    if (!ok) SQ_TRY(singular_scan(tr, j, p0, V, 4.0 * c, alpha, err));
    for (int k = 0; k < V; k++) {
        alpha[k] = mod2pi(alpha[k]);
        for (int q = 0; q < k; q++)
            if (angdist(alpha[k], alpha[q]) < 0.25 * M_PI / V)
                return SQ_FAIL(err, SQ_ERR_INTERNAL,
                               "singular point %d (valence %d) at (%.9g, %.9g): start directions "
                               "%d and %d coincide (%.6f)",
                               j, V, p0[0], p0[1], q, k, alpha[k]);
    }
    return SQ_OK;
}

sq_status sq_trace_corner_starts(const sq_tracer *tr, int k, int n, double *alpha, double *h0,
                                 sq_error *err)
{
    const sq_vertex *v = &tr->info->vertices[k];
    double t[2], p0[2] = {v->x, v->y};
    SQ_TRY(cad_face_edge_eval(tr->face, v->edge_out, 0.0, NULL, t, NULL, err));
    double beta = atan2(t[1], t[0]), dth = v->angle_deg * M_PI / 180.0;
    /* element near the vertex along the bisector, for the step size */
    double bis = beta + 0.5 * dth, q[2] = {p0[0] + 1e-6 * tr->scale * cos(bis),
                                           p0[1] + 1e-6 * tr->scale * sin(bis)}, th;
    int elem = -1;
    if (tr->field->direction(tr->field->ctx, q, &elem, &th)) elem = -1;
    double c = sq_tracer_step_at(tr, elem);
    *h0 = c;
    /* Algorithm 1 from guesses Δθ/n apart, counter-clockwise from the
     * outgoing edge (the face lies on its left; §3.3, boundary vertices) */
    int ok = 1;
    for (int j = 1; j < n && ok; j++) {
        double a;
        sq_error e2;
        if (sq_trace_start_direction(tr->field, p0, c, beta + dth * j / n, 1.0, tr->opt.tol, &a,
                                     &e2)) {
            ok = 0;
            break;
        }
        double rel = mod2pi(a - beta);
        if (!(rel > 1e-6 && rel < dth - 1e-6)) ok = 0;
        alpha[j - 1] = beta + rel;
        for (int q2 = 0; q2 < j - 1 && ok; q2++)
            if (fabs(alpha[j - 1] - alpha[q2]) < 0.25 * dth / n) ok = 0;
    }
    if (ok) return SQ_OK;
    /* the iteration does not contract at this corner: bracket and bisect */
    double roots[64];
    int nr;
    SQ_TRY(scan_roots(tr->field, p0, c, beta, beta + dth, 64 * n, tr->opt.tol, roots, 64, &nr,
                      err));
    if (nr > 64) nr = 64;
    if (nr < n - 1)
        return SQ_FAIL(err, SQ_ERR_INTERNAL,
                       "corner %d at (%.9g, %.9g), %.3f deg, %d quads: the field has %d "
                       "separatrix directions into the face, %d expected",
                       k, p0[0], p0[1], v->angle_deg, n, nr, n - 1);
    /* more than needed: the ones nearest to the guesses */
    for (int j = 1; j < n; j++) {
        int best = -1;
        double bd = HUGE_VAL;
        for (int r = 0; r < nr; r++) {
            double d = fabs(roots[r] - (beta + dth * j / n));
            if (roots[r] == roots[r] && d < bd) bd = d, best = r;
        }
        alpha[j - 1] = roots[best];
        roots[best] = NAN;
    }
    return SQ_OK;
}
