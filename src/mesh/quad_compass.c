/* semquad — the compass search that polishes the relaxed mesh's worst
 * quads (quad_relax.c runs it after the Newton steps on Winslow's energy):
 * each free vertex tries 8 directions (2 along its CAD edge) while the
 * quads around it get better. */
#include "quad_relax_private.h"

#include "quad_mesh.h"

#include <math.h>
#include <stdlib.h>

#define WORST_ETA 0.55
#define WORST_SWEEPS 50
#define FIRST_STEP 0.25         /* of the shortest side around the vertex */
#define LAST_STEP (1.0 / 256.0) /* the last step tried: above this */
#define MIN_TAPER 0.3
#define MAX_STRETCH 5.0
#define TAU_ETA 0.9

/* The worst corner of a counter-clockwise quad (corners c[4], side k from
 * c[k] to c[k+1]) by eta, from its corners' cross products det[k] =
 * (c[k+1] - c[k]) x (c[k+3] - c[k]), dot products dot[k] and squared side
 * lengths l[k], without an angle: its index, and in *bad its cos^2, or 2
 * (worse than any convex quad's) when the quad is not convex.  eta = 1 -
 * max_k |theta_k - 90 deg| / 90 deg (docs/conventions.md, "Quality"): a
 * quad with a corner of det <= 0 has a corner of 180 deg or more, eta <= 0;
 * in a convex one every theta_k lies in (0, 180 deg), where |theta_k - 90
 * deg| grows with cos^2 theta_k = dot[k]^2 / (l[k] l[k+3]).  So quads
 * compare by *bad, and only the angle that decides is taken (corner_eta):
 * this is the compass search's innermost evaluation (8 directions x up to 6
 * step lengths x the quads around each vertex, per sweep), whose four atan2
 * per quad were half the time of a 26 000-quad sliver (stress corpus 0073). */
static int worst_corner(const double det[4], const double dot[4], const double l[4], double *bad)
{
    int worst = 0;
    *bad = -1.0;
    for (int k = 0; k < 4; k++) {
        if (!(det[k] > 0.0)) {
            *bad = 2.0;
            return k;
        }
        double c2 = dot[k] * dot[k] / (l[k] * l[(k + 3) % 4]);
        if (c2 > *bad) *bad = c2, worst = k;
    }
    return worst;
}

/* eta of a quad whose worst corner (worst_corner) has cross and dot
 * products det, dot and badness bad: sq_quad_corner_eta's value
 * (quad_quality.c: the same atan2, in degrees) clamped at 0. */
static double corner_eta(double det, double dot, double bad)
{
    if (bad > 1.0) return 0.0;
    double deg = 180.0 / M_PI, eta = 1.0 - fabs(atan2(det, dot) * deg - 90.0) / 90.0;
    return eta > 0.0 ? eta : 0.0;
}

/* The quads around vertex i: their worst eta (0 for a quad that is not
 * convex), how many are distorted otherwise (corner Jacobians' ratio below
 * MIN_TAPER or sides longer than MAX_STRETCH times the shortest: a move
 * that keeps the angles may still shrink a side), the shortest of their
 * sides, and, with score set (compass phase 1, which compares it; phase 0
 * needs only the worst quad's eta), their score: the sum of min(eta,
 * TAU_ETA), plus a hundredth of the sum of eta to prefer better quads among
 * equal scores.  Minima and maxima by comparison, not fmin/fmax (library
 * calls here, a tenth of the time; no NaN reaches them from a finite
 * mesh). */
typedef struct {
    double worst, shortest, score;
    int distorted;
} around_quality;

static around_quality around(const sq_relax_mesh *m, const relax_work *w, int i, int score)
{
    around_quality r = {1.0, HUGE_VAL, 0.0, 0};
    double wbad = -1.0, wdet = 1.0, wdot = 0.0; /* the worst quad's worst corner */
    for (int t = w->start[i]; t < w->start[i + 1]; t++) {
        const int *q = &m->quad[4 * w->around[t]];
        const double *c[4];
        for (int k = 0; k < 4; k++)
            c[k] = &m->xy[2 * q[k]];
        /* sides compared by their squares */
        double det[4], dot[4], l[4], dmin = HUGE_VAL, dmax = 0.0, lmin = HUGE_VAL, lmax = 0.0;
        for (int k = 0; k < 4; k++) {
            const double *p = c[k], *a = c[(k + 1) % 4], *b = c[(k + 3) % 4];
            double ax = a[0] - p[0], ay = a[1] - p[1], bx = b[0] - p[0], by = b[1] - p[1];
            det[k] = ax * by - ay * bx;
            dot[k] = ax * bx + ay * by;
            l[k] = ax * ax + ay * ay;
            if (det[k] < dmin) dmin = det[k];
            if (det[k] > dmax) dmax = det[k];
            if (l[k] < lmin) lmin = l[k];
            if (l[k] > lmax) lmax = l[k];
        }
        double shortest = sqrt(lmin), bad;
        if (shortest < r.shortest) r.shortest = shortest;
        r.distorted += !(dmin / dmax >= MIN_TAPER) || !(lmax <= MAX_STRETCH * MAX_STRETCH * lmin);
        int k = worst_corner(det, dot, l, &bad);
        if (bad > wbad) wbad = bad, wdet = det[k], wdot = dot[k];
        if (!score) continue;
        double eta = corner_eta(det[k], dot[k], bad);
        r.score += (eta < TAU_ETA ? eta : TAU_ETA) + 0.01 * eta;
    }
    if (wbad >= 0.0) r.worst = corner_eta(wdet, wdot, wbad);
    return r;
}

