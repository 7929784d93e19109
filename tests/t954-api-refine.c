/* Mesh families through the public API (sq_mesh_refine, sq_mesh_edge_lengths,
 * sq_mesh_family_write_manifest; docs/convergence-families.md), on the
 * annulus (two true circles, r = 1 and 0.4) at order 3:
 *   - one level: 4 times the quads, every vertex of the mesh a vertex of the
 *     level, bit for bit (the refinement copies them); every node of a
 *     boundary side on its circle to 1e-13 (OpenCASCADE evaluates a circle
 *     to round-off, ~1e-16); every quad proven valid;
 *   - area: the error of an order-Q boundary at GLL arc-length nodes falls
 *     like h^(2Q) (t622's derivation; observed 6.00 at Q = 3 here): one
 *     level divides it by at least 2^(6 - 0.1);
 *   - two levels at once are one level twice, bit for bit (deterministic);
 *   - levels 0 at order 5: the same vertices, order 5;
 *   - refusals: negative levels, order 11, more quads than max_quads
 *     (SQ_ERR_USAGE, *out NULL); a manifest path that is a directory;
 *   - the manifest lists both meshes; a refined mesh's report is JSON with
 *     its quads.
 * usage: t954-api-refine EXAMPLES_DIR */
#include <semquad.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static int fails;

#define CHECK(cond, ...)                                                                           \
    do {                                                                                           \
        if (!(cond)) {                                                                             \
            printf(__VA_ARGS__);                                                                   \
            printf("\n");                                                                          \
            fails++;                                                                               \
        }                                                                                          \
    } while (0)

static int cmp_xy(const void *a, const void *b)
{
    const double *p = a, *q = b;
    if (p[0] != q[0]) return p[0] < q[0] ? -1 : 1;
    return (p[1] > q[1]) - (p[1] < q[1]);
}

/* The corner vertices of m's quads, sorted (x, y) pairs; *n of them. */
static double *corners(const sq_mesh *m, int *n)
{
    int Q = sq_mesh_order(m), nq = sq_mesh_num_quads(m), np = (Q + 1) * (Q + 1);
    const int *c = sq_mesh_quads(m);
    const double *x = sq_mesh_nodes(m);
    double *v = malloc(sizeof(double) * 8 * (size_t)nq);
    int lat[4] = {0, Q, (Q + 1) * Q + Q, (Q + 1) * Q};
    for (int q = 0; q < nq; q++)
        for (int k = 0; k < 4; k++) {
            int g = c[(size_t)q * np + lat[k]];
            v[8 * q + 2 * k] = x[3 * g];
            v[8 * q + 2 * k + 1] = x[3 * g + 1];
        }
    qsort(v, 4 * (size_t)nq, 2 * sizeof(double), cmp_xy);
    *n = 4 * nq;
    return v;
}

/* Every corner of a is a corner of b, exactly. */
static int nested(const sq_mesh *a, const sq_mesh *b)
{
    int na, nb, ok = 1;
    double *va = corners(a, &na), *vb = corners(b, &nb);
    for (int k = 0; k < na && ok; k++)
        ok = bsearch(&va[2 * k], vb, (size_t)nb, 2 * sizeof(double), cmp_xy) != NULL;
    free(va);
    free(vb);
    return ok;
}

static int same_corners(const sq_mesh *a, const sq_mesh *b)
{
    return sq_mesh_num_quads(a) == sq_mesh_num_quads(b) && nested(a, b) && nested(b, a);
}

/* Largest distance of a boundary side's node from its circle. */
static double off_circles(const sq_mesh *m)
{
    int Q = sq_mesh_order(m), np = (Q + 1) * (Q + 1);
    const int *s = sq_mesh_boundary_sides(m), *c = sq_mesh_quads(m);
    const double *x = sq_mesh_nodes(m);
    double worst = 0;
    for (int b = 0; b < sq_mesh_num_boundary_sides(m); b++) {
        int q = s[3 * b], side = s[3 * b + 1];
        for (int t = 0; t <= Q; t++) {
            int i = side == 0 ? t : side == 1 ? Q : side == 2 ? Q - t : 0;
            int j = side == 0 ? 0 : side == 1 ? t : side == 2 ? Q : Q - t;
            int g = c[(size_t)q * np + (Q + 1) * j + i];
            double r = hypot(x[3 * g], x[3 * g + 1]);
            double d = fmin(fabs(r - 1.0), fabs(r - 0.4));
            if (d > worst) worst = d;
        }
    }
    return worst;
}

static int valid(const sq_mesh *m)
{
    const double *sj = sq_mesh_scaled_jacobians(m);
    for (int q = 0; q < sq_mesh_num_quads(m); q++)
        if (!(sj[q] > 0)) return 0;
    return 1;
}

