#include "write_vtu.h"

#include "lattice_order.h"
#include "outfile.h"
#include "tri_geom.h"
#include "tri_lagrange.h"
#include "tri_nodes.h"

#include <stdlib.h>

#define VTK_LAGRANGE_TRIANGLE 69

sq_status sq_write_vtu(const char *path, const sem_tri_mesh *m, int order, const sq_vtu_data *data,
                       sq_error *err)
{
    int P = order > 0 ? order : m->order, nn = sem_tri_num_nodes(P);
    int na = data ? data->npoint_arrays : 0;
    sem_tri_lagrange *lag = NULL;
    int *ij = malloc(sizeof(int) * 2 * (size_t)nn);
    double *pd = malloc(sizeof(double) * ((size_t)na * nn * m->ntris + 1));
    sq_outfile f = {0};
    sq_status st = ij && pd ? SQ_OK : SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    if (st == SQ_OK) st = sem_tri_lagrange_create(m->order, &lag, err);
    if (st == SQ_OK) st = sq_outfile_open(path, &f, err);
    if (st != SQ_OK) goto done;
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
            double x[2], r = (double)ij[2 * n] / P, s = (double)ij[2 * n + 1] / P;
            sem_tri_geom_map(lag, &m->gxy[2 * (size_t)m->nodes_per_tri * e], r, s, x, NULL);
            fprintf(fp, "%.17g %.17g 0\n", x[0], x[1]);
            if (na) data->point_data(data->ctx, e, r, s, &pd[((size_t)e * nn + n) * na]);
        }
    fputs("</DataArray>\n</Points>\n<Cells>\n"
          "<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n", fp);
    for (long i = 0; i < npts; i++) fprintf(fp, "%ld%c", i, (i + 1) % nn ? ' ' : '\n');
    fputs("</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n", fp);
    for (int e = 0; e < m->ntris; e++) fprintf(fp, "%ld\n", (long)nn * (e + 1));
    fputs("</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n", fp);
    for (int e = 0; e < m->ntris; e++) fprintf(fp, "%d\n", VTK_LAGRANGE_TRIANGLE);
    fputs("</DataArray>\n</Cells>\n", fp);
    if (na) {
        fputs("<PointData>\n", fp);
        for (int a = 0; a < na; a++) {
            fprintf(fp, "<DataArray type=\"Float64\" Name=\"%s\" format=\"ascii\">\n",
                    data->point_names[a]);
            for (long i = 0; i < npts; i++) fprintf(fp, "%.10g\n", pd[(size_t)i * na + a]);
            fputs("</DataArray>\n", fp);
        }
        fputs("</PointData>\n", fp);
    }
    fputs("<CellData>\n", fp);
    for (int a = 0; data && a < data->ncell_arrays; a++) {
        fprintf(fp, "<DataArray type=\"Float64\" Name=\"%s\" format=\"ascii\">\n",
                data->cell_names[a]);
        for (int e = 0; e < m->ntris; e++) fprintf(fp, "%.10g\n", data->cell_data[a][e]);
        fputs("</DataArray>\n", fp);
    }
    fputs("<DataArray type=\"Int32\" Name=\"boundary_edges\" format=\"ascii\">\n", fp);
    for (int e = 0; e < m->ntris; e++)
        fprintf(fp, "%d\n", (m->btag[3 * e] >= 0) + (m->btag[3 * e + 1] >= 0) +
                                (m->btag[3 * e + 2] >= 0));
    fputs("</DataArray>\n</CellData>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n", fp);
    st = sq_outfile_commit(&f, err);
done:
    sq_outfile_abort(&f);
    sem_tri_lagrange_free(&lag);
    free(ij);
    free(pd);
    return st;
}
