/* Winslow relaxation with sliding boundary vertices (quad_relax.h): on the
 * unit square, a 6 x 4 grid whose interior vertices are shaken and whose
 * boundary vertices are moved along their edges relaxes back to the uniform
 * grid — the energy's minimizer there (conformal map of the square onto
 * itself followed by the stretch to 6 x 4 cells) — to 1e-8 (where the
 * relaxation stops: its steps are below 1e-9 of the extent), with the
 * boundary vertices still on their edges.  The work kept from that
 * relaxation (sq_relax_work: unknowns, Hessian, its factorization) serves
 * a second one of the shaken grid with an interior vertex held off the
 * grid: that vertex stays where it is, and the others end where a
 * relaxation with nothing kept puts them, to 1e-8.  And stop_on_fold (ring
 * below), bounds on the work on a thin face's mesh (strip below), the
 * Newton steps where a sliding vertex's curve bends (bend below) and on a
 * disc, whose symmetries no held vertex breaks (ogrid below). */
#include "cad.h"
#include "quad_relax.h"
#include "test_face.h"

#define NU 6
#define NV 4
#define ID(i, j) ((j) * (NU + 1) + (i))

/* m relaxed with its own work: the Newton steps taken, the compass
 * search's polls in *polls (sq_relax_work_stats). */
static int relaxed_steps(const cad_face *f, sq_relax_mesh *m, long *polls)
{
    sq_relax_work *work = NULL;
    sq_error err;
    SQ_TEST_OK(sq_quad_relax(f, m, &work, &err), err);
    int steps;
    sq_relax_work_stats(work, &steps, polls);
    sq_relax_work_free(&work);
    return steps;
}

/* square_hole's hole edge: the one through (0.75, 0.5), -1 if none. */
static int hole_edge(const cad_face *f)
{
    int hole = -1;
    sq_error err;
    for (int e = 0; e < cad_face_num_edges(f); e++) {
        double d;
        SQ_TEST_OK(cad_face_edge_project(f, e, (double[2]){0.75, 0.5}, NULL, NULL, &d, &err), err);
        if (d < 1e-9) hole = e;
    }
    return hole;
}

/* stop_on_fold on square_hole (hole r = 0.25 at (0.5, 0.5)): a ring of four
 * quads around the hole, its inner vertices sliding on the circle (turned
 * by `turn` from the quarter points and shaken), its outer ones at radius r
 * on the quarter points, held or free.  Each inner side spans about a
 * quarter of the circle: with the outer vertices held at r = 0.3 its
 * midpoint lies beyond the opposite side's line from the start (not the
 * relaxation's doing: not reported); free at r = 0.5 and turned by -0.4 the
 * relaxation pulls the outer vertices in until a side folds; not turned it
 * does not.  Returns the failures. */
static int ring(const cad_face *f, double r, double turn, int hold, int want)
{
    double xy[16];
    int quad[16], tag[16], fixed[8], hole = hole_edge(f), fails = 0;
    sq_error err;
    static const double shake[4] = {0.09, -0.05, 0.07, -0.03};
    for (int k = 0; k < 4; k++) {
        double a = 0.5 * M_PI * k + turn + shake[k], b = 0.5 * M_PI * k;
        xy[2 * k] = 0.5 + 0.25 * cos(a), xy[2 * k + 1] = 0.5 + 0.25 * sin(a);
        xy[8 + 2 * k] = 0.5 + r * cos(b), xy[8 + 2 * k + 1] = 0.5 + r * sin(b);
        fixed[k] = 0;
        fixed[4 + k] = hold;
    }
    fails += sq_check_int("t613 ring", "hole edge found", hole >= 0, 1);
    for (int k = 0; k < 4; k++) {
        /* counter-clockwise: inner k, outer k, outer k+1, inner k+1; the
         * last side on the hole */
        int c[4] = {k, 4 + k, 4 + (k + 1) % 4, (k + 1) % 4};
        for (int j = 0; j < 4; j++) {
            quad[4 * k + j] = c[j];
            tag[4 * k + j] = j == 3 ? hole : -1;
        }
    }
    sq_relax_mesh m = {8, 4, xy, quad, tag, fixed, 1, 0};
    SQ_TEST_OK(sq_quad_relax(f, &m, NULL, &err), err);
    fails += sq_check_int("t613 ring", "folded", m.folded, want);
    return fails;
}

