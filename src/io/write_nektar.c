#include "write_nektar.h"

#include "format_number.h"
#include "nektar_b64z.h"
#include "outfile.h"
#include "write_msh.h"

#include <stdlib.h>
#include <string.h>

typedef struct {
    unsigned long long key; /* lower corner << 32 | higher corner */
    int next;               /* node next to the lower corner along the side (Q >= 2) */
    int quad, side;
} side_rec;

static int cmp_side(const void *a, const void *b)
{
    const side_rec *x = a, *y = b;
    if (x->key != y->key) return x->key < y->key ? -1 : 1;
    if (x->next != y->next) return x->next < y->next ? -1 : 1;
    if (x->quad != y->quad) return x->quad < y->quad ? -1 : 1;
    return (x->side > y->side) - (x->side < y->side);
}

/* "a-b" ranges of a sorted id list, comma separated. */
static void write_ranges(FILE *fp, const int *ids, int n)
{
    for (int i = 0; i < n;) {
        int k = i;
        while (k + 1 < n && ids[k + 1] == ids[k] + 1) k++;
        if (i) fputc(',', fp);
        if (k > i) fprintf(fp, "%d-%d", ids[i], ids[k]);
        else fprintf(fp, "%d", ids[i]);
        i = k + 1;
    }
}

/* before, then id and '">' unless id < 0, then "x y 0", then after: one
 * point of a VERTEX or CURVED entry. */
static void put_point(FILE *fp, const char *before, int id, const double *xy, const char *after)
{
    char line[64 + SQ_XY0_CHARS];
    size_t n = strlen(before), k = strlen(after);
    memcpy(line, before, n);
    if (id >= 0) {
        n += (size_t)sq_format_long(line + n, id);
        line[n++] = '"', line[n++] = '>';
    }
    n += (size_t)sq_format_xy0(line + n, xy[0], xy[1]);
    memcpy(line + n, after, k);
    fwrite(line, 1, n + k, fp);
}

/* Periodic sides (docs/domains.md): the links of one transform (a chain)
 * give two composites, their masters' edges and theirs, numbered after the
 * curves' and the faces', for a <P> boundary condition each. */
static void periodic_composites(FILE *fp, const sq_quad_mesh *m, const int *edge_of, int *list)
{
    int id = m->ntags + 1 + m->nregions, chain = 0;
    for (int l = 0; l < m->nperiodic; l++) {
        int first = 1;
        for (int k = 0; k < l; k++)
            first &= memcmp(m->periodic[k].affine, m->periodic[l].affine, sizeof m->periodic[l].affine) != 0;
        if (!first) continue;
        for (int side = 0; side < 2; side++) {
            int n = 0;
            for (int k = l; k < m->nperiodic; k++) {
                const sq_quad_periodic *p = &m->periodic[k];
                if (memcmp(p->affine, m->periodic[l].affine, sizeof p->affine)) continue;
                for (int s = 0; s < m->nbnd; s++)
                    if (m->bnd_tag[s] == (side ? p->tag : p->master))
                        list[n++] = edge_of[4 * m->bnd_quad[s] + m->bnd_side[s]];
            }
            n = sq_sort_unique(list, n);
            fprintf(fp, "      <C ID=\"%d\" NAME=\"periodic_%d_%s\"> E[", id++, chain,
                    side ? "image" : "master");
            write_ranges(fp, list, n);
            fputs("] </C>\n", fp);
        }
        chain++;
    }
}

/* The entities both forms share: corner vertices numbered in node order
 * (vid, -1 for other nodes), edges (owner: quad*4+side of the lowest quad,
 * whose direction the edge takes) and each (quad, side)'s edge. */
typedef struct {
    int nv, ne;
    int *vid, *owner, *edge_of;
} nektar_topology;

/* Edges: element sides matched by their corner pair (and, from Q = 2, by
 * the node next to the lower corner, so two different sides between the
 * same corners stay apart).  rec holds 4 nquads records. */
