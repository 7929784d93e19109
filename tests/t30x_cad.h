/* Shared by the cad/ tests (t301–t305): failure counting, the edge
 * evaluation and Green's-theorem area the face tests integrate with, loop
 * closure, the outer loop's box and a loop's diameter. */
#ifndef SQ_T30X_CAD_H
#define SQ_T30X_CAD_H

#include "cad.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

static int failures = 0;

#define CHECK(cond, ...)                                                                           \
    do {                                                                                           \
        if (!(cond)) {                                                                             \
            fprintf(stderr, "%s:%d: ", __FILE__, __LINE__);                                        \
            fprintf(stderr, __VA_ARGS__);                                                          \
            fprintf(stderr, "\n");                                                                 \
            ++failures;                                                                            \
        }                                                                                          \
    } while (0)

#define NEAR(name, value, expected, tol)                                                           \
    CHECK(fabs((value) - (expected)) <= (tol), "%s: value %.17g expected %.17g tolerance %.3g",    \
          (name), (double)(value), (double)(expected), (double)(tol))

/* 5-point Gauss–Legendre on [-1, 1] (not every test integrates). */
__attribute__((unused)) static const double GX[5] = {-0.9061798459386640, -0.5384693101056831, 0.0,
                                                     0.5384693101056831, 0.9061798459386640};
__attribute__((unused)) static const double GW[5] = {0.2369268850561891, 0.4786286704993665,
                                                     0.5688888888888889, 0.4786286704993665,
                                                     0.2369268850561891};

/* Evaluate edge e at arc length s or stop the test. */
static inline void eval(const cad_face *f, int e, double s, double p[2], double t[2], double *k)
{
    sq_error err;
    if (cad_face_edge_eval(f, e, s, p, t, k, &err) != SQ_OK) {
        fprintf(stderr, "cad_face_edge_eval(edge %d, s %g): %s\n", e, s, err.msg);
        exit(1);
    }
}

/* Signed area of loop l (or of all loops if l < 0): 1/2 sum int (x t_y -
 * y t_x) ds, 5-point Gauss–Legendre on `panels` panels per edge. */
static inline double green(const cad_face *f, int l, int panels)
{
    double a = 0;
    for (int e = 0; e < cad_face_num_edges(f); ++e) {
        if (l >= 0 && cad_face_edge_loop(f, e) != l) continue;
        double L = cad_face_edge_length(f, e), h = L / panels;
        for (int i = 0; i < panels; ++i)
            for (int q = 0; q < 5; ++q) {
                double s = (i + 0.5) * h + 0.5 * h * GX[q], p[2], t[2];
                eval(f, e, s, p, t, NULL);
                a += 0.5 * GW[q] * 0.5 * h * (p[0] * t[1] - p[1] * t[0]);
            }
    }
    return a;
}

/* Every loop of f closes: each edge ends within tol of the next one's start. */
__attribute__((unused)) static void check_closed(const char *name, const cad_face *f, double tol)
{
    for (int l = 0; l < cad_face_num_loops(f); ++l) {
        int first = cad_face_loop_first_edge(f, l), n = cad_face_loop_num_edges(f, l);
        for (int k = 0; k < n; ++k) {
            int e = first + k, nx = first + (k + 1) % n;
            double a[2], b[2];
            eval(f, e, cad_face_edge_length(f, e), a, NULL, NULL);
            eval(f, nx, 0, b, NULL, NULL);
            char what[200];
            snprintf(what, sizeof what, "%s: gap between edges %d and %d", name, e, nx);
            NEAR(what, hypot(a[0] - b[0], a[1] - b[1]), 0.0, tol);
        }
    }
}

/* The vertices of the first n edges (the outer loop) span the box
 * [want[0], want[2]] x [want[1], want[3]] within tol. */
__attribute__((unused)) static void check_box(const char *name, const cad_face *f, int n,
                                              const double want[4], double tol)
{
    double lo[2] = {HUGE_VAL, HUGE_VAL}, hi[2] = {-HUGE_VAL, -HUGE_VAL};
    for (int e = 0; e < n; ++e) {
        double p[2];
        eval(f, e, 0, p, NULL, NULL);
        for (int d = 0; d < 2; ++d) lo[d] = fmin(lo[d], p[d]), hi[d] = fmax(hi[d], p[d]);
    }
    const double got[4] = {lo[0], lo[1], hi[0], hi[1]};
    static const char *side[4] = {"xmin", "ymin", "xmax", "ymax"};
    for (int i = 0; i < 4; ++i) {
        char what[160];
        snprintf(what, sizeof what, "%s box %s", name, side[i]);
        NEAR(what, got[i], want[i], tol);
    }
}

/* Largest distance between two points of loop l, sampled at 400 points per
 * edge: short of the true one by at most the sample spacing. */
__attribute__((unused)) static double loop_diameter(const cad_face *f, int l)
{
    enum { N = 400 };
    static double pts[4 * N][2];
    int np = 0;
    for (int e = 0; e < cad_face_num_edges(f); ++e) {
        if (cad_face_edge_loop(f, e) != l) continue;
        for (int i = 0; i < N && np < 4 * N; ++i) eval(f, e, cad_face_edge_length(f, e) * i / N, pts[np++], NULL, NULL);
    }
    double d = 0;
    for (int i = 0; i < np; ++i)
        for (int j = i + 1; j < np; ++j) d = fmax(d, hypot(pts[i][0] - pts[j][0], pts[i][1] - pts[j][1]));
    return d;
}

#endif