/* The disc's symmetries (disc.step, the unit circle: no corner): an O-grid
 * like the disc's layout (a central square of ON x ON quads, 4 ON x OM
 * blocks from its sides to the circle; its corners the 4 valence-3 points),
 * every vertex free and shaken alike in its four quarters.  Nothing is held:
 * the Newton directions are kept orthogonal to the disc's rotation and its
 * two other conformal automorphisms (quad_relax.c, prepare).  Held, one
 * boundary vertex left the rest to turn about it at almost no cost in
 * energy, a soft mode that took the steps: 10 measured, 7 now; the bound
 * is the midpoint, 8 (sq_relax_work_stats counts them).  The shake keeps
 * the four quarters alike and the relaxation what the start has (the
 * energy and the removed motions turn with the quarters), so the result is
 * the symmetric optimum: the central square's corners at one radius and
 * turned alike, to round-off (spreads of 0 and 1e-16 measured; the bound,
 * 1e-8, is the relaxation's own, CONVERGED of the extent over 1 - rho). */
#define ON 16
#define OM 8
static int ogrid(const cad_face *f)
{
    const int nc = (ON + 1) * (ON + 1), nv = nc + OM * 4 * ON, nq = ON * ON + OM * 4 * ON;
    const double half = 0.4;
    double xy[2 * ((ON + 1) * (ON + 1) + OM * 4 * ON)], sq[2 * 4 * ON];
    int quad[4 * (ON * ON + OM * 4 * ON)], tag[4 * (ON * ON + OM * 4 * ON)];
    int fixed[(ON + 1) * (ON + 1) + OM * 4 * ON], perim[4 * ON], fails = 0;
    for (int j = 0; j <= ON; j++)
        for (int i = 0; i <= ON; i++) {
            xy[2 * (j * (ON + 1) + i)] = half * (2.0 * i / ON - 1.0);
            xy[2 * (j * (ON + 1) + i) + 1] = half * (2.0 * j / ON - 1.0);
        }
    /* the square's boundary counter-clockwise from (-half, -half) */
    for (int p = 0; p < 4 * ON; p++) {
        int side = p / ON, t = p % ON;
        int i = side == 0 ? t : side == 1 ? ON : side == 2 ? ON - t : 0;
        int j = side == 0 ? 0 : side == 1 ? t : side == 2 ? ON : ON - t;
        perim[p] = j * (ON + 1) + i;
        sq[2 * p] = xy[2 * perim[p]], sq[2 * p + 1] = xy[2 * perim[p] + 1];
    }
    /* ring l (1..OM) from the square to the circle, at the angles of the
     * square's points spread evenly */
    for (int l = 1; l <= OM; l++)
        for (int p = 0; p < 4 * ON; p++) {
            double a = -0.75 * M_PI + 2.0 * M_PI * p / (4 * ON), t = (double)l / OM;
            int v = nc + (l - 1) * 4 * ON + p;
            xy[2 * v] = (1.0 - t) * sq[2 * p] + t * cos(a);
            xy[2 * v + 1] = (1.0 - t) * sq[2 * p + 1] + t * sin(a);
        }
    /* shaken alike in the four quarters: z + 0.01 z s(z^4), s complex */
    for (int v = 0; v < nv; v++) {
        fixed[v] = 0;
        const double x = xy[2 * v], y = xy[2 * v + 1], r2 = x * x + y * y;
        const double z4r = r2 * r2 * cos(4.0 * atan2(y, x)), z4i = r2 * r2 * sin(4.0 * atan2(y, x));
        if (v < nc + (OM - 1) * 4 * ON) { /* inside: by up to 1e-2 */
            const double sr = sin(30.0 * z4r + 7.0 * z4i), si = cos(50.0 * z4i - 11.0 * z4r);
            xy[2 * v] += 0.01 * (x * sr - y * si), xy[2 * v + 1] += 0.01 * (x * si + y * sr);
        } else { /* on the circle: turned by up to 1e-2 */
            double a = atan2(y, x) + 0.01 * sin(3.0 * z4r + 5.0 * z4i);
            xy[2 * v] = cos(a), xy[2 * v + 1] = sin(a);
        }
    }
    int q = 0;
    for (int j = 0; j < ON; j++)
        for (int i = 0; i < ON; i++, q++) {
            int c[4] = {j * (ON + 1) + i, j * (ON + 1) + i + 1, (j + 1) * (ON + 1) + i + 1,
                        (j + 1) * (ON + 1) + i};
            for (int k = 0; k < 4; k++)
                quad[4 * q + k] = c[k], tag[4 * q + k] = -1;
        }
    for (int l = 0; l < OM; l++)
        for (int p = 0; p < 4 * ON; p++, q++) {
            /* counter-clockwise: inner p, outer p, outer p+1, inner p+1 */
            int p1 = (p + 1) % (4 * ON);
            int in0 = l ? nc + (l - 1) * 4 * ON + p : perim[p],
                in1 = l ? nc + (l - 1) * 4 * ON + p1 : perim[p1];
            int c[4] = {in0, nc + l * 4 * ON + p, nc + l * 4 * ON + p1, in1};
            for (int k = 0; k < 4; k++)
                quad[4 * q + k] = c[k], tag[4 * q + k] = k == 1 && l == OM - 1 ? 0 : -1;
        }
    sq_relax_mesh m = {nv, nq, xy, quad, tag, fixed};
    long polls;
    const int steps = relaxed_steps(f, &m, &polls);
    fprintf(stderr, "t613 ogrid: %d quads, %d Newton steps\n", nq, steps);
    fails += sq_check_int("t613 ogrid", "Newton steps <= 8", steps <= 8, 1);
    const int corner[4] = {0, ON, nc - 1, ON * (ON + 1)};
    double rmin = HUGE_VAL, rmax = 0.0, tmin = HUGE_VAL, tmax = -HUGE_VAL;
    for (int k = 0; k < 4; k++) {
        const double *x = &xy[2 * corner[k]], r = hypot(x[0], x[1]);
        /* the turn from the diagonal, in (-pi/4, pi/4] */
        double t = atan2(x[1], x[0]) - (-0.75 * M_PI + 0.5 * M_PI * k);
        t -= 2.0 * M_PI * round(t / (2.0 * M_PI));
        rmin = fmin(rmin, r), rmax = fmax(rmax, r);
        tmin = fmin(tmin, t), tmax = fmax(tmax, t);
    }
    fprintf(stderr,
            "t613 ogrid: corners at radius %.6f (spread %.1e), turned by %.3e (spread %.1e)\n",
            rmin, rmax - rmin, tmin, tmax - tmin);
    fails += sq_check_abs("t613 ogrid", "spread of the corners' radii", rmax - rmin, 0.0, 1e-8);
    fails += sq_check_abs("t613 ogrid", "spread of the corners' turns", tmax - tmin, 0.0, 1e-8);
    return fails;
}

