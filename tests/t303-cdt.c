/* t303 — cad_cdt_mesh: constrained Delaunay refinement with CGAL.  Unit
 * square minus a seeded square hole: angle and size bounds, exact area, no
 * triangle in the hole, Steiner points on segments flagged, graded sizes from
 * a callback; concave domain without holes; duplicates; bad input.
 * Tolerances (CGAL with exact predicates, no BLAS): straight triangles'
 * lengths and areas are a few roundings each, summed over at most a few
 * hundred triangles: N U of the area <= 3 is below 1e-12, edge lengths a
 * few U relative (1e-12); angles through acos of a few-U cosine, 20 to 30
 * degrees from its singular ends: a few U in degrees (1e-9); a Steiner
 * point on a segment is CGAL's constructed midpoint, a few U of l. */
#include "cad.h"
#include "t30x_cad.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct {
    double area, min_angle, max_edge;
    int nsteiner_on_seg;
} stats;

/* Checks common to every output; returns statistics. */
static stats check_mesh(const char *name, const cad_cdt_input *in, const cad_cdt_output *out,
                        double (*hsize)(const double *, void *))
{
    stats st = {0, 180, 0, 0};
    for (int t = 0; t < out->ntris; ++t) {
        const int *v = out->tri + 3 * t;
        double p[3][2];
        for (int j = 0; j < 3; ++j) {
            CHECK(v[j] >= 0 && v[j] < out->nverts, "%s: triangle %d vertex %d out of range", name, t, v[j]);
            if (v[j] < 0 || v[j] >= out->nverts) return st;
            p[j][0] = out->xy[2 * v[j]];
            p[j][1] = out->xy[2 * v[j] + 1];
        }
        double a = 0.5 * ((p[1][0] - p[0][0]) * (p[2][1] - p[0][1]) -
                          (p[2][0] - p[0][0]) * (p[1][1] - p[0][1]));
        CHECK(a > 0, "%s: triangle %d not counter-clockwise (area %g)", name, t, a);
        st.area += a;
        double c[2] = {(p[0][0] + p[1][0] + p[2][0]) / 3, (p[0][1] + p[1][1] + p[2][1]) / 3};
        double lmax = 0;
        for (int j = 0; j < 3; ++j) {
            const double *A = p[j], *B = p[(j + 1) % 3], *C = p[(j + 2) % 3];
            double ux = B[0] - A[0], uy = B[1] - A[1], wx = C[0] - A[0], wy = C[1] - A[1];
            double ang = atan2(fabs(ux * wy - uy * wx), ux * wx + uy * wy) * 180 / M_PI;
            if (ang < st.min_angle) st.min_angle = ang;
            lmax = fmax(lmax, hypot(ux, uy));
        }
        if (lmax > st.max_edge) st.max_edge = lmax;
        double h = in->max_size > 0 ? in->max_size : HUGE_VAL;
        if (hsize) h = fmin(h, hsize(c, in->size_ctx));
        CHECK(lmax <= h * (1 + 1e-12), "%s: triangle %d longest edge %g above the bound %g at (%g, %g)",
              name, t, lmax, h, c[0], c[1]);
    }
    for (int i = 0; i < out->nverts; ++i) {
        double x = out->xy[2 * i], y = out->xy[2 * i + 1];
        int s = out->source[i], k = out->on_segment[i];
        if (s >= 0) {
            CHECK(s < in->npoints && x == in->xy[2 * s] && y == in->xy[2 * s + 1],
                  "%s: vertex %d source %d does not match its input point", name, i, s);
            CHECK(k == -1, "%s: input vertex %d has on_segment %d, expected -1", name, i, k);
            continue;
        }
        /* A Steiner vertex: is it on one of the segments? */
        int on = -1;
        for (int j = 0; j < in->nsegments; ++j) {
            const double *P = in->xy + 2 * in->seg[2 * j], *Q = in->xy + 2 * in->seg[2 * j + 1];
            double dx = Q[0] - P[0], dy = Q[1] - P[1], l = hypot(dx, dy);
            double t = ((x - P[0]) * dx + (y - P[1]) * dy) / (l * l);
            double d = fabs((x - P[0]) * dy - (y - P[1]) * dx) / l;
            if (t > 0 && t < 1 && d <= 1e-12 * l) on = j;
        }
        CHECK(k == on, "%s: Steiner vertex %d at (%.17g, %.17g) has on_segment %d, expected %d",
              name, i, x, y, k, on);
        if (on >= 0) ++st.nsteiner_on_seg;
    }
    return st;
}

