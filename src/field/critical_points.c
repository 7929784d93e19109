#include "critical_points.h"

#include "field.h"
#include "locate.h"
#include "tri_basis.h"

#include <complex.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#define NEWTON_MAX_IT 120
#define NEWTON_MAX_HOPS 32
#define FLAG_TOL 1e-6 /* |(u, v)| is 1 on the boundary */
/* Newton converges only linearly (factor (m-1)/m) to a zero of
 * multiplicity m and then wanders at the round-off floor of (u, v): an
 * iterate with |(u, v)| below STALL_RES counts as converged. */
#define STALL_RES 1e-13
/* Near a zero of multiplicity m (w ≈ c z^m) a Newton step multiplies |w|
 * by ((m-1)/m)^m: 0 for a simple zero, at most 1/e for any m.  Below
 * STALL_RES, a step that does not take |w| under STALL_GAIN x the least so
 * far gains nothing but round-off: Newton stops at that least iterate (it
 * used to wander there to NEWTON_MAX_IT, ~100 evaluations per start). */
#define STALL_GAIN 0.5
/* Roots closer than this (times the element size) are one zero: under
 * round-off a zero of multiplicity m splits into up to m roots about
 * (round-off)^(1/m) apart (1e-4 of the element size for m = 4). */
#define CLUSTER_REL 1e-2
/* Roots closer to each other than this times their distance to the
 * boundary are one singular point (a cluster). */
#define CLUSTER_BOUNDARY_REL 0.05
/* samples of (u, v) on the circle fitting a degenerate zero's expansion */
#define FIT_SAMPLES 256

sq_status sq_face_boundary_distance(const cad_face *face, const double p[2], double *dist,
                                    sq_error *err)
{
    double best = HUGE_VAL;
    for (int e = 0; e < cad_face_num_edges(face); e++) {
        double d;
        SQ_TRY(cad_face_edge_project(face, e, p, NULL, NULL, &d, err));
        if (d < best) best = d;
    }
    *dist = best;
    return SQ_OK;
}

/* Unwrapped change of atan2(v, u) from a to b, assuming it is less than π
 * in magnitude. */
static double turn(const double a[2], const double b[2])
{
    return atan2(a[0] * b[1] - a[1] * b[0], a[0] * b[0] + a[1] * b[1]);
}

sq_status sq_field_winding(const sq_guiding_field *g, const double c[2], double rho, int *index,
                           sq_error *err)
{
    for (int n = 64; n <= 8192; n *= 2) {
        double total = 0.0, first[2], prev[2], cur[2];
        int elem = -1, ok = 1;
        for (int k = 0; k <= n && ok; k++) {
            double a = 2.0 * M_PI * (k % n) / n, x[2] = {c[0] + rho * cos(a), c[1] + rho * sin(a)};
            if (sq_guiding_field_eval(g, x, &elem, cur, NULL)) {
                return SQ_FAIL(err, SQ_ERR_INTERNAL,
                               "index circle of radius %g around (%g, %g) leaves the face", rho,
                               c[0], c[1]);
            }
            if (k == 0)
                memcpy(first, cur, sizeof first);
            else {
                double d = turn(prev, cur);
                if (fabs(d) > 0.5 * M_PI) ok = 0; /* too coarse: refine */
                total += d;
            }
            memcpy(prev, cur, sizeof prev);
        }
        (void)first;
        if (ok) {
            *index = (int)lround(total / (2.0 * M_PI));
            return SQ_OK;
        }
    }
    return SQ_FAIL(err, SQ_ERR_INTERNAL, "cannot resolve the index around (%g, %g)", c[0], c[1]);
}

/* The Dubiner modes of order P at the lattice points (i/S, j/S), i + j <=
 * S, in scan order (j outer): every element is scanned at the same points. */