/* The curve's bending (quad_relax.c, newton_direction): square_hole's hole
 * (r = 0.25 at (0.5, 0.5)) inside a ring of 2 x BK quads whose outer
 * vertices are held on the square of half side 1/2 around it, the middle
 * ones free, the inner ones sliding on the circle; all shaken.  At the
 * optimum the energy's gradient at the inner vertices is normal to the
 * circle, not zero, and its term kappa n . grad E in their second
 * derivative (kappa = 4, cells about as long as the radius) is what the
 * Newton steps need to converge quadratically: 21 steps measured without
 * it, 8 with it; the bound is the midpoint, 14.  Every corner stays
 * convex (the relaxation's promise). */
#define BK 8
static int bend(const cad_face *f)
{
    double xy[2 * 3 * BK];
    int quad[4 * 2 * BK], tag[4 * 2 * BK], fixed[3 * BK], hole = hole_edge(f), fails = 0;
    fails += sq_check_int("t613 bend", "hole edge found", hole >= 0, 1);
    for (int p = 0; p < BK; p++) {
        const double a = 2.0 * M_PI * p / BK, c = cos(a), s = sin(a);
        const double sq = 0.5 / fmax(fabs(c), fabs(s)); /* the square's point on the ray */
        const double ai = a + 0.03 * sin(5.0 * p);
        xy[2 * p] = 0.5 + 0.25 * cos(ai), xy[2 * p + 1] = 0.5 + 0.25 * sin(ai);
        xy[2 * (BK + p)] = 0.5 + 0.5 * (0.25 + sq) * c + 0.03 * sin(3.0 * p);
        xy[2 * (BK + p) + 1] = 0.5 + 0.5 * (0.25 + sq) * s + 0.03 * cos(7.0 * p);
        xy[2 * (2 * BK + p)] = 0.5 + sq * c, xy[2 * (2 * BK + p) + 1] = 0.5 + sq * s;
        fixed[p] = fixed[BK + p] = 0;
        fixed[2 * BK + p] = 1;
    }
    for (int l = 0; l < 2; l++)
        for (int p = 0; p < BK; p++) {
            /* counter-clockwise: inner p, outer p, outer p+1, inner p+1;
             * the last side on the hole in the first layer */
            const int q = l * BK + p, p1 = (p + 1) % BK;
            const int c[4] = {l * BK + p, (l + 1) * BK + p, (l + 1) * BK + p1, l * BK + p1};
            for (int k = 0; k < 4; k++)
                quad[4 * q + k] = c[k], tag[4 * q + k] = l == 0 && k == 3 ? hole : -1;
        }
    sq_relax_mesh m = {3 * BK, 2 * BK, xy, quad, tag, fixed};
    long polls;
    const int steps = relaxed_steps(f, &m, &polls);
    fprintf(stderr, "t613 bend: %d Newton steps\n", steps);
    fails += sq_check_int("t613 bend", "Newton steps <= 14", steps <= 14, 1);
    int concave = 0;
    for (int q = 0; q < 2 * BK; q++)
        for (int k = 0; k < 4; k++) {
            const double *o = &xy[2 * quad[4 * q + k]], *a = &xy[2 * quad[4 * q + (k + 1) % 4]],
                         *b = &xy[2 * quad[4 * q + (k + 3) % 4]];
            concave += (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]) <= 0.0;
        }
    fails += sq_check_int("t613 bend", "corners not convex", concave, 0);
    return fails;
}

