#include "svg_mesh.h"

#include "tri_geom.h"

#include <math.h>

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
