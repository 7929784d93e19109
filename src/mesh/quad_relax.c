#include "quad_relax_private.h"

#include "quad_mesh.h"
#include "sparse.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define MAX_NEWTON 60
#define MAX_HALVINGS 30
#define MAX_DOUBLINGS 4
#define MAX_PARABOLA_STEP 16.0 /* longest step from the parabola */
#define CONVERGED 1e-9
#define STALL_DROP 1e-9
/* a linear tail: decreases falling by less than 10 a step (quadratic
 * convergence cuts them by 100 and more near the optimum; at 1/4 a tail of
 * ratio 0.24, stress face 0003_bspline, ran 8 more projected steps) */
#define EXACT_RATIO 0.1
#define EXACT_DROP 1e-4 /* the first exact steps' threshold (sq_quad_relax) */
#define PCG_RTOL 5e-2
#define PCG_MAXIT 6
/* the exact Hessian is further from the factor that preconditions it
 * than the projected one: its steps get more iterations, still far
 * cheaper than a factorization (at 6 the disc's exact steps at --size
 * 0.05 went unsolved at 2e-7 of the energy, 16 steps; at 20 they took
 * 7-9 iterations, 13 steps) */
#define PCG_MAXIT_EXACT 20
#define DOUBLE_RHO 1.1

void sq_relax_work_free(sq_relax_work **pw)
{
    if (!pw || !*pw) return;
    relax_work *w = *pw;
    free(w->fixed0);
    free(w->dof);
    free(w->var);
    free(w->edge);
    free(w->s);
    free(w->len);
    free(w->tan);
    free(w->kappa);
    free(w->start);
    free(w->around);
    free(w->pos);
    sem_sparse_free(&w->A);
    free(w);
    *pw = NULL;
}

void sq_relax_work_stats(const sq_relax_work *w, int *newton_steps, long *polls)
{
    *newton_steps = w->steps;
    *polls = w->polls;
}

static int cmp_long(const void *a, const void *b)
{
    long x = *(const long *)a, y = *(const long *)b;
    return (x > y) - (x < y);
}

/* The lower triangle of the Hessian's 2 x 2 block pattern: block column b
 * (moving vertex i) holds the blocks of the moving vertices >= i that share
 * a quad with i, the diagonal first. */
static sq_status block_pattern(const sq_relax_mesh *m, relax_work *w, sq_error *err)
{
    long nb = w->ndof / 2;
    w->bptr = malloc(sizeof(long) * ((size_t)nb + 1));
    w->brow = malloc(sizeof(long) * (16 * (size_t)m->nq + 1));
    if (!w->bptr || !w->brow) return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    long k = 0;
    w->bptr[0] = 0;
    for (int i = 0; i < m->nv; i++) {
        if (w->dof[i] < 0) continue;
        long b = w->dof[i] / 2, first = k;
        for (int t = w->start[i]; t < w->start[i + 1]; t++)
            for (int c = 0; c < 4; c++) {
                int v = m->quad[4 * w->around[t] + c];
                if (w->dof[v] >= 2 * b) w->brow[k++] = w->dof[v] / 2;
            }
        qsort(&w->brow[first], (size_t)(k - first), sizeof(long), cmp_long);
        long u = first;
        for (long p = first; p < k; p++)
            if (p == first || w->brow[p] != w->brow[u - 1]) w->brow[u++] = w->brow[p];
        k = u;
        w->bptr[b + 1] = k;
    }
    return SQ_OK;
}

/* Corner k of quad q: its vertex c and the next (a) and previous (b). */
static void corner_vertices(const sq_relax_mesh *m, int q, int k, int v[3])
{
    v[0] = m->quad[4 * q + k];
    v[1] = m->quad[4 * q + (k + 1) % 4];
    v[2] = m->quad[4 * q + (k + 3) % 4];
}

/* The Hessian, its pattern set, and where each corner's blocks go. */
static sq_status create_hessian(const sq_relax_mesh *m, relax_work *w, sq_error *err)
{
    SQ_TRY(sem_sparse_create_blocks(w->ndof / 2, 2, w->bptr, w->brow, &w->A, err));
    w->pos = malloc(sizeof *w->pos * (96 * (size_t)m->nq + 1));
    if (!w->pos) return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    for (int q = 0; q < m->nq; q++)
        for (int k = 0; k < 4; k++) {
            int v[3];
            corner_vertices(m, q, k, v);
            int32_t *pos = &w->pos[24 * (4 * q + k)];
            for (int r = 0; r < 3; r++)
                for (int t = r; t < 3; t++, pos += 4) {
                    long p[4] = {-1, -1, -1, -1};
                    if (w->dof[v[r]] >= 0 && w->dof[v[t]] >= 0)
                        SQ_TRY(sem_sparse_block_positions(w->A, w->dof[v[r]] / 2, w->dof[v[t]] / 2,
                                                          p, err));
                    for (int e = 0; e < 4; e++) {
                        if (p[e] > INT32_MAX)
                            return SQ_FAIL(err, SQ_ERR_USAGE,
                                           "relaxation: the Hessian of %d quads has more than "
                                           "2^31 entries; mesh fewer quads (--size, --max-quads)",
                                           m->nq);
                        pos[e] = (int32_t)p[e];
                    }
                }
        }
    return SQ_OK;
}

/* The motions that leave the energy (nearly) unchanged (relax_work): 1
 * where every edge of the face is a closed circle about one centre, the
 * rotation about it; 3 where the face is a disc (one such circle), the
 * rotation and the disc's two other conformal automorphisms, under which
 * Winslow's energy, the Dirichlet energy of the inverse map (Winslow 1966),
 * changes only by its discretization; else 0.  A circle: its centres of
 * curvature x + n / kappa (n the left normal) at ROTATION_SAMPLES points of
 * each edge within ROTATION_TOL of its radius of c.  The edges' evaluation
 * is exact to round-off (a circle's: 1e-15 of its radius); an edge that
 * merely approximates a circle (a B-spline to 1e-6) is not one, and the
 * energy is not invariant under these motions there. */
#define ROTATION_SAMPLES 8
#define ROTATION_TOL 1e-9
static sq_status symmetries(const cad_face *face, relax_work *w, sq_error *err)
{
    w->symmetries = 0;
    double *c = w->centre;
    for (int e = 0; e < cad_face_num_edges(face); e++) {
        if (!cad_face_edge_closed(face, e)) return SQ_OK;
        const double L = cad_face_edge_length(face, e);
        for (int k = 0; k < ROTATION_SAMPLES; k++) {
            double x[2], t[2], kappa;
            SQ_TRY(cad_face_edge_eval(face, e, k * L / ROTATION_SAMPLES, x, t, &kappa, err));
            if (!(fabs(kappa) > 0.0)) return SQ_OK;
            double ck[2] = {x[0] - t[1] / kappa, x[1] + t[0] / kappa};
            if (e == 0 && k == 0) c[0] = ck[0], c[1] = ck[1], w->radius = 1.0 / fabs(kappa);
            if (!(hypot(ck[0] - c[0], ck[1] - c[1]) <= ROTATION_TOL / fabs(kappa))) return SQ_OK;
        }
    }
    w->symmetries = cad_face_num_edges(face) == 1 ? 3 : 1;
    return SQ_OK;
}

/* Which vertices move and how: interior free vertices in the plane (two
 * unknowns), boundary vertices whose two boundary sides lie on one CAD edge
 * along it (one unknown, the arc length); every other vertex is fixed. */
