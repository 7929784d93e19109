/* t225: point location (sem/locate.h) on the curved disc mesh (radius 1,
 * 90 triangles, geometry order 4) and on a square with a hole (the hint
 * walk must fall back to the grid across the hole).
 *  - random points: a found (element, r, s) maps back to the point to
 *    1e-12 through the independent Lagrange form of the map (tri_geom.h),
 *    (r,s) is in the reference triangle; points well inside the disc
 *    (|x| < 0.99) are found, points well outside (|x| > 1.01) are not;
 *  - the hint walk from a random element and from the previous answer
 *    along a path agrees with the grid search (same element, or a point
 *    on their common boundary);
 *  - element nodes are found in their own element or a neighbour.
 * The map-back tolerance: Newton stops at a step below 1e-13 in reference
 * units (sem/locate.c), leaving ~1e-26 after its quadratic step, or at a
 * stall at the coordinates' round-off; the locator's map and tri_geom's
 * Lagrange form each carry n kappa_1 U sum |l| |x| (sem_roundoff.h: 1.7e-13
 * at P = 4, |x| <= 1.5): 1e-12. */
#include "locate.h"
#include "test_meshes.h"
#include "test_util.h"

#include <time.h>

static double urand(unsigned long *st)
{
    *st = *st * 6364136223846793005UL + 1442695040888963407UL;
    return (double)(*st >> 11) / 9007199254740992.0;
}

/* Distance from the point to the map of (e, r, s) via the Lagrange form. */
static double mapback(const sem_tri_mesh *m, const sem_tri_lagrange *L, int e, double r, double s,
                      const double xy[2])
{
    double x[2];
    sem_tri_geom_map(L, m->gxy + 2 * (size_t)m->nodes_per_tri * e, r, s, x, NULL);
    return hypot(x[0] - xy[0], x[1] - xy[1]);
}

static int check_mesh(const char *name, const sem_tri_mesh *m, double (*inside)(const double *),
                      double lo, double hi, int npts)
{
    int fail = 0;
    sq_error err;
    sem_locator *loc = NULL;
    sem_tri_lagrange *L = NULL;
    SQ_TEST_OK(sem_locator_create(m, &loc, &err), err);
    SQ_TEST_OK(sem_tri_lagrange_create(m->order, &L, &err), err);
    unsigned long st = 12345;
    int nin = 0, nout = 0;
    for (int k = 0; k < npts; ++k) {
        const double xy[2] = {lo + (hi - lo) * urand(&st), lo + (hi - lo) * urand(&st)};
        int e = -1;
        double r = NAN, s = NAN;
        const int rc = sem_locator_find(loc, xy, -1, &e, &r, &s);
        const double d = inside(xy); /* > 0 inside, < 0 outside, margin */
        char what[96];
        snprintf(what, sizeof what, "%s point %d (%.6f, %.6f)", name, k, xy[0], xy[1]);
        if (d > 0.01) fail += sq_check_int(what, "found (0)", rc, 0);
        if (d < -0.01) fail += sq_check_int(what, "outside (1)", rc, 1);
        if (rc != 0) {
            ++nout;
            /* a hint must not change the verdict */
            int e2 = -1;
            double r2, s2;
            fail += sq_check_int(what, "outside with a hint", sem_locator_find(loc, xy, k % m->ntris, &e2, &r2, &s2), 1);
            continue;
        }
        ++nin;
        fail += sq_check_abs(what, "map back distance", mapback(m, L, e, r, s, xy), 0.0, 1e-12);
        if (!sem_locator_inside(r, s)) {
            printf("%s: (r,s) = (%g,%g) outside the reference triangle\n", what, r, s);
            ++fail;
        }
        /* walk from a random hint */
        const int hint = (int)(urand(&st) * m->ntris);
        int e2 = -1;
        double r2 = NAN, s2 = NAN;
        fail += sq_check_int(what, "found from a hint", sem_locator_find(loc, xy, hint, &e2, &r2, &s2), 0);
        if (e2 != e) /* on a shared boundary: both must contain it */
            fail += sq_check_abs(what, "hint walk map back", mapback(m, L, e2, r2, s2, xy), 0.0, 1e-12);
    }
    if (nin < npts / 4 || nout < npts / 20) {
        printf("%s: %d inside, %d outside of %d: sample not representative\n", name, nin, nout, npts);
        ++fail;
    }
    /* every geometry node of every element */
    for (int e = 0; e < m->ntris; ++e)
        for (int n = 0; n < m->nodes_per_tri; ++n) {
            const double *xy = m->gxy + 2 * ((size_t)m->nodes_per_tri * e + n);
            int f = -1;
            double r, s;
            if (sem_locator_find(loc, xy, e, &f, &r, &s) != 0) {
                printf("%s: node %d of element %d not found\n", name, n, e);
                ++fail;
                continue;
            }
            char what[64];
            snprintf(what, sizeof what, "%s node %d of element %d", name, n, e);
            fail += sq_check_abs(what, "map back distance", mapback(m, L, f, r, s, xy), 0.0, 1e-12);
        }
    /* a path with the previous element as hint (the tracing use), timed */
    {
        const int nstep = 200000;
        int e = -1, bad = 0;
        double r, s;
        struct timespec t0, t1;
        clock_gettime(CLOCK_MONOTONIC, &t0);
        for (int k = 0; k < nstep; ++k) {
            const double th = 2 * TM_PI * k / nstep * 3, rad = 0.25 + 0.5 * k / nstep;
            const double xy[2] = {0.5 * (lo + hi) + rad * (hi - lo) * 0.5 * cos(th),
                                  0.5 * (lo + hi) + rad * (hi - lo) * 0.5 * sin(th)};
            if (sem_locator_find(loc, xy, e, &e, &r, &s) != 0) {
                e = -1;
                continue;
            }
            if (k % 997 == 0 && mapback(m, L, e, r, s, xy) > 1e-12) ++bad;
        }
        clock_gettime(CLOCK_MONOTONIC, &t1);
        const double us = ((t1.tv_sec - t0.tv_sec) * 1e6 + (t1.tv_nsec - t0.tv_nsec) * 1e-3) / nstep;
        if (getenv("SQ_VERBOSE")) printf("%s: %.3f us per located point along a path\n", name, us);
        fail += sq_check_int(name, "path points not mapping back", bad, 0);
    }
    sem_tri_lagrange_free(&L);
    sem_locator_free(&loc);
    return fail;
}

