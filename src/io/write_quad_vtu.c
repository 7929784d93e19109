#include "write_quad_vtu.h"

#include "format_number.h"
#include "outfile.h"
#include "quad_order.h"
#include "write_msh.h"

#include <stdlib.h>

#define VTK_LAGRANGE_QUADRILATERAL 70

static void cell_array(FILE *fp, const char *name, const double *v, int n)
{
    fprintf(fp, "<DataArray type=\"Float64\" Name=\"%s\" format=\"ascii\">\n", name);
    for (int i = 0; i < n; i++) fprintf(fp, "%.10g\n", v[i]);
    fputs("</DataArray>\n", fp);
}

/* Periodic links (docs/domains.md): point data naming each linked node's
 * partner (0-based, the node it is the image of, or its image), -1 for
 * the others; a node of several links names its first. */
static sq_status point_partners(FILE *fp, const sq_quad_mesh *m, sq_error *err)
{
    if (m->nperiodic == 0) return SQ_OK;
    int *partner = malloc(sizeof(int) * ((size_t)m->nnodes + 1));
    if (!partner) return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    for (int v = 0; v < m->nnodes; v++) partner[v] = -1;
    for (int l = 0; l < m->nperiodic; l++)
        for (int k = 0; k < m->periodic[l].nnodes; k++) {
            int a = m->periodic[l].master_node[k], b = m->periodic[l].node[k];
            if (partner[b] < 0) partner[b] = a;
            if (partner[a] < 0) partner[a] = b;
        }
    fputs("<PointData>\n<DataArray type=\"Int64\" Name=\"periodic_partner\" format=\"ascii\">\n", fp);
    for (int v = 0; v < m->nnodes; v++) fprintf(fp, "%d\n", partner[v]);
    fputs("</DataArray>\n</PointData>\n", fp);
    free(partner);
    return SQ_OK;
}

/* A domain's faces (docs/domains.md): field data naming each face, a
 * string array (VTK writes a string in ASCII as its character codes and a
 * terminating 0) beside the faces' numbers in the same order, so that the
 * cells' `face` numbers can be looked up by name. */
static void face_names(FILE *fp, const sq_quad_mesh *m)
{
    if (!m->region) return;
    fprintf(fp, "<FieldData>\n<Array type=\"String\" Name=\"face_name\" NumberOfTuples=\"%d\" "
                "format=\"ascii\">\n",
            m->nregions);
    for (int r = 0; r < m->nregions; r++) {
        char buf[32];
        for (const unsigned char *c = (const unsigned char *)sq_quad_mesh_region_name(
                 m, r, buf, sizeof buf);
             *c; c++)
            fprintf(fp, "%d ", *c);
        fputs("0\n", fp);
    }
    fprintf(fp, "</Array>\n<DataArray type=\"Int32\" Name=\"face_number\" "
                "NumberOfTuples=\"%d\" format=\"ascii\">\n",
            m->nregions);
    for (int r = 0; r < m->nregions; r++) fprintf(fp, "%d\n", m->region_face[r]);
    fputs("</DataArray>\n</FieldData>\n", fp);
}

sq_status sq_write_quad_vtu(const char *path, const sq_quad_mesh *m0, const sq_progress *progress,
                            sq_error *err)
{
    SQ_TRY(sq_quad_mesh_check(m0, err));
    long done = 0, total = (long)m0->nnodes + m0->nquads;
    sq_progress_every(progress, "write", 0, total);
    int Q = m0->order, npe = (Q + 1) * (Q + 1), nq = m0->nquads;
    sq_quad_mesh *eq = NULL;
    const sq_quad_mesh *m = m0;
    if (m0->nodes != SQ_NODES_EQUISPACED) {
        SQ_TRY(sq_quad_mesh_resample(m0, SQ_NODES_EQUISPACED, &eq, err));
        m = eq;
    }
    int *ij = malloc(sizeof(int) * 2 * (size_t)npe);
    double *eta = malloc(sizeof(double) * ((size_t)nq + 1));
    double *etac = malloc(sizeof(double) * ((size_t)nq + 1));
    double *sj = malloc(sizeof(double) * ((size_t)nq + 1));
    sq_outfile f = {0};
    sq_quad_quality qq;
    sq_status st = ij && eta && etac && sj ? SQ_OK : SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    /* quality of the mesh as given (its own nodes) */
    if (st == SQ_OK && nq) st = sq_quad_mesh_quality(m0, eta, sj, 1, &qq, err);
    if (st == SQ_OK && nq) st = sq_quad_mesh_eta_curved(m0, etac, err);
    if (st == SQ_OK) st = sq_outfile_open(path, &f, err);
    if (st != SQ_OK) goto done;
    sq_quad_vtk_order(Q, ij);
    FILE *fp = f.fp;
    fprintf(fp, "<?xml version=\"1.0\"?>\n"
                "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\">\n"
                "<UnstructuredGrid>\n");
    face_names(fp, m0);
    fprintf(fp, "<Piece NumberOfPoints=\"%d\" NumberOfCells=\"%d\">\n"
                "<Points>\n<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n",
            m->nnodes, nq);
    for (int v = 0; v < m->nnodes; v++) {
        char line[SQ_XY0_CHARS + 1];
        int n = sq_format_xy0(line, m->xy[2 * v], m->xy[2 * v + 1]);
        line[n++] = '\n';
        fwrite(line, 1, (size_t)n, fp);
        sq_progress_every(progress, "write", ++done, total);
    }
    fputs("</DataArray>\n</Points>\n<Cells>\n"
          "<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n", fp);
    for (int q = 0; q < nq; q++) {
        const int *c = &m->conn[(size_t)q * npe];
        char line[12 * 121 + 1]; /* up to 121 nodes (order 10) of 11 characters */
        int n = 0;
        for (int k = 0; k < npe; k++) {
            n += sq_format_long(line + n, c[sq_quad_node(Q, ij[2 * k], ij[2 * k + 1])]);
            line[n++] = k + 1 < npe ? ' ' : '\n';
        }
        fwrite(line, 1, (size_t)n, fp);
        sq_progress_every(progress, "write", ++done, total);
    }
    fputs("</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n", fp);
    for (int q = 0; q < nq; q++) fprintf(fp, "%ld\n", (long)npe * (q + 1));
    fputs("</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n", fp);
    for (int q = 0; q < nq; q++) fprintf(fp, "%d\n", VTK_LAGRANGE_QUADRILATERAL);
    fputs("</DataArray>\n</Cells>\n", fp);
    st = point_partners(fp, m, err);
    if (st != SQ_OK) goto done;
    fputs("<CellData Scalars=\"eta\">\n", fp);
    cell_array(fp, "eta", eta, nq);
    cell_array(fp, "eta_curved", etac, nq);
    cell_array(fp, "scaled_jacobian", sj, nq);
    fputs("<DataArray type=\"Int32\" Name=\"patch\" format=\"ascii\">\n", fp);
    for (int q = 0; q < nq; q++) fprintf(fp, "%d\n", m->patch[q]);
    if (m->region) { /* a domain's faces (docs/domains.md) */
        fputs("</DataArray>\n<DataArray type=\"Int32\" Name=\"face\" format=\"ascii\">\n", fp);
        for (int q = 0; q < nq; q++) fprintf(fp, "%d\n", m->region_face[m->region[q]]);
    }
    fputs("</DataArray>\n</CellData>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n", fp);
    st = sq_outfile_commit(&f, err);
done:
    sq_outfile_abort(&f);
    sq_quad_mesh_free(&eq);
    free(ij);
    free(eta);
    free(etac);
    free(sj);
    return st;
}