static sq_status prepare(const cad_face *face, const sq_relax_mesh *m, relax_work *w, sq_error *err)
{
    int *nb = calloc((size_t)m->nv + 1, sizeof(int));
    w->nv = m->nv;
    w->nq = m->nq;
    w->fixed0 = malloc((size_t)m->nv + 1);
    w->var = malloc(sizeof(int) * ((size_t)m->nv + 1));
    w->dof = malloc(sizeof(int) * ((size_t)m->nv + 1));
    w->edge = malloc(sizeof(int) * ((size_t)m->nv + 1));
    w->s = calloc((size_t)m->nv + 1, sizeof(double));
    w->len = calloc((size_t)m->nv + 1, sizeof(double));
    w->tan = calloc(2 * (size_t)m->nv + 1, sizeof(double));
    w->kappa = calloc((size_t)m->nv + 1, sizeof(double));
    w->start = calloc((size_t)m->nv + 2, sizeof(int));
    w->around = malloc(sizeof(int) * (4 * (size_t)m->nq + 1));
    if (!nb || !w->fixed0 || !w->var || !w->dof || !w->edge || !w->s || !w->len || !w->tan ||
        !w->kappa || !w->start || !w->around) {
        free(nb);
        return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    }
    for (int i = 0; i < m->nv; i++) {
        w->edge[i] = -1;
        w->fixed0[i] = m->fixed[i] != 0;
    }
    for (int q = 0; q < m->nq; q++)
        for (int k = 0; k < 4; k++)
            w->start[m->quad[4 * q + k] + 2]++;
    for (int i = 0; i < m->nv; i++)
        w->start[i + 2] += w->start[i + 1];
    for (int q = 0; q < m->nq; q++)
        for (int k = 0; k < 4; k++)
            w->around[w->start[m->quad[4 * q + k] + 1]++] = q;
    for (int q = 0; q < m->nq; q++)
        for (int k = 0; k < 4; k++) {
            int t = m->side_tag[4 * q + k];
            if (t < 0) continue;
            for (int e = 0; e < 2; e++) {
                int a = m->quad[4 * q + (k + e) % 4];
                /* -2 once the vertex joins two different CAD edges */
                w->edge[a] = nb[a]++ == 0 || w->edge[a] == t ? t : -2;
            }
        }
    sq_status st = SQ_OK;
    w->ndof = 0;
    /* held: fixed by the caller, or on the boundary without two sides on
     * one CAD edge.  With nothing held and every edge a circle about one
     * centre (a disc, a ring: no corner, no singular point held) the energy
     * does not change under a rotation about it, and on a disc hardly under
     * its other conformal automorphisms (symmetries): the Newton
     * directions are kept orthogonal to these motions (symmetry_basis),
     * and the mesh keeps the place along them that its start gives it.
     * Holding one boundary vertex instead left a soft mode, the rest
     * turning about it, and the disc's automorphisms softer still: the
     * inexact directions drifted along them and the steps then crawled
     * back along their curved orbits (the disc at --size 0.025: turns of 3
     * degrees a step, 24 Newton steps; 10 with the motions removed, its
     * energy 1e-10 of itself above; half_disc: 7).  With nothing held
     * otherwise (closed edges that are not concentric circles: no such
     * symmetry) the first boundary vertex is held, as a safeguard. */
    char *held = malloc((size_t)m->nv + 1);
    if (!held) st = SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    int any_held = 0, first_bnd = -1;
    for (int i = 0; i < m->nv && st == SQ_OK; i++) {
        held[i] = m->fixed[i] || (nb[i] != 0 && (nb[i] != 2 || w->edge[i] < 0));
        any_held |= held[i];
        if (first_bnd < 0 && nb[i] != 0) first_bnd = i;
    }
    if (st == SQ_OK && !any_held && first_bnd >= 0) st = symmetries(face, w, err);
    if (st == SQ_OK && !any_held && first_bnd >= 0 && !w->symmetries) held[first_bnd] = 1;
    for (int i = 0; i < m->nv && st == SQ_OK; i++) {
        w->dof[i] = -1;
        if (held[i]) {
            w->edge[i] = -1;
            continue;
        }
        /* two unknowns also for a sliding vertex (the second one pinned
         * at zero): the Hessian is then made of 2 x 2 blocks */
        w->dof[i] = w->ndof;
        w->ndof += 2;
        if (nb[i] == 0) continue;
        double a[2], b[2], L = cad_face_edge_length(face, w->edge[i]);
        st = cad_face_edge_eval(face, w->edge[i], 0.0, a, NULL, NULL, err);
        if (st == SQ_OK) st = cad_face_edge_eval(face, w->edge[i], L, b, NULL, NULL, err);
        w->len[i] = hypot(a[0] - b[0], a[1] - b[1]) < 1e-9 * L ? L : -L;
    }
    free(held);
    free(nb);
    if (st == SQ_OK) st = block_pattern(m, w, err);
    if (st == SQ_OK && w->ndof > 0) st = create_hessian(m, w, err);
    /* the Hessian holds its own copy of the pattern: 128 B a quad less at
     * the factorization's peak */
    free(w->bptr);
    free(w->brow);
    w->bptr = w->brow = NULL;
    return st;
}

/* This relaxation: the vertices that move (a vertex the caller now fixes
 * keeps its unknowns, held at zero) and where the sliding ones are. */
static sq_status begin(const cad_face *face, const sq_relax_mesh *m, relax_work *w, sq_error *err)
{
    w->modes = w->symmetries;
    for (int i = 0; i < m->nv; i++) {
        w->var[i] = m->fixed[i] ? -1 : w->dof[i];
        if (m->fixed[i]) w->modes = 0;
        if (w->dof[i] >= 0 && w->edge[i] >= 0)
            SQ_TRY(cad_face_edge_project(face, w->edge[i], &m->xy[2 * i], &w->s[i], NULL, NULL, err));
    }
    return SQ_OK;
}

sq_status qr_on_edge(const cad_face *face, const relax_work *w, int i, double *s, double x[2],
                     double t[2], double *kappa, sq_error *err)
{
    double L = fabs(w->len[i]);
    if (w->len[i] > 0.0)
        *s -= L * floor(*s / L);
    else
        *s = fmin(fmax(*s, 0.0), L);
    return cad_face_edge_eval(face, w->edge[i], *s, x, t, kappa, err);
}

/* Winslow energy of one corner with edges e = (a - c, b - c):
 * f = (|e1|^2 + |e2|^2) / (e1 x e2), the discrete |J|_F^2 / det J of the map
 * from the unit square, which is the Dirichlet energy of the inverse map
 * (Winslow 1966); +inf when the corner is not convex. */
static double corner_energy(const double e[4])
{
    double D = e[0] * e[3] - e[1] * e[2];
    return D > 0.0 ? (e[0] * e[0] + e[1] * e[1] + e[2] * e[2] + e[3] * e[3]) / D : HUGE_VAL;
}

/* chi(D, eps) = (D + sqrt(D^2 + eps^2)) / 2, the positive stand-in for a
 * corner's area D of Garanzha, Kaporin, Kudryavtseva, Protais, Ray and
 * Sokolov (ACM TOG 40(4) 2021, "Foldover-free maps in 50 lines of code",
 * eq. (3)): it tends to max(D, 0) as eps -> 0; its first and second
 * derivatives in D in c[0], c[1].  Written without the cancellation of
 * D + sqrt(.) where D < 0. */
static double chi(double D, double eps, double c[2])
{
    double r = sqrt(D * D + eps * eps), e2 = eps * eps;
    c[0] = D >= 0.0 ? 0.5 * (1.0 + D / r) : 0.5 * e2 / (r * (r - D));
    c[1] = 0.5 * e2 / (r * r * r);
    return D >= 0.0 ? 0.5 * (D + r) : 0.5 * e2 / (r - D);
}

/* The untangling energy of a corner: Winslow's with its area D replaced by
 * chi(D, eps), finite on a folded corner (Garanzha et al. 2021, eq. (4),
 * its shape term). */
static double untangle_energy(const double e[4], double eps)
{
    double c[2];
    return (e[0] * e[0] + e[1] * e[1] + e[2] * e[2] + e[3] * e[3]) /
           chi(e[0] * e[3] - e[1] * e[2], eps, c);
}

/* Gradient and projected Hessian of untangle_energy, by the splitting of
 * corner_derivatives: f = phi(a, b) = (a + b) / chi((a - b) / 2), so
 *   g = 2 phi_a u + 2 phi_b w,
 *   H = 2 phi_a P+ + 2 phi_b P- + 4 [phi_aa u u^T + phi_ab (u w^T + w u^T)
 *       + phi_bb w w^T],
 * with S = a + b, x = chi, x' and x'' its derivatives in D:
 *   phi_a = 1 / x - S x' / (2 x^2),  phi_b = 1 / x + S x' / (2 x^2),
 *   phi_aa = -x' / x^2 + k,  phi_bb = x' / x^2 + k,  phi_ab = -k,
 *   k = S x'^2 / (2 x^3) - S x'' / (4 x^2).
 * Its eigenvalues: 2 phi_a normal to u in P+'s plane, 2 phi_b normal to w
 * in P-'s, and those of the 2 x 2 block of the plane of uh, wh; each
 * clamped to zero.  (At eps = 0, D > 0 these are corner_derivatives'.) */
