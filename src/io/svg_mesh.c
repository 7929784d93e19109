#include "svg_mesh.h"

#include "tri_geom.h"

#include <math.h>
#include <string.h>

#define NSUB 16 /* polyline points per curved edge */

void sq_svg_mesh_bbox(const sem_tri_mesh *m, double bb[4])
{
    bb[0] = bb[1] = HUGE_VAL;
    bb[2] = bb[3] = -HUGE_VAL;
    size_t n = (size_t)m->nodes_per_tri * (size_t)m->ntris;
    for (size_t i = 0; i < n; i++) {
        double x = m->gxy[2 * i], y = m->gxy[2 * i + 1];
        bb[0] = fmin(bb[0], x);
        bb[1] = fmin(bb[1], y);
        bb[2] = fmax(bb[2], x);
        bb[3] = fmax(bb[3], y);
    }
}

void sq_svg_mesh_edges(sq_svg *svg, const sem_tri_mesh *m, const sem_tri_lagrange *lag,
                       int interior, const char *interior_color, double interior_width,
                       const char *boundary_color, double boundary_width)
{
    static const double c[3][2] = {{0, 0}, {1, 0}, {0, 1}};
    double pts[2 * (NSUB + 1)];
    for (int pass = !interior; pass < 2; pass++)
        for (int e = 0; e < m->ntris; e++)
            for (int k = 0; k < 3; k++) {
                int bnd = m->btag[3 * e + k] >= 0;
                if (bnd != pass) continue;
                /* a shared edge once, from the element with the lower index */
                if (!bnd && m->neigh[3 * e + k] >= 0 && m->neigh[3 * e + k] < e) continue;
                const double *a = c[k], *b = c[(k + 1) % 3];
                for (int i = 0; i <= NSUB; i++) {
                    double u = (double)i / NSUB;
                    sem_tri_geom_map(lag, &m->gxy[2 * (size_t)m->nodes_per_tri * e],
                                     a[0] + u * (b[0] - a[0]), a[1] + u * (b[1] - a[1]),
                                     &pts[2 * i], NULL);
                }
                sq_svg_polyline(svg, NSUB + 1, pts, 0, bnd ? boundary_color : interior_color,
                                bnd ? boundary_width : interior_width, "none");
            }
}

void sq_svg_mesh_isolines(sq_svg *svg, const sem_tri_mesh *m, const sem_tri_lagrange *lag, int S,
                          sq_svg_scalar_fn f, void *ctx, double level0, double step, double tol,
                          const unsigned char *skip, const char *color, double width)
{
    for (int e = 0; e < m->ntris; e++) {
        if (skip && skip[e]) continue;
        const double *g = &m->gxy[2 * (size_t)m->nodes_per_tri * e];
        for (int j = 0; j < S; j++)
            for (int i = 0; i + j < S; i++)
                for (int up = 0; up < 2; up++) {
                    if (up && i + j + 1 >= S) continue;
                    /* the lattice cell's lower or upper sub-triangle */
                    int ci[3][2] = {{i, j}, {i + 1, j}, {i, j + 1}};
                    if (up) {
                        ci[0][0] = i + 1, ci[0][1] = j + 1;
                        ci[1][0] = i, ci[1][1] = j + 1;
                        ci[2][0] = i + 1, ci[2][1] = j;
                    }
                    double rs[3][2], val[3], lo = HUGE_VAL, hi = -HUGE_VAL;
                    for (int q = 0; q < 3; q++) {
                        rs[q][0] = (double)ci[q][0] / S;
                        rs[q][1] = (double)ci[q][1] / S;
                        val[q] = f(ctx, e, rs[q][0], rs[q][1]);
                        lo = fmin(lo, val[q]);
                        hi = fmax(hi, val[q]);
                    }
                    double k0 = step > 0.0 ? ceil((lo - level0) / step) : 0.0;
                    double k1 = step > 0.0 ? floor((hi - level0) / step) : 0.0;
                    for (double k = k0; k <= k1; k += 1.0) {
                        double lv = level0 + k * (step > 0.0 ? step : 0.0), pts[4];
                        int np = 0;
                        for (int q = 0; q < 3 && np < 2; q++) {
                            int w = (q + 1) % 3;
                            if ((val[q] < lv - tol) == (val[w] < lv - tol)) continue;
                            double t = (lv - val[q]) / (val[w] - val[q]);
                            sem_tri_geom_map(lag, g, rs[q][0] + t * (rs[w][0] - rs[q][0]),
                                             rs[q][1] + t * (rs[w][1] - rs[q][1]), &pts[2 * np],
                                             NULL);
                            np++;
                        }
                        if (np == 2) sq_svg_polyline(svg, 2, pts, 0, color, width, "none");
                    }
                }
    }
}

sq_status sq_svg_mesh_open(const char *path, const sem_tri_mesh *m, const char *interior_color,
                           double interior_width, sq_svg_mesh_picture *pic, sq_error *err)
{
    memset(pic, 0, sizeof *pic);
    SQ_TRY(sem_tri_lagrange_create(m->order, &pic->lag, err));
    sq_status st = sq_outfile_open(path, &pic->file, err);
    if (st != SQ_OK) {
        sem_tri_lagrange_free(&pic->lag);
        return st;
    }
    sq_svg_mesh_bbox(m, pic->bbox);
    sq_svg_begin(&pic->svg, pic->file.fp, pic->bbox, 900.0, 700.0);
    sq_svg_mesh_edges(&pic->svg, m, pic->lag, 1, interior_color, interior_width, "#1a1a1a", 2.0);
    return SQ_OK;
}

sq_status sq_svg_mesh_close(sq_svg_mesh_picture *pic, sq_status status, sq_error *err)
{
    sem_tri_lagrange_free(&pic->lag);
    if (status != SQ_OK) {
        sq_outfile_abort(&pic->file);
        return status;
    }
    sq_svg_end(&pic->svg);
    return sq_outfile_commit(&pic->file, err);
}