static double *lattice_modes(int P, int S)
{
    const int nm = (P + 1) * (P + 2) / 2, np = (S + 1) * (S + 2) / 2;
    double *phi = malloc(sizeof(double) * (size_t)nm * np), *o = phi;
    if (!phi) return NULL;
    for (int j = 0; j <= S; j++)
        for (int i = 0; i <= S - j; i++, o += nm)
            sem_tri_dubiner(P, (double)i / S, (double)j / S, o, NULL, NULL);
    return phi;
}

/* Lattice scan of element e (modes: lattice_modes): does it hold sign
 * changes of both u and v?  best[2]: the lattice point (r, s) of least
 * |(u, v)|. */
static int flag_element(const sem_field *f, int e, int S, const double *modes, double best[2])
{
    double umin = HUGE_VAL, umax = -HUGE_VAL, vmin = HUGE_VAL, vmax = -HUGE_VAL, bmin = HUGE_VAL;
    for (int j = 0; j <= S; j++)
        for (int i = 0; i <= S - j; i++, modes += f->nmodes) {
            double r = (double)i / S, s = (double)j / S, uv[2];
            sem_field_eval_modes(f, e, modes, NULL, NULL, uv, NULL, NULL);
            umin = fmin(umin, uv[0]);
            umax = fmax(umax, uv[0]);
            vmin = fmin(vmin, uv[1]);
            vmax = fmax(vmax, uv[1]);
            double m = hypot(uv[0], uv[1]);
            if (m < bmin) {
                bmin = m;
                best[0] = r;
                best[1] = s;
            }
        }
    /* A root on a mesh vertex or edge leaves only round-off (CG) or the
     * inter-element jump (DG) of sign change in some of the elements around
     * it: accept near-zero extremes. */
    return umin <= FLAG_TOL && umax >= -FLAG_TOL && vmin <= FLAG_TOL && vmax >= -FLAG_TOL;
}

/* Iterates may leave the element: the polynomial and the map extend
 * smoothly. */
int sq_field_newton_local(const sem_field *f, int e, double *r, double *s, int *evals)
{
    double best = HUGE_VAL, br = *r, bs = *s;
    for (int it = 0; it < NEWTON_MAX_IT; it++) {
        double uv[2], dr[2], ds[2];
        sem_field_eval_ref(f, e, *r, *s, uv, dr, ds);
        if (evals) ++*evals;
        double res = hypot(uv[0], uv[1]);
        if (best < STALL_RES && !(res < STALL_GAIN * best)) break;
        if (res < best) best = res, br = *r, bs = *s;
        double det = dr[0] * ds[1] - ds[0] * dr[1];
        if (det == 0.0 || !isfinite(det)) break;
        double delta_r = -(ds[1] * uv[0] - ds[0] * uv[1]) / det;
        double delta_s = -(-dr[1] * uv[0] + dr[0] * uv[1]) / det;
        double len = hypot(delta_r, delta_s);
        if (len > 0.25) { /* damp: far from the element the extension means nothing */
            delta_r *= 0.25 / len;
            delta_s *= 0.25 / len;
        }
        *r += delta_r;
        *s += delta_s;
        if (fabs(*r) > 3.0 || fabs(*s) > 3.0) return 1;
        if (len < 1e-14) return 0;
    }
    *r = br, *s = bs;
    return best < STALL_RES ? 0 : 1;
}

/* A root of element e's polynomial from (r, s); if it lies outside e, the
 * search continues in the element that holds it (a root is owned by the
 * element containing it; NekMesh drops such roots).  A DG field jumps across
 * edges, so a root within DG_MARGIN of its element (in reference units) is
 * accepted where it is.  A zero on an edge (or a vertex) of a DG field can
 * also leave every polynomial around it with its root just across, in the
 * next element: the hops then come back to an element already seen, and the
 * candidate nearest its own element, if within DG_EDGE_MARGIN, is taken,
 * moved onto that element's boundary (the equilateral triangle's centre at
 * P = 4, a mesh vertex).  Returns 0 with the owner and its (r, s). */