static void untangle_derivatives(const double e[4], double eps, double g[4], double H[16])
{
    static const double PM[16] = {0.5, 0, 0, -0.5, 0, 0.5, 0.5, 0, 0, 0.5, 0.5, 0, -0.5, 0, 0, 0.5};
    double c0 = 0.5 * (e[0] + e[3]), c1 = 0.5 * (e[1] - e[2]);
    double w0 = 0.5 * (e[0] - e[3]), w1 = 0.5 * (e[1] + e[2]);
    double u[4] = {c0, c1, -c1, c0}, w[4] = {w0, w1, w1, -w0};
    double a = 2.0 * (c0 * c0 + c1 * c1), b = 2.0 * (w0 * w0 + w1 * w1), S = a + b, c[2];
    double x = chi(0.5 * (a - b), eps, c), x2 = x * x;
    double pa = 1.0 / x - S * c[0] / (2.0 * x2), pb = 1.0 / x + S * c[0] / (2.0 * x2);
    double k = S * c[0] * c[0] / (2.0 * x2 * x) - S * c[1] / (4.0 * x2);
    double paa = -c[0] / x2 + k, pbb = c[0] / x2 + k, pab = -k;
    double ra = sqrt(a), rb = sqrt(b);
    double uh[4] = {M_SQRT1_2, 0.0, 0.0, M_SQRT1_2}, wh[4] = {M_SQRT1_2, 0.0, 0.0, -M_SQRT1_2};
    for (int i = 0; i < 4; i++) {
        g[i] = 2.0 * pa * u[i] + 2.0 * pb * w[i];
        if (ra > 0.0) uh[i] = u[i] / ra;
        if (rb > 0.0) wh[i] = w[i] / rb;
    }
    double M11 = 2.0 * pa + 4.0 * a * paa, M22 = 2.0 * pb + 4.0 * b * pbb,
           M12 = 4.0 * ra * rb * pab;
    double half = 0.5 * (M11 - M22), r = sqrt(half * half + M12 * M12);
    double lp = fmax(0.5 * (M11 + M22) + r, 0.0), lm = fmax(0.5 * (M11 + M22) - r, 0.0);
    double v0 = half >= 0.0 ? r + half : M12, v1 = half >= 0.0 ? M12 : r - half;
    double nv = sqrt(v0 * v0 + v1 * v1), z[4], y[4];
    if (!(nv > 0.0)) v0 = 1.0, v1 = 0.0, nv = 1.0; /* M a multiple of I */
    for (int i = 0; i < 4; i++) {
        z[i] = (v0 * uh[i] + v1 * wh[i]) / nv;
        y[i] = (-v1 * uh[i] + v0 * wh[i]) / nv;
    }
    double qa = fmax(2.0 * pa, 0.0), qb = fmax(2.0 * pb, 0.0);
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++)
            H[4 * i + j] = qa * ((i == j) - PM[4 * i + j] - uh[i] * uh[j]) +
                           qb * (PM[4 * i + j] - wh[i] * wh[j]) + lp * z[i] * z[j] +
                           lm * y[i] * y[j];
}

/* With sizes: per quad, its target (quad_relax.h) from l0 and l1, its
 * mean lengths of sides 0 and 2 and of sides 1 and 3 at the start, scaled
 * by c = min(1, h(d0) / l0, h(d1) / l1), h(dk) the size at its centre in
 * the direction dk of sides k and k + 2 (the same h both ways without
 * boundary layers: c = min(1, h / max(l0, l1))):
 * t[2 q] = sqrt(l1 / l0), t[2 q + 1] = c^2 l0 l1 (its area). */
static void start_targets(const sq_relax_mesh *m, double *t)
{
    for (int q = 0; q < m->nq; q++) {
        double l[2] = {0.0, 0.0}, x[2] = {0.0, 0.0}, d[2][2] = {{0.0, 0.0}, {0.0, 0.0}};
        for (int k = 0; k < 4; k++) {
            const double *a = &m->xy[2 * m->quad[4 * q + k]],
                         *b = &m->xy[2 * m->quad[4 * q + (k + 1) % 4]];
            l[k % 2] += 0.5 * hypot(b[0] - a[0], b[1] - a[1]);
            /* sides k and k + 2 run opposite ways round the quad */
            double sgn = k < 2 ? 1.0 : -1.0;
            d[k % 2][0] += sgn * (b[0] - a[0]);
            d[k % 2][1] += sgn * (b[1] - a[1]);
            x[0] += 0.25 * a[0];
            x[1] += 0.25 * a[1];
        }
        double c = 1.0;
        for (int k = 0; k < 2; k++)
            c = fmin(c, sq_size_field_eval_dir(m->sizes, x, d[k], m->far) / l[k]);
        t[2 * q] = sqrt(l[1] / l[0]);
        t[2 * q + 1] = c * c * l[0] * l[1];
    }
}

/* The edges e of corner k of quad q in its target's frame (quad_relax.h:
 * (s e1, e2 / s), s^2 = l2 / l1 the target's sides along e2 and e1), s
 * returned; unchanged, s = 1, without targets (t NULL). */
static double corner_target(const double *t, int q, int k, double e[4])
{
    if (!t) return 1.0;
    /* e1 lies along side k, e2 along side k + 3 */
    double s = k % 2 ? 1.0 / t[2 * q] : t[2 * q];
    e[0] *= s;
    e[1] *= s;
    e[2] /= s;
    e[3] /= s;
    return s;
}

/* The size term of a corner of area D = e1 x e2 against its target's
 * area A (quad_relax.h): SIZE_WEIGHT (tau + 1 / tau), tau = D / A, and
 * its first and second derivatives in D. */
#define SIZE_WEIGHT 0.5
static double size_term(double D, double A, double *d1, double *d2)
{
    *d1 = SIZE_WEIGHT * (1.0 / A - A / (D * D));
    *d2 = 2.0 * SIZE_WEIGHT * A / (D * D * D);
    return SIZE_WEIGHT * (D / A + A / D);
}

/* A corner's energy: Winslow's, or with targets t its shape and size
 * terms (e in the target's frame, whose cross product is the corner's). */
static double target_energy(const double *t, int q, const double e[4])
{
    double f = corner_energy(e), d1, d2;
    if (!t || !(f < HUGE_VAL)) return f;
    return f + size_term(e[0] * e[3] - e[1] * e[2], t[2 * q + 1], &d1, &d2);
}

/* The mesh's energy: with eps > 0 the untangling one (target unused). */
static double energy(const sq_relax_mesh *m, const double *target, double eps)
{
    double E = 0.0;
    for (int q = 0; q < m->nq && E < HUGE_VAL; q++)
        for (int k = 0; k < 4; k++) {
            int v[3];
            corner_vertices(m, q, k, v);
            const double *c = &m->xy[2 * v[0]], *a = &m->xy[2 * v[1]], *b = &m->xy[2 * v[2]];
            double e[4] = {a[0] - c[0], a[1] - c[1], b[0] - c[0], b[1] - c[1]};
            if (eps > 0.0) {
                E += untangle_energy(e, eps);
                continue;
            }
            corner_target(target, q, k, e);
            E += target_energy(target, q, e);
        }
    return E;
}

