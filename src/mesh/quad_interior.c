/* semquad — the size measure across each quad patch's interior
 * (docs/sizes.md, "How the blocks honour it"): where the user's size h(x)
 * is smaller inside a patch than along its sides (a refinement inside
 * it), the chords crossing it need more segments than their sides' own
 * integral of 1/h gives.  Measured along the lines of the patch's
 * transfinite map from arc-length fractions of its sides, sampled on a
 * grid. */
#include "quad_mesher_private.h"

#include <math.h>
#include <stdlib.h>

#define GRID 24 /* grid intervals per direction of a patch */

/* Point at arc-length fraction u of side s of quad patch p. */
static sq_status side_point(const sq_layout *L, const cad_face *face, const sq_layout_patch *p,
                            int s, double u, double x[2], sq_error *err)
{
    double total = 0.0;
    for (int h = p->side_start[s]; h < p->side_start[s + 1]; h++)
        total += L->edges[p->half[h].edge].length;
    double rest = u * total;
    for (int h = p->side_start[s];; h++) {
        const sq_layout_half *hf = &p->half[h];
        double len = L->edges[hf->edge].length;
        if (rest <= len || h == p->side_start[s + 1] - 1) {
            double t = len > 0.0 ? fmin(rest / len, 1.0) : 0.0;
            return sq_layout_edge_point(L, face, hf->edge, hf->reversed ? 1.0 - t : t, x, err);
        }
        rest -= len;
    }
}

/* The grid x[(GRID + 1)^2] of patch p's transfinite map: u along side 0
 * (corner 0 to 1), v from side 0 to side 2; side 2 and side 3 are walked
 * against u and v. */
static sq_status patch_grid(const sq_layout *L, const cad_face *face, const sq_layout_patch *p,
                            double (*x)[2], sq_error *err)
{
    double s[4][GRID + 1][2];
    for (int k = 0; k < 4; k++)
        for (int i = 0; i <= GRID; i++)
            SQ_TRY(side_point(L, face, p, k, (double)i / GRID, s[k][i], err));
    for (int j = 0; j <= GRID; j++)
        for (int i = 0; i <= GRID; i++) {
            double u = (double)i / GRID, v = (double)j / GRID;
            qm_coons(s[0][i], s[2][GRID - i], s[3][GRID - j], s[1][j], s[0][0], s[1][0], s[2][0],
                     s[3][0], u, v, x[j * (GRID + 1) + i]);
        }
    return SQ_OK;
}

/* The integral of size / h(x, t) along the grid line from x[a] by steps
 * of `step` (GRID intervals, t the line's direction), midpoint rule. */
static double line_measure(const sq_size_field *f, double size, const double (*x)[2], int a,
                           int step)
{
    double m = 0.0;
    for (int i = 0; i < GRID; i++) {
        const double *p = x[a + i * step], *q = x[a + (i + 1) * step];
        double mid[2] = {0.5 * (p[0] + q[0]), 0.5 * (p[1] + q[1])}, t[2] = {q[0] - p[0], q[1] - p[1]};
        m += hypot(t[0], t[1]) * size / sq_size_field_eval_dir(f, mid, t, size);
    }
    return m;
}

sq_status qm_interior_measure(const sq_layout *L, const cad_face *face,
                              const sq_mesher_options *o, double size, double *need,
                              sq_error *err)
{
    double(*x)[2] = malloc(sizeof(double[2]) * (GRID + 1) * (GRID + 1));
    if (!x) return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    sq_status st = SQ_OK;
    for (int q = 0; q < L->npatches && st == SQ_OK; q++) {
        need[2 * q] = need[2 * q + 1] = 0.0;
        if ((st = patch_grid(L, face, &L->patches[q], x, err)) != SQ_OK) break;
        /* the lines strictly inside: the sides have their own measure */
        for (int j = 1; j < GRID; j++) {
            need[2 * q] = fmax(need[2 * q], line_measure(o->sizes, size, x, j * (GRID + 1), 1));
            need[2 * q + 1] = fmax(need[2 * q + 1], line_measure(o->sizes, size, x, j, GRID + 1));
        }
    }
    free(x);
    return st;
}
