/* Gmsh MSH 4.1 output: the node orders against Gmsh's documented 9- and
 * 16-node quads; the files re-read by a small parser (sections, counts,
 * element types for Q = 1..10, node positions = the element map at Gmsh's
 * equispaced reference points, physical groups); and
 * tests/msh_quad_stats.py (an independent measure through Gmsh's own
 * reader) on the files agrees with sq_quad_mesh_quality (exit 77 after the
 * own checks if python3 with gmsh and numpy is missing).  argv[1]: path of
 * msh_quad_stats.py. */
#include "quad_order.h"
#include "t6xx-quad-meshes.h"
#include "write_msh.h"

#include <unistd.h>

typedef struct {
    char version[16];
    int nnodes, nelem, nphys;
    double *xyz;   /* by tag-1 */
    int ntype[128]; /* elements per type */
    int nquad_nodes, *quad_nodes; /* node tags of the quads, in file order */
    int nline_by_curve[16];
    char phys[16][32];
} msh_file;

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

/* Returns 0 and fills f, or prints what is wrong and returns 1. */
static int parse_msh(const char *path, msh_file *f)
{
    memset(f, 0, sizeof *f);
    char *s = slurp(path), *p;
    if (!s) return printf("%s: cannot read\n", path), 1;
    int bad = 0;
    if (strncmp(s, "$MeshFormat\n", 12)) bad = printf("%s: no $MeshFormat first\n", path);
    int ftype = -1, dsize = 0;
    sscanf(s + 12, "%15s %d %d", f->version, &ftype, &dsize);
    if (strcmp(f->version, "4.1") || ftype != 0 || dsize != 8)
        bad = printf("%s: format line %s %d %d\n", path, f->version, ftype, dsize);
    if ((p = strstr(s, "$PhysicalNames\n"))) {
        p += 15;
        f->nphys = (int)strtol(p, &p, 10);
        for (int i = 0; i < f->nphys && i < 16; i++) {
            int dim = (int)strtol(p, &p, 10), tag = (int)strtol(p, &p, 10);
            char name[32] = "";
            sscanf(p, " \"%31[^\"]\"", name);
            p = strchr(p, '\n');
            if (tag >= 1 && tag < 16) snprintf(f->phys[tag], 32, "%d:%s", dim, name);
        }
    } else bad = printf("%s: no $PhysicalNames\n", path);
    if (!strstr(s, "$Entities\n") || !strstr(s, "$EndEntities\n")) bad = printf("%s: no $Entities\n", path);
    if (!(p = strstr(s, "$Nodes\n"))) {
        free(s);
        return printf("%s: no $Nodes\n", path), 1;
    }
    p += 7;
    int nb = (int)strtol(p, &p, 10);
    f->nnodes = (int)strtol(p, &p, 10);
    int mint = (int)strtol(p, &p, 10), maxt = (int)strtol(p, &p, 10);
    if (mint != 1 || maxt != f->nnodes) bad = printf("%s: node tags %d..%d\n", path, mint, maxt);
    f->xyz = calloc(3 * (size_t)f->nnodes + 3, sizeof(double));
    int *tags = malloc(sizeof(int) * ((size_t)f->nnodes + 1)), seen = 0;
    for (int b = 0; b < nb; b++) {
        strtol(p, &p, 10), strtol(p, &p, 10);
        int param = (int)strtol(p, &p, 10), n = (int)strtol(p, &p, 10);
        if (param) bad = printf("%s: parametric nodes\n", path);
        for (int i = 0; i < n; i++) tags[i] = (int)strtol(p, &p, 10);
        for (int i = 0; i < n; i++) {
            double x = strtod(p, &p), y = strtod(p, &p), z = strtod(p, &p);
            if (tags[i] < 1 || tags[i] > f->nnodes) {
                bad = printf("%s: node tag %d\n", path, tags[i]);
                continue;
            }
            f->xyz[3 * (tags[i] - 1)] = x, f->xyz[3 * (tags[i] - 1) + 1] = y, f->xyz[3 * (tags[i] - 1) + 2] = z;
        }
        seen += n;
    }
    free(tags);
    if (seen != f->nnodes) bad = printf("%s: %d nodes in blocks, header %d\n", path, seen, f->nnodes);
    if (!(p = strstr(s, "$Elements\n")) || !strstr(s, "$EndElements")) {
        free(s);
        return printf("%s: no $Elements\n", path), 1;
    }
    p += 10;
    nb = (int)strtol(p, &p, 10);
    f->nelem = (int)strtol(p, &p, 10);
    strtol(p, &p, 10), strtol(p, &p, 10);
    int count = 0;
    f->quad_nodes = malloc(sizeof(int) * 121 * ((size_t)f->nelem + 1));
    for (int b = 0; b < nb; b++) {
        int dim = (int)strtol(p, &p, 10), ent = (int)strtol(p, &p, 10);
        int type = (int)strtol(p, &p, 10), n = (int)strtol(p, &p, 10);
        if (type < 0 || type >= 128) return printf("%s: element type %d\n", path, type), 1;
        f->ntype[type] += n;
        if (dim == 1 && ent >= 1 && ent < 16) f->nline_by_curve[ent] += n;
        for (int e = 0; e < n; e++) {
            char *eol = strchr(p + 1, '\n');
            strtol(p, &p, 10); /* element tag */
            while (p < eol) {
                char *q = p;
                long v = strtol(p, &p, 10);
                if (p == q) break;
                if (dim == 2) f->quad_nodes[f->nquad_nodes++] = (int)v;
            }
            p = eol;
        }
        count += n;
    }
    if (count != f->nelem) bad = printf("%s: %d elements in blocks, header %d\n", path, count, f->nelem);
    free(s);
    return bad != 0;
}