/* Is y better than x: no more distorted quads, and phase 0 raises the
 * worst eta (where it is below WORST_ETA); phase 1 raises the score
 * without lowering the worst. */
static int better(int phase, around_quality y, around_quality x)
{
    if (y.distorted > x.distorted) return 0;
    return phase == 0 ? y.worst > x.worst + 1e-12
                      : y.score > x.score + 1e-12 && y.worst >= x.worst - 1e-12;
}

/* Compass search on the vertices, after the energy's optimum: phase 0,
 * where a quad is still poor (a corner that the layout forces to an
 * awkward angle pulls its neighbours along), raises the worst eta around
 * each vertex; phase 1 lifts the quads just below eta = TAU_ETA (the
 * neighbours of quads whose angles a corner or a singular point fixes)
 * without lowering any worst eta.  Each move must improve the quads it
 * touches.  The step is a fraction of the shortest side around the vertex,
 * kept per vertex from one visit to the next as compass search keeps its
 * step length (Kolda, Lewis and Torczon, SIAM Review 45(3) 2003, Alg. 3.1:
 * halved after a poll without a better point, doubled up to FIRST_STEP
 * after a success) rather than restarted at FIRST_STEP: a vertex that keeps
 * improving by small moves (a thin face's many flat quads, each revisited
 * after every neighbour's move) then polls 8-16 points, not up to 48 */
sq_status qr_compass(const cad_face *face, const sq_relax_mesh *m, relax_work *w, int phase,
                     sq_error *err)
{
    static const double DIR[8][2] = {{1, 0},  {0.7071, 0.7071},   {0, 1},  {-0.7071, 0.7071},
                                     {-1, 0}, {-0.7071, -0.7071}, {0, -1}, {0.7071, -0.7071}};
    /* a vertex is looked at again only after a neighbour moved */
    char *active = malloc((size_t)m->nv + 1);
    double *frac = malloc(sizeof(double) * ((size_t)m->nv + 1));
    if (!active || !frac) {
        free(active);
        free(frac);
        return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    }
    for (int i = 0; i < m->nv; i++) {
        active[i] = w->var[i] >= 0;
        frac[i] = FIRST_STEP;
    }
    sq_status st = SQ_OK;
    for (int sweep = 0; sweep < WORST_SWEEPS && st == SQ_OK; sweep++) {
        int moved = 0;
        for (int i = 0; i < m->nv && st == SQ_OK; i++) {
            if (!active[i]) continue;
            active[i] = 0;
            around_quality cur = around(m, w, i, phase);
            w->polls++;
            if (phase == 0 ? cur.worst >= WORST_ETA : cur.worst >= TAU_ETA) continue;
            double *x = &m->xy[2 * i], x0[2] = {x[0], x[1]}, s0 = w->s[i], len = cur.shortest;
            for (double f = frac[i]; f > LAST_STEP && st == SQ_OK; f *= 0.5) {
                double h = f * len;
                around_quality best = cur;
                double bx[2] = {x0[0], x0[1]}, bs = s0;
                int ndir = w->edge[i] >= 0 ? 2 : 8;
                for (int k = 0; k < ndir && st == SQ_OK; k++) {
                    if (w->edge[i] >= 0) {
                        w->s[i] = s0 + (k ? -h : h);
                        st = qr_on_edge(face, w, i, &w->s[i], x, NULL, NULL, err);
                    } else {
                        x[0] = x0[0] + h * DIR[k][0];
                        x[1] = x0[1] + h * DIR[k][1];
                    }
                    around_quality e = around(m, w, i, phase);
                    w->polls++;
                    if (better(phase, e, best)) {
                        best = e;
                        bx[0] = x[0], bx[1] = x[1], bs = w->s[i];
                    }
                }
                x[0] = bx[0], x[1] = bx[1], w->s[i] = bs;
                if (better(phase, best, cur)) {
                    moved = 1;
                    frac[i] = fmin(2.0 * f, FIRST_STEP);
                    for (int t = w->start[i]; t < w->start[i + 1]; t++)
                        for (int k = 0; k < 4; k++) {
                            int v = m->quad[4 * w->around[t] + k];
                            active[v] = w->var[v] >= 0;
                        }
                    break;
                }
            }
        }
        if (!moved) break;
    }
    free(active);
    free(frac);
    return st;
}
