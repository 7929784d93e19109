#include "write_msh.h"

#include "format_number.h"
#include "outfile.h"
#include "quad_order.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

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

/* What both encodings write: the equispaced mesh, Gmsh's node orders, the
 * boundary lines per curve and the bounding boxes of the curves (bb[4t..])
 * and of the surface (bb[4 ntags..]). */
typedef struct {
    FILE *fp;
    int binary;
    const sq_quad_mesh *m0; /* the caller's mesh (its names) */
    const sq_quad_mesh *m;  /* equispaced */
    int *ij, lo[11], *count;
    double *bb;
    const sq_progress *progress;
    long done, total;
} msh_writer;

/* Binary MSH 4.1 stores numbers in the writer's byte order, sizes as
 * size_t (data-size 8); the int 1 after the version lets readers tell. */
static void put_size(msh_writer *w, size_t v) { fwrite(&v, sizeof v, 1, w->fp); }
static void put_int(msh_writer *w, int v) { fwrite(&v, sizeof v, 1, w->fp); }

static void bounding_boxes(msh_writer *w)
{
    const sq_quad_mesh *m = w->m;
    int Q = m->order, npe = (Q + 1) * (Q + 1), nt = m->ntags;
    double *bb = w->bb;
    for (int t = 0; t <= nt; t++) bb[4 * t] = bb[4 * t + 1] = HUGE_VAL, bb[4 * t + 2] = bb[4 * t + 3] = -HUGE_VAL;
    for (int v = 0; v < m->nnodes; v++) {
        double *b = &bb[4 * nt];
        b[0] = fmin(b[0], m->xy[2 * v]), b[1] = fmin(b[1], m->xy[2 * v + 1]);
        b[2] = fmax(b[2], m->xy[2 * v]), b[3] = fmax(b[3], m->xy[2 * v + 1]);
    }
    for (int s = 0; s < m->nbnd; s++) {
        int t = m->bnd_tag[s];
        const int *c = &m->conn[(size_t)m->bnd_quad[s] * npe];
        w->count[t]++;
        for (int k = 0; k <= Q; k++) {
            const double *x = &m->xy[2 * (size_t)c[sq_quad_side_node(Q, m->bnd_side[s], k)]];
            double *b = &bb[4 * t];
            b[0] = fmin(b[0], x[0]), b[1] = fmin(b[1], x[1]);
            b[2] = fmax(b[2], x[0]), b[3] = fmax(b[3], x[1]);
        }
    }
    for (int t = 0; t <= nt; t++)
        if (bb[4 * t] > bb[4 * t + 2]) bb[4 * t] = bb[4 * t + 1] = bb[4 * t + 2] = bb[4 * t + 3] = 0.0;
}

/* Physical names (text in both encodings): one group per boundary curve or
 * group of curves named alike (the physical tag of its least curve); one
 * surface, "domain", or one per face of a domain, "face_N" (docs/domains.md). */
static void physical_names(msh_writer *w)
{
    const sq_quad_mesh *m = w->m;
    int nt = m->ntags, ns = m->nregions > 0 ? m->nregions : 1, ngroups = 0;
    for (int t = 0; t < nt; t++) ngroups += sq_quad_mesh_tag_group(w->m0, t) == t;
    fprintf(w->fp, "$PhysicalNames\n%d\n", ngroups + ns);
    for (int t = 0; t < nt; t++) {
        char buf[32];
        if (sq_quad_mesh_tag_group(w->m0, t) == t)
            fprintf(w->fp, "1 %d \"%s\"\n", t + 1, sq_quad_mesh_tag_name(w->m0, t, buf, sizeof buf));
    }
    if (m->nregions == 0) fprintf(w->fp, "2 %d \"domain\"\n", nt + 1);
    for (int r = 0; r < m->nregions; r++) fprintf(w->fp, "2 %d \"face_%d\"\n", nt + 1 + r, m->region_face[r]);
    fputs("$EndPhysicalNames\n", w->fp);
}

