/* VTU output of high-order quads: well-formed XML (every element closed in
 * order), NumberOfPoints/NumberOfCells right, connectivity indices in
 * range and (Q+1)^2 per cell, offsets k (Q+1)^2, types all 70
 * (VTK_LAGRANGE_QUADRILATERAL), cell arrays eta, eta_curved,
 * scaled_jacobian, patch with one value per cell; connectivity in VTK's
 * order (points at the element map of VTK's reference points); the SVG
 * writer's output is well-formed XML too.  Q = 1..10, GLL and equispaced. */
#include "quad_order.h"
#include "t6xx-quad-meshes.h"
#include "write_quad_svg.h"
#include "write_quad_vtu.h"

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

/* Tags balanced and properly nested (no attributes with '>' in them). */
static int well_formed(const char *s, const char *ctx)
{
    char stack[64][48];
    int depth = 0, roots = 0;
    for (const char *p = strchr(s, '<'); p; p = strchr(p + 1, '<')) {
        if (p[1] == '?' || p[1] == '!') continue;
        const char *e = strchr(p, '>');
        if (!e) return printf("%s: unterminated tag\n", ctx), 1;
        int close = p[1] == '/', empty = e[-1] == '/';
        const char *n = p + 1 + close;
        size_t len = strcspn(n, " />\n");
        if (len >= 48) return printf("%s: long tag name\n", ctx), 1;
        if (close) {
            if (!depth || strncmp(stack[depth - 1], n, len) || stack[depth - 1][len])
                return printf("%s: </%.*s> does not close <%s>\n", ctx, (int)len, n,
                              depth ? stack[depth - 1] : "(none)"), 1;
            depth--;
        } else if (!empty) {
            if (depth == 64) return printf("%s: too deep\n", ctx), 1;
            if (!depth) roots++;
            memcpy(stack[depth], n, len);
            stack[depth++][len] = 0;
        }
    }
    if (depth) return printf("%s: <%s> not closed\n", ctx, stack[depth - 1]), 1;
    if (roots != 1) return printf("%s: %d root elements\n", ctx, roots), 1;
    return 0;
}

/* The text of <DataArray ... Name="name" ...> ... </DataArray>. */
static const char *array(const char *s, const char *name, const char **end)
{
    char k[64];
    snprintf(k, sizeof k, "Name=\"%s\"", name);
    const char *p = strstr(s, k);
    if (!p) return NULL;
    *end = strstr(p, "</DataArray>");
    return strchr(p, '>') + 1;
}

