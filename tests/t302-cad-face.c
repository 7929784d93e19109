/* t302 — cad_face on the examples: loops and edges, lengths, curvature,
 * coordinates, orientation (area by Green's theorem with the edge
 * evaluation), closure, arc-length parametrization and projection, Green
 * integrals along pieces of edges.
 *
 * Tolerances (OpenCASCADE and cad/cad_face.cpp, no BLAS), by what bounds them:
 *  - lengths, Green integrals of circle arcs and lines, points and tangents
 *    of analytic edges (1e-13, values <= 2 pi): adaptive Gauss-Legendre
 *    stopped at 1e-15 of each piece (cad_face.cpp, adapt) summed over a few
 *    tens of pieces, and OCC's closed forms: a few tens of U of the value;
 *  - curvature (1e-12 max(1, kappa)): OCC's second derivative over the
 *    speed squared, a few U relative, of curvatures <= 2;
 *  - |tangent| = 1 (1e-13): the normalised first derivative, a few U;
 *  - projection s, distance and foot (1e-9 L): the code's own slack, 1e-9 L
 *    (cad_face.cpp, cad_face_edge_eval), after Newton from a 1e-12 L
 *    chord table;
 *    tangent at the nearest point the same, relative;
 *  - arc length against int t ds (1e-10 L): s -> u is inverted by Newton
 *    to max(1e-15 L, 1e-8 (sb - sa)) of a table piece (cad_face.cpp,
 *    u_of_s), which a piece's quadratic convergence turns into 1e-16 L;
 *    the test's own 64 x 5-point Gauss rule is exact to far below;
 *  - areas by green() (1e-10, <= 20): the same, summed over all edges;
 *  - corner positions (1e-9): an edge's start is its curve at the first
 *    parameter, a few U from the file's point unless the loop closes a gap
 *    (these files have none); 1e-9 is the code's arc-length slack;
 *  - the naca0012 B-spline (1e-6): its STEP points carry 6 digits. */
#include "cad.h"
#include "t30x_cad.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static cad_model *model;

static cad_face *open_face(const char *name)
{
    char path[4096];
    snprintf(path, sizeof path, "%s/%s.step", getenv("SQ_EXAMPLES"), name);
    sq_error err;
    cad_model_free(&model);
    if (cad_model_read(path, &model, &err) != SQ_OK) {
        fprintf(stderr, "%s: %s\n", path, err.msg);
        exit(1);
    }
    cad_face *f = NULL;
    if (cad_face_create(model, 0, &f, &err) != SQ_OK) {
        fprintf(stderr, "%s face 0: %s\n", path, err.msg);
        exit(1);
    }
    return f;
}

/* Projection of points anywhere around the face (far from the edge, near
 * centres of curvature, beyond its ends): never farther than the closest
 * of 20 000 points along the edge, each refined by golden-section search
 * between its neighbours (the projection prunes chords by a bound, this
 * search does not). */