/* Gradient g[4] and Hessian H[16] of corner_energy in e, the Hessian made
 * positive semi-definite by clamping its eigenvalues to zero (projected
 * Newton), in closed form.
 *
 * The edge matrix F = [e1 e2] splits into its conformal part u (a scaled
 * rotation) and its anti-conformal part w (symmetric, traceless): with
 * e = (e1x, e1y, e2x, e2y), u = P+ e and w = P- e, P+- = (I +- C) / 2 the
 * projections onto the eigenspaces (eigenvalues +-1) of the constant
 * Hessian C of D = e1 x e2 = e^T C e / 2.  Then D = (a - b) / 2 and
 * |e|^2 = a + b with a = |u|^2, b = |w|^2 (the |f_z|^2 and |f_zbar|^2 of
 * complex analysis), so f = 2 (a + b) / (a - b) = phi(a, b) depends on e
 * only through the two squared norms, like the isotropic energies whose
 * analytic eigensystems Smith, de Goes and Kim (ACM TOG 38(1) 2019) derive
 * from the singular values.  With s = a - b = 2 D:
 *   g = 2 phi_a u + 2 phi_b w,  phi_a = -4 b / s^2,  phi_b = 4 a / s^2,
 *   H = 2 phi_a P+ + 2 phi_b P- + 4 [phi_aa u u^T + phi_ab (u w^T + w u^T)
 *       + phi_bb w w^T],
 *   phi_aa = 8 b / s^3,  phi_bb = 8 a / s^3,  phi_ab = -4 (a + b) / s^3.
 * Its eigenvectors: in P+'s plane, the direction normal to u, eigenvalue
 * 2 phi_a <= 0 (clamped away); in P-'s plane, the direction normal to w,
 * eigenvalue 2 phi_b = 8 a / s^2 > 0; and in the plane of the unit vectors
 * uh = u / |u|, wh = w / |w| the 2 x 2 block
 *   M = [8 b (3a + b), -16 sqrt(ab) (a + b); ., 8 a (a + 3b)] / s^3,
 * whose determinant -64 a b / s^4 <= 0 leaves one eigenvalue lp >= 0 (the
 * other is clamped).  So the projected Hessian is
 *   H+ = 8 a / s^2 (P- - wh wh^T) + lp z z^T,  z = v0 uh + v1 wh,
 * (v0, v1) M's unit eigenvector for lp.  With w = 0 (a conformal corner)
 * any unit wh in P-'s plane gives the same H+ = 8 / a P-.  exact: H itself
 * (the last step of a linear tail, sq_quad_relax), with P+ = I - P-. */
static void corner_derivatives(const double e[4], int exact, double g[4], double H[16])
{
    /* P- = (I - C) / 2 */
    static const double PM[16] = {0.5, 0, 0, -0.5, 0, 0.5, 0.5, 0, 0, 0.5, 0.5, 0, -0.5, 0, 0, 0.5};
    double c0 = 0.5 * (e[0] + e[3]), c1 = 0.5 * (e[1] - e[2]);
    double w0 = 0.5 * (e[0] - e[3]), w1 = 0.5 * (e[1] + e[2]);
    double u[4] = {c0, c1, -c1, c0}, w[4] = {w0, w1, w1, -w0};
    double a = 2.0 * (c0 * c0 + c1 * c1), b = 2.0 * (w0 * w0 + w1 * w1);
    double s = 2.0 * (e[0] * e[3] - e[1] * e[2]), s2 = s * s, s3 = s2 * s;
    if (exact) {
        const double fa = -8.0 * b / s2, fb = 8.0 * a / s2, faa = 32.0 * b / s3,
                     fbb = 32.0 * a / s3, fab = -16.0 * (a + b) / s3;
        for (int i = 0; i < 4; i++) {
            g[i] = 8.0 * (a * w[i] - b * u[i]) / s2;
            for (int j = 0; j < 4; j++)
                H[4 * i + j] = fa * ((i == j) - PM[4 * i + j]) + fb * PM[4 * i + j] +
                               faa * u[i] * u[j] + fab * (u[i] * w[j] + w[i] * u[j]) +
                               fbb * w[i] * w[j];
        }
        return;
    }
    double ra = sqrt(a), rb = sqrt(b), uh[4], wh[4] = {M_SQRT1_2, 0.0, 0.0, -M_SQRT1_2};
    for (int i = 0; i < 4; i++) {
        g[i] = 8.0 * (a * w[i] - b * u[i]) / s2;
        uh[i] = u[i] / ra;
        if (rb > 0.0) wh[i] = w[i] / rb;
    }
    double M11 = 8.0 * b * (3.0 * a + b) / s3, M22 = 8.0 * a * (a + 3.0 * b) / s3,
           M12 = -16.0 * ra * rb * (a + b) / s3;
    /* sqrt rather than hypot (a library call, the relaxation's hottest):
     * these magnitudes are far from overflow for any corner with s > 0 */
    double half = 0.5 * (M11 - M22), lp = 0.5 * (M11 + M22) + sqrt(half * half + M12 * M12);
    /* of the two (equivalent) forms of the eigenvector, the one away from
     * cancellation */
    double v0 = half >= 0.0 ? lp - M22 : M12, v1 = half >= 0.0 ? M12 : lp - M11;
    double nv = sqrt(v0 * v0 + v1 * v1), z[4];
    for (int i = 0; i < 4; i++)
        z[i] = (v0 * uh[i] + v1 * wh[i]) / nv;
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++)
            H[4 * i + j] = 8.0 * a / s2 * (PM[4 * i + j] - wh[i] * wh[j]) + lp * z[i] * z[j];
}

/* With a target: the shape term's derivatives ge, He (in the target's
 * frame, edges e there) taken back to the corner's edges, g = S g~,
 * H = S H~ S with S = diag(s, s, 1/s, 1/s), and the size term's added:
 * its gradient f' grad D, grad D = C e, and its Hessian f'' grad D grad D^T
 * + f' C made semi-definite by keeping the part of f' C on the eigenspace
 * of C whose eigenvalue has the sign of f' (P+ = (I + C) / 2 when f' > 0,
 * else P-), both terms then semi-definite (f'' > 0 on a convex corner);
 * exact: f' C itself. */
static void target_derivatives(double area, double s, const double e[4], int exact, double ge[4],
                               double He[16])
{
    static const double C[16] = {0, 0, 0, 1, 0, 0, -1, 0, 0, -1, 0, 0, 1, 0, 0, 0};
    double S[4] = {s, s, 1.0 / s, 1.0 / s}, d1, d2;
    /* the corner's own edges' D = e1 x e2: the same in the target's frame */
    size_term(e[0] * e[3] - e[1] * e[2], area, &d1, &d2);
    /* C e of the corner's own edges (e1, e2) = (e~1 / s, s e~2) */
    double gD[4] = {e[3] * s, -e[2] * s, -e[1] / s, e[0] / s};
    double sign = d1 > 0.0 ? 1.0 : -1.0;
    for (int i = 0; i < 4; i++) {
        ge[i] = S[i] * ge[i] + d1 * gD[i];
        for (int j = 0; j < 4; j++)
            He[4 * i + j] =
                S[i] * S[j] * He[4 * i + j] + d2 * gD[i] * gD[j] +
                (exact ? d1 * C[4 * i + j] : fabs(d1) * 0.5 * ((i == j) + sign * C[4 * i + j]));
    }
}

/* How vertex p moves: dz = T du with u its unknowns, T the identity for a
 * free vertex, (tangent, 0) for a sliding one; 0 when it does not move. */
static int vertex_frame(const relax_work *w, int p, double T[4])
{
    if (w->var[p] < 0) return 0;
    int slides = w->edge[p] >= 0;
    T[0] = slides ? w->tan[2 * p] : 1.0;
    T[1] = 0.0;
    T[2] = slides ? w->tan[2 * p + 1] : 0.0;
    T[3] = slides ? 0.0 : 1.0;
    return 1;
}

/* The Hessian blocks of one corner between its vertices c, a, b (roles 0,
 * 1, 2) in the plane, from the 2 x 2 blocks Hij of He (e = (e1, e2) with
 * e1 = a - c, e2 = b - c): aa = H11, ab = H12, bb = H22, ca = -(H11 + H21),
 * cb = -(H12 + H22), cc = H11 + H12 + H21 + H22; in the order (c,c) (c,a)
 * (c,b) (a,a) (a,b) (b,b), each row-major. */