/* The relaxation's work on a thin face's split-road mesh (stress corpus
 * class sliver: 0073, 25 920 quads, took 18 s of CPU, most of it in the
 * compass search): a strip of N pairs of right triangles, each cell
 * 1/N by 1/(25 N) (0073's triangles, of base about 25 times their height),
 * each triangle split in 3 quads at its centroid and edge midpoints
 * (quad_split.c), the strip's boundary held, its free vertices shaken.
 * The work is counted, not timed (sq_relax_work_stats), so the bounds hold
 * on any machine, up to the few decisions round-off may flip:
 * - Newton: 10 iterations measured (exact steps from 1e-4 of the energy,
 *   quad_relax.c), 30 with exact steps from 1e-9 alone, 46 without the
 *   stall test (before bf727d6: a linear convergence run on by inexact
 *   directions); the bound, 38, fails the last.
 * - compass search: it polls the quads around a vertex at most 8
 *   directions x 6 steps + 1 = 49 times a visit, visits a vertex only after
 *   a neighbour moved, at most 50 sweeps a phase, 2 phases (4900 polls per
 *   vertex at most); 364 per free vertex measured (413 when each visit
 *   started again from the longest step, before bf727d6).  The bound, twice
 *   the measured, fails a search that visits every vertex every sweep
 *   (about 2000), not the step lengths' detail.
 * Every quad stays convex (the relaxation's promise). */