static void refusals(const sq_mesh *l1)
{
    sq_error err;
    sq_mesh *r = (sq_mesh *)1;
    CHECK(sq_mesh_refine(l1, -1, 0, NULL, &r, &err) == SQ_ERR_USAGE && !r, "levels -1 accepted");
    r = (sq_mesh *)1;
    CHECK(sq_mesh_refine(l1, 0, 11, NULL, &r, &err) == SQ_ERR_USAGE && !r, "order 11 accepted");
    sq_options o;
    sq_options_init(&o);
    o.max_quads = 4.0 * sq_mesh_num_quads(l1);
    r = (sq_mesh *)1;
    CHECK(sq_mesh_refine(l1, 2, 0, &o, &r, &err) == SQ_ERR_USAGE && !r,
          "16 times the quads accepted under max_quads = 4 times");
    const sq_mesh *ms[1] = {l1};
    const char *files[1] = {"x.msh"};
    int lv[1] = {1};
    CHECK(sq_mesh_family_write_manifest("/tmp", 1, ms, files, lv, &err) == SQ_ERR_USAGE,
          "a manifest over a directory accepted");
}

static void manifest(const sq_mesh *l1, const sq_mesh *l2)
{
    sq_error err;
    char path[] = "/tmp/t954-manifest-XXXXXX";
    int fd = mkstemp(path);
    if (fd >= 0) close(fd);
    const sq_mesh *ms[2] = {l1, l2};
    const char *files[2] = {"a_L1.msh", "a_L2.msh"};
    int lv[2] = {1, 2};
    CHECK(sq_mesh_family_write_manifest(path, 2, ms, files, lv, &err) == SQ_OK, "manifest: %s",
          err.msg);
    char text[8192] = "", want[64];
    FILE *f = fopen(path, "r");
    size_t n = f ? fread(text, 1, sizeof text - 1, f) : 0;
    text[n] = '\0';
    if (f) fclose(f);
    remove(path);
    for (int k = 0; k < 2; k++) {
        snprintf(want, sizeof want, "\"quads\": %d", sq_mesh_num_quads(ms[k]));
        CHECK(strstr(text, want) && strstr(text, files[k]), "manifest lacks %s of %s", want,
              files[k]);
    }
    char *json = NULL;
    snprintf(want, sizeof want, "\"quads\": %d", sq_mesh_num_quads(l2));
    CHECK(sq_mesh_report(l2, &json, &err) == SQ_OK && strstr(json, want),
          "the refined mesh's report lacks %s", want);
    sq_free(json);
}

int main(int argc, char **argv)
{
    if (argc != 2) return fprintf(stderr, "usage: t954-api-refine EXAMPLES_DIR\n"), 2;
    char path[4096];
    snprintf(path, sizeof path, "%s/annulus.step", argv[1]);
    sq_error err;
    sq_options o;
    sq_options_init(&o);
    o.order = 3;
    sq_model *model = NULL;
    sq_mesh *l1 = NULL, *l2 = NULL, *l3 = NULL, *l3b = NULL, *q5 = NULL;
    if (sq_model_open(path, &o, &model, &err) || sq_face_mesh(model, -1, &o, &l1, &err) ||
        sq_mesh_refine(l1, 1, 0, NULL, &l2, &err) || sq_mesh_refine(l2, 1, 0, NULL, &l3, &err) ||
        sq_mesh_refine(l1, 2, 0, NULL, &l3b, &err) || sq_mesh_refine(l1, 0, 5, NULL, &q5, &err)) {
        printf("%s\n", err.msg);
        return 1;
    }
    CHECK(sq_mesh_num_quads(l2) == 4 * sq_mesh_num_quads(l1) && sq_mesh_order(l2) == 3,
          "level 2: %d quads of order %d", sq_mesh_num_quads(l2), sq_mesh_order(l2));
    CHECK(nested(l1, l2) && nested(l2, l3), "not nested");
    CHECK(off_circles(l2) <= 1e-13 && off_circles(l3) <= 1e-13, "boundary nodes %.3g off",
          fmax(off_circles(l2), off_circles(l3)));
    CHECK(valid(l2) && valid(l3) && valid(q5), "a refined quad is not proven valid");
    double exact = M_PI * (1.0 - 0.16), e1 = fabs(sq_mesh_area(l1) - exact),
           e2 = fabs(sq_mesh_area(l2) - exact);
    CHECK(e1 / e2 >= pow(2.0, 5.9), "area errors %.3g, %.3g: rate %.2f < 5.9", e1, e2,
          log2(e1 / e2));
    CHECK(sq_mesh_num_nodes(l3) == sq_mesh_num_nodes(l3b) &&
              !memcmp(sq_mesh_nodes(l3), sq_mesh_nodes(l3b),
                      3 * sizeof(double) * (size_t)sq_mesh_num_nodes(l3)),
          "two levels at once differ from one level twice");
    CHECK(sq_mesh_order(q5) == 5 && same_corners(l1, q5), "order 5: not the same quads");
    double m1, x1, m2, x2;
    CHECK(!sq_mesh_edge_lengths(l1, &m1, &x1, &err) && !sq_mesh_edge_lengths(l2, &m2, &x2, &err) &&
              m2 < 0.55 * m1 && m2 > 0.45 * m1 && x2 <= x1,
          "h: %g %g then %g %g", m1, x1, m2, x2);
    refusals(l1);
    manifest(l1, l2);
    sq_mesh_free(&q5);
    sq_mesh_free(&l3b);
    sq_mesh_free(&l3);
    sq_mesh_free(&l2);
    sq_mesh_free(&l1);
    sq_model_free(&model);
    return fails != 0;
}