#define DG_MARGIN 1e-6
#define DG_EDGE_MARGIN 0.05
static int newton(const sq_guiding_field *g, int e, double r, double s, int *eo, double *ro,
                  double *so)
{
    const sem_locator *loc = sem_field_evaluator_locator(g->ev);
    int seen[NEWTON_MAX_HOPS + 1], nseen = 0, be = -1;
    double bmargin = DG_EDGE_MARGIN, br = 0.0, bs = 0.0;
    for (int hop = 0; hop <= NEWTON_MAX_HOPS; hop++) {
        seen[nseen++] = e;
        if (sq_field_newton_local(g->uv, e, &r, &s, NULL)) return 1;
        double margin = fmax(fmax(-r, -s), r + s - 1.0);
        if (margin <= DG_MARGIN) {
            double uv[2];
            sem_field_eval_ref(g->uv, e, r, s, uv, NULL, NULL);
            if (!(hypot(uv[0], uv[1]) < 1e-9)) return 1;
            *eo = e;
            *ro = r;
            *so = s;
            return 0;
        }
        if (margin < bmargin) be = e, bmargin = margin, br = r, bs = s;
        double x[2];
        int en;
        sem_locator_map(loc, e, r, s, x, NULL);
        if (sem_locator_find(loc, x, e, &en, &r, &s)) return 1; /* left the face */
        int cycle = 0;
        for (int k = 0; k < nseen && !cycle; k++)
            cycle = seen[k] == en;
        if (cycle) {
            if (be < 0) return 1;
            br = fmax(br, 0.0);
            bs = fmax(bs, 0.0);
            if (br + bs > 1.0) {
                const double d = 0.5 * (br + bs - 1.0);
                br = fmax(br - d, 0.0);
                bs = fmax(bs - d, 0.0);
            }
            *eo = be;
            *ro = br;
            *so = bs;
            return 0;
        }
        e = en;
    }
    return 1;
}

static double element_size(const sem_tri_mesh *m, int e)
{
    const double *a = &m->vxy[2 * m->tri[3 * e]], *b = &m->vxy[2 * m->tri[3 * e + 1]],
                 *c = &m->vxy[2 * m->tri[3 * e + 2]];
    return sqrt(0.5 * fabs((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])));
}

/* Fourier coefficient k of w = u + iv on the circle of radius rho around c. */
static sq_status circle_mode(const sq_guiding_field *g, const double c[2], double rho, int k,
                             double complex *a, sq_error *err)
{
    int elem = -1;
    *a = 0.0;
    for (int j = 0; j < FIT_SAMPLES; j++) {
        double t = 2.0 * M_PI * j / FIT_SAMPLES, x[2] = {c[0] + rho * cos(t), c[1] + rho * sin(t)};
        double uv[2];
        if (sq_guiding_field_eval(g, x, &elem, uv, NULL))
            return SQ_FAIL(err, SQ_ERR_INTERNAL, "fit circle around (%g, %g) leaves the face", c[0],
                           c[1]);
        *a += (uv[0] + I * uv[1]) * cexp(-I * (double)k * t) / FIT_SAMPLES;
    }
    return SQ_OK;
}

/* A zero of index m, |m| >= 2: w ≈ c (z − z0)^m (m > 0) or
 * c conj(z − z0)^|m| (m < 0).  On a circle of radius rho around zc
 * (δ = z0 − zc), w's modes ±|m| and ±(|m| − 1) are c rho^|m| and
 * −|m| c δ rho^(|m|−1) (δ conjugated for m < 0) whatever the higher
 * terms: z0 is the centroid of the roots of the truncated expansion
 * (Vieta), which round-off does not move even where it splits the zero. */
