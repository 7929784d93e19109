#include "write_msh.h"
#include "write_lines.h"

#include "format_number.h"
#include "msh_entities.h"
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

/* What both encodings write: the equispaced mesh, Gmsh's node orders and
 * the model entities (msh_entities.h). */
typedef struct {
    FILE *fp;
    int binary;
    const sq_quad_mesh *m0; /* the caller's mesh (its names) */
    const sq_quad_mesh *m;  /* equispaced */
    int *ij, lo[11];
    sq_msh_entities ent;
    sq_write_count count; /* progress: nodes and elements written */
    int threads;          /* text formatted on this many (write_lines.h) */
} msh_writer;

/* Binary MSH 4.1 stores numbers in the writer's byte order, sizes as
 * size_t (data-size 8); the int 1 after the version lets readers tell. */
static void put_size(msh_writer *w, size_t v) { fwrite(&v, sizeof v, 1, w->fp); }
static void put_int(msh_writer *w, int v) { fwrite(&v, sizeof v, 1, w->fp); }

/* Physical names (text in both encodings): one group per boundary curve or
 * group of curves named alike (the physical tag of its least curve); one
 * surface, "domain", or one per face of a domain, its name in the file or
 * "face_N" (docs/domains.md). */
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
    for (int r = 0; r < m->nregions; r++) {
        char buf[32];
        fprintf(w->fp, "2 %d \"%s\"\n", nt + 1 + r, sq_quad_mesh_region_name(w->m0, r, buf, sizeof buf));
    }
    fputs("$EndPhysicalNames\n", w->fp);
}

/* One entity of dimension dim: tag, bounding box b (z = 0) or, for a
 * point, its position (b[0], b[1]), its physical group (none: 0), the
 * nbound entities bounding it (signed tags). */
static void entity(msh_writer *w, int dim, int tag, const double *b, int physical, const int *bound,
                   int nbound)
{
    int point = dim == 0, nbox = point ? 3 : 6;
    double box[6] = {b[0], b[1], 0.0, point ? 0.0 : b[2], point ? 0.0 : b[3], 0.0};
    if (w->binary) {
        put_int(w, tag);
        fwrite(box, sizeof *box, (size_t)nbox, w->fp);
        put_size(w, physical > 0);
        if (physical > 0) put_int(w, physical);
        if (point) return;
        put_size(w, (size_t)nbound);
        for (int k = 0; k < nbound; k++) put_int(w, bound[k]);
        return;
    }
    fprintf(w->fp, "%d", tag);
    for (int k = 0; k < nbox; k++) {
        char x[SQ_DOUBLE_CHARS];
        sq_format_double(x, box[k]);
        fprintf(w->fp, " %s", x);
    }
    if (physical > 0) fprintf(w->fp, " 1 %d", physical);
    else fputs(" 0", w->fp);
    if (!point) fprintf(w->fp, " %d", nbound);
    for (int k = 0; !point && k < nbound; k++) fprintf(w->fp, " %d", bound[k]);
    fputc('\n', w->fp);
}

/* Entities (msh_entities.h): point p+1 at its node, no physical group;
 * curve c+1 (physical tag: a boundary curve t's group, an interface none)
 * from its first point to its last (the last signed -); surface r+1 with
 * physical tag ntags+1+r, bounded by its curves (signed - where the curve
 * runs with the surface on its right). bound holds room for 2 tags per
 * curve. */
static void entities(msh_writer *w, int *bound)
{
    const sq_msh_entities *e = &w->ent;
    int nt = w->m->ntags;
    fputs("$Entities\n", w->fp);
    if (w->binary) {
        size_t n[4] = {(size_t)e->npoints, (size_t)e->ncurves, (size_t)e->nsurfaces, 0};
        fwrite(n, sizeof *n, 4, w->fp);
    } else
        fprintf(w->fp, "%d %d %d 0\n", e->npoints, e->ncurves, e->nsurfaces);
    for (int p = 0; p < e->npoints; p++) {
        const double *x = &w->m->xy[2 * (size_t)e->point_node[p]];
        entity(w, 0, p + 1, x, 0, NULL, 0);
    }
    for (int c = 0; c < e->ncurves; c++) {
        int n = 0;
        if (e->curve_ends[2 * c] >= 0) bound[n++] = e->curve_ends[2 * c] + 1;
        if (e->curve_ends[2 * c + 1] >= 0) bound[n++] = -(e->curve_ends[2 * c + 1] + 1);
        entity(w, 1, c + 1, &e->curve_bb[4 * c], c < nt ? sq_quad_mesh_tag_group(w->m0, c) + 1 : 0, bound, n);
    }
    for (int r = 0; r < e->nsurfaces; r++) {
        int n = 0;
        for (int c = 0; c < e->ncurves; c++)
            if (e->curve_faces[2 * c] == r || e->curve_faces[2 * c + 1] == r)
                bound[n++] = e->curve_faces[2 * c] == r ? c + 1 : -(c + 1);
        entity(w, 2, r + 1, &e->surface_bb[4 * r], nt + 1 + r, bound, n);
    }
    fputs(w->binary ? "\n$EndEntities\n" : "$EndEntities\n", w->fp);
}

