/* Nektar++ XML output checked against the structural rules of the format by
 * a small parser: VERTEX/EDGE/ELEMENT/CURVED/COMPOSITE/DOMAIN present; every
 * quad's four edges consecutive (each shares a vertex with the next) and
 * counter-clockwise (positive signed area of its vertex polygon); each edge
 * used by one or two quads; curved edges with NUMPOINTS = Q+1 points equal
 * to the mesh nodes from the edge's first vertex to its second; faces with
 * NUMPOINTS = (Q+1)^2 a perfect square, points equal to the nodes in
 * lattice order; composites of the boundary curves covering every boundary
 * edge exactly once, with the right tag; Q = 1..10, GLL and equispaced. */
#include "t6xx-quad-meshes.h"
#include "write_nektar.h"

#include <unistd.h>

static char *slurp(const char *path)
{
    FILE *fp = fopen(path, "rb");
    if (!fp) return NULL;
    fseek(fp, 0, SEEK_END);
    long n = ftell(fp);
    rewind(fp);
    char *s = malloc((size_t)n + 1);
    if (fread(s, 1, (size_t)n, fp) != (size_t)n) n = 0;
    s[n] = 0;
    fclose(fp);
    return s;
}

/* Integer attribute NAME="..." inside the tag starting at p (-1 if none). */
static long attr(const char *p, const char *name)
{
    char k[32];
    snprintf(k, sizeof k, " %s=\"", name);
    const char *end = strchr(p, '>'), *a = strstr(p, k);
    if (!a || a > end) return -1;
    return strtol(a + strlen(k), NULL, 10);
}

static const char *attr_str(const char *p, const char *name, char *buf, size_t n)
{
    char k[32];
    snprintf(k, sizeof k, " %s=\"", name);
    const char *end = strchr(p, '>'), *a = strstr(p, k);
    buf[0] = 0;
    if (!a || a > end) return buf;
    a += strlen(k);
    size_t i = 0;
    while (a[i] && a[i] != '"' && i + 1 < n) buf[i] = a[i], i++;
    buf[i] = 0;
    return buf;
}

/* Section text between <NAME> (or <NAME ...>) and </NAME>, NULL if absent. */
static char *section(const char *s, const char *name, const char **end)
{
    char open[32], close[32];
    snprintf(open, sizeof open, "<%s", name);
    snprintf(close, sizeof close, "</%s>", name);
    const char *a = strstr(s, open), *b = strstr(s, close);
    if (!a || !b || b < a) return NULL;
    *end = b;
    return (char *)strchr(a, '>') + 1;
}

/* Expand "Q[0-3,7]" style lists into ids (returns count). */
static int expand(const char *p, char letter, int *ids, int max)
{
    int n = 0;
    while (*p == ' ') p++;
    if (*p != letter || p[1] != '[') return -1;
    p += 2;
    while (*p && *p != ']') {
        char *q;
        long a = strtol(p, &q, 10), b = a;
        if (*q == '-') b = strtol(q + 1, &q, 10);
        for (long i = a; i <= b && n < max; i++) ids[n++] = (int)i;
        p = *q == ',' ? q + 1 : q;
        if (q == p && *p != ']' && *p != ',') break;
    }
    return n;
}

static int side_node(int Q, int k, int s)
{
    switch (k) {
    case 0: return sq_quad_node(Q, s, 0);
    case 1: return sq_quad_node(Q, Q, s);
    case 2: return sq_quad_node(Q, Q - s, Q);
    default: return sq_quad_node(Q, 0, Q - s);
    }
}

