#include "write_tri.h"

#include "json_writer.h"
#include "lattice_order.h"
#include "outfile.h"
#include "svg.h"
#include "tri_geom.h"
#include "tri_lagrange.h"

#include <math.h>
#include <stdlib.h>

#define VTK_LAGRANGE_TRIANGLE 69

/* Element e's geometry at (r, s). */
static void map_point(const sem_tri_lagrange *lag, const sem_tri_mesh *m, int e, double r,
                      double s, double x[2])
{
    sem_tri_geom_map(lag, &m->gxy[2 * (size_t)m->nodes_per_tri * (size_t)e], r, s, x, NULL);
}

sq_status sq_write_tri_vtu(const char *path, const sq_triangulation *t, sq_error *err)
{
    const sem_tri_mesh *m = t->mesh;
    int P = m->order, nn = m->nodes_per_tri;
    sem_tri_lagrange *lag = NULL;
    int *ij = malloc(sizeof(int) * 2 * (size_t)nn);
    if (!ij) return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    sq_status st = sem_tri_lagrange_create(P, &lag, err);
    sq_outfile f = {0};
    if (st == SQ_OK) st = sq_outfile_open(path, &f, err);
    if (st != SQ_OK) {
        free(ij);
        sem_tri_lagrange_free(&lag);
        return st;
    }
    sq_tri_lattice_order(P, ij);
    FILE *fp = f.fp;
    long npts = (long)nn * m->ntris;
    fprintf(fp, "<?xml version=\"1.0\"?>\n"
                "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\">\n"
                "<UnstructuredGrid>\n<Piece NumberOfPoints=\"%ld\" NumberOfCells=\"%d\">\n"
                "<Points>\n<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n",
            npts, m->ntris);
    for (int e = 0; e < m->ntris; e++)
        for (int n = 0; n < nn; n++) {
            double x[2];
            map_point(lag, m, e, (double)ij[2 * n] / P, (double)ij[2 * n + 1] / P, x);
            fprintf(fp, "%.17g %.17g 0\n", x[0], x[1]);
        }
    fputs("</DataArray>\n</Points>\n<Cells>\n"
          "<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n", fp);
    for (long i = 0; i < npts; i++) fprintf(fp, "%ld%c", i, (i + 1) % nn ? ' ' : '\n');
    fputs("</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n", fp);
    for (int e = 0; e < m->ntris; e++) fprintf(fp, "%ld\n", (long)nn * (e + 1));
    fputs("</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n", fp);
    for (int e = 0; e < m->ntris; e++) fprintf(fp, "%d\n", VTK_LAGRANGE_TRIANGLE);
    fputs("</DataArray>\n</Cells>\n<CellData>\n"
          "<DataArray type=\"Float64\" Name=\"scaled_jacobian\" format=\"ascii\">\n", fp);
    for (int e = 0; e < m->ntris; e++) fprintf(fp, "%.6g\n", t->jac[e]);
    fputs("</DataArray>\n<DataArray type=\"Int32\" Name=\"boundary_edges\" format=\"ascii\">\n", fp);
    for (int e = 0; e < m->ntris; e++)
        fprintf(fp, "%d\n", (m->btag[3 * e] >= 0) + (m->btag[3 * e + 1] >= 0) +
                                (m->btag[3 * e + 2] >= 0));
    fputs("</DataArray>\n</CellData>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n", fp);
    free(ij);
    sem_tri_lagrange_free(&lag);
    return sq_outfile_commit(&f, err);
}

static void mesh_bbox(const sem_tri_mesh *m, double bb[4])
{
    bb[0] = bb[1] = HUGE_VAL;
    bb[2] = bb[3] = -HUGE_VAL;
    size_t n = (size_t)m->nodes_per_tri * (size_t)m->ntris;
    for (size_t i = 0; i < n; i++) {
        double x = m->gxy[2 * i], y = m->gxy[2 * i + 1];
        if (x < bb[0]) bb[0] = x;
        if (y < bb[1]) bb[1] = y;
        if (x > bb[2]) bb[2] = x;
        if (y > bb[3]) bb[3] = y;
    }
}