static int check_vtu(const char *path, const sq_quad_mesh *m, const char *ctx)
{
    char *s = slurp(path);
    if (!s) return printf("%s: cannot read\n", ctx), 1;
    int f = well_formed(s, ctx), Q = m->order, npe = (Q + 1) * (Q + 1), nq = m->nquads;
    const char *p = strstr(s, "<Piece ");
    if (!p) return free(s), printf("%s: no Piece\n", ctx), 1;
    long np = strtol(strstr(p, "NumberOfPoints=\"") + 16, NULL, 10);
    long nc = strtol(strstr(p, "NumberOfCells=\"") + 15, NULL, 10);
    f += sq_check_int(ctx, "NumberOfPoints", np, m->nnodes);
    f += sq_check_int(ctx, "NumberOfCells", nc, nq);
    /* points */
    const char *end, *a = strstr(s, "<Points>");
    double *xyz = malloc(sizeof(double) * 3 * (size_t)(np + 1));
    a = strchr(strstr(a, "<DataArray"), '>') + 1;
    char *t = (char *)a;
    for (long i = 0; i < 3 * np; i++) xyz[i] = strtod(t, &t);
    /* connectivity, offsets, types */
    int *conn = malloc(sizeof(int) * (size_t)npe * (size_t)(nc + 1)), nconn = 0;
    a = array(s, "connectivity", &end);
    for (t = (char *)a; a;) {
        char *t0 = t;
        long v = strtol(t, &t, 10);
        if (t == t0 || t > end) break;
        if (v < 0 || v >= np) printf("%s: connectivity %ld out of range\n", ctx, v), f++;
        if (nconn < npe * nc) conn[nconn] = (int)v;
        nconn++;
    }
    f += sq_check_int(ctx, "connectivity entries", nconn, (long)npe * nc);
    a = array(s, "offsets", &end);
    long k = 0;
    for (t = (char *)a; a; k++) {
        char *t0 = t;
        long v = strtol(t, &t, 10);
        if (t == t0 || t > end) break;
        if (v != (k + 1) * npe) {
            printf("%s: offset %ld = %ld, expected %ld\n", ctx, k, v, (k + 1) * npe);
            f++;
            break;
        }
    }
    f += sq_check_int(ctx, "offsets", k, nc);
    a = array(s, "types", &end);
    k = 0;
    for (t = (char *)a; a; k++) {
        char *t0 = t;
        long v = strtol(t, &t, 10);
        if (t == t0 || t > end) break;
        if (v != 70) printf("%s: cell type %ld\n", ctx, v), f++;
    }
    f += sq_check_int(ctx, "types", k, nc);
    const char *names[] = {"eta", "eta_curved", "scaled_jacobian", "patch"};
    for (int i = 0; i < 4; i++) {
        a = array(s, names[i], &end);
        if (!a) {
            printf("%s: no cell array %s\n", ctx, names[i]);
            f++;
            continue;
        }
        k = 0;
        for (t = (char *)a;; k++) {
            char *t0 = t;
            strtod(t, &t);
            if (t == t0 || t > end) break;
        }
        f += sq_check_int(ctx, names[i], k, nc);
    }
    /* VTK order: point of node k is the element map at VTK's reference point */
    if (nconn == npe * nc) {
        sq_quad_basis b;
        sq_error err;
        SQ_TEST_OK(sq_quad_basis_init(&b, Q, m->nodes, &err), err);
        int ij[2 * 121];
        sq_quad_vtk_order(Q, ij);
        double worst = 0.0;
        for (int e = 0; e < nq; e++)
            for (int n = 0; n < npe; n++) {
                double x[2];
                sq_quad_mesh_map(m, &b, e, (double)ij[2 * n] / Q, (double)ij[2 * n + 1] / Q, x, NULL);
                const double *y = &xyz[3 * conn[e * npe + n]];
                worst = fmax(worst, hypot(x[0] - y[0], x[1] - y[1]));
            }
        /* written with full precision; the map at a node: (Q + 1) U Lambda |x| */
        f += sq_check_abs(ctx, "points vs element map", worst, 0.0, 1e-12);
    }
    free(s), free(xyz), free(conn);
    return f;
}

int main(void)
{
    char dir[] = "/tmp/sq_t606_XXXXXX";
    if (!mkdtemp(dir)) return printf("cannot make a temporary directory\n"), 1;
    int f = 0;
    char path[256];
    for (int Q = 1; Q <= 10; Q++)
        for (int k = 0; k < 2; k++)
            for (int which = 0; which < 2; which++) {
                sq_node_kind kind = k ? SQ_NODES_EQUISPACED : SQ_NODES_GLL;
                sq_quad_mesh *m = which ? t6_quarter_disc(2, Q, kind) : t6_annulus(3, Q, kind);
                char ctx[80];
                snprintf(ctx, sizeof ctx, "%s Q=%d %s", which ? "disc" : "annulus", Q, k ? "equi" : "gll");
                snprintf(path, sizeof path, "%s/m.vtu", dir);
                sq_error err;
                SQ_TEST_OK(sq_write_quad_vtu(path, m, NULL, &err), err);
                f += check_vtu(path, m, ctx);
                remove(path);
                if (Q == 4) {
                    snprintf(path, sizeof path, "%s/m.svg", dir);
                    SQ_TEST_OK(sq_write_quad_svg(path, m, NULL, &err), err);
                    char *s = slurp(path);
                    f += s ? well_formed(s, "svg") : 1;
                    if (s && !strstr(s, "<svg")) printf("svg: no <svg>\n"), f++;
                    free(s);
                    remove(path);
                }
                sq_quad_mesh_free(&m);
            }
    rmdir(dir);
    return f ? 1 : 0;
}