static int check(const char *path, const sq_quad_mesh *m, const char *ctx)
{
    char *s = slurp(path);
    if (!s) return printf("%s: cannot read %s\n", ctx, path), 1;
    int f = 0, Q = m->order, npe = (Q + 1) * (Q + 1);
    const char *end;
    char *geo = section(s, "GEOMETRY", &end);
    if (!geo || !strstr(s, "<GEOMETRY DIM=\"2\" SPACE=\"2\">") || !strstr(s, "<NEKTAR>") ||
        !strstr(s, "</NEKTAR>")) {
        free(s);
        return printf("%s: no NEKTAR/GEOMETRY DIM=2 SPACE=2\n", ctx), 1;
    }
    /* vertices */
    int maxv = m->nnodes, nv = 0;
    double *vx = calloc(2 * (size_t)maxv, sizeof(double));
    char *p = section(s, "VERTEX", &end);
    for (p = p ? strstr(p, "<V ") : NULL; p && p < end; p = strstr(p + 1, "<V ")) {
        long id = attr(p, "ID");
        if (id < 0 || id >= maxv) return printf("%s: vertex id %ld\n", ctx, id), 1;
        char *t = strchr(p, '>') + 1;
        vx[2 * id] = strtod(t, &t);
        vx[2 * id + 1] = strtod(t, &t);
        nv++;
    }
    /* edges */
    int maxe = 4 * m->nquads, ne = 0;
    int *ev = malloc(sizeof(int) * 2 * (size_t)maxe), *use = calloc((size_t)maxe, sizeof(int));
    p = section(s, "EDGE", &end);
    for (p = p ? strstr(p, "<E ") : NULL; p && p < end; p = strstr(p + 1, "<E ")) {
        long id = attr(p, "ID");
        if (id != ne) f += sq_check_int(ctx, "edge id in order", id, ne);
        if (id < 0 || id >= maxe) return printf("%s: edge id %ld\n", ctx, id), 1;
        char *t = strchr(p, '>') + 1;
        ev[2 * id] = (int)strtol(t, &t, 10);
        ev[2 * id + 1] = (int)strtol(t, &t, 10);
        if (ev[2 * id] < 0 || ev[2 * id] >= nv || ev[2 * id + 1] < 0 || ev[2 * id + 1] >= nv)
            return printf("%s: edge %ld vertices %d %d\n", ctx, id, ev[2 * id], ev[2 * id + 1]), 1;
        ne++;
    }
    /* elements: consecutive edges, counter-clockwise */
    int nq = 0, *qe = malloc(sizeof(int) * 4 * (size_t)m->nquads), *qv = malloc(sizeof(int) * 4 * (size_t)m->nquads);
    p = section(s, "ELEMENT", &end);
    for (p = p ? strstr(p, "<Q ") : NULL; p && p < end; p = strstr(p + 1, "<Q ")) {
        long id = attr(p, "ID");
        if (id != nq || nq >= m->nquads) return printf("%s: quad id %ld\n", ctx, id), 1;
        char *t = strchr(p, '>') + 1;
        int *e = &qe[4 * nq], *v = &qv[4 * nq];
        for (int k = 0; k < 4; k++) e[k] = (int)strtol(t, &t, 10);
        for (int k = 0; k < 4; k++)
            if (e[k] < 0 || e[k] >= ne) return printf("%s: quad %d edge %d\n", ctx, nq, e[k]), 1;
        for (int k = 0; k < 4; k++) use[e[k]]++;
        /* vertex k = the vertex of edge k not shared with edge k+1... as
         * Nektar++'s QuadGeom: v1 = common(e0, e1), v0 = other end of e0 */
        for (int k = 0; k < 4; k++) {
            const int *a = &ev[2 * e[k]], *b = &ev[2 * e[(k + 1) % 4]];
            int common = a[0] == b[0] || a[0] == b[1] ? a[0] : a[1] == b[0] || a[1] == b[1] ? a[1] : -1;
            if (common < 0) {
                printf("%s: quad %d edges %d and %d share no vertex\n", ctx, nq, e[k], e[(k + 1) % 4]);
                f++;
                common = a[1];
            }
            v[(k + 1) % 4] = common;
        }
        double area = 0.0;
        for (int k = 0; k < 4; k++) {
            const double *a = &vx[2 * v[k]], *b = &vx[2 * v[(k + 1) % 4]];
            area += a[0] * b[1] - b[0] * a[1];
        }
        if (!(area > 0)) printf("%s: quad %d clockwise (area %g)\n", ctx, nq, 0.5 * area), f++;
        /* against the mesh: vertex k = corner k of quad nq */
        for (int k = 0; k < 4; k++) {
            int g = m->conn[(size_t)nq * npe + side_node(Q, k, 0)];
            f += sq_check_abs(ctx, "quad vertex x", vx[2 * v[k]], m->xy[2 * g], 0.0);
            f += sq_check_abs(ctx, "quad vertex y", vx[2 * v[k] + 1], m->xy[2 * g + 1], 0.0);
        }
        nq++;
    }
    f += sq_check_int(ctx, "quads", nq, m->nquads);
    for (int e = 0; e < ne; e++)
        if (use[e] < 1 || use[e] > 2) printf("%s: edge %d used %d times\n", ctx, e, use[e]), f++;
    /* curved edges and faces */
    char type[64];
    const char *want_type = m->nodes == SQ_NODES_GLL ? "GaussLobattoLegendre" : "PolyEvenlySpaced";
    char *cur = section(s, "CURVED", &end);
    const char *cend = end;
    if (Q == 1 && cur) printf("%s: CURVED at Q = 1\n", ctx), f++;
    if (Q >= 2) {
        if (!cur) return printf("%s: no CURVED\n", ctx), 1;
        int nce = 0, ncf = 0;
        for (p = strstr(cur, "<E "); p && p < cend; p = strstr(p + 1, "<E ")) {
            long id = attr(p, "EDGEID"), np = attr(p, "NUMPOINTS");
            f += sq_check_str(ctx, "edge TYPE", attr_str(p, "TYPE", type, sizeof type), want_type);
            f += sq_check_int(ctx, "edge NUMPOINTS", np, Q + 1);
            if (id < 0 || id >= ne) return printf("%s: curved edge id %ld\n", ctx, id), 1;
            /* first and last points are the edge's vertices */
            char *t = strchr(p, '>') + 1;
            double pts[3 * 11];
            for (int k = 0; k < 3 * (Q + 1); k++) pts[k] = strtod(t, &t);
            f += sq_check_abs(ctx, "edge start", hypot(pts[0] - vx[2 * ev[2 * id]], pts[1] - vx[2 * ev[2 * id] + 1]), 0, 0);
            f += sq_check_abs(ctx, "edge end", hypot(pts[3 * Q] - vx[2 * ev[2 * id + 1]], pts[3 * Q + 1] - vx[2 * ev[2 * id + 1] + 1]), 0, 0);
            /* the points are the nodes of a side of a quad using the edge */
            int found = 0;
            for (int q = 0; q < nq && !found; q++)
                for (int k = 0; k < 4 && !found; k++) {
                    if (qe[4 * q + k] != id) continue;
                    for (int dir = 0; dir < 2 && !found; dir++) {
                        int ok = 1;
                        for (int s2 = 0; s2 <= Q && ok; s2++) {
                            int g = m->conn[(size_t)q * npe + side_node(Q, k, dir ? Q - s2 : s2)];
                            ok = pts[3 * s2] == m->xy[2 * g] && pts[3 * s2 + 1] == m->xy[2 * g + 1];
                        }
                        found = ok;
                    }
                }
            if (!found) printf("%s: curved edge %ld points are not the mesh nodes\n", ctx, id), f++;
            nce++;
        }
        f += sq_check_int(ctx, "curved edges", nce, ne);
        for (p = strstr(cur, "<F "); p && p < cend; p = strstr(p + 1, "<F ")) {
            long id = attr(p, "FACEID"), np = attr(p, "NUMPOINTS");
            long r = lround(sqrt((double)np));
            if (r * r != np) printf("%s: face NUMPOINTS %ld not a square\n", ctx, np), f++;
            f += sq_check_int(ctx, "face NUMPOINTS", np, npe);
            f += sq_check_str(ctx, "face TYPE", attr_str(p, "TYPE", type, sizeof type), want_type);
            if (id < 0 || id >= nq) return printf("%s: face id %ld\n", ctx, id), 1;
            char *t = strchr(p, '>') + 1;
            int cnt = 0;
            for (int k = 0; k < npe; k++) {
                char *t0 = t;
                double x = strtod(t, &t), y = strtod(t, &t);
                strtod(t, &t);
                if (t == t0) break;
                int g = m->conn[(size_t)id * npe + k];
                if (x != m->xy[2 * g] || y != m->xy[2 * g + 1]) {
                    printf("%s: face %ld point %d (%g, %g) is not node %d\n", ctx, id, k, x, y, g);
                    f++;
                    break;
                }
                cnt++;
            }
            while (*t == ' ' || *t == '\n') t++;
            if (strncmp(t, "</F>", 4)) printf("%s: face %ld has extra points\n", ctx, id), f++;
            f += sq_check_int(ctx, "face points read", cnt, npe);
            ncf++;
        }
        f += sq_check_int(ctx, "curved faces", ncf, nq);
    }
    /* composites: C[0] all quads; one per boundary curve covering its edges once */
    int *ids = malloc(sizeof(int) * ((size_t)maxe + m->nquads + 1));
    int *cover = calloc((size_t)ne + 1, sizeof(int)), *ctag = malloc(sizeof(int) * ((size_t)ne + 1));
    p = section(s, "COMPOSITE", &end);
    int have_c0 = 0;
    for (p = p ? strstr(p, "<C ") : NULL; p && p < end; p = strstr(p + 1, "<C ")) {
        long id = attr(p, "ID");
        char *t = strchr(p, '>') + 1;
        if (id == 0) {
            int n = expand(t, 'Q', ids, m->nquads + 1);
            f += sq_check_int(ctx, "C[0] quads", n, nq);
            for (int i = 0; i < n && i < nq; i++) f += ids[i] != i;
            have_c0 = 1;
            continue;
        }
        int n = expand(t, 'E', ids, maxe);
        if (n < 0) printf("%s: composite %ld not an edge list\n", ctx, id), f++;
        for (int i = 0; i < n; i++) {
            if (ids[i] < 0 || ids[i] >= ne) return printf("%s: composite edge %d\n", ctx, ids[i]), 1;
            cover[ids[i]]++;
            ctag[ids[i]] = (int)id - 1;
        }
    }
    f += sq_check_int(ctx, "C[0] present", have_c0, 1);
    /* boundary edges = edges used by one quad; each in exactly one composite */
    int nb = 0;
    for (int e = 0; e < ne; e++) {
        if (use[e] == 1) {
            nb++;
            if (cover[e] != 1) printf("%s: boundary edge %d in %d composites\n", ctx, e, cover[e]), f++;
        } else if (cover[e]) printf("%s: interior edge %d in a composite\n", ctx, e), f++;
    }
    f += sq_check_int(ctx, "boundary edges", nb, m->nbnd);
    for (int b = 0; b < m->nbnd; b++) {
        int e = qe[4 * m->bnd_quad[b] + m->bnd_side[b]];
        if (cover[e] == 1) f += sq_check_int(ctx, "composite of the boundary side", ctag[e], m->bnd_tag[b]);
    }
    char *dom = section(s, "DOMAIN", &end);
    if (!dom || !strstr(dom, "C[0]") || strstr(dom, "C[0]") > end) printf("%s: DOMAIN not C[0]\n", ctx), f++;
    free(s), free(vx), free(ev), free(use), free(qe), free(qv), free(ids), free(cover), free(ctag);
    return f;
}

int main(void)
{
    char dir[] = "/tmp/sq_t605_XXXXXX";
    if (!mkdtemp(dir)) return printf("cannot make a temporary directory\n"), 1;
    int f = 0;
    for (int Q = 1; Q <= 10; Q++)
        for (int k = 0; k < 2; k++)
            for (int which = 0; which < 2; which++) {
                sq_node_kind kind = k ? SQ_NODES_EQUISPACED : SQ_NODES_GLL;
                sq_quad_mesh *m = which ? t6_quarter_disc(2, Q, kind) : t6_annulus(3, Q, kind);
                char ctx[80], path[256];
                snprintf(ctx, sizeof ctx, "%s Q=%d %s", which ? "disc" : "annulus", Q, k ? "equi" : "gll");
                snprintf(path, sizeof path, "%s/m.xml", dir);
                sq_error err;
                SQ_TEST_OK(sq_write_nektar(path, m, NULL, &err), err);
                f += check(path, m, ctx);
                remove(path);
                sq_quad_mesh_free(&m);
            }
    rmdir(dir);
    return f ? 1 : 0;
}