static void msh_free(msh_file *f) { free(f->xyz), free(f->quad_nodes); }

/* Gmsh reference manual, node ordering: 9-node and 16-node quadrangles. */
static int check_orders(void)
{
    const int q2[] = {0, 0, 2, 0, 2, 2, 0, 2, 1, 0, 2, 1, 1, 2, 0, 1, 1, 1};
    const int q3[] = {0, 0, 3, 0, 3, 3, 0, 3, 1, 0, 2, 0, 3, 1, 3, 2,
                      2, 3, 1, 3, 0, 2, 0, 1, 1, 1, 2, 1, 2, 2, 1, 2};
    const int v3[] = {0, 0, 3, 0, 3, 3, 0, 3, 1, 0, 2, 0, 3, 1, 3, 2,
                      1, 3, 2, 3, 0, 1, 0, 2, 1, 1, 2, 1, 1, 2, 2, 2};
    int ij[2 * 121], f = 0;
    sq_quad_gmsh_order(2, ij);
    for (int k = 0; k < 18; k++) f += sq_check_int("gmsh order Q=2", "ij", ij[k], q2[k]);
    sq_quad_gmsh_order(3, ij);
    for (int k = 0; k < 32; k++) f += sq_check_int("gmsh order Q=3", "ij", ij[k], q3[k]);
    sq_quad_vtk_order(3, ij);
    for (int k = 0; k < 32; k++) f += sq_check_int("vtk order Q=3", "ij", ij[k], v3[k]);
    for (int Q = 1; Q <= 10; Q++) {
        int seen[11][11] = {{0}};
        sq_quad_gmsh_order(Q, ij);
        for (int k = 0; k < (Q + 1) * (Q + 1); k++) seen[ij[2 * k]][ij[2 * k + 1]]++;
        sq_quad_vtk_order(Q, ij);
        for (int k = 0; k < (Q + 1) * (Q + 1); k++) seen[ij[2 * k]][ij[2 * k + 1]] += 10;
        for (int i = 0; i <= Q; i++)
            for (int j = 0; j <= Q; j++) f += sq_check_int("orders", "multiplicity", seen[i][j], 11);
    }
    return f;
}