sq_status sq_write_tri_svg(const char *path, const sq_triangulation *t, sq_error *err)
{
    enum { NSUB = 16 }; /* polyline points per curved edge */
    const sem_tri_mesh *m = t->mesh;
    sem_tri_lagrange *lag = NULL;
    SQ_TRY(sem_tri_lagrange_create(m->order, &lag, err));
    sq_outfile f;
    sq_status st = sq_outfile_open(path, &f, err);
    if (st != SQ_OK) {
        sem_tri_lagrange_free(&lag);
        return st;
    }
    double bb[4], pts[2 * (NSUB + 1)];
    mesh_bbox(m, bb);
    sq_svg svg;
    sq_svg_begin(&svg, f.fp, bb, 900.0, 700.0);
    /* interior edges first, then the boundary on top */
    for (int pass = 0; pass < 2; pass++)
        for (int e = 0; e < m->ntris; e++)
            for (int k = 0; k < 3; k++) {
                int bnd = m->btag[3 * e + k] >= 0;
                if (bnd != pass) continue;
                /* draw a shared edge once, from the element with the lower index */
                if (!bnd && m->neigh[3 * e + k] < e) continue;
                static const double c[3][2] = {{0, 0}, {1, 0}, {0, 1}};
                const double *a = c[k], *b = c[(k + 1) % 3];
                for (int i = 0; i <= NSUB; i++) {
                    double u = (double)i / NSUB;
                    map_point(lag, m, e, a[0] + u * (b[0] - a[0]), a[1] + u * (b[1] - a[1]),
                              &pts[2 * i]);
                }
                sq_svg_polyline(&svg, NSUB + 1, pts, 0, bnd ? "#1a1a1a" : "#3366aa",
                                bnd ? 2.0 : 0.8, "none");
            }
    for (int v = 0; v < m->nverts; v++)
        sq_svg_circle(&svg, m->vxy[2 * v], m->vxy[2 * v + 1], 1.8, "#3366aa");
    char caption[160];
    snprintf(caption, sizeof caption,
             "%d triangles, order %d, min angle %.1f deg, min scaled Jacobian %.3f", m->ntris,
             m->order, t->min_angle_deg, t->min_scaled_jacobian);
    sq_svg_text(&svg, bb[0], bb[1], 0.0, 16.0, 12.0, "#333333", caption);
    sq_svg_end(&svg);
    sem_tri_lagrange_free(&lag);
    return sq_outfile_commit(&f, err);
}

sq_status sq_write_tri_report(const char *path, const char *input, int face,
                              const sq_triangulation *t, sq_error *err)
{
    sq_outfile f;
    SQ_TRY(sq_outfile_open(path, &f, err));
    sq_json j;
    sq_json_init(&j, f.fp);
    sq_json_begin_object(&j);
    sq_json_key(&j, "input");
    sq_json_string(&j, input);
    sq_json_key(&j, "face");
    sq_json_int(&j, face);
    sq_json_key(&j, "triangles");
    sq_json_int(&j, t->mesh->ntris);
    sq_json_key(&j, "vertices");
    sq_json_int(&j, t->mesh->nverts);
    sq_json_key(&j, "order");
    sq_json_int(&j, t->mesh->order);
    sq_json_key(&j, "size");
    sq_json_number(&j, t->size);
    sq_json_key(&j, "min_angle_deg");
    sq_json_number(&j, t->min_angle_deg);
    sq_json_key(&j, "min_scaled_jacobian");
    sq_json_number(&j, t->min_scaled_jacobian);
    sq_json_key(&j, "area");
    sq_json_number(&j, t->area);
    sq_json_end_object(&j);
    return sq_outfile_commit(&f, err);
}