static sq_status topology(const sq_quad_mesh *m, side_rec *rec, nektar_topology *t, sq_error *err)
{
    int Q = m->order, npe = (Q + 1) * (Q + 1), nq = m->nquads, ns = 4 * nq;
    for (int v = 0; v < m->nnodes; v++) t->vid[v] = -1;
    for (int q = 0; q < nq; q++)
        for (int k = 0; k < 4; k++) t->vid[m->conn[(size_t)q * npe + sq_quad_side_node(Q, k, 0)]] = 0;
    t->nv = 0;
    for (int v = 0; v < m->nnodes; v++)
        if (t->vid[v] == 0) t->vid[v] = t->nv++;
    for (int q = 0; q < nq; q++) {
        const int *c = &m->conn[(size_t)q * npe];
        for (int k = 0; k < 4; k++) {
            int a = c[sq_quad_side_node(Q, k, 0)], b = c[sq_quad_side_node(Q, k, Q)];
            side_rec *r = &rec[4 * q + k];
            unsigned long long lo = (unsigned)(a < b ? a : b), hi = (unsigned)(a < b ? b : a);
            r->key = lo << 32 | hi;
            r->next = Q >= 2 ? c[sq_quad_side_node(Q, k, a < b ? 1 : Q - 1)] : 0;
            r->quad = q;
            r->side = k;
        }
    }
    qsort(rec, (size_t)ns, sizeof *rec, cmp_side);
    t->ne = 0;
    for (int i = 0; i < ns;) {
        int k = i;
        while (k < ns && rec[k].key == rec[i].key && rec[k].next == rec[i].next) k++;
        if (k - i > 2)
            return SQ_FAIL(err, SQ_ERR_USAGE, "non-manifold mesh: %d quads share one side", k - i);
        t->owner[t->ne] = 4 * rec[i].quad + rec[i].side;
        for (int s = i; s < k; s++) t->edge_of[4 * rec[s].quad + rec[s].side] = t->ne;
        t->ne++;
        i = k;
    }
    return SQ_OK;
}

/* Node s (0..Q) of edge e, from its first vertex to its second. */
static int edge_node(const sq_quad_mesh *m, const nektar_topology *t, int e, int s)
{
    int q = t->owner[e] / 4, k = t->owner[e] % 4, npe = (m->order + 1) * (m->order + 1);
    return m->conn[(size_t)q * npe + sq_quad_side_node(m->order, k, s)];
}

/* VERTEX, EDGE, ELEMENT and (Q >= 2) CURVED as text. */
static void text_entities(FILE *fp, const sq_quad_mesh *m, const nektar_topology *t,
                          const sq_progress *progress, long *done, long total)
{
    int Q = m->order, npe = (Q + 1) * (Q + 1), nq = m->nquads;
    const char *ptype = m->nodes == SQ_NODES_GLL ? "GaussLobattoLegendre" : "PolyEvenlySpaced";
    fputs("    <VERTEX>\n", fp);
    for (int v = 0; v < m->nnodes; v++)
        if (t->vid[v] >= 0)
            put_point(fp, "      <V ID=\"", t->vid[v], &m->xy[2 * v], "</V>\n");
    fputs("    </VERTEX>\n    <EDGE>\n", fp);
    for (int e = 0; e < t->ne; e++) {
        fprintf(fp, "      <E ID=\"%d\">%d %d</E>\n", e, t->vid[edge_node(m, t, e, 0)],
                t->vid[edge_node(m, t, e, Q)]);
        sq_progress_every(progress, "write", ++*done, total);
    }
    fputs("    </EDGE>\n    <ELEMENT>\n", fp);
    for (int q = 0; q < nq; q++) {
        const int *eq = &t->edge_of[4 * q];
        fprintf(fp, "      <Q ID=\"%d\">%d %d %d %d</Q>\n", q, eq[0], eq[1], eq[2], eq[3]);
        sq_progress_every(progress, "write", ++*done, total);
    }
    fputs("    </ELEMENT>\n", fp);
    if (Q < 2) return;
    /* Nektar++ needs every edge of a quad with a face curve to carry Q+1
     * points too, so all edges are written. */
    fputs("    <CURVED>\n", fp);
    for (int e = 0; e < t->ne; e++) {
        fprintf(fp, "      <E ID=\"%d\" EDGEID=\"%d\" NUMPOINTS=\"%d\" TYPE=\"%s\">", e, e, Q + 1,
                ptype);
        for (int s = 0; s <= Q; s++)
            put_point(fp, s ? " " : "", -1, &m->xy[2 * (size_t)edge_node(m, t, e, s)], "");
        fputs("</E>\n", fp);
        sq_progress_every(progress, "write", ++*done, total);
    }
    for (int q = 0; q < nq; q++) {
        const int *c = &m->conn[(size_t)q * npe];
        fprintf(fp, "      <F ID=\"%d\" FACEID=\"%d\" NUMPOINTS=\"%d\" TYPE=\"%s\">", q, q, npe,
                ptype);
        for (int n = 0; n < npe; n++) put_point(fp, n ? " " : "", -1, &m->xy[2 * (size_t)c[n]], "");
        fputs("</F>\n", fp);
        sq_progress_every(progress, "write", ++*done, total);
    }
    fputs("    </CURVED>\n", fp);
}