static double in_disc(const double *x) { return 1.0 - hypot(x[0], x[1]); }
/* unit square minus [0.375, 0.625]^2 */
static double in_holed(const double *x)
{
    const double d_out = fmin(fmin(x[0], 1 - x[0]), fmin(x[1], 1 - x[1]));
    const double d_hole = fmax(fabs(x[0] - 0.5), fabs(x[1] - 0.5)) - 0.125;
    return fmin(d_out, d_hole);
}

/* The 8 x 8 square mesh (geometry order 2) without the cells of
 * [0.375, 0.625]^2. */
static sem_tri_mesh *holed_square(void)
{
    sem_tri_mesh *full = tm_square(8, 2), *m = NULL;
    if (!full) return NULL;
    int keep = 0;
    int *ok = calloc((size_t)full->ntris, sizeof(int));
    for (int t = 0; t < full->ntris; ++t) {
        double cx = 0, cy = 0;
        for (int k = 0; k < 3; ++k) {
            cx += full->vxy[2 * full->tri[3 * t + k]] / 3;
            cy += full->vxy[2 * full->tri[3 * t + k] + 1] / 3;
        }
        ok[t] = !(fabs(cx - 0.5) < 0.125 && fabs(cy - 0.5) < 0.125);
        keep += ok[t];
    }
    if (sem_tri_mesh_create(2, full->nverts, keep, &m, NULL) == SQ_OK) {
        for (int v = 0; v < 2 * full->nverts; ++v) m->vxy[v] = full->vxy[v];
        int j = 0;
        for (int t = 0; t < full->ntris; ++t) {
            if (!ok[t]) continue;
            for (int k = 0; k < 3; ++k) m->tri[3 * j + k] = full->tri[3 * t + k];
            for (int n = 0; n < 2 * m->nodes_per_tri; ++n)
                m->gxy[2 * (size_t)m->nodes_per_tri * j + n] = full->gxy[2 * (size_t)m->nodes_per_tri * t + n];
            ++j;
        }
        if (sem_tri_mesh_build_neighbours(m, NULL) != SQ_OK) sem_tri_mesh_free(&m);
    }
    free(ok);
    sem_tri_mesh_free(&full);
    return m;
}

int main(void)
{
    int fail = 0;
    sem_tri_mesh *disc = tm_disc(1.0, 3, 4), *holed = holed_square();
    if (!disc || !holed) return 1;
    fail += check_mesh("disc", disc, in_disc, -1.2, 1.2, 20000);
    fail += check_mesh("holed square", holed, in_holed, -0.1, 1.1, 20000);
    /* non-finite input */
    sem_locator *loc = NULL;
    sq_error err;
    SQ_TEST_OK(sem_locator_create(disc, &loc, &err), err);
    const double bad[2] = {NAN, 0.0};
    int e;
    double r, s;
    fail += sq_check_int("NaN point", "outside", sem_locator_find(loc, bad, 0, &e, &r, &s), 1);
    sem_locator_free(&loc);
    sem_tri_mesh_free(&disc);
    sem_tri_mesh_free(&holed);
    return fail ? 1 : 0;
}