static void corner_blocks(const double He[16], double M[6][4])
{
    double H[2][2][4];
    for (int i = 0; i < 2; i++)
        for (int j = 0; j < 2; j++)
            for (int r = 0; r < 2; r++)
                for (int c = 0; c < 2; c++)
                    H[i][j][2 * r + c] = He[4 * (2 * i + r) + 2 * j + c];
    for (int k = 0; k < 4; k++) {
        M[3][k] = H[0][0][k];
        M[4][k] = H[0][1][k];
        M[5][k] = H[1][1][k];
        M[1][k] = -(H[0][0][k] + H[1][0][k]);
        M[2][k] = -(H[0][1][k] + H[1][1][k]);
        M[0][k] = H[0][0][k] + H[0][1][k] + H[1][0][k] + H[1][1][k];
    }
}

/* Vertex p's velocity under symmetry k (relax_work) in its unknowns: the
 * rotation about the centre, i (z - c); the disc's automorphisms
 * z -> (z - a) / (1 - conj(a) z) at a = 0, in w = (z - c) / R: dw = b -
 * conj(b) w^2 for b = 1 and i (tangent to the circle on it).  A sliding
 * vertex's: the component along its tangent (the pinned unknown 0). */
static void symmetry_velocity(const relax_work *w, const double *xy, int p, int k, double v[2])
{
    const double x = (xy[0] - w->centre[0]) / w->radius, y = (xy[1] - w->centre[1]) / w->radius;
    const double R = w->radius;
    if (k == 0) /* i w */
        v[0] = -R * y, v[1] = R * x;
    else if (k == 1) /* 1 - w^2 */
        v[0] = R * (1.0 - x * x + y * y), v[1] = -2.0 * R * x * y;
    else /* i (1 + w^2) */
        v[0] = -2.0 * R * x * y, v[1] = R * (1.0 + x * x - y * y);
    if (w->edge[p] < 0) return;
    const double *t = &w->tan[2 * p];
    v[0] = t[0] * v[0] + t[1] * v[1];
    v[1] = 0.0;
}

/* The symmetries' velocities at m's vertices in the unknowns (w->modes of
 * them, 3 ndof in b), orthonormalized by Gram-Schmidt in the unknowns' dot
 * product; one that is nearly a combination of those before it, below
 * 1e-12 of its squared norm (a mesh too small to tell them apart), is left
 * zero. */
static void symmetry_basis(const sq_relax_mesh *m, const relax_work *w, double *b)
{
    const size_t n = (size_t)w->ndof;
    for (int k = 0; k < w->modes; k++) {
        double *bk = &b[k * n], nn = 0.0, n0 = 0.0;
        for (int i = 0; i < m->nv; i++)
            if (w->var[i] >= 0) symmetry_velocity(w, &m->xy[2 * i], i, k, &bk[w->var[i]]);
        for (size_t r = 0; r < n; r++)
            n0 += bk[r] * bk[r];
        for (int j = 0; j < k; j++) {
            double dot = 0.0;
            for (size_t r = 0; r < n; r++)
                dot += bk[r] * b[j * n + r];
            for (size_t r = 0; r < n; r++)
                bk[r] -= dot * b[j * n + r];
        }
        for (size_t r = 0; r < n; r++)
            nn += bk[r] * bk[r];
        for (size_t r = 0; r < n; r++)
            bk[r] = nn > 1e-12 * n0 ? bk[r] / sqrt(nn) : 0.0;
    }
}

/* x (unknowns) less its components along the symmetries (b from
 * symmetry_basis). */
static void remove_symmetries(const relax_work *w, const double *b, double *x)
{
    const size_t n = (size_t)w->ndof;
    for (int k = 0; k < w->modes; k++) {
        double dot = 0.0;
        for (size_t r = 0; r < n; r++)
            dot += x[r] * b[k * n + r];
        for (size_t r = 0; r < n; r++)
            x[r] -= dot * b[k * n + r];
    }
}

/* The Newton direction d: (H + shift) d = -g, H the sum of the corners'
 * projected Hessians, assembled in place in w->A.  Solved by conjugate
 * gradients preconditioned with the last factorization (made at an earlier
 * step, or by the relaxation before), to PCG_RTOL: a few iterations while
 * the vertices move little, much cheaper than factoring; by factoring H
 * when fresh, at the first step of all, or when PCG_MAXIT iterations do
 * not do: *factored.  exact: H the corners' exact Hessians, by PCG only.
 * eps > 0: the untangling energy's (target unused).  *gd = g . d. */
static sq_status newton_direction(const sq_relax_mesh *m, relax_work *w, int fresh, int exact,
                                  const double *target, double eps, double *d, double *gd,
                                  int *factored, sq_error *err)
{
    double *g = calloc((size_t)w->ndof + 1, sizeof(double)),
           *gx = calloc(2 * (size_t)m->nv + 1, sizeof(double)),
           *diag = calloc((size_t)w->ndof + 1, sizeof(double)),
           *sym = w->modes ? malloc(sizeof(double) * (3 * (size_t)w->ndof + 1)) : NULL;
    sq_status st = !g || !gx || !diag || (w->modes && !sym)
                       ? SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory")
                   : w->factored ? sem_sparse_reset(w->A, err)
                                 : SQ_OK; /* the first assembly */
    sem_sparse *A = w->A;
    fresh |= !w->factored;
    double *x = st == SQ_OK ? sem_sparse_values(A) : NULL;
    for (int q = 0; q < m->nq && st == SQ_OK; q++)
        for (int k = 0; k < 4 && st == SQ_OK; k++) {
            int v[3];
            corner_vertices(m, q, k, v);
            const double *c = &m->xy[2 * v[0]], *a = &m->xy[2 * v[1]], *b = &m->xy[2 * v[2]];
            double e[4] = {a[0] - c[0], a[1] - c[1], b[0] - c[0], b[1] - c[1]}, ge[4], He[16];
            if (eps > 0.0) {
                untangle_derivatives(e, eps, ge, He);
            } else {
                double sc = corner_target(target, q, k, e);
                corner_derivatives(e, exact, ge, He);
                if (target) target_derivatives(target[2 * q + 1], sc, e, exact, ge, He);
            }
            /* the gradient in the plane, per vertex (a sliding vertex's
             * component along its tangent below) */
            gx[2 * v[0]] -= ge[0] + ge[2];
            gx[2 * v[0] + 1] -= ge[1] + ge[3];
            gx[2 * v[1]] += ge[0];
            gx[2 * v[1] + 1] += ge[1];
            gx[2 * v[2]] += ge[2];
            gx[2 * v[2] + 1] += ge[3];
            double T[3][4], M[6][4];
            int moves[3];
            for (int r = 0; r < 3; r++)
                moves[r] = vertex_frame(w, v[r], T[r]);
            corner_blocks(He, M);
            const int32_t *pos = &w->pos[24 * (4 * q + k)];
            for (int r = 0, pr = 0; r < 3; r++)
                for (int t = r; t < 3; t++, pr++, pos += 4) {
                    if (!moves[r] || !moves[t]) continue;
                    /* K = T_r^T M T_t */
                    const double *B = M[pr], *R = T[r], *C = T[t];
                    double MT[4] = {B[0] * C[0] + B[1] * C[2], B[0] * C[1] + B[1] * C[3],
                                    B[2] * C[0] + B[3] * C[2], B[2] * C[1] + B[3] * C[3]};
                    double K[4] = {R[0] * MT[0] + R[2] * MT[2], R[0] * MT[1] + R[2] * MT[3],
                                   R[1] * MT[0] + R[3] * MT[2], R[1] * MT[1] + R[3] * MT[3]};
                    if (r == t) {
                        diag[w->dof[v[r]]] += K[0];
                        diag[w->dof[v[r]] + 1] += K[3];
                    }
                    for (int e = 0; e < 4; e++)
                        if (pos[e] >= 0) x[pos[e]] += K[e];
                }
        }
    for (int i = 0; i < m->nv && st == SQ_OK; i++) {
        int k = w->dof[i];
        if (k < 0) continue;
        if (w->var[i] < 0) {
            /* held this time: unit diagonal, no coupling, no right-hand side */
            st = sem_sparse_add(A, k, k, 1.0, err);
            if (st == SQ_OK) st = sem_sparse_add(A, k + 1, k + 1, 1.0, err);
            continue;
        }
        const double *t = &w->tan[2 * i], *gi = &gx[2 * i];
        if (w->edge[i] < 0) {
            g[k] = gi[0];
            g[k + 1] = gi[1];
            continue;
        }
        g[k] = t[0] * gi[0] + t[1] * gi[1];
        /* Along the curve x(s), E'' = t^T H t + x''(s) . grad E with
         * x'' = kappa n, n the left normal (the chain rule): the curve's
         * own bending, the Weingarten term of a Hessian restricted to a
         * submanifold (Absil, Mahony & Trumpf 2013, "An extrinsic look at
         * the Riemannian Hessian").  At the optimum grad E is normal
         * to the curve, not zero, so without it the steps converge only
         * linearly where the curve bends (stress face 0003_bspline: 28
         * steps at a ratio of 0.4, 17 with it; nautilus at --size 0.05:
         * 25 steps and 16 factorizations, 10 and 3); in the projected
         * Hessian its positive part alone, as for the corners' eigenvalues,
         * all of it in the exact one */
        const double bend = w->kappa[i] * (t[0] * gi[1] - t[1] * gi[0]);
        if (exact || bend > 0.0) st = sem_sparse_add(A, k, k, bend, err);
        /* the pinned second unknown: a unit diagonal, no coupling, no
         * right-hand side */
        if (st == SQ_OK) st = sem_sparse_add(A, k + 1, k + 1, 1.0, err);
    }
    /* a small shift keeps the system definite where a projected Hessian
     * lost rank */
    for (int i = 0; i < w->ndof && st == SQ_OK; i++)
        st = sem_sparse_add(A, i, i, 1e-8 * diag[i] + 1e-300, err);
    for (int i = 0; i < w->ndof; i++)
        g[i] = -g[i];
    /* on a symmetric face only H's shift holds the symmetries' motions: the
     * right-hand side and the direction are kept orthogonal to them
     * (prepare) */
    if (st == SQ_OK && w->modes) {
        symmetry_basis(m, w, sym);
        remove_symmetries(w, sym, g);
    }
    int iters = 0, converged = 0;
    if (st == SQ_OK && !fresh)
        st = sem_sparse_pcg(A, g, d, PCG_RTOL, exact ? PCG_MAXIT_EXACT : PCG_MAXIT, &iters,
                            &converged, err);
    /* the exact Hessian is not factored (it may be indefinite): without a
     * solution by PCG there is no exact step (the caller goes back to
     * projected steps or stops: tail_retreat) */
    if (st == SQ_OK && exact && !converged) {
        memset(d, 0, sizeof(double) * ((size_t)w->ndof + 1));
        converged = 1;
    }
    *factored = !converged;
    if (st == SQ_OK && !converged) st = sem_sparse_factor(A, err);
    w->factored |= st == SQ_OK && !converged;
    if (st == SQ_OK && !converged) st = sem_sparse_solve(A, g, d, err);
    if (st == SQ_OK && w->modes) remove_symmetries(w, sym, d);
    *gd = 0.0;
    for (int i = 0; i < w->ndof; i++)
        *gd -= g[i] * d[i];
    free(g);
    free(gx);
    free(diag);
    free(sym);
    return st;
}

