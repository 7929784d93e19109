#include "write_quad_svg.h"

#include "outfile.h"
#include "svg.h"
#include "write_msh.h"

#include <math.h>
#include <stdlib.h>

#define NSUB 8 /* polyline segments per curved side */

void sq_quad_eta_color(double eta, char out[8])
{
    /* red (0.5) -> yellow (0.75) -> green (1.0) */
    static const double stop[3][3] = {{215, 48, 39}, {254, 224, 100}, {26, 152, 80}};
    double t = (eta - 0.5) / 0.5;
    t = t < 0 ? 0 : t > 1 ? 1 : t;
    int k = t < 0.5 ? 0 : 1;
    double s = t < 0.5 ? t / 0.5 : (t - 0.5) / 0.5;
    int rgb[3];
    for (int c = 0; c < 3; c++) rgb[c] = (int)lround(stop[k][c] + s * (stop[k + 1][c] - stop[k][c]));
    snprintf(out, 8, "#%02x%02x%02x", rgb[0], rgb[1], rgb[2]);
}

/* Polyline of local side k of quad q (NSUB+1 points, corner k to k+1). */
static void side_poly(const sq_quad_mesh *m, const sq_quad_basis *b, int q, int k, double *pts)
{
    static const double c[5][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0, 0}};
    for (int i = 0; i <= NSUB; i++) {
        double s = (double)i / NSUB;
        double u = c[k][0] + s * (c[k + 1][0] - c[k][0]), v = c[k][1] + s * (c[k + 1][1] - c[k][1]);
        sq_quad_mesh_map(m, b, q, u, v, &pts[2 * i], NULL);
    }
}

sq_status sq_write_quad_svg(const char *path, const sq_quad_mesh *m, const sq_progress *progress,
                            sq_error *err)
{
    SQ_TRY(sq_quad_mesh_check(m, err));
    if (m->nquads == 0) return SQ_FAIL(err, SQ_ERR_USAGE, "no quads to draw");
    long done = 0, total = (long)m->nquads + m->nbnd;
    sq_progress_every(progress, "write", 0, total);
    sq_quad_basis b;
    SQ_TRY(sq_quad_basis_init(&b, m->order, m->nodes, err));
    double *eta = malloc(sizeof(double) * (size_t)m->nquads);
    if (!eta) return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    sq_quad_quality qq;
    sq_status st = sq_quad_mesh_quality(m, eta, NULL, 1, &qq, err);
    sq_outfile f = {0};
    if (st == SQ_OK) st = sq_outfile_open(path, &f, err);
    if (st != SQ_OK) {
        free(eta);
        return st;
    }
    double bb[4] = {HUGE_VAL, HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
    for (int v = 0; v < m->nnodes; v++) {
        bb[0] = fmin(bb[0], m->xy[2 * v]), bb[1] = fmin(bb[1], m->xy[2 * v + 1]);
        bb[2] = fmax(bb[2], m->xy[2 * v]), bb[3] = fmax(bb[3], m->xy[2 * v + 1]);
    }
    /* room below the mesh for the legend and the caption */
    double w = bb[2] - bb[0], h = bb[3] - bb[1];
    double sc = fmin(860.0 / (w > 0 ? w : 1), 600.0 / (h > 0 ? h : 1));
    double pad = 70.0 / sc;
    double box[4] = {bb[0], bb[1] - pad, bb[2], bb[3]};
    sq_svg svg;
    sq_svg_begin(&svg, f.fp, box, 900.0, 640.0 + 70.0);
    double poly[2 * 4 * NSUB + 2], pts[2 * (NSUB + 1)];
    char col[8];
    for (int q = 0; q < m->nquads; q++) {
        for (int k = 0; k < 4; k++) {
            side_poly(m, &b, q, k, pts);
            for (int i = 0; i < NSUB; i++) {
                poly[2 * (k * NSUB + i)] = pts[2 * i];
                poly[2 * (k * NSUB + i) + 1] = pts[2 * i + 1];
            }
        }
        sq_quad_eta_color(eta[q], col);
        sq_svg_polyline(&svg, 4 * NSUB, poly, 1, "#333333", 0.5, col);
        sq_progress_every(progress, "write", ++done, total);
    }
    for (int s = 0; s < m->nbnd; s++) {
        side_poly(m, &b, m->bnd_quad[s], m->bnd_side[s], pts);
        sq_svg_polyline(&svg, NSUB + 1, pts, 0, "#111111", 2.0, "none");
        sq_progress_every(progress, "write", ++done, total);
    }
    /* legend: ramp from eta 0.5 to 1 */
    double lx = bb[0], ly = bb[1] - 0.35 * pad, lw = fmin(w, 300.0 / svg.scale) / 20.0;
    for (int i = 0; i < 20; i++) {
        double r[8] = {lx + i * lw, ly, lx + (i + 1) * lw, ly, lx + (i + 1) * lw, ly - 0.18 * pad,
                       lx + i * lw, ly - 0.18 * pad};
        sq_quad_eta_color(0.5 + 0.5 * (i + 0.5) / 20.0, col);
        sq_svg_polyline(&svg, 4, r, 1, col, 0.5, col);
    }
    sq_svg_text(&svg, lx, ly, 0.0, -4.0, 11.0, "#333333", "eta  0.5");
    sq_svg_text(&svg, lx + 20 * lw, ly, -18.0, -4.0, 11.0, "#333333", "1.0");
    char caption[256];
    snprintf(caption, sizeof caption, "%d quads, order %d (%s), %d interior irregular vertices",
             m->nquads, m->order, m->nodes == SQ_NODES_GLL ? "GLL" : "equispaced",
             qq.irregular_interior);
    sq_svg_text(&svg, bb[0], bb[1] - 0.75 * pad, 0.0, 0.0, 12.0, "#333333", caption);
    snprintf(caption, sizeof caption,
             "eta mean %.3f, worst %.3f, tau %.1f %%, min scaled Jacobian %.3f", qq.eta_mean,
             qq.eta_min, qq.tau_percent, qq.min_scaled_jacobian);
    sq_svg_text(&svg, bb[0], bb[1] - 0.75 * pad, 0.0, 15.0, 12.0, "#333333", caption);
    sq_svg_end(&svg);
    free(eta);
    return sq_outfile_commit(&f, err);
}
