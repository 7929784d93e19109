#include "write_msh.h"

#include "outfile.h"
#include "quad_order.h"

#include <math.h>
#include <stdlib.h>

sq_status sq_quad_mesh_check(const sq_quad_mesh *m, sq_error *err)
{
    if (!m || m->order < 1 || m->order > 10)
        return SQ_FAIL(err, SQ_ERR_USAGE, "quad mesh missing or order outside 1..10");
    size_t n = (size_t)(m->order + 1) * (m->order + 1) * (size_t)m->nquads;
    for (size_t k = 0; k < n; k++)
        if (m->conn[k] < 0 || m->conn[k] >= m->nnodes)
            return SQ_FAIL(err, SQ_ERR_USAGE, "quad %zu refers to node %d of %d", k / ((size_t)(m->order + 1) * (m->order + 1)),
                           m->conn[k], m->nnodes);
    for (int b = 0; b < m->nbnd; b++)
        if (m->bnd_quad[b] < 0 || m->bnd_quad[b] >= m->nquads || m->bnd_side[b] < 0 ||
            m->bnd_side[b] > 3 || m->bnd_tag[b] < 0 || m->bnd_tag[b] >= m->ntags)
            return SQ_FAIL(err, SQ_ERR_USAGE,
                           "boundary side %d (quad %d, side %d, tag %d) out of range (%d quads, "
                           "%d tags)",
                           b, m->bnd_quad[b], m->bnd_side[b], m->bnd_tag[b], m->nquads, m->ntags);
    return SQ_OK;
}


/* Periodic links (docs/domains.md): per link the curve entity, its
 * master's, the 4x4 affine map (row by row) taking the master onto it,
 * and the node pairs (node, master's node). */
static void write_periodic(FILE *fp, const sq_quad_mesh *m)
{
    if (m->nperiodic == 0) return;
    fprintf(fp, "$Periodic\n%d\n", m->nperiodic);
    for (int l = 0; l < m->nperiodic; l++) {
        const sq_quad_periodic *p = &m->periodic[l];
        const double *T = p->affine;
        fprintf(fp, "1 %d %d\n16 %.17g %.17g 0 %.17g %.17g %.17g 0 %.17g 0 0 1 0 0 0 0 1\n%d\n",
                p->tag + 1, p->master + 1, T[0], T[1], T[2], T[3], T[4], T[5], p->nnodes);
        for (int k = 0; k < p->nnodes; k++) fprintf(fp, "%d %d\n", p->node[k] + 1, p->master_node[k] + 1);
    }
    fputs("$EndPeriodic\n", fp);
}