/* Vertices at p + t d (sliding ones along their curve from s0). */
static sq_status place(const cad_face *face, const sq_relax_mesh *m, relax_work *w, const double *p,
                       const double *s0, const double *d, double t, sq_error *err)
{
    for (int i = 0; i < m->nv; i++) {
        int k = w->var[i];
        if (k < 0) continue;
        if (w->edge[i] >= 0) {
            w->s[i] = s0[i] + t * d[k];
            SQ_TRY(qr_on_edge(face, w, i, &w->s[i], &m->xy[2 * i], NULL, NULL, err));
        } else {
            m->xy[2 * i] = p[2 * i] + t * d[k];
            m->xy[2 * i + 1] = p[2 * i + 1] + t * d[k + 1];
        }
    }
    return SQ_OK;
}

/* Arc length of boundary vertex v on CAD edge t: its own if it slides
 * there, else the projection (a held vertex, projected once: *held < 0). */
static sq_status arc_length(const cad_face *face, const relax_work *w, int v, int t, const double xy[2],
                            double *held, double *s, sq_error *err)
{
    if (w->edge[v] == t) {
        *s = w->s[v];
        return SQ_OK;
    }
    if (*held < 0.0) SQ_TRY(cad_face_edge_project(face, t, xy, held, NULL, NULL, err));
    *s = *held;
    return SQ_OK;
}

/* Does the curve under a boundary side cross the line of its quad's
 * opposite side: its point halfway (in arc length) between the side's ends
 * to the right of the opposite side, the curved quad folded whatever its
 * interior nodes.  held: 2 per quad side, the arc lengths of held ends;
 * was: 1 per quad side, its state at the start, filled when init.  *grown:
 * a side folded that was not at the start (one that was, such as a thin
 * boundary-layer cell on a curved wall that the caller rebuilds after the
 * relaxation, is not the relaxation's doing). */
static sq_status boundary_folds(const cad_face *face, const sq_relax_mesh *m, const relax_work *w,
                                double *held, char *was, int init, int *grown, sq_error *err)
{
    *grown = 0;
    for (int q = 0; q < m->nq && !*grown; q++)
        for (int k = 0; k < 4 && !*grown; k++) {
            int t = m->side_tag[4 * q + k];
            if (t < 0 || (!init && was[4 * q + k])) continue;
            const int *c = &m->quad[4 * q];
            double sa, sb, L = cad_face_edge_length(face, t), x[2];
            double *h = &held[2 * (4 * q + k)];
            SQ_TRY(arc_length(face, w, c[k], t, &m->xy[2 * c[k]], &h[0], &sa, err));
            SQ_TRY(arc_length(face, w, c[(k + 1) % 4], t, &m->xy[2 * c[(k + 1) % 4]], &h[1], &sb,
                              err));
            double mid = 0.5 * (sa + sb);
            /* on a closed edge, the side may span its closing point */
            if (fabs(sb - sa) > 0.5 * L) mid += mid < 0.5 * L ? 0.5 * L : -0.5 * L;
            SQ_TRY(cad_face_edge_eval(face, t, mid, x, NULL, NULL, err));
            const double *p = &m->xy[2 * c[(k + 2) % 4]], *r = &m->xy[2 * c[(k + 3) % 4]];
            int f = (r[0] - p[0]) * (x[1] - p[1]) - (r[1] - p[1]) * (x[0] - p[0]) < 0.0;
            if (init)
                was[4 * q + k] = (char)f;
            else
                *grown = f;
        }
    return SQ_OK;
}

/* Does the kept work fit this relaxation: the same mesh, nothing free
 * that was fixed when it was made. */
static int work_fits(const relax_work *w, const sq_relax_mesh *m)
{
    if (w->nv != m->nv || w->nq != m->nq) return 0;
    for (int i = 0; i < m->nv; i++)
        if (w->fixed0[i] && !m->fixed[i]) return 0;
    return 1;
}

/* The work for relaxing m: the kept one where it fits, else made (and
 * kept when keep is not NULL); then begun. */
static sq_status acquire(const cad_face *face, const sq_relax_mesh *m, sq_relax_work **keep,
                         relax_work **out, sq_error *err)
{
    relax_work *w = keep ? *keep : NULL;
    if (w && !work_fits(w, m)) {
        sq_relax_work_free(keep);
        w = NULL;
    }
    sq_status st = SQ_OK;
    if (!w) {
        w = calloc(1, sizeof *w);
        st = w ? prepare(face, m, w, err) : SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
        if (st != SQ_OK) sq_relax_work_free(&w);
        if (keep) *keep = w;
    }
    *out = w;
    return st == SQ_OK ? begin(face, m, w, err) : st;
}

/* The smallest area e1 x e2 of a corner of m and the mean of their
 * absolute values; *stuck: a corner that is not convex has none of its
 * three vertices moving. */
static double smallest_corner(const sq_relax_mesh *m, const relax_work *w, double *mean,
                              int *stuck)
{
    double lo = HUGE_VAL, sum = 0.0;
    *stuck = 0;
    for (int q = 0; q < m->nq; q++)
        for (int k = 0; k < 4; k++) {
            int v[3];
            corner_vertices(m, q, k, v);
            const double *c = &m->xy[2 * v[0]], *a = &m->xy[2 * v[1]], *b = &m->xy[2 * v[2]];
            double D = (a[0] - c[0]) * (b[1] - c[1]) - (a[1] - c[1]) * (b[0] - c[0]);
            lo = fmin(lo, D);
            sum += fabs(D);
            *stuck |= !(D > 0.0) && w->var[v[0]] < 0 && w->var[v[1]] < 0 && w->var[v[2]] < 0;
        }
    *mean = sum / (4.0 * m->nq + 1e-300);
    return lo;
}