/* The text lines of a node block: node[k]'s tag (node_tag_line) or its
 * coordinates (node_xy_line). */
typedef struct {
    const sq_quad_mesh *m;
    const int *node;
} node_lines;

static int node_tag_line(const void *ctx, long k, char *buf)
{
    const node_lines *l = ctx;
    int len = sq_format_long(buf, l->node[k] + 1);
    buf[len++] = '\n';
    return len;
}

static int node_xy_line(const void *ctx, long k, char *buf)
{
    const node_lines *l = ctx;
    const double *x = &l->m->xy[2 * (size_t)l->node[k]];
    int len = sq_format_xy0(buf, x[0], x[1]);
    buf[len++] = '\n';
    return len;
}

/* One block of nodes: entity (dim, tag), not parametric, node[n] (mesh
 * indices, tags + 1). */
static sq_status node_block(msh_writer *w, int dim, int tag, const int *node, int n,
                            sq_error *err)
{
    const sq_quad_mesh *m = w->m;
    if (w->binary) {
        put_int(w, dim), put_int(w, tag), put_int(w, 0), put_size(w, (size_t)n);
        for (int k = 0; k < n; k++) put_size(w, (size_t)node[k] + 1);
        for (int k = 0; k < n; k++) {
            double x[3] = {m->xy[2 * (size_t)node[k]], m->xy[2 * (size_t)node[k] + 1], 0.0};
            fwrite(x, sizeof *x, 3, w->fp);
            sq_progress_every(w->count.progress, "write", ++w->count.done, w->count.total);
        }
        return SQ_OK;
    }
    fprintf(w->fp, "%d %d 0 %d\n", dim, tag, n);
    node_lines l = {m, node};
    SQ_TRY(sq_write_lines(w->fp, n, 24, node_tag_line, &l, w->threads, NULL, err));
    return sq_write_lines(w->fp, n, SQ_XY0_CHARS + 1, node_xy_line, &l, w->threads, &w->count,
                          err);
}

/* Nodes: one block per entity holding nodes (points, curves, surfaces),
 * node tag = mesh index + 1 (so not contiguous within a block). */