/* One entity: tag, bounding box (z = 0), its physical group, the curves
 * bounding it (nbound of them, tags 1..nbound). */
static void entity(msh_writer *w, int tag, const double *b, int physical, int nbound)
{
    if (w->binary) {
        double box[6] = {b[0], b[1], 0.0, b[2], b[3], 0.0};
        put_int(w, tag);
        fwrite(box, sizeof *box, 6, w->fp);
        put_size(w, 1);
        put_int(w, physical);
        put_size(w, (size_t)nbound);
        for (int t = 0; t < nbound; t++) put_int(w, t + 1);
        return;
    }
    char x[4][SQ_DOUBLE_CHARS];
    for (int k = 0; k < 4; k++) sq_format_double(x[k], b[k]);
    fprintf(w->fp, "%d %s %s 0 %s %s 0 1 %d %d", tag, x[0], x[1], x[2], x[3], physical, nbound);
    for (int t = 0; t < nbound; t++) fprintf(w->fp, " %d", t + 1);
    fputc('\n', w->fp);
}

/* Entities: no points; curve t+1 with physical t's group and no bounding
 * points; surface r+1 with physical nt+1+r bounded by all curves. */
static void entities(msh_writer *w)
{
    const sq_quad_mesh *m = w->m;
    int nt = m->ntags, ns = m->nregions > 0 ? m->nregions : 1;
    fputs("$Entities\n", w->fp);
    if (w->binary) {
        size_t n[4] = {0, (size_t)nt, (size_t)ns, 0};
        fwrite(n, sizeof *n, 4, w->fp);
    } else
        fprintf(w->fp, "0 %d %d 0\n", nt, ns);
    for (int t = 0; t < nt; t++) entity(w, t + 1, &w->bb[4 * t], sq_quad_mesh_tag_group(w->m0, t) + 1, 0);
    for (int r = 0; r < ns; r++) entity(w, r + 1, &w->bb[4 * nt], nt + 1 + r, nt);
    fputs(w->binary ? "\n$EndEntities\n" : "$EndEntities\n", w->fp);
}

/* Nodes: one block on the surface, tags 1..nnodes, not parametric. */
static void nodes(msh_writer *w)
{
    const sq_quad_mesh *m = w->m;
    size_t n = (size_t)m->nnodes;
    fputs("$Nodes\n", w->fp);
    if (w->binary) {
        size_t head[4] = {1, n, n ? 1 : 0, n};
        fwrite(head, sizeof *head, 4, w->fp);
        put_int(w, 2), put_int(w, 1), put_int(w, 0), put_size(w, n);
        for (size_t v = 0; v < n; v++) put_size(w, v + 1);
        for (size_t v = 0; v < n; v++) {
            double x[3] = {m->xy[2 * v], m->xy[2 * v + 1], 0.0};
            fwrite(x, sizeof *x, 3, w->fp);
            sq_progress_every(w->progress, "write", ++w->done, w->total);
        }
        fputs("\n$EndNodes\n", w->fp);
        return;
    }
    fprintf(w->fp, "1 %d %d %d\n2 1 0 %d\n", m->nnodes, m->nnodes ? 1 : 0, m->nnodes, m->nnodes);
    char line[SQ_XY0_CHARS + 1];
    for (int v = 0; v < m->nnodes; v++) {
        int n = sq_format_long(line, v + 1);
        line[n++] = '\n';
        fwrite(line, 1, (size_t)n, w->fp);
    }
    for (int v = 0; v < m->nnodes; v++) {
        int n = sq_format_xy0(line, m->xy[2 * v], m->xy[2 * v + 1]);
        line[n++] = '\n';
        fwrite(line, 1, (size_t)n, w->fp);
        sq_progress_every(w->progress, "write", ++w->done, w->total);
    }
    fputs("$EndNodes\n", w->fp);
}