/* The boundary vertices that slide: their arc lengths and tangents at
 * their current places, the frame of the next Newton direction. */
static sq_status onto_edges(const cad_face *face, sq_relax_mesh *m, relax_work *w, sq_error *err)
{
    for (int i = 0; i < m->nv; i++)
        if (w->var[i] >= 0 && w->edge[i] >= 0)
            SQ_TRY(qr_on_edge(face, w, i, &w->s[i], &m->xy[2 * i], &w->tan[2 * i], &w->kappa[i],
                              err));
    return SQ_OK;
}

/* Backtracking along d from m's vertices (saved in p and s0): the step
 * t d for t = 1, 1/2, ... until the energy (target, eps) falls below E;
 * *E1 that energy, *h the halvings it took.  When none of MAX_HALVINGS
 * does (*h = MAX_HALVINGS) or a placement fails, m is put back at p, s0. */
static sq_status backtrack(const cad_face *face, sq_relax_mesh *m, relax_work *w, const double *d,
                           const double *target, double eps, double E, double *p, double *s0,
                           double *E1, int *h, sq_error *err)
{
    memcpy(p, m->xy, sizeof(double) * 2 * (size_t)m->nv);
    memcpy(s0, w->s, sizeof(double) * (size_t)m->nv);
    sq_status st = SQ_OK;
    double t = 1.0;
    *E1 = HUGE_VAL;
    for (*h = 0; *h < MAX_HALVINGS && st == SQ_OK; ++*h, t *= 0.5) {
        st = place(face, m, w, p, s0, d, t, err);
        if (st == SQ_OK && (*E1 = energy(m, target, eps)) < E) return SQ_OK;
    }
    memcpy(m->xy, p, sizeof(double) * 2 * (size_t)m->nv);
    memcpy(w->s, s0, sizeof(double) * (size_t)m->nv);
    return st;
}

/* One projected Newton step on the untangling energy at eps, from energy
 * *E, halved until it decreases (*E updated; unchanged when no step does).
 * d, p, s0: scratch of the sizes sq_quad_relax gives them. */
static sq_status untangle_step(const cad_face *face, sq_relax_mesh *m, relax_work *w, double eps,
                               double *d, double *p, double *s0, double *E, sq_error *err)
{
    double gd = 0.0, E1;
    int factored = 0, h;
    sq_status st = onto_edges(face, m, w, err);
    if (st == SQ_OK) st = newton_direction(m, w, 0, 0, NULL, eps, d, &gd, &factored, err);
    if (st != SQ_OK || !(gd < 0.0)) return st;
    st = backtrack(face, m, w, d, NULL, eps, *E, p, s0, &E1, &h, err);
    if (st == SQ_OK && h < MAX_HALVINGS) *E = E1;
    return st;
}

/* Untangling (Garanzha et al. 2021, section 3): the untangling energy
 * minimized for a decreasing sequence of eps until every corner is convex.
 * After each round of UNTANGLE_STEPS Newton steps, with sigma = max(1 -
 * E / E0, 1/10) (E0, E the energy before and after the round) and D- the
 * smallest corner area, mu = (1 - sigma) chi(D-, eps) and the next eps =
 * 2 sqrt(mu (mu - D-)), the eps at which chi(D-, eps) = mu: the worst
 * corner's stand-in area shrinks with the energy's progress, so the
 * barrier of the folded corners grows as fast as the minimization can
 * follow.  The first eps is the one with mu a tenth of the mean corner
 * area.  It gives up after UNTANGLE_ROUNDS rounds, a round that lowers
 * nothing, UNTANGLE_PATIENCE rounds in which the worst corner did not
 * open further, or a folded corner with no vertex that moves. */
#define UNTANGLE_ROUNDS 100
#define UNTANGLE_STEPS 4
#define UNTANGLE_PATIENCE 8
sq_status sq_quad_untangle(const cad_face *face, sq_relax_mesh *m, sq_relax_work **keep,
                           sq_error *err)
{
    relax_work *w = NULL;
    sq_status st = acquire(face, m, keep, &w, err);
    double *d = NULL, *p = NULL, *s0 = NULL, mean = 0.0;
    if (st == SQ_OK) {
        d = malloc(sizeof(double) * ((size_t)w->ndof + 1));
        p = malloc(sizeof(double) * 2 * ((size_t)m->nv + 1));
        s0 = malloc(sizeof(double) * ((size_t)m->nv + 1));
        if (!d || !p || !s0) st = SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    }
    int stuck = 0;
    double lo = st == SQ_OK ? smallest_corner(m, w, &mean, &stuck) : 0.0, mu = 0.1 * mean;
    double eps = lo < mu ? 2.0 * sqrt(mu * (mu - lo)) : 0.0;
    int round = 0, since = 0;
    double best = lo;
    /* eps = 0 only where every corner is degenerate: nothing to untangle */
    for (; round < UNTANGLE_ROUNDS && st == SQ_OK && w->ndof > 0 && !(lo > 0.0) && !stuck &&
           eps > 0.0;
         round++) {
        double E0 = energy(m, NULL, eps), E = E0, c[2];
        for (int k = 0; k < UNTANGLE_STEPS && st == SQ_OK; k++)
            st = untangle_step(face, m, w, eps, d, p, s0, &E, err);
        lo = smallest_corner(m, w, &mean, &stuck);
        /* no step lowered the energy: the minimizer at this eps, which
         * the next eps does not change where the fold stays; or the worst
         * corner has not opened for UNTANGLE_PATIENCE rounds */
        if (!(E < E0 * (1.0 - STALL_DROP))) break;
        if (round == 0 || lo > best) best = lo, since = round;
        if (round - since >= UNTANGLE_PATIENCE) break;
        double sigma = fmax(1.0 - E / E0, 0.1);
        mu = (1.0 - sigma) * chi(lo, eps, c);
        if (lo < mu) eps = 2.0 * sqrt(mu * (mu - lo));
    }
    m->folded = !(lo > 0.0);
    if (!keep) sq_relax_work_free(&w);
    free(d);
    free(p);
    free(s0);
    return st;
}

/* Where the Newton steps stand in their tail: the exact steps that end a
 * linear one (tail_done). */
typedef struct {
    int exact;         /* the next step is an exact Newton step */
    int early;         /* its tail began above STALL_DROP of the energy */
    double exact_drop; /* decreases below it (of E) in a linear tail begin them */
    double last_drop;  /* the last step's decrease */
} relax_tail;

/* An exact step failed (PCG found no descent direction, or it needed
 * halving): returns 1 and goes back to projected steps, with a tenfold
 * lower threshold for the next exact ones, where the tail began above
 * STALL_DROP (its model was not yet right, the relaxation goes on);
 * 0 where it did not (the relaxation ends: it is within STALL_DROP). */
static int tail_retreat(relax_tail *t)
{
    if (!t->early) return 0;
    t->exact = t->early = 0;
    t->exact_drop = fmax(0.1 * t->exact_drop, STALL_DROP);
    return 1;
}

/* After a step from energy E to E1 (h halvings, no vertex moved by more
 * than `moved`): 1 when the relaxation has converged; t updated. */