static sq_status nodes(msh_writer *w, sq_error *err)
{
    const sq_msh_entities *e = &w->ent;
    int nent = e->npoints + e->ncurves + e->nsurfaces, nblocks = 0;
    size_t n = (size_t)w->m->nnodes;
    for (int k = 0; k < nent; k++) nblocks += e->first[k + 1] > e->first[k];
    fputs("$Nodes\n", w->fp);
    if (w->binary) {
        size_t head[4] = {(size_t)nblocks, n, n ? 1 : 0, n};
        fwrite(head, sizeof *head, 4, w->fp);
    } else
        fprintf(w->fp, "%d %zu %d %zu\n", nblocks, n, n ? 1 : 0, n);
    for (int k = 0; k < nent; k++) {
        int dim = k < e->npoints ? 0 : k < e->npoints + e->ncurves ? 1 : 2;
        int tag = k - (dim == 0 ? 0 : dim == 1 ? e->npoints : e->npoints + e->ncurves) + 1;
        if (e->first[k + 1] > e->first[k])
            SQ_TRY(node_block(w, dim, tag, &e->node[e->first[k]], e->first[k + 1] - e->first[k],
                              err));
    }
    fputs(w->binary ? "\n$EndNodes\n" : "$EndNodes\n", w->fp);
    return SQ_OK;
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

/* An element's text line: its tag and n nodes (mesh indices, written + 1)
 * into line (ELEMENT_CHARS); its length. */
#define ELEMENT_CHARS (12 * (121 + 1) + 1) /* up to 121 nodes (order 10) of 11 characters */
static int element_line(char *line, int tag, const int *c, const int *which, int n)
{
    int len = sq_format_long(line, tag);
    for (int k = 0; k < n; k++) {
        line[len++] = ' ';
        len += sq_format_long(line + len, c[which[k]] + 1);
    }
    line[len++] = '\n';
    return len;
}

/* One element, one record in rec (room for n + 1) when binary. */
static void element(msh_writer *w, int tag, const int *c, const int *which, int n, size_t *rec)
{
    if (w->binary) {
        rec[0] = (size_t)tag;
        for (int k = 0; k < n; k++) rec[k + 1] = (size_t)c[which[k]] + 1;
        fwrite(rec, sizeof *rec, (size_t)n + 1, w->fp);
    } else {
        char line[ELEMENT_CHARS];
        fwrite(line, 1, (size_t)element_line(line, tag, c, which, n), w->fp);
    }
    sq_progress_every(w->count.progress, "write", ++w->count.done, w->count.total);
}

/* The text lines of surface `region`'s quads: quad k's, or none when it
 * lies in another surface. */
typedef struct {
    const sq_quad_mesh *m;
    const int *which;
    int region;
} quad_lines;

static int quad_line(const void *ctx, long k, char *buf)
{
    const quad_lines *l = ctx;
    const sq_quad_mesh *m = l->m;
    if (m->region && m->region[k] != l->region) return 0;
    int npe = (m->order + 1) * (m->order + 1);
    return element_line(buf, (int)k + 1, &m->conn[(size_t)k * npe], l->which, npe);
}

/* Elements: the quads (tags 1..nquads) per surface, then a block of lines
 * per curve; which[] holds the local nodes in Gmsh's order. */
static sq_status elements(msh_writer *w, int *which, size_t *rec, sq_error *err)
{
    const sq_quad_mesh *m = w->m;
    int Q = m->order, npe = (Q + 1) * (Q + 1), nt = m->ntags, ns = m->nregions > 0 ? m->nregions : 1;
    int nblocks = ns, nel = m->nquads + m->nbnd;
    for (int t = 0; t < nt; t++) nblocks += w->ent.curve_sides[t] > 0;
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
        quad_lines l = {m, which, r};
        if (!w->binary)
            SQ_TRY(sq_write_lines(w->fp, m->nquads, ELEMENT_CHARS, quad_line, &l, w->threads,
                                  &w->count, err));
        for (int q = 0; w->binary && q < m->nquads; q++)
            if (!m->region || m->region[q] == r) element(w, q + 1, &m->conn[(size_t)q * npe], which, npe, rec);
    }
    int tag = m->nquads;
    for (int t = 0; t < nt; t++) {
        if (!w->ent.curve_sides[t]) continue;
        block(w, 1, t + 1, sq_gmsh_line_type(Q), w->ent.curve_sides[t]);
        for (int s = 0; s < m->nbnd; s++) {
            if (m->bnd_tag[s] != t) continue;
            for (int k = 0; k <= Q; k++) which[k] = sq_quad_side_node(Q, m->bnd_side[s], w->lo[k]);
            element(w, ++tag, &m->conn[(size_t)m->bnd_quad[s] * npe], which, Q + 1, rec);
        }
    }
    fputs(w->binary ? "\n$EndElements\n" : "$EndElements\n", w->fp);
    return SQ_OK;
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

static sq_status write_msh(const char *path, const sq_quad_mesh *m0, int binary, int threads,
                           const sq_progress *progress, sq_error *err)
{
    SQ_TRY(sq_quad_mesh_check(m0, err));
    msh_writer w = {.binary = binary, .m0 = m0, .m = m0, .threads = threads,
                    .count = {progress, 0, (long)m0->nnodes + m0->nquads + m0->nbnd}};
    sq_progress_every(progress, "write", 0, w.count.total);
    sq_quad_mesh *eq = NULL;
    if (m0->nodes != SQ_NODES_EQUISPACED) {
        SQ_TRY(sq_quad_mesh_resample(m0, SQ_NODES_EQUISPACED, &eq, err));
        w.m = eq;
    }
    int Q = w.m->order, npe = (Q + 1) * (Q + 1);
    sq_status st = sq_msh_entities_build(w.m, &w.ent, err);
    w.ij = malloc(sizeof(int) * 2 * (size_t)npe);
    int *which = malloc(sizeof(int) * (size_t)npe);
    size_t *rec = malloc(sizeof(size_t) * ((size_t)npe + 1));
    int *bound = malloc(sizeof(int) * (2 * (size_t)w.ent.ncurves + 1));
    sq_outfile f = {0};
    if (st == SQ_OK && !(w.ij && which && rec && bound)) st = SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    if (st == SQ_OK) st = sq_outfile_open(path, &f, err);
    if (st == SQ_OK) {
        w.fp = f.fp;
        sq_quad_gmsh_order(Q, w.ij);
        sq_line_order(Q, w.lo);
        fputs(binary ? "$MeshFormat\n4.1 1 8\n" : "$MeshFormat\n4.1 0 8\n", w.fp);
        if (binary) {
            put_int(&w, 1);
            fputc('\n', w.fp);
        }
        fputs("$EndMeshFormat\n", w.fp);
        physical_names(&w);
        entities(&w, bound);
        st = nodes(&w, err);
        if (st == SQ_OK) st = elements(&w, which, rec, err);
        if (st == SQ_OK) periodic(&w);
        if (st == SQ_OK) st = sq_outfile_commit(&f, err);
    }
    sq_outfile_abort(&f);
    sq_quad_mesh_free(&eq);
    sq_msh_entities_free(&w.ent);
    free(w.ij);
    free(which);
    free(rec);
    free(bound);
    return st;
}

sq_status sq_write_msh(const char *path, const sq_quad_mesh *m, const sq_progress *progress,
                       sq_error *err)
{
    return write_msh(path, m, 0, 1, progress, err);
}

sq_status sq_write_msh_threads(const char *path, const sq_quad_mesh *m, int threads,
                               const sq_progress *progress, sq_error *err)
{
    return write_msh(path, m, 0, threads, progress, err);
}

sq_status sq_write_msh_binary(const char *path, const sq_quad_mesh *m,
                              const sq_progress *progress, sq_error *err)
{
    return write_msh(path, m, 1, 1, progress, err);
}