static sq_status fit_degenerate(const sq_guiding_field *g, double c[2], double rho, int m,
                                double coef[2], sq_error *err)
{
    const int n = abs(m), sg = m > 0 ? 1 : -1;
    double complex am = 0.0, am1 = 0.0;
    for (int it = 0; it < 3; it++) {
        SQ_TRY(circle_mode(g, c, rho, sg * n, &am, err));
        SQ_TRY(circle_mode(g, c, rho, sg * (n - 1), &am1, err));
        if (cabs(am) == 0.0) break;
        double complex d = -am1 * rho / (n * am);
        if (sg < 0) d = conj(d);
        c[0] += creal(d);
        c[1] += cimag(d);
        if (cabs(d) < 1e-12 * rho) break;
    }
    SQ_TRY(circle_mode(g, c, rho, sg * n, &am, err));
    am /= pow(rho, n);
    coef[0] = creal(am);
    coef[1] = cimag(am);
    return SQ_OK;
}

/* The largest index circle around point q: inside the face and holding
 * no other point. */
static double index_circle_limit(const sq_critical_point *p, int n, int q)
{
    double lim = 0.9 * p[q].dist_boundary;
    for (int o = 0; o < n; o++)
        if (o != q) lim = fmin(lim, 0.9 * hypot(p[o].x - p[q].x, p[o].y - p[q].y));
    return lim;
}

/* The index on the circle of radius rho, else on smaller and larger ones
 * (up to lim): a circle that passes over a second zero Newton missed, or
 * through a near-zero of (u, v), cannot be read.  A zero whose index no
 * circle gives is not isolated at the field's resolution (a valence-3 and
 * a valence-5 point on top of each other: indices +1 and -1): it is kept
 * with index 0 and flagged `unresolved`, so that it starts no separatrix. */
static void read_index(const sq_guiding_field *g, const double c[2], double rho, double lim,
                       sq_critical_point *pt)
{
    static const double factor[] = {1.0, 0.5, 2.0, 0.25, 4.0, 0.125};
    for (size_t k = 0; k < sizeof factor / sizeof factor[0]; k++) {
        const double r = factor[k] * rho;
        if (k > 0 && r >= lim) continue;
        sq_error e = {0};
        if (sq_field_winding(g, c, r, &pt->index, &e) == SQ_OK) return;
    }
    pt->index = 0;
    pt->unresolved = 1;
}