/* A block header: dimension, entity, element type, count. */
static void block(msh_writer *w, int dim, int tag, int type, int n)
{
    if (!w->binary) {
        fprintf(w->fp, "%d %d %d %d\n", dim, tag, type, n);
        return;
    }
    put_int(w, dim), put_int(w, tag), put_int(w, type), put_size(w, (size_t)n);
}

/* One element: its tag and n nodes (mesh indices, written + 1), one record
 * in rec (room for n + 1). */
static void element(msh_writer *w, int tag, const int *c, const int *which, int n, size_t *rec)
{
    if (w->binary) {
        rec[0] = (size_t)tag;
        for (int k = 0; k < n; k++) rec[k + 1] = (size_t)c[which[k]] + 1;
        fwrite(rec, sizeof *rec, (size_t)n + 1, w->fp);
    } else {
        char line[12 * (121 + 1) + 1]; /* up to 121 nodes (order 10) of 11 characters */
        int len = sq_format_long(line, tag);
        for (int k = 0; k < n; k++) {
            line[len++] = ' ';
            len += sq_format_long(line + len, c[which[k]] + 1);
        }
        line[len++] = '\n';
        fwrite(line, 1, (size_t)len, w->fp);
    }
    sq_progress_every(w->progress, "write", ++w->done, w->total);
}

/* Elements: the quads (tags 1..nquads) per surface, then a block of lines
 * per curve; which[] holds the local nodes in Gmsh's order. */
static void elements(msh_writer *w, int *which, size_t *rec)
{
    const sq_quad_mesh *m = w->m;
    int Q = m->order, npe = (Q + 1) * (Q + 1), nt = m->ntags, ns = m->nregions > 0 ? m->nregions : 1;
    int nblocks = ns, nel = m->nquads + m->nbnd;
    for (int t = 0; t < nt; t++) nblocks += w->count[t] > 0;
    fputs("$Elements\n", w->fp);
    if (w->binary) {
        size_t head[4] = {(size_t)nblocks, (size_t)nel, nel ? 1 : 0, (size_t)nel};
        fwrite(head, sizeof *head, 4, w->fp);
    } else
        fprintf(w->fp, "%d %d %d %d\n", nblocks, nel, nel ? 1 : 0, nel);
    for (int k = 0; k < npe; k++) which[k] = sq_quad_node(Q, w->ij[2 * k], w->ij[2 * k + 1]);
    for (int r = 0; r < ns; r++) {
        int nr = 0;
        for (int q = 0; q < m->nquads; q++) nr += !m->region || m->region[q] == r;
        block(w, 2, r + 1, sq_gmsh_quad_type(Q), nr);
        for (int q = 0; q < m->nquads; q++)
            if (!m->region || m->region[q] == r) element(w, q + 1, &m->conn[(size_t)q * npe], which, npe, rec);
    }
    int tag = m->nquads;
    for (int t = 0; t < nt; t++) {
        if (!w->count[t]) continue;
        block(w, 1, t + 1, sq_gmsh_line_type(Q), w->count[t]);
        for (int s = 0; s < m->nbnd; s++) {
            if (m->bnd_tag[s] != t) continue;
            for (int k = 0; k <= Q; k++) which[k] = sq_quad_side_node(Q, m->bnd_side[s], w->lo[k]);
            element(w, ++tag, &m->conn[(size_t)m->bnd_quad[s] * npe], which, Q + 1, rec);
        }
    }
    fputs(w->binary ? "\n$EndElements\n" : "$EndElements\n", w->fp);
}

/* Periodic links (docs/domains.md): per link the curve entity, its
 * master's, the 4x4 affine map (row by row) taking the master onto it, and
 * the node pairs (node, master's node). */
