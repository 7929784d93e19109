#include "write_nektar.h"

#include "format_number.h"
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

sq_status sq_write_nektar(const char *path, const sq_quad_mesh *m, const sq_progress *progress,
                          sq_error *err)
{
    SQ_TRY(sq_quad_mesh_check(m, err));
    int Q = m->order, npe = (Q + 1) * (Q + 1), nq = m->nquads, ns = 4 * nq;
    const char *ptype = m->nodes == SQ_NODES_GLL ? "GaussLobattoLegendre" : "PolyEvenlySpaced";
    int *vid = malloc(sizeof(int) * ((size_t)m->nnodes + 1));
    side_rec *rec = malloc(sizeof *rec * ((size_t)ns + 1));
    int *edge_of = malloc(sizeof(int) * ((size_t)ns + 1)); /* per (quad, side) */
    int *owner = malloc(sizeof(int) * ((size_t)ns + 1));   /* per edge: quad*4+side */
    int *list = malloc(sizeof(int) * ((size_t)m->nbnd + nq + 1));
    sq_outfile f = {0};
    sq_status st = vid && rec && edge_of && owner && list
                       ? SQ_OK
                       : SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    if (st == SQ_OK) st = sq_outfile_open(path, &f, err);
    if (st != SQ_OK) goto done;
    FILE *fp = f.fp;
    /* vertices: corner nodes, numbered in node order */
    for (int v = 0; v < m->nnodes; v++) vid[v] = -1;
    for (int q = 0; q < nq; q++)
        for (int k = 0; k < 4; k++) vid[m->conn[(size_t)q * npe + sq_quad_side_node(Q, k, 0)]] = 0;
    int nv = 0;
    for (int v = 0; v < m->nnodes; v++)
        if (vid[v] == 0) vid[v] = nv++;
    /* edges: element sides matched by their corner pair (and, from Q = 2,
     * by the node next to the lower corner, so two different sides between
     * the same corners stay apart) */
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
    int ne = 0;
    for (int i = 0; i < ns;) {
        int k = i;
        while (k < ns && rec[k].key == rec[i].key && rec[k].next == rec[i].next) k++;
        if (k - i > 2) {
            st = SQ_FAIL(err, SQ_ERR_USAGE, "non-manifold mesh: %d quads share one side", k - i);
            goto done;
        }
        owner[ne] = 4 * rec[i].quad + rec[i].side; /* lowest quad: its direction */
        for (int s = i; s < k; s++) edge_of[4 * rec[s].quad + rec[s].side] = ne;
        ne++;
        i = k;
    }
    long done = 0, total = (long)(ne + nq) * (Q >= 2 ? 2 : 1);
    sq_progress_every(progress, "write", 0, total);
    fputs("<?xml version=\"1.0\" encoding=\"utf-8\"?>\n<NEKTAR>\n"
          "  <GEOMETRY DIM=\"2\" SPACE=\"2\">\n    <VERTEX>\n", fp);
    for (int v = 0; v < m->nnodes; v++)
        if (vid[v] >= 0)
            put_point(fp, "      <V ID=\"", vid[v], &m->xy[2 * v], "</V>\n");
    fputs("    </VERTEX>\n    <EDGE>\n", fp);
    for (int e = 0; e < ne; e++) {
        int q = owner[e] / 4, k = owner[e] % 4;
        const int *c = &m->conn[(size_t)q * npe];
        fprintf(fp, "      <E ID=\"%d\">%d %d</E>\n", e, vid[c[sq_quad_side_node(Q, k, 0)]],
                vid[c[sq_quad_side_node(Q, k, Q)]]);
        sq_progress_every(progress, "write", ++done, total);
    }
    fputs("    </EDGE>\n    <ELEMENT>\n", fp);
    for (int q = 0; q < nq; q++) {
        fprintf(fp, "      <Q ID=\"%d\">%d %d %d %d</Q>\n", q, edge_of[4 * q], edge_of[4 * q + 1],
                edge_of[4 * q + 2], edge_of[4 * q + 3]);
        sq_progress_every(progress, "write", ++done, total);
    }
    fputs("    </ELEMENT>\n", fp);
    if (Q >= 2) {
        /* Nektar++ needs every edge of a quad with a face curve to carry Q+1
         * points too, so all edges are written. */
        fputs("    <CURVED>\n", fp);
        for (int e = 0; e < ne; e++) {
            int q = owner[e] / 4, k = owner[e] % 4;
            const int *c = &m->conn[(size_t)q * npe];
            fprintf(fp, "      <E ID=\"%d\" EDGEID=\"%d\" NUMPOINTS=\"%d\" TYPE=\"%s\">", e, e,
                    Q + 1, ptype);
            for (int s = 0; s <= Q; s++)
                put_point(fp, s ? " " : "", -1, &m->xy[2 * (size_t)c[sq_quad_side_node(Q, k, s)]], "");
            fputs("</E>\n", fp);
            sq_progress_every(progress, "write", ++done, total);
        }
        for (int q = 0; q < nq; q++) {
            const int *c = &m->conn[(size_t)q * npe];
            fprintf(fp, "      <F ID=\"%d\" FACEID=\"%d\" NUMPOINTS=\"%d\" TYPE=\"%s\">", q, q, npe,
                    ptype);
            for (int n = 0; n < npe; n++) put_point(fp, n ? " " : "", -1, &m->xy[2 * (size_t)c[n]], "");
            fputs("</F>\n", fp);
            sq_progress_every(progress, "write", ++done, total);
        }
        fputs("    </CURVED>\n", fp);
    }
    /* the quads: composite 0; of a domain's faces, one composite per face
     * after the boundary's, nt+1+r (docs/domains.md) */
    fputs("    <COMPOSITE>\n", fp);
    for (int r = 0; r < (m->nregions > 0 ? m->nregions : 1); r++) {
        int n = 0;
        for (int q = 0; q < nq; q++)
            if (!m->region || m->region[q] == r) list[n++] = q;
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
    fputs("  </GEOMETRY>\n</NEKTAR>\n", fp);
    st = sq_outfile_commit(&f, err);
done:
    sq_outfile_abort(&f);
    free(vid);
    free(rec);
    free(edge_of);
    free(owner);
    free(list);
    return st;
}