sq_status sq_critical_points_find(const sq_guiding_field *g, const cad_face *face,
                                  sq_critical_point **pts, int *npts, sq_error *err)
{
    const sem_tri_mesh *m = g->mesh;
    const sem_locator *loc = sem_field_evaluator_locator(g->ev);
    int S = 2 * g->order > 8 ? 2 * g->order : 8, n = 0, cap = 8;
    sq_critical_point *p = malloc(sizeof *p * (size_t)cap);
    /* the modes at the lattice once, not at every element's every point */
    double *modes = lattice_modes(g->uv->P, S);
    if (!p || !modes) {
        free(p);
        free(modes);
        return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    }
    sq_status st = SQ_OK;
    for (int e = 0; e < m->ntris && st == SQ_OK; e++) {
        double best[2] = {1.0 / 3.0, 1.0 / 3.0};
        if (!flag_element(g->uv, e, S, modes, best)) continue;
        const double starts[2][2] = {{best[0], best[1]}, {1.0 / 3.0, 1.0 / 3.0}};
        for (int k = 0; k < 2; k++) {
            int er;
            double rr, sr, x[2];
            if (newton(g, e, starts[k][0], starts[k][1], &er, &rr, &sr)) continue;
            sem_locator_map(loc, er, rr, sr, x, NULL);
            int dup = 0;
            for (int q = 0; q < n && !dup; q++)
                dup = hypot(p[q].x - x[0], p[q].y - x[1]) < CLUSTER_REL * element_size(m, er);
            if (dup) continue;
            if (n == cap) {
                sq_critical_point *np = realloc(p, sizeof *p * (size_t)(cap *= 2));
                if (!np) {
                    st = SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
                    break;
                }
                p = np;
            }
            double uv[2];
            sem_field_eval_ref(g->uv, er, rr, sr, uv, NULL, NULL);
            p[n] = (sq_critical_point){.x = x[0],
                                       .y = x[1],
                                       .elem = er,
                                       .r = rr,
                                       .s = sr,
                                       .residual = hypot(uv[0], uv[1])};
            n++;
        }
    }
    for (int q = 0; q < n && st == SQ_OK; q++) {
        const double c[2] = {p[q].x, p[q].y};
        st = sq_face_boundary_distance(face, c, &p[q].dist_boundary, err);
    }
    /* clusters: a zero of multiplicity m that the discretization error
     * splits into m simple roots (the disc's z^4 at P = 4: four roots 0.01
     * apart) is one singular point at the layout's scale */
    double *spread = calloc((size_t)n + 1, sizeof *spread);
    if (st == SQ_OK && !spread) st = SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    for (int q = 0; q < n && st == SQ_OK; q++) {
        double sx = p[q].x, sy = p[q].y;
        int cnt = 1;
        for (int o = q + 1; o < n; o++) {
            double d = hypot(p[o].x - p[q].x, p[o].y - p[q].y);
            if (d >= CLUSTER_BOUNDARY_REL * fmin(p[q].dist_boundary, p[o].dist_boundary)) continue;
            sx += p[o].x, sy += p[o].y, cnt++;
            spread[q] = fmax(spread[q], d);
            p[o--] = p[--n]; /* drop o, look at the one moved there */
        }
        if (cnt > 1) {
            const double c[2] = {sx / cnt, sy / cnt};
            int e;
            double r, s;
            if (!sem_locator_find(loc, c, p[q].elem, &e, &r, &s))
                p[q].x = c[0], p[q].y = c[1], p[q].elem = e, p[q].r = r, p[q].s = s;
            st = sq_face_boundary_distance(face, c, &p[q].dist_boundary, err);
        }
    }
    /* indices on circles that hold no other point and stay in the face (and
     * enclose a cluster) */
    for (int q = 0; q < n && st == SQ_OK; q++) {
        double c[2] = {p[q].x, p[q].y}, rho = 0.25 * element_size(m, p[q].elem);
        /* Markov's inequality |p'| <= 2 P^2 / h max|p| on an element of size
         * h: a zero of (u, v) within h / (2 P^2) of the boundary, where
         * |(u, v)| = 1, is below what the element's polynomial resolves */
        const double h = element_size(m, p[q].elem);
        p[q].near_boundary = p[q].dist_boundary < h / (2.0 * g->order * g->order);
        rho = fmin(rho, 0.5 * p[q].dist_boundary);
        for (int o = 0; o < n; o++)
            if (o != q) rho = fmin(rho, 0.4 * hypot(p[o].x - c[0], p[o].y - c[1]));
        rho = fmax(rho, 2.5 * spread[q]);
        if (p[q].near_boundary) {
            p[q].index = 0; /* no circle fits: reported with its distance */
        } else {
            read_index(g, c, rho, index_circle_limit(p, n, q), &p[q]);
        }
        p[q].valence = 4 - p[q].index;
        if (st == SQ_OK && abs(p[q].index) > 1) {
            st = fit_degenerate(g, c, rho, p[q].index, p[q].coef, err);
            double r, s, uv[2];
            int e;
            if (st == SQ_OK && !sem_locator_find(loc, c, p[q].elem, &e, &r, &s)) {
                sem_field_eval_ref(g->uv, e, r, s, uv, NULL, NULL);
                p[q].x = c[0], p[q].y = c[1], p[q].elem = e, p[q].r = r, p[q].s = s;
                p[q].residual = hypot(uv[0], uv[1]);
                st = sq_face_boundary_distance(face, c, &p[q].dist_boundary, err);
            }
        }
    }
    free(spread);
    free(modes);
    if (st != SQ_OK) {
        free(p);
        return st;
    }
    *pts = p;
    *npts = n;
    return SQ_OK;
}