static void periodic(msh_writer *w)
{
    const sq_quad_mesh *m = w->m;
    if (m->nperiodic == 0) return;
    fputs("$Periodic\n", w->fp);
    if (w->binary) put_size(w, (size_t)m->nperiodic);
    else fprintf(w->fp, "%d\n", m->nperiodic);
    for (int l = 0; l < m->nperiodic; l++) {
        const sq_quad_periodic *p = &m->periodic[l];
        const double *T = p->affine;
        double A[16] = {T[0], T[1], 0, T[2], T[3], T[4], 0, T[5], 0, 0, 1, 0, 0, 0, 0, 1};
        if (!w->binary) {
            fprintf(w->fp, "1 %d %d\n16", p->tag + 1, p->master + 1);
            for (int k = 0; k < 16; k++) {
                char x[SQ_DOUBLE_CHARS];
                sq_format_double(x, A[k]);
                fprintf(w->fp, " %s", x);
            }
            fprintf(w->fp, "\n%d\n", p->nnodes);
            for (int k = 0; k < p->nnodes; k++)
                fprintf(w->fp, "%d %d\n", p->node[k] + 1, p->master_node[k] + 1);
            continue;
        }
        put_int(w, 1), put_int(w, p->tag + 1), put_int(w, p->master + 1), put_size(w, 16);
        fwrite(A, sizeof *A, 16, w->fp);
        put_size(w, (size_t)p->nnodes);
        for (int k = 0; k < p->nnodes; k++)
            put_size(w, (size_t)p->node[k] + 1), put_size(w, (size_t)p->master_node[k] + 1);
    }
    fputs(w->binary ? "\n$EndPeriodic\n" : "$EndPeriodic\n", w->fp);
}

static sq_status write_msh(const char *path, const sq_quad_mesh *m0, int binary,
                           const sq_progress *progress, sq_error *err)
{
    SQ_TRY(sq_quad_mesh_check(m0, err));
    msh_writer w = {.binary = binary, .m0 = m0, .m = m0, .progress = progress,
                    .total = (long)m0->nnodes + m0->nquads + m0->nbnd};
    sq_progress_every(progress, "write", 0, w.total);
    sq_quad_mesh *eq = NULL;
    if (m0->nodes != SQ_NODES_EQUISPACED) {
        SQ_TRY(sq_quad_mesh_resample(m0, SQ_NODES_EQUISPACED, &eq, err));
        w.m = eq;
    }
    int Q = w.m->order, npe = (Q + 1) * (Q + 1), nt = w.m->ntags;
    w.ij = malloc(sizeof(int) * 2 * (size_t)npe);
    w.count = calloc((size_t)nt + 1, sizeof *w.count);
    w.bb = malloc(sizeof(double) * 4 * ((size_t)nt + 1));
    int *which = malloc(sizeof(int) * (size_t)npe);
    size_t *rec = malloc(sizeof(size_t) * ((size_t)npe + 1));
    sq_outfile f = {0};
    sq_status st = w.ij && w.count && w.bb && which && rec
                       ? SQ_OK : SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    if (st == SQ_OK) st = sq_outfile_open(path, &f, err);
    if (st == SQ_OK) {
        w.fp = f.fp;
        sq_quad_gmsh_order(Q, w.ij);
        sq_line_order(Q, w.lo);
        bounding_boxes(&w);
        fputs(binary ? "$MeshFormat\n4.1 1 8\n" : "$MeshFormat\n4.1 0 8\n", w.fp);
        if (binary) {
            put_int(&w, 1);
            fputc('\n', w.fp);
        }
        fputs("$EndMeshFormat\n", w.fp);
        physical_names(&w);
        entities(&w);
        nodes(&w);
        elements(&w, which, rec);
        periodic(&w);
        st = sq_outfile_commit(&f, err);
    }
    sq_outfile_abort(&f);
    sq_quad_mesh_free(&eq);
    free(w.ij);
    free(w.count);
    free(w.bb);
    free(which);
    free(rec);
    return st;
}

sq_status sq_write_msh(const char *path, const sq_quad_mesh *m, const sq_progress *progress,
                       sq_error *err)
{
    return write_msh(path, m, 0, progress, err);
}

sq_status sq_write_msh_binary(const char *path, const sq_quad_mesh *m,
                              const sq_progress *progress, sq_error *err)
{
    return write_msh(path, m, 1, progress, err);
}