/* open, then the records b[0..n) encoded (nektar_b64z.h), then close. */
static sq_status b64z_element(FILE *fp, const char *open, const unsigned char *b, size_t n,
                              const char *close, sq_error *err)
{
    fputs(open, fp);
    SQ_TRY(sq_write_b64z(fp, b, n, err));
    fputs(close, fp);
    return SQ_OK;
}

#define B64Z_ATTRS " COMPRESSED=\"B64Z-LittleEndian\" BITSIZE=\"64\">"

/* A MeshVertex record {id, x, y, 0} at p; returns its end. */
static unsigned char *put_vertex(unsigned char *p, long long id, const double *xy)
{
    return sq_le64_double(sq_le64_double(sq_le64_double(sq_le64_int(p, id), xy[0]), xy[1]), 0.0);
}

/* MeshVertex records {id, x, y, z = 0} of the nodes of each edge (from its
 * first vertex), then of each quad (lattice order), numbered from 0: the
 * POINTS of CURVED's DATAPOINTS. */
static unsigned char *curve_points(unsigned char *p, const sq_quad_mesh *m, const nektar_topology *t)
{
    int Q = m->order, npe = (Q + 1) * (Q + 1);
    long long id = 0;
    for (int e = 0; e < t->ne; e++)
        for (int s = 0; s <= Q; s++) p = put_vertex(p, id++, &m->xy[2 * (size_t)edge_node(m, t, e, s)]);
    for (size_t n = 0; n < (size_t)m->nquads * npe; n++)
        p = put_vertex(p, id++, &m->xy[2 * (size_t)m->conn[n]]);
    return p;
}

/* CURVED compressed (Nektar++ MeshGraphIOXmlCompressed: E and F hold
 * MeshCurvedInfo records, DATAPOINTS ID 0 the INDEX of every curve's
 * points, in order, and the POINTS); buf holds 32 bytes a point. */
static sq_status compressed_curves(FILE *fp, const sq_quad_mesh *m, const nektar_topology *t,
                                   unsigned char *buf, sq_error *err)
{
    int Q = m->order, npe = (Q + 1) * (Q + 1), nq = m->nquads;
    /* LibUtilities::PointsType: eGaussLobattoLegendre 4, ePolyEvenlySpaced 17 */
    int ptype = m->nodes == SQ_NODES_GLL ? 4 : 17;
    long long off = 0, npts = (long long)t->ne * (Q + 1) + (long long)nq * npe;
    unsigned char *p = buf;
    for (int e = 0; e < t->ne; e++, off += Q + 1) {
        long long rec[6] = {e, e, Q + 1, 0, off, ptype};
        for (int k = 0; k < 6; k++) p = sq_le64_int(p, rec[k]);
    }
    fputs("    <CURVED" B64Z_ATTRS "\n", fp);
    SQ_TRY(b64z_element(fp, "      <E>", buf, (size_t)(p - buf), "</E>\n", err));
    p = buf;
    for (int q = 0; q < nq; q++, off += npe) {
        long long rec[6] = {q, q, npe, 0, off, ptype};
        for (int k = 0; k < 6; k++) p = sq_le64_int(p, rec[k]);
    }
    SQ_TRY(b64z_element(fp, "      <F>", buf, (size_t)(p - buf), "</F>\n", err));
    p = buf;
    for (long long i = 0; i < npts; i++) p = sq_le64_int(p, i);
    SQ_TRY(b64z_element(fp, "      <DATAPOINTS ID=\"0\">\n        <INDEX>", buf, (size_t)(p - buf),
                        "</INDEX>\n", err));
    p = curve_points(buf, m, t);
    SQ_TRY(b64z_element(fp, "        <POINTS>", buf, (size_t)(p - buf),
                        "</POINTS>\n      </DATAPOINTS>\n", err));
    fputs("    </CURVED>\n", fp);
    return SQ_OK;
}