static int check_file(const char *path, const sq_quad_mesh *m, const char *ctx)
{
    msh_file mf;
    if (parse_msh(path, &mf)) return 1;
    int Q = m->order, npe = (Q + 1) * (Q + 1), f = 0;
    f += sq_check_int(ctx, "nodes", mf.nnodes, m->nnodes);
    f += sq_check_int(ctx, "elements", mf.nelem, m->nquads + m->nbnd);
    f += sq_check_int(ctx, "quads of the type", mf.ntype[sq_gmsh_quad_type(Q)], m->nquads);
    f += sq_check_int(ctx, "lines of the type", mf.ntype[sq_gmsh_line_type(Q)], m->nbnd);
    f += sq_check_int(ctx, "quad node tags", mf.nquad_nodes, npe * m->nquads);
    f += sq_check_int(ctx, "physical groups", mf.nphys, m->ntags + 1);
    for (int t = 0; t < m->ntags; t++) {
        char want[32];
        int n = 0;
        snprintf(want, sizeof want, "1:boundary_%d", t);
        f += sq_check_str(ctx, "physical name", mf.phys[t + 1], want);
        for (int s = 0; s < m->nbnd; s++) n += m->bnd_tag[s] == t;
        f += sq_check_int(ctx, "lines on the curve", mf.nline_by_curve[t + 1], n);
    }
    f += sq_check_str(ctx, "physical name", mf.phys[m->ntags + 1], "2:domain");
    /* node k of quad e lies at the element map of Gmsh's reference point */
    sq_quad_basis b;
    sq_error err;
    SQ_TEST_OK(sq_quad_basis_init(&b, Q, m->nodes, &err), err);
    int ij[2 * 121];
    sq_quad_gmsh_order(Q, ij);
    double worst = 0.0;
    for (int e = 0; e < m->nquads && mf.nquad_nodes == npe * m->nquads; e++)
        for (int k = 0; k < npe; k++) {
            double x[2];
            sq_quad_mesh_map(m, &b, e, (double)ij[2 * k] / Q, (double)ij[2 * k + 1] / Q, x, NULL);
            const double *y = &mf.xyz[3 * (mf.quad_nodes[e * npe + k] - 1)];
            worst = fmax(worst, hypot(x[0] - y[0], x[1] - y[1]) + fabs(y[2]));
        }
    /* written with %.17g (exact round trip); the map at a node is the 1D
     * Lagrange sums, delta up to (Q + 1) U Lambda |x|: 1e-12 */
    f += sq_check_abs(ctx, "node positions vs element map", worst, 0.0, 1e-12);
    msh_free(&mf);
    return f;
}

static const char *find_python(void)
{
    static const char *cands[] = {"/usr/bin/python3", "/usr/local/bin/python3"};
    for (int i = 0; i < 2; i++)
        if (access(cands[i], X_OK) == 0) return cands[i];
    return NULL;
}

static double json_num(const char *s, const char *key, int *missing)
{
    char k[64];
    snprintf(k, sizeof k, "\"%s\": ", key);
    const char *p = strstr(s, k);
    if (!p) {
        (*missing)++;
        printf("msh_quad_stats: no key %s\n", key);
        return NAN;
    }
    return strtod(p + strlen(k), NULL);
}