#define STRIP_N 400
static int strip(const cad_face *f)
{
    enum {
        N = STRIP_N,
        NB = 0,
        NT = N + 1,
        MB = 2 * (N + 1),
        MT = MB + N,
        MV = MT + N,
        MD = MV + N + 1,
        CL = MD + N,
        CU = CL + N,
        NVS = CU + N
    };
    static double xy[2 * NVS];
    static int quad[4 * 6 * N], tag[4 * 6 * N], fixed[NVS];
    const double h = 1.0 / N, w = h / 25.0, y0 = 0.5;
    for (int j = 0; j <= N; j++) {
        xy[2 * (NB + j)] = xy[2 * (NT + j)] = j * h;
        xy[2 * (NB + j) + 1] = y0;
        xy[2 * (NT + j) + 1] = y0 + w;
    }
    int nq = 0;
    for (int j = 0; j < N; j++) {
        /* lower (b_j, b_j+1, t_j+1) and upper (b_j, t_j+1, t_j), counter-
         * clockwise, with their edges' midpoints in the same order */
        int tri[2][3] = {{NB + j, NB + j + 1, NT + j + 1}, {NB + j, NT + j + 1, NT + j}};
        int mid[2][3] = {{MB + j, MV + j + 1, MD + j}, {MD + j, MT + j, MV + j}};
        int cen[2] = {CL + j, CU + j};
        for (int t = 0; t < 2; t++) {
            double *c = &xy[2 * cen[t]];
            c[0] = c[1] = 0.0;
            for (int k = 0; k < 3; k++) {
                const double *a = &xy[2 * tri[t][k]], *b = &xy[2 * tri[t][(k + 1) % 3]];
                double *m = &xy[2 * mid[t][k]];
                m[0] = 0.5 * (a[0] + b[0]), m[1] = 0.5 * (a[1] + b[1]);
                c[0] += a[0] / 3.0, c[1] += a[1] / 3.0;
            }
            for (int k = 0; k < 3; k++, nq++) {
                int q[4] = {tri[t][k], mid[t][k], cen[t], mid[t][(k + 2) % 3]};
                for (int e = 0; e < 4; e++) {
                    quad[4 * nq + e] = q[e];
                    tag[4 * nq + e] = -1;
                }
            }
        }
    }
    for (int i = 0; i < NVS; i++)
        fixed[i] = i < MV || i == MV || i == MV + N;
    /* the free vertices shaken, deterministically, off the split's
     * positions (the relaxation's optimum is not where they start) */
    int nfree = 0;
    for (int i = 0; i < NVS; i++)
        if (!fixed[i]) {
            nfree++;
            xy[2 * i] += 0.03 * h * sin(3.0 * i);
            xy[2 * i + 1] += 0.03 * w * cos(5.0 * i);
        }
    sq_relax_mesh m = {NVS, nq, xy, quad, tag, fixed};
    long polls;
    const int steps = relaxed_steps(f, &m, &polls);
    int convex = 1;
    for (int q = 0; q < nq; q++)
        for (int k = 0; k < 4; k++) {
            const double *p = &xy[2 * quad[4 * q + k]], *a = &xy[2 * quad[4 * q + (k + 1) % 4]],
                         *b = &xy[2 * quad[4 * q + (k + 3) % 4]];
            convex &= (a[0] - p[0]) * (b[1] - p[1]) - (a[1] - p[1]) * (b[0] - p[0]) > 0.0;
        }
    int fails = sq_check_int("t613 strip", "every quad convex", convex, 1);
    fails += sq_check_int("t613 strip", "Newton iterations <= 38", steps <= 38, 1);
    printf("t613 strip: %d quads, %d free vertices, %d Newton iterations, %.1f polls per free "
           "vertex\n",
           nq, nfree, steps, (double)polls / nfree);
    fails += sq_check_int("t613 strip", "compass polls per free vertex <= 730",
                          polls <= 730L * nfree, 1);
    return fails;
}