/* Unit square (points 0-3) with a square hole [0.4, 0.6]^2 (points 4-7). */
static const double sq_xy[] = {0, 0, 1, 0, 1, 1, 0, 1, 0.4, 0.4, 0.4, 0.6, 0.6, 0.6, 0.6, 0.4};
static const int sq_seg[] = {0, 1, 1, 2, 2, 3, 3, 0, 4, 5, 5, 6, 6, 7, 7, 4};
static const double sq_hole[] = {0.5, 0.5};

static double graded(const double xy[2], void *ctx)
{
    (void)ctx;
    return 0.01 + 0.25 * hypot(xy[0], xy[1]);
}

static double no_bound(const double xy[2], void *ctx)
{
    (void)xy;
    (void)ctx;
    return -1;
}

int main(void)
{
    sq_error err;
    cad_cdt_input in;
    cad_cdt_output out;
    stats st;

    /* 1. Square with a hole, 20 degrees, size 0.2. */
    memset(&in, 0, sizeof in);
    in.npoints = 8;
    in.xy = sq_xy;
    in.nsegments = 8;
    in.seg = sq_seg;
    in.nholes = 1;
    in.holes = sq_hole;
    in.min_angle_deg = 20;
    in.max_size = 0.2;
    CHECK(cad_cdt_mesh(&in, &out, &err) == SQ_OK, "square with hole: %s", err.msg);
    st = check_mesh("square with hole", &in, &out, NULL);
    CHECK(st.min_angle >= 20 - 1e-9, "square with hole: smallest angle %.12g, expected >= 20",
          st.min_angle);
    NEAR("square with hole: area", st.area, 1 - 0.04, 1e-12);
    CHECK(st.nsteiner_on_seg > 0, "square with hole: no Steiner vertex on the segments");
    int seen[8] = {0};
    for (int i = 0; i < out.nverts; ++i)
        if (out.source[i] >= 0) seen[out.source[i]] = 1;
    for (int i = 0; i < 8; ++i) CHECK(seen[i], "square with hole: input point %d missing", i);
    for (int t = 0; t < out.ntris; ++t) {
        double cx = 0, cy = 0;
        for (int j = 0; j < 3; ++j) {
            cx += out.xy[2 * out.tri[3 * t + j]] / 3;
            cy += out.xy[2 * out.tri[3 * t + j] + 1] / 3;
        }
        CHECK(!(cx > 0.4 && cx < 0.6 && cy > 0.4 && cy < 0.6),
              "square with hole: triangle %d has its centroid (%g, %g) in the hole", t, cx, cy);
    }
    int ntris_uniform = out.ntris;
    cad_cdt_output_free(&out);
    CHECK(out.xy == NULL && out.ntris == 0, "cad_cdt_output_free must zero the struct");
    cad_cdt_output_free(&out); /* twice is fine */

    /* 2. Graded sizes from the callback: small near the origin. */
    in.size = graded;
    in.max_size = 0.2;
    CHECK(cad_cdt_mesh(&in, &out, &err) == SQ_OK, "graded: %s", err.msg);
    st = check_mesh("graded", &in, &out, graded);
    CHECK(st.min_angle >= 20 - 1e-9, "graded: smallest angle %.12g, expected >= 20", st.min_angle);
    NEAR("graded: area", st.area, 0.96, 1e-12);
    {
        double near_max = 0, far_min = HUGE_VAL;
        for (int t = 0; t < out.ntris; ++t) {
            double cx = 0, cy = 0, lmax = 0;
            for (int j = 0; j < 3; ++j) {
                int a = out.tri[3 * t + j], b = out.tri[3 * t + (j + 1) % 3];
                cx += out.xy[2 * a] / 3;
                cy += out.xy[2 * a + 1] / 3;
                lmax = fmax(lmax, hypot(out.xy[2 * a] - out.xy[2 * b], out.xy[2 * a + 1] - out.xy[2 * b + 1]));
            }
            double r = hypot(cx, cy);
            if (r < 0.1) near_max = fmax(near_max, lmax);
            if (r > 1.0) far_min = fmin(far_min, lmax);
        }
        CHECK(near_max > 0 && near_max <= 0.035, "graded: longest edge near the origin %g, expected <= 0.035", near_max);
        CHECK(far_min > near_max, "graded: edges far away (%g) should be longer than near the origin (%g)",
              far_min, near_max);
        CHECK(out.ntris > ntris_uniform, "graded: %d triangles, expected more than %d", out.ntris,
              ntris_uniform);
    }
    cad_cdt_output_free(&out);

    /* 3. A callback returning "no bound" and no max size: angle only. */
    in.size = no_bound;
    in.max_size = 0;
    in.min_angle_deg = 30;
    CHECK(cad_cdt_mesh(&in, &out, &err) == SQ_OK, "angle only: %s", err.msg);
    st = check_mesh("angle only", &in, &out, NULL);
    CHECK(st.min_angle >= 30 - 1e-9, "angle only: smallest angle %.12g, expected >= 30", st.min_angle);
    NEAR("angle only: area", st.area, 0.96, 1e-12);
    cad_cdt_output_free(&out);
    in.size = NULL;

    /* 4. L-shape (concave, no hole), with a duplicated point and a zero-length segment. */
    {
        const double xy[] = {0, 0, 2, 0, 2, 1, 1, 1, 1, 2, 0, 2, 1, 1};
        const int seg[] = {0, 1, 1, 2, 2, 6, 6, 3, 3, 4, 4, 5, 5, 0};
        cad_cdt_input l;
        memset(&l, 0, sizeof l);
        l.npoints = 7;
        l.xy = xy;
        l.nsegments = 7;
        l.seg = seg;
        l.min_angle_deg = 25;
        l.max_size = 0.5;
        CHECK(cad_cdt_mesh(&l, &out, &err) == SQ_OK, "L-shape: %s", err.msg);
        st = check_mesh("L-shape", &l, &out, NULL);
        NEAR("L-shape: area", st.area, 3.0, 1e-12);
        CHECK(st.min_angle >= 25 - 1e-9, "L-shape: smallest angle %.12g, expected >= 25", st.min_angle);
        int dup = 0;
        for (int i = 0; i < out.nverts; ++i) dup += out.xy[2 * i] == 1 && out.xy[2 * i + 1] == 1;
        CHECK(dup == 1, "L-shape: the duplicated point appears %d times, expected once", dup);
        cad_cdt_output_free(&out);
    }

    /* 5. Bad input. */
    {
        const double xy[] = {0, 0, 1, 1, 1, 0, 0, 1}; /* a bow tie: segments cross */
        const int seg[] = {0, 1, 1, 2, 2, 3, 3, 0};
        cad_cdt_input b;
        memset(&b, 0, sizeof b);
        b.npoints = 4;
        b.xy = xy;
        b.nsegments = 4;
        b.seg = seg;
        b.min_angle_deg = 20;
        sq_status s = cad_cdt_mesh(&b, &out, &err);
        CHECK(s == SQ_ERR_GEOMETRY && err.msg[0], "bow tie: status %d (%s), expected %d", s, err.msg,
              SQ_ERR_GEOMETRY);
        CHECK(out.xy == NULL && out.ntris == 0, "bow tie: output not empty");
        b.min_angle_deg = 35;
        const int seg2[] = {0, 2, 2, 1, 1, 3, 3, 0};
        b.seg = seg2;
        s = cad_cdt_mesh(&b, &out, &err);
        CHECK(s == SQ_ERR_USAGE, "min angle 35: status %d, expected %d", s, SQ_ERR_USAGE);
        b.min_angle_deg = 20;
        const int seg3[] = {0, 2, 2, 1, 1, 7, 3, 0};
        b.seg = seg3;
        s = cad_cdt_mesh(&b, &out, &err);
        CHECK(s == SQ_ERR_USAGE, "segment to point 7 of 4: status %d, expected %d", s, SQ_ERR_USAGE);
        CHECK(cad_cdt_mesh(NULL, &out, &err) == SQ_ERR_USAGE, "NULL input: expected SQ_ERR_USAGE");
    }
    return failures ? 1 : 0;
}