/* VERTEX, EDGE, ELEMENT and (Q >= 2) CURVED in Nektar++'s compressed form
 * (MeshGraphIOXmlCompressed): the same entities, ids and coordinates as
 * text_entities, each section one base64 text (nektar_b64z.h). */
static sq_status compressed_entities(FILE *fp, const sq_quad_mesh *m, const nektar_topology *t,
                                     const sq_progress *progress, long *done, long total,
                                     sq_error *err)
{
    int Q = m->order, npe = (Q + 1) * (Q + 1), nq = m->nquads;
    size_t npts = Q >= 2 ? (size_t)t->ne * (Q + 1) + (size_t)nq * npe : 0;
    size_t cap = 32 * (size_t)t->nv;
    if (cap < 48 * ((size_t)t->ne + nq)) cap = 48 * ((size_t)t->ne + nq); /* >= edges, quads */
    if (cap < 32 * npts) cap = 32 * npts;
    unsigned char *buf = malloc(cap + 1), *p = buf;
    if (!buf) return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    for (int v = 0; v < m->nnodes; v++)
        if (t->vid[v] >= 0)
            p = put_vertex(p, t->vid[v], &m->xy[2 * v]);
    sq_status st = b64z_element(fp, "    <VERTEX" B64Z_ATTRS, buf, (size_t)(p - buf), "</VERTEX>\n", err);
    p = buf;
    for (int e = 0; e < t->ne; e++) {
        p = sq_le64_int(sq_le64_int(sq_le64_int(p, e), t->vid[edge_node(m, t, e, 0)]),
                        t->vid[edge_node(m, t, e, Q)]);
        sq_progress_every(progress, "write", ++*done, total);
    }
    if (st == SQ_OK)
        st = b64z_element(fp, "    <EDGE" B64Z_ATTRS, buf, (size_t)(p - buf), "</EDGE>\n", err);
    p = buf;
    for (int q = 0; q < nq; q++) {
        p = sq_le64_int(p, q);
        for (int k = 0; k < 4; k++) p = sq_le64_int(p, t->edge_of[4 * q + k]);
        sq_progress_every(progress, "write", ++*done, total);
    }
    if (st == SQ_OK)
        st = b64z_element(fp, "    <ELEMENT>\n      <Q" B64Z_ATTRS, buf, (size_t)(p - buf),
                          "</Q>\n    </ELEMENT>\n", err);
    if (st == SQ_OK && Q >= 2) {
        st = compressed_curves(fp, m, t, buf, err);
        *done += t->ne + nq;
        sq_progress_every(progress, "write", *done, total);
    }
    free(buf);
    return st;
}

/* the quads: composite 0; of a domain's faces, one composite per face
 * after the boundary's, nt+1+r (docs/domains.md); then the curves', the
 * periodic sides' and DOMAIN. */