int main(void)
{
    cad_model *model = NULL;
    cad_face *f = NULL;
    sq_error err;
    sq_test_open_face("square.step", &model, &f);
    int nv = (NU + 1) * (NV + 1), nq = NU * NV, fails = 0;
    double xy[2 * (NU + 1) * (NV + 1)];
    int quad[4 * NU * NV], tag[4 * NU * NV], fixed[(NU + 1) * (NV + 1)];
    for (int j = 0; j <= NV; j++)
        for (int i = 0; i <= NU; i++) {
            double x = (double)i / NU, y = (double)j / NV;
            int bx = i == 0 || i == NU, by = j == 0 || j == NV;
            /* a deterministic shake: inside in both directions, on the
             * boundary along it (corners stay) */
            double dx = 0.3 / NU * sin(3.0 * i + 5.0 * j), dy = 0.3 / NV * cos(7.0 * i + 2.0 * j);
            xy[2 * ID(i, j)] = x + (bx ? 0.0 : dx);
            xy[2 * ID(i, j) + 1] = y + (by ? 0.0 : dy);
            fixed[ID(i, j)] = bx && by;
        }
    for (int j = 0; j < NV; j++)
        for (int i = 0; i < NU; i++) {
            int q = j * NU + i, c[4] = {ID(i, j), ID(i + 1, j), ID(i + 1, j + 1), ID(i, j + 1)};
            for (int k = 0; k < 4; k++) {
                quad[4 * q + k] = c[k];
                tag[4 * q + k] = -1;
                int on = (k == 0 && j == 0) || (k == 1 && i == NU - 1) || (k == 2 && j == NV - 1) ||
                         (k == 3 && i == 0);
                if (!on) continue;
                /* the CAD edge under the side's (unshaken) midpoint */
                int a = c[k], b = c[(k + 1) % 4];
                double mid[2] = {0.5 * ((a % (NU + 1)) + (b % (NU + 1))) / NU,
                                 0.5 * ((a / (NU + 1)) + (b / (NU + 1))) / NV};
                for (int e = 0; e < cad_face_num_edges(f); e++) {
                    double d;
                    SQ_TEST_OK(cad_face_edge_project(f, e, mid, NULL, NULL, &d, &err), err);
                    if (d < 1e-9) tag[4 * q + k] = e;
                }
                fails += sq_check_int("t613", "side on a CAD edge", tag[4 * q + k] >= 0, 1);
            }
        }
    double shaken[2 * (NU + 1) * (NV + 1)];
    memcpy(shaken, xy, sizeof xy);
    sq_relax_mesh m = {nv, nq, xy, quad, tag, fixed};
    sq_relax_work *work = NULL;
    SQ_TEST_OK(sq_quad_relax(f, &m, &work, &err), err);
    double worst = 0.0;
    for (int j = 0; j <= NV; j++)
        for (int i = 0; i <= NU; i++)
            worst = fmax(worst, hypot(xy[2 * ID(i, j)] - (double)i / NU,
                                      xy[2 * ID(i, j) + 1] - (double)j / NV));
    /* the relaxation stops when no vertex moves by 1e-9 of the extent
     * (src/mesh/quad_relax.c, CONVERGED): the fixed point is within 1e-9 / (1 -
     * rho) of it, rho the steps' contraction; 1e-8 holds for rho <= 0.9 */
    fails += sq_check_abs("t613", "largest distance to the uniform grid", worst, 0.0, 1e-8);
    /* again, ID(2, 2) held at (0.36, 0.52) */
    double alone[2 * (NU + 1) * (NV + 1)];
    shaken[2 * ID(2, 2)] = 0.36;
    shaken[2 * ID(2, 2) + 1] = 0.52;
    fixed[ID(2, 2)] = 1;
    memcpy(xy, shaken, sizeof xy);
    memcpy(alone, shaken, sizeof xy);
    SQ_TEST_OK(sq_quad_relax(f, &m, &work, &err), err);
    fails += sq_check_int("t613 kept work", "work kept", work != NULL, 1);
    sq_relax_mesh m2 = {nv, nq, alone, quad, tag, fixed};
    SQ_TEST_OK(sq_quad_relax(f, &m2, NULL, &err), err);
    double apart = 0.0;
    for (int i = 0; i < 2 * nv; i++)
        apart = fmax(apart, fabs(xy[i] - alone[i]));
    fails += sq_check_abs("t613 kept work", "largest distance to a relaxation without it", apart,
                          0.0, 1e-8);
    fails += sq_check_abs("t613 kept work", "held vertex moved by",
                          hypot(xy[2 * ID(2, 2)] - 0.36, xy[2 * ID(2, 2) + 1] - 0.52), 0.0, 0.0);
    fails += sq_check_abs("t613 kept work", "its neighbour (3, 2) off the grid by",
                          hypot(xy[2 * ID(3, 2)] - 0.5, xy[2 * ID(3, 2) + 1] - 0.5), 0.02, 0.01);
    sq_relax_work_free(&work);
    sq_relax_work_free(&work); /* NULL-safe */
    fails += strip(f);
    cad_face_free(&f);
    cad_model_free(&model);
    sq_test_open_face("disc.step", &model, &f);
    fails += ogrid(f);
    cad_face_free(&f);
    cad_model_free(&model);
    sq_test_open_face("square_hole.step", &model, &f);
    fails += ring(f, 0.3, 0.0, 1, 0);
    fails += ring(f, 0.5, -0.4, 0, 1);
    fails += ring(f, 0.5, 0.0, 0, 0);
    fails += bend(f);
    cad_face_free(&f);
    cad_model_free(&model);
    return fails != 0;
}