/* msh_quad_stats.py on the file agrees with sq_quad_mesh_quality. */
static int check_msh_quad_stats(const char *py, const char *qs, const char *path, const sq_quad_mesh *m,
                           const char *ctx)
{
    char cmd[2048], buf[8192];
    snprintf(cmd, sizeof cmd, "'%s' '%s' '%s'", py, qs, path);
    FILE *pp = popen(cmd, "r");
    if (!pp) return printf("%s: cannot run %s\n", ctx, cmd), 1;
    size_t n = fread(buf, 1, sizeof buf - 1, pp);
    buf[n] = 0;
    int rc = pclose(pp);
    if (rc != 0) return printf("%s: %s failed (%d): %s\n", ctx, cmd, rc, buf), 1;
    sq_quad_quality q;
    sq_error err;
    SQ_TEST_OK(sq_quad_mesh_quality(m, NULL, NULL, 1, &q, &err), err);
    int f = 0, miss = 0;
    f += sq_check_int(ctx, "msh_quad_stats quads", (long)json_num(buf, "quads", &miss), m->nquads);
    /* msh_quad_stats.py recomputes eta from the %.17g nodes: the same
     * angles, a few U each, and the JSON's digits; tau is a ratio of counts */
    f += sq_check_abs(ctx, "msh_quad_stats eta_mean", json_num(buf, "eta_mean", &miss), q.eta_mean, 1e-12);
    f += sq_check_abs(ctx, "msh_quad_stats eta_min", json_num(buf, "eta_min", &miss), q.eta_min, 1e-12);
    f += sq_check_abs(ctx, "msh_quad_stats eta_pct_gt_0.9", json_num(buf, "eta_pct_gt_0.9", &miss),
                      q.tau_percent, 1e-9);
    f += sq_check_int(ctx, "msh_quad_stats interior_irregular",
                      (long)json_num(buf, "interior_irregular", &miss), q.irregular_interior);
    f += sq_check_int(ctx, "msh_quad_stats boundary_irregular",
                      (long)json_num(buf, "boundary_irregular", &miss), q.irregular_boundary);
    f += sq_check_int(ctx, "msh_quad_stats inverted_quads", (long)json_num(buf, "inverted_quads", &miss), 0);
    f += sq_check_int(ctx, "msh_quad_stats vertices", (long)json_num(buf, "vertices", &miss), q.vertices);
    f += sq_check_int(ctx, "msh_quad_stats boundary_vertices",
                      (long)json_num(buf, "boundary_vertices", &miss), q.boundary_vertices);
    f += sq_check_int(ctx, "msh_quad_stats euler_chi", (long)json_num(buf, "euler_chi", &miss), 1);
    return f + miss;
}

int main(int argc, char **argv)
{
    int f = check_orders();
    char dir[] = "/tmp/sq_t603_XXXXXX";
    if (!mkdtemp(dir)) return printf("cannot make a temporary directory\n"), 1;
    const char *qs = argc > 1 ? argv[1] : "tests/msh_quad_stats.py";
    const char *py = find_python();
    char probe[256];
    snprintf(probe, sizeof probe, "'%s' -c 'import gmsh, numpy' 2>/dev/null", py ? py : "false");
    int have_qs = py && access(qs, R_OK) == 0 && system(probe) == 0, qs_runs = 0;
    char path[256];
    for (int Q = 1; Q <= 10; Q++)
        for (int k = 0; k < 2; k++)
            for (int which = 0; which < 2; which++) {
                sq_node_kind kind = k ? SQ_NODES_EQUISPACED : SQ_NODES_GLL;
                sq_quad_mesh *m = which ? t6_quarter_disc(3, Q, kind) : t6_annulus(4, Q, kind);
                char ctx[80];
                snprintf(ctx, sizeof ctx, "%s Q=%d %s", which ? "disc" : "annulus", Q,
                         k ? "equi" : "gll");
                snprintf(path, sizeof path, "%s/m%d%d%d.msh", dir, Q, k, which);
                sq_error err;
                SQ_TEST_OK(sq_write_msh(path, m, NULL, &err), err);
                f += check_file(path, m, ctx);
                /* Gmsh's start-up per file: a subset of orders */
                if (have_qs && (Q == 1 || Q == 2 || Q == 4 || Q == 10)) {
                    f += check_msh_quad_stats(py, qs, path, m, ctx);
                    qs_runs++;
                }
                remove(path);
                sq_quad_mesh_free(&m);
            }
    /* an unwritable target fails with SQ_ERR_OUTPUT and leaves nothing */
    sq_quad_mesh *m = t6_square(2, 2, SQ_NODES_GLL);
    sq_error err;
    f += sq_check_int("unwritable", "status", sq_write_msh("/nonexistent-dir/x.msh", m, NULL, &err),
                      SQ_ERR_OUTPUT);
    m->bnd_tag[0] = 7; /* out of range */
    snprintf(path, sizeof path, "%s/bad.msh", dir);
    f += sq_check_int("bad tag", "status", sq_write_msh(path, m, NULL, &err), SQ_ERR_USAGE);
    f += sq_check_int("bad tag", "file left", access(path, F_OK) == 0, 0);
    sq_quad_mesh_free(&m);
    rmdir(dir);
    if (f) return 1;
    return have_qs && qs_runs ? 0 : 77;
}