static int tail_done(relax_tail *t, double E, double E1, int h, double moved, double extent)
{
    const double drop = E - E1;
    /* converged: a step moved no vertex by more than CONVERGED of the
     * mesh's extent.  Tight, as the compass search after this decides
     * on small differences of its quality measure: stopped at 1e-6 of
     * the extent, two paths to the same optimum ended in compass
     * results 4e-4 apart in mean eta (triangle.step) */
    int done = moved < CONVERGED * extent || drop < 1e-15 * E;
    /* or stalled: a decrease below STALL_DROP of the energy and at
     * least half the step before's is linear convergence (the inexact
     * directions of a near-symmetry, e.g. a thin ring's vertices drifting
     * along it: stress 0073 moved 1e-5 of the extent per step for 30
     * steps while the energy fell by 1e-10 of itself); stopping leaves
     * what is left of a geometric series of ratio r, r / (1 - r) times
     * the last decrease: under 10 STALL_DROP of the energy for r < 0.9. */
    done |= drop < STALL_DROP * E && drop >= 0.5 * t->last_drop;
    /* A linear tail that this does not stop yet (a ratio from EXACT_RATIO)
     * is ended by exact Newton steps.  Its cause is the projected Hessian,
     * which overestimates the curvature along a soft mode (measured on the
     * disc's rotation along its circle, before its symmetries were removed
     * (prepare): each decrease 1.1-1.8 times its model's, rho): with PCG
     * run to 1e-6 the tail stays linear (0.35).  Near the
     * optimum the exact Hessian is definite there; its step, by PCG
     * preconditioned with the projected Hessian's factor, takes the rest
     * of the series at once, and the tests above stop the relaxation after
     * it or after a few more exact steps.  They begin below EXACT_DROP of
     * the energy; one that fails there goes back to projected steps and
     * the next begin ten times lower (tail_retreat), down to STALL_DROP,
     * below which an exact step that needs halving is the last (its model
     * is off, and the energy within STALL_DROP).  Begun at STALL_DROP
     * alone, the disc at --size 0.1 took 15 steps, the annulus 17; from
     * EXACT_DROP, 9 and 10, to the same energy to 1e-15. */
    if (t->exact && h > 0) done |= !tail_retreat(t);
    /* Exact steps converge quadratically: the next decrease is about
     * this one times its ratio to the one before, (E - E1)^2 /
     * last_drop.  Where that is below the 1e-15 E that stops the
     * relaxation anyway, the exact step just taken is the last (the
     * disc at --size 0.1, its singular points 2e-11 off: exact
     * decreases of 1.2e-10, 1.5e-13, 1.9e-15 and 1.9e-16 of E, the last
     * two, at E's round-off, for nothing; which tail a run takes turns
     * on such last digits). */
    done |= t->exact && drop * drop < 1e-15 * E * t->last_drop;
    if (!t->exact && drop < t->exact_drop * E && drop >= EXACT_RATIO * t->last_drop) {
        t->exact = 1;
        t->early = drop >= STALL_DROP * E;
    }
    t->last_drop = drop;
    return done;
}

sq_status sq_quad_relax(const cad_face *face, sq_relax_mesh *m, sq_relax_work **keep, sq_error *err)
{
    relax_work *w = NULL;
    sq_status st = acquire(face, m, keep, &w, err);
    if (st == SQ_OK) w->steps = 0, w->polls = 0;
    double *d = NULL, *p = NULL, *s0 = NULL, *held = NULL, *target = NULL;
    char *was = NULL;
    m->folded = 0;
    if (st == SQ_OK) {
        d = malloc(sizeof(double) * ((size_t)w->ndof + 1));
        p = malloc(sizeof(double) * 2 * ((size_t)m->nv + 1));
        s0 = malloc(sizeof(double) * ((size_t)m->nv + 1));
        held = malloc(sizeof(double) * 8 * ((size_t)m->nq + 1));
        was = malloc(4 * (size_t)m->nq + 1);
        if (m->sizes) target = malloc(sizeof(double) * 2 * ((size_t)m->nq + 1));
        if (!d || !p || !s0 || !held || !was || (m->sizes && !target))
            st = SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
        if (target) start_targets(m, target);
        for (long i = 0; held && i < 8L * m->nq; i++)
            held[i] = -1.0;
    }
    /* a mesh with a non-convex corner is left to the caller's untangling */
    double E = st == SQ_OK ? energy(m, target, 0.0) : HUGE_VAL, lo[2] = {HUGE_VAL, HUGE_VAL},
           hi[2] = {-HUGE_VAL, -HUGE_VAL};
    for (int i = 0; i < m->nv; i++)
        for (int c = 0; c < 2; c++) {
            lo[c] = fmin(lo[c], m->xy[2 * i + c]);
            hi[c] = fmax(hi[c], m->xy[2 * i + c]);
        }
    const double extent = hypot(hi[0] - lo[0], hi[1] - lo[1]);
    if (st == SQ_OK && m->stop_on_fold) st = boundary_folds(face, m, w, held, was, 1, &m->folded, err);
    int fresh = 0;
    relax_tail t = {0, 0, EXACT_DROP, HUGE_VAL};
    for (int it = 0; it < MAX_NEWTON && st == SQ_OK && w->ndof > 0 && E < HUGE_VAL; it++) {
        sq_progress_report(&m->progress, "relax", it, MAX_NEWTON);
        double gd = 0.0, E1;
        int factored = 0, h;
        st = onto_edges(face, m, w, err);
        if (st == SQ_OK)
            st = newton_direction(m, w, fresh, t.exact, target, 0.0, d, &gd, &factored, err);
        if (st == SQ_OK && t.exact && !(gd < 0.0)) { /* no exact step */
            if (tail_retreat(&t)) continue;
            break;
        }
        if (st != SQ_OK) break;
        fresh = 0;
        w->steps++;
        st = backtrack(face, m, w, d, target, 0.0, E, p, s0, &E1, &h, err);
        /* no decrease left: converged, or an inexact direction, retried
         * with a factorization (m is back where the step began) */
        if (st != SQ_OK || h == MAX_HALVINGS) {
            if (st == SQ_OK && !factored && !t.exact) {
                fresh = 1;
                continue;
            }
            if (st == SQ_OK && t.exact && tail_retreat(&t)) continue;
            break;
        }
        double rho = h == 0 ? (E - E1) / (-0.5 * gd) : 0.0;
        /* a full step that decreased the energy by more than its quadratic
         * model predicted was too short (the projected Hessian overestimates
         * the curvature where it clamped negative eigenvalues): lengthened
         * to the minimum of the parabola through E(0), E'(0) = g.d and E(1),
         * t = 1 / (2 - rho), or, where that parabola has none (rho >= 2),
         * doubled while the energy keeps decreasing.  From DOUBLE_RHO = 1.1,
         * not only for much larger ratios: naca0012's first steps have
         * ratios 1.2-1.3 */
        if (h == 0 && rho > DOUBLE_RHO && rho < 2.0 - 1.0 / MAX_PARABOLA_STEP) {
            st = place(face, m, w, p, s0, d, 1.0 / (2.0 - rho), err);
            double E2 = st == SQ_OK ? energy(m, target, 0.0) : HUGE_VAL;
            if (E2 < E1)
                E1 = E2;
            else if (st == SQ_OK)
                st = place(face, m, w, p, s0, d, 1.0, err);
        } else if (h == 0 && rho > DOUBLE_RHO) {
            double tx = 1.0;
            for (int x = 0; x < MAX_DOUBLINGS && st == SQ_OK; x++, tx *= 2.0) {
                st = place(face, m, w, p, s0, d, 2.0 * tx, err);
                double E2 = st == SQ_OK ? energy(m, target, 0.0) : HUGE_VAL;
                if (!(E2 < E1)) break;
                E1 = E2;
            }
            if (st == SQ_OK) st = place(face, m, w, p, s0, d, tx, err);
        }
        double moved = 0.0;
        for (int i = 0; i < m->nv; i++)
            moved =
                fmax(moved, fabs(m->xy[2 * i] - p[2 * i]) + fabs(m->xy[2 * i + 1] - p[2 * i + 1]));
        const int done = tail_done(&t, E, E1, h, moved, extent);
        E = E1;
        /* a fold that the relaxation made is not undone by its later steps
         * (naca0012 with its singular points free: from the 3rd step on) */
        if (m->stop_on_fold && st == SQ_OK)
            st = boundary_folds(face, m, w, held, was, 0, &m->folded, err);
        if (m->folded || done) break;
    }
    for (int phase = 0; phase < 2 && st == SQ_OK && !m->folded; phase++)
        st = qr_compass(face, m, w, phase, err);
    if (!keep) sq_relax_work_free(&w);
    free(held);
    free(was);
    free(target);
    free(d);
    free(p);
    free(s0);
    return st;
}