static void far_projection(const char *name, const cad_face *f, int e, double L)
{
    char what[256];
    double bb[4] = {HUGE_VAL, HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
    enum { NS = 20000 };
    static double xs[NS + 1][2];
    for (int i = 0; i <= NS; ++i) {
        eval(f, e, L * i / NS, xs[i], NULL, NULL);
        bb[0] = fmin(bb[0], xs[i][0]), bb[1] = fmin(bb[1], xs[i][1]);
        bb[2] = fmax(bb[2], xs[i][0]), bb[3] = fmax(bb[3], xs[i][1]);
    }
    const double w = bb[2] - bb[0] + 0.1 * L, h = bb[3] - bb[1] + 0.1 * L;
    unsigned long long r = 12345;
    for (int k = 0; k < 12; ++k) {
        double q[2];
        for (int c = 0; c < 2; ++c) {
            r = r * 6364136223846793005ULL + 1442695040888963407ULL;
            double u = (double)(r >> 11) / 9007199254740992.0;
            q[c] = c == 0 ? bb[0] - 0.05 * L + 2 * w * u - 0.5 * w : bb[1] - 0.05 * L + 2 * h * u - 0.5 * h;
        }
        int best = 0;
        double bd = HUGE_VAL;
        for (int i = 0; i <= NS; ++i) {
            double d = hypot(xs[i][0] - q[0], xs[i][1] - q[1]);
            if (d < bd) bd = d, best = i;
        }
        double a = L * (best > 0 ? best - 1 : 0) / NS, b = L * (best < NS ? best + 1 : NS) / NS;
        for (int it = 0; it < 80; ++it) {
            double m1 = b - 0.618033988749895 * (b - a), m2 = a + 0.618033988749895 * (b - a), p1[2],
                   p2[2];
            eval(f, e, m1, p1, NULL, NULL);
            eval(f, e, m2, p2, NULL, NULL);
            double d1 = hypot(p1[0] - q[0], p1[1] - q[1]), d2 = hypot(p2[0] - q[0], p2[1] - q[1]);
            bd = fmin(bd, fmin(d1, d2));
            if (d1 < d2) b = m2;
            else a = m1;
        }
        double s, dist;
        sq_error err;
        sq_status st = cad_face_edge_project(f, e, q, &s, NULL, &dist, &err);
        CHECK(st == SQ_OK, "%s edge %d project: %s", name, e, err.msg);
        snprintf(what, sizeof what, "%s edge %d projection of (%g, %g): excess over the search",
                 name, e, q[0], q[1]);
        NEAR(what, fmax(0.0, dist - bd), 0.0, 1e-9 * L);
    }
}

/* Generic checks valid for every face. */
static void check_generic(const char *name, const cad_face *f)
{
    char what[256];
    double o[3], x[3], y[3];
    cad_face_frame(f, o, x, y);
    /* Every example lies in z = 0: the frame is the file's own x, y. */
    snprintf(what, sizeof what, "%s frame", name);
    NEAR(what,
         fabs(o[0]) + fabs(o[1]) + fabs(o[2]) + fabs(x[0] - 1) + fabs(x[1]) + fabs(x[2]) +
             fabs(y[0]) + fabs(y[1] - 1) + fabs(y[2]),
         0.0, 1e-15);
    int ne = 0;
    for (int l = 0; l < cad_face_num_loops(f); ++l) {
        int first = cad_face_loop_first_edge(f, l), n = cad_face_loop_num_edges(f, l);
        CHECK(first == ne, "%s loop %d first edge %d, expected %d", name, l, first, ne);
        ne += n;
        /* Orientation: outer counter-clockwise, holes clockwise. */
        double a = green(f, l, 64);
        CHECK(l == 0 ? a > 0 : a < 0, "%s loop %d signed area %g has the wrong sign", name, l, a);
        for (int k = 0; k < n; ++k) {
            int e = first + k, next = first + (k + 1) % n;
            CHECK(cad_face_edge_loop(f, e) == l, "%s edge %d loop %d, expected %d", name, e,
                  cad_face_edge_loop(f, e), l);
            double L = cad_face_edge_length(f, e), p1[2], p0[2];
            eval(f, e, L, p1, NULL, NULL);
            eval(f, next, 0, p0, NULL, NULL);
            snprintf(what, sizeof what, "%s: gap from edge %d to edge %d", name, e, next);
            CHECK(p1[0] == p0[0] && p1[1] == p0[1], "%s: (%.17g, %.17g) vs (%.17g, %.17g)", what,
                  p1[0], p1[1], p0[0], p0[1]);
            /* Arc length: p(b) - p(a) = int_a^b t ds, and |t| = 1. */
            for (int j = 0; j < 7; ++j) {
                double a0 = L * j / 7.0, b0 = a0 + L / 7.0 * 0.37, pa[2], pb[2], t[2], dx = 0,
                       dy = 0;
                eval(f, e, a0, pa, t, NULL);
                snprintf(what, sizeof what, "%s edge %d |tangent| at s=%g", name, e, a0);
                NEAR(what, hypot(t[0], t[1]), 1.0, 1e-13);
                eval(f, e, b0, pb, NULL, NULL);
                int m = 64;
                for (int i = 0; i < m; ++i)
                    for (int q = 0; q < 5; ++q) {
                        double hh = (b0 - a0) / m, s = a0 + (i + 0.5) * hh + 0.5 * hh * GX[q];
                        eval(f, e, s, NULL, t, NULL);
                        dx += 0.5 * hh * GW[q] * t[0];
                        dy += 0.5 * hh * GW[q] * t[1];
                    }
                snprintf(what, sizeof what, "%s edge %d arc length on [%g, %g]", name, e, a0, b0);
                NEAR(what, hypot(pb[0] - pa[0] - dx, pb[1] - pa[1] - dy), 0.0, 1e-10 * L);
            }
            /* Projection: a point off the edge by d along the normal comes back. */
            for (int j = 1; j < 6; ++j) {
                double s0 = L * j / 6.0, p[2], t[2], kap, q[2], s, foot[2], dist;
                eval(f, e, s0, p, t, &kap);
                double d = 0.01 * L;
                if (fabs(kap) > 0 && d > 0.2 / fabs(kap)) d = 0.2 / fabs(kap);
                q[0] = p[0] - d * t[1];
                q[1] = p[1] + d * t[0];
                sq_error err;
                sq_status st = cad_face_edge_project(f, e, q, &s, foot, &dist, &err);
                CHECK(st == SQ_OK, "%s edge %d project: %s", name, e, err.msg);
                snprintf(what, sizeof what, "%s edge %d projection s", name, e);
                NEAR(what, s, s0, 1e-9 * L);
                snprintf(what, sizeof what, "%s edge %d projection distance", name, e);
                NEAR(what, dist, d, 1e-9 * L);
                snprintf(what, sizeof what, "%s edge %d projection foot", name, e);
                NEAR(what, hypot(foot[0] - p[0], foot[1] - p[1]), 0.0, 1e-9 * L);
                /* the tangent at the nearest point: the tangent at s0 */
                double tn[2] = {0.0, 0.0};
                st = cad_face_edge_tangent_near(f, e, q, tn, &err);
                CHECK(st == SQ_OK, "%s edge %d tangent_near: %s", name, e, err.msg);
                snprintf(what, sizeof what, "%s edge %d tangent at the nearest point", name, e);
                NEAR(what, hypot(tn[0] - t[0], tn[1] - t[1]), 0.0, 1e-9);
            }
            far_projection(name, f, e, L);
        }
    }
    CHECK(ne == cad_face_num_edges(f), "%s: loops hold %d edges, face has %d", name, ne,
          cad_face_num_edges(f));
}

/* Edges of the given type in loop l: count, and total length. */
static int count_type(const cad_face *f, int l, cad_edge_type type, double *len)
{
    int c = 0;
    if (len) *len = 0;
    for (int e = 0; e < cad_face_num_edges(f); ++e)
        if (cad_face_edge_loop(f, e) == l && cad_face_edge_type(f, e) == type) {
            ++c;
            if (len) *len += cad_face_edge_length(f, e);
        }
    return c;
}

/* Curvature of every edge of type `type` in loop l at a few points. */
static void check_curvature(const char *name, const cad_face *f, int l, cad_edge_type type,
                            double kappa)
{
    char what[256];
    for (int e = 0; e < cad_face_num_edges(f); ++e) {
        if (cad_face_edge_loop(f, e) != l || cad_face_edge_type(f, e) != type) continue;
        for (int j = 0; j <= 4; ++j) {
            double k;
            eval(f, e, cad_face_edge_length(f, e) * j / 4.0, NULL, NULL, &k);
            snprintf(what, sizeof what, "%s loop %d %s edge %d curvature", name, l,
                     cad_edge_type_name(type), e);
            NEAR(what, k, kappa, 1e-12 * fmax(1.0, fabs(kappa)));
        }
    }
}

/* The corners (edge start points) must be exactly the given points. */
static void check_corners(const char *name, const cad_face *f, int n, const double *pts)
{
    CHECK(cad_face_num_edges(f) == n, "%s: %d edges, expected %d corners", name,
          cad_face_num_edges(f), n);
    for (int i = 0; i < n; ++i) {
        double best = HUGE_VAL;
        for (int e = 0; e < cad_face_num_edges(f); ++e) {
            double p[2];
            eval(f, e, 0, p, NULL, NULL);
            best = fmin(best, hypot(p[0] - pts[2 * i], p[1] - pts[2 * i + 1]));
        }
        char what[256];
        snprintf(what, sizeof what, "%s corner (%g, %g) distance to the nearest edge start", name,
                 pts[2 * i], pts[2 * i + 1]);
        NEAR(what, best, 0.0, 1e-9);
    }
}

int main(void)
{
    if (!getenv("SQ_EXAMPLES")) {
        fprintf(stderr, "SQ_EXAMPLES not set\n");
        return 1;
    }
    const double pi = M_PI;
    double len;
    cad_face *f;

    f = open_face("half_disc");
    check_generic("half_disc", f);
    CHECK(cad_face_num_loops(f) == 1 && cad_face_num_edges(f) == 2, "half_disc: %d loops %d edges",
          cad_face_num_loops(f), cad_face_num_edges(f));
    CHECK(count_type(f, 0, CAD_EDGE_CIRCLE, &len) == 1, "half_disc: one circle expected");
    NEAR("half_disc arc length", len, pi, 1e-13);
    CHECK(count_type(f, 0, CAD_EDGE_LINE, &len) == 1, "half_disc: one line expected");
    NEAR("half_disc segment length", len, 2.0, 1e-13);
    check_curvature("half_disc", f, 0, CAD_EDGE_CIRCLE, 1.0);
    check_curvature("half_disc", f, 0, CAD_EDGE_LINE, 0.0);
    NEAR("half_disc area", green(f, -1, 64), pi / 2, 1e-10);
    check_corners("half_disc", f, 2, (const double[]){1, 0, -1, 0});
    for (int e = 0; e < 2; ++e) /* the arc is the upper half: y >= 0 */
        if (cad_face_edge_type(f, e) == CAD_EDGE_CIRCLE) {
            double p[2], t[2];
            eval(f, e, pi / 2, p, t, NULL);
            NEAR("half_disc arc midpoint x", p[0], 0.0, 1e-13);
            NEAR("half_disc arc midpoint y", p[1], 1.0, 1e-13);
            NEAR("half_disc arc midpoint tangent x (travel to -x)", t[0], -1.0, 1e-13);
            /* x dy - y dx = r^2 dtheta about the centre (the frame's origin) */
            double g[3];
            sq_error err;
            CHECK(cad_face_edge_green(f, e, 0.0, pi / 2, &g[0], &err) == SQ_OK &&
                      cad_face_edge_green(f, e, 0.3, 2.5, &g[1], &err) == SQ_OK &&
                      cad_face_edge_green(f, e, 2.5, 0.3, &g[2], &err) == SQ_OK,
                  "half_disc: cad_face_edge_green failed");
            NEAR("half_disc arc Green integral, first quarter", g[0], pi / 2, 1e-13);
            NEAR("half_disc arc Green integral, s in [0.3, 2.5]", g[1], 2.2, 1e-13);
            NEAR("half_disc arc Green integral, empty range", g[2], 0.0, 0.0);
        }
    cad_face_free(&f);

    f = open_face("annulus");
    check_generic("annulus", f);
    CHECK(cad_face_num_loops(f) == 2 && cad_face_loop_num_edges(f, 0) == 1 &&
              cad_face_loop_num_edges(f, 1) == 1,
          "annulus: %d loops", cad_face_num_loops(f));
    NEAR("annulus outer length", cad_face_edge_length(f, 0), 2 * pi, 1e-13);
    NEAR("annulus hole length", cad_face_edge_length(f, 1), 0.8 * pi, 1e-13);
    check_curvature("annulus", f, 0, CAD_EDGE_CIRCLE, 1.0);
    check_curvature("annulus", f, 1, CAD_EDGE_CIRCLE, -2.5);
    NEAR("annulus area", green(f, -1, 64), 0.84 * pi, 1e-10);
    NEAR("annulus hole area", green(f, 1, 64), -0.16 * pi, 1e-10);
    {
        /* the hole (r = 0.4) travelled clockwise: r^2 dtheta < 0 */
        double g;
        sq_error err;
        CHECK(cad_face_edge_green(f, 1, 0.1, 0.1 + 0.4 * pi, &g, &err) == SQ_OK,
              "annulus: cad_face_edge_green failed");
        NEAR("annulus hole Green integral over half the hole", g, -0.16 * pi, 1e-13);
    }
    cad_face_free(&f);

    f = open_face("square_hole");
    check_generic("square_hole", f);
    CHECK(cad_face_num_loops(f) == 2 && cad_face_loop_num_edges(f, 0) == 4 &&
              cad_face_loop_num_edges(f, 1) == 1 && count_type(f, 0, CAD_EDGE_LINE, NULL) == 4 &&
              count_type(f, 1, CAD_EDGE_CIRCLE, &len) == 1,
          "square_hole: loops/edges");
    NEAR("square_hole hole length", len, 0.5 * pi, 1e-13);
    check_curvature("square_hole", f, 1, CAD_EDGE_CIRCLE, -4.0);
    NEAR("square_hole area", green(f, -1, 64), 1 - pi / 16, 1e-10);
    {
        double foot[2], s, d, p[2] = {0.5, 0.5};
        sq_error err;
        cad_face_edge_project(f, 4, p, &s, foot, &d, &err);
        /* any circle point is a foot here: its distance is a few U; a
         * projection's Newton converges quadratically, so the iterate after
         * its last step (below the 1e-9 L slack) is at round-off: 1e-12 */
        NEAR("square_hole: distance from the hole centre to the hole", d, 0.25, 1e-12);
        p[0] = 2;
        p[1] = 0.5;
        cad_face_edge_project(f, 4, p, &s, foot, &d, &err);
        NEAR("square_hole: projection of (2, 0.5) on the hole, x", foot[0], 0.75, 1e-12);
        NEAR("square_hole: projection of (2, 0.5) on the hole, y", foot[1], 0.5, 1e-12);
        p[0] = 3;
        p[1] = -1;
        cad_face_edge_project(f, 1, p, &s, foot, &d, &err); /* edge from (1,0) to (1,1) */
        NEAR("square_hole: clamped projection s", s, 0.0, 1e-13);
        NEAR("square_hole: clamped projection distance", d, sqrt(5.0), 1e-13);
        CHECK(cad_face_edge_project(f, 5, p, &s, foot, &d, &err) == SQ_ERR_USAGE,
              "project on edge 5 of 5: expected SQ_ERR_USAGE");
        CHECK(cad_face_edge_tangent_near(f, 5, p, foot, &err) == SQ_ERR_USAGE,
              "tangent_near on edge 5 of 5: expected SQ_ERR_USAGE");
        CHECK(cad_face_edge_eval(f, 0, 1.5, p, NULL, NULL, &err) == SQ_ERR_USAGE,
              "eval beyond the edge: expected SQ_ERR_USAGE");
        CHECK(cad_face_edge_eval(f, 9, 0, p, NULL, NULL, &err) == SQ_ERR_USAGE,
              "eval on edge 9 of 5: expected SQ_ERR_USAGE");
    }
    check_corners(
        "square_hole outer", f, 5,
        (const double[]){0, 0, 1, 0, 1, 1, 0, 1, 0.75, 0.5}); /* hole starts at (0.75,.5)? */
    cad_face_free(&f);

    f = open_face("square");
    check_generic("square", f);
    check_corners("square", f, 4, (const double[]){0, 0, 1, 0, 1, 1, 0, 1});
    check_curvature("square", f, 0, CAD_EDGE_LINE, 0.0);
    NEAR("square area", green(f, -1, 8), 1.0, 1e-12);
    cad_face_free(&f);

    f = open_face("triangle");
    check_generic("triangle", f);
    check_corners("triangle", f, 3, (const double[]){0, 0, 1, 0, 0.5, sqrt(3.0) / 2});
    NEAR("triangle area", green(f, -1, 8), sqrt(3.0) / 4, 1e-10);
    cad_face_free(&f);

    f = open_face("lshape");
    check_generic("lshape", f);
    check_corners("lshape", f, 6, (const double[]){0, 0, 2, 0, 2, 1, 1, 1, 1, 2, 0, 2});
    NEAR("lshape area", green(f, -1, 8), 3.0, 1e-12);
    cad_face_free(&f);

    f = open_face("polygon");
    check_generic("polygon", f);
    check_corners("polygon", f, 5, (const double[]){0, 0, 3, 0, 4, 1.5, 1.5, 2.5, 0.5, 1.8});
    NEAR("polygon area", green(f, -1, 8), 6.85, 1e-10);
    cad_face_free(&f);

    f = open_face("quarter_circle");
    check_generic("quarter_circle", f);
    check_corners("quarter_circle", f, 3, (const double[]){0, 0, 1, 0, 0, 1});
    CHECK(count_type(f, 0, CAD_EDGE_CIRCLE, &len) == 1, "quarter_circle: one arc");
    NEAR("quarter_circle arc length", len, pi / 2, 1e-13);
    check_curvature("quarter_circle", f, 0, CAD_EDGE_CIRCLE, 1.0);
    NEAR("quarter_circle area", green(f, -1, 64), pi / 4, 1e-10);
    cad_face_free(&f);

    f = open_face("two_holes");
    check_generic("two_holes", f);
    check_corners("two_holes", f, 6, (const double[]){1, 0, 3, 0, 4, 1, 4, 2, 0, 2, 0, 1});
    CHECK(count_type(f, 0, CAD_EDGE_CIRCLE, &len) == 2, "two_holes: two notches");
    NEAR("two_holes notch length", len, pi, 1e-13);
    check_curvature("two_holes", f, 0, CAD_EDGE_CIRCLE, -1.0);
    NEAR("two_holes area", green(f, -1, 64), 8 - pi / 2, 1e-10);
    cad_face_free(&f);

    f = open_face("nautilus");
    check_generic("nautilus", f);
    check_corners("nautilus", f, 3, (const double[]){1, 0, -1, 0, 0, 0});
    for (int e = 0; e < 3; ++e)
        if (cad_face_edge_type(f, e) == CAD_EDGE_CIRCLE) {
            double L = cad_face_edge_length(f, e), k;
            eval(f, e, 0.5 * L, NULL, NULL, &k);
            NEAR("nautilus arc curvature", k, L > 2 ? 1.0 : 2.0, 1e-12);
            NEAR("nautilus arc length", L, L > 2 ? pi : pi / 2, 1e-13);
        }
    NEAR("nautilus area", green(f, -1, 64), 5 * pi / 8, 1e-10);
    cad_face_free(&f);

    f = open_face("naca0012");
    check_generic("naca0012", f);
    CHECK(cad_face_num_loops(f) == 2 && cad_face_loop_num_edges(f, 0) == 4 &&
              cad_face_loop_num_edges(f, 1) == 1 && count_type(f, 1, CAD_EDGE_BSPLINE, NULL) == 1,
          "naca0012: 4 lines and one B-spline hole expected");
    NEAR("naca0012 area", green(f, -1, 4000), 20 - 0.081706, 1e-6);
    {
        /* The airfoil: from the trailing edge (1,0), through the leading edge (0,0). */
        int e = 4;
        double L = cad_face_edge_length(f, e), p[2], best = HUGE_VAL, xmin = HUGE_VAL;
        eval(f, e, 0, p, NULL, NULL);
        NEAR("naca0012 trailing edge x", p[0], 1.0, 1e-6);
        NEAR("naca0012 trailing edge y", p[1], 0.0, 1e-6);
        for (int i = 0; i <= 2000; ++i) {
            eval(f, e, L * i / 2000.0, p, NULL, NULL);
            xmin = fmin(xmin, p[0]);
            best = fmin(best, hypot(p[0], p[1]));
        }
        NEAR("naca0012 leading edge x", xmin, 0.0, 1e-4);
        CHECK(L > 2.0 && L < 2.1, "naca0012 airfoil length %g, expected about 2.04", L);
        /* Curvature of the B-spline = d(tangent angle)/ds, by central differences. */
        for (int i = 1; i < 50; ++i) {
            double s = L * (i + 0.123) / 50, h = 1e-5, ta[2], tb[2], k;
            eval(f, e, s - h, NULL, ta, NULL);
            eval(f, e, s + h, NULL, tb, NULL);
            eval(f, e, s, NULL, NULL, &k);
            double fd =
                atan2(ta[0] * tb[1] - ta[1] * tb[0], ta[0] * tb[0] + ta[1] * tb[1]) / (2 * h);
            char what[128];
            snprintf(what, sizeof what, "naca0012 airfoil curvature at s=%g", s);
            NEAR(what, k, fd, 1e-3 * fmax(1.0, fabs(k)));
            /* The airfoil is a hole, walked clockwise: it turns right (k < 0). */
            CHECK(k < 0, "naca0012 airfoil curvature %g at s=%g should be negative", k, s);
        }
    }
    cad_face_free(&f);

    cad_model_free(&model);
    return failures ? 1 : 0;
}