static void composites(FILE *fp, const sq_quad_mesh *m, const int *edge_of, int *list)
{
    int nq = m->nquads;
    fputs("    <COMPOSITE>\n", fp);
    for (int r = 0; r < (m->nregions > 0 ? m->nregions : 1); r++) {
        int n = 0;
        for (int q = 0; q < nq; q++)
            if (!m->region || m->region[q] == r) list[n++] = q;
        if (m->region_name && m->region_name[r])
            fprintf(fp, "      <C ID=\"%d\" NAME=\"%s\"> Q[", m->ntags + 1 + r, m->region_name[r]);
        else
            fprintf(fp, "      <C ID=\"%d\"> Q[", m->region ? m->ntags + 1 + r : 0);
        write_ranges(fp, list, n);
        fputs("] </C>\n", fp);
    }
    /* curves named alike (docs/formats.md) are one composite, the least
     * curve's, with the name as its NAME */
    for (int t = 0; t < m->ntags; t++) {
        int n = 0;
        if (sq_quad_mesh_tag_group(m, t) != t) continue;
        for (int s = 0; s < m->nbnd; s++)
            if (sq_quad_mesh_tag_group(m, m->bnd_tag[s]) == t)
                list[n++] = edge_of[4 * m->bnd_quad[s] + m->bnd_side[s]];
        if (!n) continue;
        n = sq_sort_unique(list, n);
        if (m->tag_name && m->tag_name[t])
            fprintf(fp, "      <C ID=\"%d\" NAME=\"%s\"> E[", t + 1, m->tag_name[t]);
        else
            fprintf(fp, "      <C ID=\"%d\"> E[", t + 1);
        write_ranges(fp, list, n);
        fputs("] </C>\n", fp);
    }
    periodic_composites(fp, m, edge_of, list);
    if (m->nregions > 1)
        fprintf(fp, "    </COMPOSITE>\n    <DOMAIN> C[%d-%d] </DOMAIN>\n", m->ntags + 1,
                m->ntags + m->nregions);
    else if (m->nregions == 1)
        fprintf(fp, "    </COMPOSITE>\n    <DOMAIN> C[%d] </DOMAIN>\n", m->ntags + 1);
    else
        fputs("    </COMPOSITE>\n    <DOMAIN> C[0] </DOMAIN>\n", fp);
}

static sq_status write_nektar(const char *path, const sq_quad_mesh *m, int compressed,
                              const sq_progress *progress, sq_error *err)
{
    SQ_TRY(sq_quad_mesh_check(m, err));
    int nq = m->nquads, ns = 4 * nq;
    nektar_topology t = {0};
    t.vid = malloc(sizeof(int) * ((size_t)m->nnodes + 1));
    side_rec *rec = malloc(sizeof *rec * ((size_t)ns + 1));
    t.edge_of = malloc(sizeof(int) * ((size_t)ns + 1));
    t.owner = malloc(sizeof(int) * ((size_t)ns + 1));
    int *list = malloc(sizeof(int) * ((size_t)m->nbnd + nq + 1));
    sq_outfile f = {0};
    sq_status st = t.vid && rec && t.edge_of && t.owner && list
                       ? SQ_OK
                       : SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    if (st == SQ_OK) st = sq_outfile_open(path, &f, err);
    if (st == SQ_OK) st = topology(m, rec, &t, err);
    if (st != SQ_OK) goto done;
    long done = 0, total = (long)(t.ne + nq) * (m->order >= 2 ? 2 : 1);
    sq_progress_every(progress, "write", 0, total);
    fputs("<?xml version=\"1.0\" encoding=\"utf-8\"?>\n<NEKTAR>\n"
          "  <GEOMETRY DIM=\"2\" SPACE=\"2\">\n", f.fp);
    if (compressed)
        st = compressed_entities(f.fp, m, &t, progress, &done, total, err);
    else
        text_entities(f.fp, m, &t, progress, &done, total);
    if (st != SQ_OK) goto done;
    composites(f.fp, m, t.edge_of, list);
    fputs("  </GEOMETRY>\n</NEKTAR>\n", f.fp);
    st = sq_outfile_commit(&f, err);
done:
    sq_outfile_abort(&f);
    free(t.vid);
    free(rec);
    free(t.edge_of);
    free(t.owner);
    free(list);
    return st;
}

sq_status sq_write_nektar(const char *path, const sq_quad_mesh *m, const sq_progress *progress,
                          sq_error *err)
{
    return write_nektar(path, m, 0, progress, err);
}

sq_status sq_write_nektar_compressed(const char *path, const sq_quad_mesh *m,
                                     const sq_progress *progress, sq_error *err)
{
    return write_nektar(path, m, 1, progress, err);
}