sq_status sq_write_msh(const char *path, const sq_quad_mesh *m0, const sq_progress *progress,
                       sq_error *err)
{
    SQ_TRY(sq_quad_mesh_check(m0, err));
    long done = 0, total = (long)m0->nnodes + m0->nquads + m0->nbnd;
    sq_progress_every(progress, "write", 0, total);
    sq_quad_mesh *eq = NULL;
    const sq_quad_mesh *m = m0;
    if (m0->nodes != SQ_NODES_EQUISPACED) {
        SQ_TRY(sq_quad_mesh_resample(m0, SQ_NODES_EQUISPACED, &eq, err));
        m = eq;
    }
    int Q = m->order, npe = (Q + 1) * (Q + 1), nt = m->ntags;
    int *ij = malloc(sizeof(int) * 2 * (size_t)npe), lo[11];
    int *count = calloc((size_t)nt + 1, sizeof *count);
    double *bb = malloc(sizeof(double) * 4 * ((size_t)nt + 1));
    sq_outfile f = {0};
    sq_status st = ij && count && bb ? SQ_OK : SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    if (st == SQ_OK) st = sq_outfile_open(path, &f, err);
    if (st != SQ_OK) goto done;
    sq_quad_gmsh_order(Q, ij);
    sq_line_order(Q, lo);
    /* bounding boxes of the curves (from their sides' nodes) and the surface */
    for (int t = 0; t <= nt; t++) bb[4 * t] = bb[4 * t + 1] = HUGE_VAL, bb[4 * t + 2] = bb[4 * t + 3] = -HUGE_VAL;
    for (int v = 0; v < m->nnodes; v++) {
        double *b = &bb[4 * nt];
        b[0] = fmin(b[0], m->xy[2 * v]), b[1] = fmin(b[1], m->xy[2 * v + 1]);
        b[2] = fmax(b[2], m->xy[2 * v]), b[3] = fmax(b[3], m->xy[2 * v + 1]);
    }
    for (int s = 0; s < m->nbnd; s++) {
        int t = m->bnd_tag[s];
        const int *c = &m->conn[(size_t)m->bnd_quad[s] * npe];
        count[t]++;
        for (int k = 0; k <= Q; k++) {
            const double *x = &m->xy[2 * (size_t)c[sq_quad_side_node(Q, m->bnd_side[s], k)]];
            double *b = &bb[4 * t];
            b[0] = fmin(b[0], x[0]), b[1] = fmin(b[1], x[1]);
            b[2] = fmax(b[2], x[0]), b[3] = fmax(b[3], x[1]);
        }
    }
    for (int t = 0; t <= nt; t++)
        if (bb[4 * t] > bb[4 * t + 2]) bb[4 * t] = bb[4 * t + 1] = bb[4 * t + 2] = bb[4 * t + 3] = 0.0;
    FILE *fp = f.fp;
    fputs("$MeshFormat\n4.1 0 8\n$EndMeshFormat\n", fp);
    /* physical names: dim tag "name" */
    /* one surface, "domain"; or one per face of a domain, "face_N"
     * (docs/domains.md) */
    int ns = m->nregions > 0 ? m->nregions : 1;
    /* a group of named curves is the physical group of its least tag */
    int ngroups = 0;
    for (int t = 0; t < nt; t++) ngroups += sq_quad_mesh_tag_group(m0, t) == t;
    fprintf(fp, "$PhysicalNames\n%d\n", ngroups + ns);
    for (int t = 0; t < nt; t++) {
        char buf[32];
        if (sq_quad_mesh_tag_group(m0, t) == t)
            fprintf(fp, "1 %d \"%s\"\n", t + 1, sq_quad_mesh_tag_name(m0, t, buf, sizeof buf));
    }
    if (m->nregions == 0) fprintf(fp, "2 %d \"domain\"\n", nt + 1);
    for (int r = 0; r < m->nregions; r++) fprintf(fp, "2 %d \"face_%d\"\n", nt + 1 + r, m->region_face[r]);
    fputs("$EndPhysicalNames\n", fp);
    /* entities: no points; curve t+1 with physical t+1 and no bounding
     * points; surface r+1 with physical nt+1+r bounded by all curves */
    fprintf(fp, "$Entities\n0 %d %d 0\n", nt, ns);
    for (int t = 0; t < nt; t++)
        fprintf(fp, "%d %.17g %.17g 0 %.17g %.17g 0 1 %d 0\n", t + 1, bb[4 * t], bb[4 * t + 1],
                bb[4 * t + 2], bb[4 * t + 3], sq_quad_mesh_tag_group(m0, t) + 1);
    for (int r = 0; r < ns; r++) {
        fprintf(fp, "%d %.17g %.17g 0 %.17g %.17g 0 1 %d %d", r + 1, bb[4 * nt], bb[4 * nt + 1],
                bb[4 * nt + 2], bb[4 * nt + 3], nt + 1 + r, nt);
        for (int t = 0; t < nt; t++) fprintf(fp, " %d", t + 1);
        fputc('\n', fp);
    }
    fputs("$EndEntities\n", fp);
    /* nodes: one block on the surface, tags 1..nnodes, not parametric */
    fprintf(fp, "$Nodes\n1 %d %d %d\n2 1 0 %d\n", m->nnodes, m->nnodes ? 1 : 0, m->nnodes,
            m->nnodes);
    for (int v = 0; v < m->nnodes; v++) fprintf(fp, "%d\n", v + 1);
    for (int v = 0; v < m->nnodes; v++) {
        fprintf(fp, "%.17g %.17g 0\n", m->xy[2 * v], m->xy[2 * v + 1]);
        sq_progress_every(progress, "write", ++done, total);
    }
    fputs("$EndNodes\n", fp);
    /* elements: the quads (tags 1..nquads), then a block of lines per curve */
    int nblocks = ns, nel = m->nquads + m->nbnd;
    for (int t = 0; t < nt; t++) nblocks += count[t] > 0;
    fprintf(fp, "$Elements\n%d %d %d %d\n", nblocks, nel, nel ? 1 : 0, nel);
    for (int r = 0; r < ns; r++) {
        int nr = 0;
        for (int q = 0; q < m->nquads; q++) nr += !m->region || m->region[q] == r;
        fprintf(fp, "2 %d %d %d\n", r + 1, sq_gmsh_quad_type(Q), nr);
        for (int q = 0; q < m->nquads; q++) {
            if (m->region && m->region[q] != r) continue;
            const int *c = &m->conn[(size_t)q * npe];
            fprintf(fp, "%d", q + 1);
            for (int k = 0; k < npe; k++)
                fprintf(fp, " %d", c[sq_quad_node(Q, ij[2 * k], ij[2 * k + 1])] + 1);
            fputc('\n', fp);
            sq_progress_every(progress, "write", ++done, total);
        }
    }
    int tag = m->nquads;
    for (int t = 0; t < nt; t++) {
        if (!count[t]) continue;
        fprintf(fp, "1 %d %d %d\n", t + 1, sq_gmsh_line_type(Q), count[t]);
        for (int s = 0; s < m->nbnd; s++) {
            if (m->bnd_tag[s] != t) continue;
            const int *c = &m->conn[(size_t)m->bnd_quad[s] * npe];
            fprintf(fp, "%d", ++tag);
            for (int k = 0; k <= Q; k++) fprintf(fp, " %d", c[sq_quad_side_node(Q, m->bnd_side[s], lo[k])] + 1);
            fputc('\n', fp);
            sq_progress_every(progress, "write", ++done, total);
        }
    }
    fputs("$EndElements\n", fp);
    write_periodic(fp, m);
    st = sq_outfile_commit(&f, err);
done:
    sq_outfile_abort(&f);
    sq_quad_mesh_free(&eq);
    free(ij);
    free(count);
    free(bb);
    return st;
}
