/* Each layout repair triggered by a case built for it, the repaired layout
 * valid: a duplicated separatrix (Jezdimirović §6.1 Fig. 15), a crossing
 * made a regular node, a limit cycle (open end) cut at its orthogonal
 * crossing and the T-junction left repaired by continuing it (Fig. 16–17),
 * a triangular patch split by midpoint division (Marcon §3.4), a boundary
 * valence-2 point split into two valence-3 points (Jezdimirović §6.3,
 * Fig. 18), an annulus cut along the field into quads. */
#include "layout.h"
#include "t51x_layout.h"
#include "test_util.h"

#include <gsl/gsl_errno.h>

static void line(sq_separatrix *s, const cad_face *f, double ax, double ay, double bx, double by)
{
    int n = 21;
    s->npts = n;
    s->xy = malloc(2 * (size_t)n * sizeof *s->xy);
    for (int j = 0; j < n; j++) {
        double t = (double)j / (n - 1);
        s->xy[2 * j] = ax + t * (bx - ax);
        s->xy[2 * j + 1] = ay + t * (by - ay);
    }
    double a[2] = {ax, ay}, b[2] = {bx, by};
    s->start = nearest_foot(f, a, NULL);
    s->end = nearest_foot(f, b, NULL);
    s->merged = 0;
}

typedef struct {
    cad_model *m;
    cad_face *f;
    sq_face_info info;
} shape;

static void open_shape(shape *sh, const char *file)
{
    char path[4096];
    sq_error err;
    sq_test_path(path, sizeof path, 0, file);
    SQ_TEST_OK(cad_model_read(path, &sh->m, &err), err);
    SQ_TEST_OK(cad_face_create(sh->m, 0, &sh->f, &err), err);
    SQ_TEST_OK(sq_face_info_compute(sh->f, &sh->info, &err), err);
}

static void close_shape(shape *sh)
{
    sq_face_info_free(&sh->info);
    cad_face_free(&sh->f);
    cad_model_free(&sh->m);
}

/* radial cross field around the origin: theta = polar angle */
static int radial_dir(void *ctx, const double x[2], int *elem, double *theta)
{
    (void)ctx;
    (void)elem;
    double r = hypot(x[0], x[1]);
    if (r > 1.0 + 1e-12 || r < 0.4 - 1e-12) return 1; /* boundary points' few U */
    *theta = atan2(x[1], x[0]);
    return 0;
}

static int polar_dir(void *ctx, const double x[2], int *elem, double *theta)
{
    (void)ctx;
    (void)elem;
    if (hypot(x[0], x[1]) > 1.0 + 1e-12 || x[0] < -1e-12 || x[1] < -1e-12) return 1;
    *theta = atan2(x[1], x[0]);
    return 0;
}

static double radial_size(void *ctx, int elem)
{
    (void)ctx;
    (void)elem;
    return 0.1;
}

static int build(const char *name, shape *sh, int nsing, const sq_singularity *sing,
                 sq_separatrix *s, int ns, const sq_cross_field *field, sq_layout *L)
{
    int quads[16];
    for (int k = 0; k < sh->info.nvertices; k++) quads[k] = sh->info.vertices[k].smooth ? 2 : 1;
    sq_separatrix_set set = {ns, ns, s};
    sq_error err;
    sq_status st = sq_layout_build(sh->f, &sh->info, quads, nsing, sing, &set, field, NULL, L, &err);
    for (int k = 0; k < ns; k++) free(s[k].xy);
    if (st != SQ_OK) {
        printf("%s: sq_layout_build: %s\n", name, err.msg);
        return 1;
    }
    double sum = 0.0;
    for (int p = 0; p < L->npatches; p++) sum += L->patches[p].area;
    /* patch areas by cad_split's adaptive Green rule: 1e-9 (t320) */
    return sq_check_rel(name, "area sum", sum, sh->info.area, 1e-9);
}

int main(void)
{
    gsl_set_error_handler_off();
    int fails = 0;
    sq_layout L;
    shape sq;
    open_shape(&sq, "square.step");
    sq_separatrix s[8];
    /* duplicate: the cross of t510 plus a second copy of one arm, traced
     * back from the boundary and slightly off */
    {
        sq_singularity c = {0.5, 0.5, 4, SQ_ORIGIN_IMPOSED};
        double mids[4][2] = {{0.5, 0}, {1, 0.5}, {0.5, 1}, {0, 0.5}};
        for (int k = 0; k < 4; k++) {
            line(&s[k], sq.f, 0.5, 0.5, mids[k][0], mids[k][1]);
            s[k].start = (sq_sep_end){SQ_END_SINGULAR, 0, 0};
        }
        line(&s[4], sq.f, 1.0, 0.5, 0.5, 0.5);
        s[4].end = (sq_sep_end){SQ_END_SINGULAR, 0, 0};
        for (int j = 1; j < 20; j++) s[4].xy[2 * j + 1] += 0.002 * sin(M_PI * j / 20.0);
        fails += build("duplicate", &sq, 1, &c, s, 5, NULL, &L);
        fails += sq_check_int("duplicate", "removed", L.stats.duplicates_removed, 1);
        fails += sq_check_int("duplicate", "quad patches", L.stats.quad_patches, 4);
        sq_layout_free(&L);
    }
    /* crossing of two midlines: a regular node */
    {
        line(&s[0], sq.f, 0.5, 0.0, 0.5, 1.0);
        line(&s[1], sq.f, 0.0, 0.5, 1.0, 0.5);
        fails += build("crossing", &sq, 0, NULL, s, 2, NULL, &L);
        fails += sq_check_int("crossing", "crossings split", L.stats.crossings_split, 1);
        fails += sq_check_int("crossing", "quad patches", L.stats.quad_patches, 4);
        fails += sq_check_int("crossing", "separatrices", L.stats.separatrices, 4);
        sq_layout_free(&L);
    }
    /* limit cycle: an open line from the left crossing the vertical midline
     * and stopping short of the right side; cut at the crossing, the T it
     * leaves repaired by continuing to the right side */
    {
        line(&s[0], sq.f, 0.5, 0.0, 0.5, 1.0);
        line(&s[1], sq.f, 0.0, 0.5, 0.8, 0.53);
        s[1].end = (sq_sep_end){SQ_END_OPEN, -1, 0};
        fails += build("limit cycle", &sq, 0, NULL, s, 2, NULL, &L);
        fails += sq_check_int("limit cycle", "cut", L.stats.limit_cycles_cut, 1);
        fails += sq_check_int("limit cycle", "T-junctions", L.stats.t_junctions, 1);
        fails += sq_check_int("limit cycle", "quad patches", L.stats.quad_patches, 4);
        sq_layout_free(&L);
    }
    close_shape(&sq);
    /* triangle: no separatrix, three corners of one quad each: one
     * triangular patch, split into three quads by midpoint division */
    {
        shape tr;
        open_shape(&tr, "triangle.step");
        fails += build("triangle", &tr, 0, NULL, NULL, 0, NULL, &L);
        fails += sq_check_int("triangle", "repaired", L.stats.triangles_repaired, 1);
        fails += sq_check_int("triangle", "quad patches", L.stats.quad_patches, 3);
        fails += sq_check_int("triangle", "separatrices", L.stats.separatrices, 3);
        fails += sq_check_int("triangle", "inserted nodes", L.nsing, 1);
        if (L.nsing == 1) {
            /* the repair's node from straight separatrices of a synthetic
             * field: closed forms, then cad_split's 1e-9 snap; areas by
             * its Green rule (t320) */
            fails += sq_check_abs("triangle", "node x", L.sing[0].x, 0.5, 1e-9);
            fails += sq_check_abs("triangle", "node y", L.sing[0].y, sqrt(3.0) / 6, 1e-9);
        }
        for (int p = 0; p < L.npatches; p++)
            fails += sq_check_rel("triangle", "patch area", L.patches[p].area, sqrt(3.0) / 12, 1e-9);
        sq_layout_free(&L);
        close_shape(&tr);
    }
    /* obtuse quadrilateral (0,0), (0.7,-0.2), (2,0), (1,1.6), one quad per
     * vertex: the 155.3° vertex is a boundary valence-2 point, within 30°
     * of straight, so the one patch is a quad in topology with three
     * geometric corners.  Split (Fig. 18): a valence-3 node at the patch's
     * barycentre (89/90, 7/15) joined to that vertex (now two quads) and to
     * the midpoints (0.5, 0.8), (1.5, 0.8) of the upper sides: three quads.
     * (Midpoint division would put a foot at (0.9902, -0.1554) instead and
     * leave the vertex a corner of no patch: invalid.) */
    {
        shape ki;
        open_shape(&ki, "obtuse_quad.step");
        const char *nm = "valence-2";
        fails += build(nm, &ki, 0, NULL, NULL, 0, NULL, &L);
        fails += sq_check_int(nm, "valence-2 points split", L.stats.valence2_split, 1);
        fails += sq_check_int(nm, "midpoint divisions", L.stats.triangles_repaired, 0);
        fails += sq_check_int(nm, "patches", L.npatches, 3);
        fails += sq_check_int(nm, "quad patches", L.stats.quad_patches, 3);
        fails += sq_check_int(nm, "separatrices", L.stats.separatrices, 3);
        sq_layout_defects d;
        fails += sq_check_int(nm, "defects", sq_layout_check(&L, &d), 0);
        fails += sq_check_int(nm, "crossings", d.count[SQ_DEFECT_CROSSING], 0);
        sq_layout_defects_free(&d);
        fails += sq_check_int(nm, "inserted nodes", L.nsing, 1);
        if (L.nsing == 1) {
            fails += sq_check_int(nm, "node valence", L.sing[0].valence, 3);
            fails += sq_check_int(nm, "node role", L.role[0], SQ_LROLE_VALENCE2);
            /* as for the triangle: closed forms and the 1e-9 snap */
            fails += sq_check_abs(nm, "node x", L.sing[0].x, 89.0 / 90, 1e-9);
            fails += sq_check_abs(nm, "node y", L.sing[0].y, 7.0 / 15.0, 1e-9);
        }
        /* patches having each node as a corner: the node 3, the split
         * vertex 2 (three edges there now), the other vertices 1 */
        for (int v = 0; v < L.nnodes; v++) {
            const sq_layout_node *n = &L.nodes[v];
            int c = 0;
            for (int p = 0; p < L.npatches; p++)
                for (int k = 0; k < L.patches[p].ncorners; k++) c += L.patches[p].corners[k] == v;
            if (n->kind == SQ_LNODE_SINGULAR) {
                fails += sq_check_int(nm, "node corner of", c, 3);
            } else if (n->kind == SQ_LNODE_CORNER && fabs(n->y + 0.2) < 1e-12) { /* the file's point */
                fails += sq_check_int(nm, "split vertex corner of", c, 2);
                fails += sq_check_int(nm, "split vertex edges", n->degree, 3);
                fails += sq_check_int(nm, "split vertex quads", L.vertex_quads[n->id], 2);
            } else if (n->kind == SQ_LNODE_CORNER) {
                fails += sq_check_int(nm, "vertex corner of", c, 1);
            }
        }
        /* the three quads' areas (shoelace), matched to the patches by size */
        const double S[2] = {89.0 / 90, 7.0 / 15}, quads[3][8] = {
            {0, 0, 0.7, -0.2, S[0], S[1], 0.5, 0.8},
            {0.7, -0.2, 2, 0, 1.5, 0.8, S[0], S[1]},
            {1.5, 0.8, 1, 1.6, 0.5, 0.8, S[0], S[1]}};
        for (int p = 0; p < L.npatches; p++) {
            fails += sq_check_int(nm, "patch corners", L.patches[p].ncorners, 4);
            double a = L.patches[p].area, want = 0.0;
            for (int q = 0; q < 3; q++) {
                double w = 0.0;
                for (int k = 0; k < 4; k++)
                    w += 0.5 * (quads[q][2 * k] * quads[q][(2 * k + 3) % 8] -
                                quads[q][(2 * k + 2) % 8] * quads[q][2 * k + 1]);
                if (fabs(w - a) < fabs(want - a)) want = w;
            }
            fails += sq_check_rel(nm, "patch area", a, want, 1e-9);
        }
        sq_layout_free(&L);
        close_shape(&ki);
    }
    /* quarter circle with a quarter circle of radius 0.5 around the corner:
     * a triangular patch beside a quad; midpoint division puts a T-junction
     * on the inner arc, continued along the radial field to the outer arc:
     * 5 quads */
    {
        shape qc;
        open_shape(&qc, "quarter_circle.step");
        int n = 41;
        s[0].npts = n;
        s[0].xy = malloc(2 * (size_t)n * sizeof *s[0].xy);
        for (int j = 0; j < n; j++) {
            double a = 0.5 * M_PI * j / (n - 1);
            s[0].xy[2 * j] = 0.5 * cos(a);
            s[0].xy[2 * j + 1] = 0.5 * sin(a);
        }
        double a[2] = {0.5, 0}, b[2] = {0, 0.5};
        s[0].start = nearest_foot(qc.f, a, NULL);
        s[0].end = nearest_foot(qc.f, b, NULL);
        s[0].merged = 0;
        sq_cross_field field = {NULL, polar_dir, radial_size, NULL};
        fails += build("quarter", &qc, 0, NULL, s, 1, &field, &L);
        fails += sq_check_int("quarter", "triangles", L.stats.triangles_repaired, 1);
        fails += sq_check_int("quarter", "T-junctions", L.stats.t_junctions, 1);
        fails += sq_check_int("quarter", "quad patches", L.stats.quad_patches, 5);
        sq_layout_free(&L);
        close_shape(&qc);
    }
    /* annulus: one annular patch, cut along the radial field lines */
    {
        shape an;
        open_shape(&an, "annulus.step");
        sq_cross_field field = {NULL, radial_dir, radial_size, NULL};
        fails += build("annulus", &an, 0, NULL, NULL, 0, &field, &L);
        fails += sq_check_int("annulus", "cut", L.stats.annuli_cut, 1);
        fails += sq_check_int("annulus", "quad patches", L.stats.quad_patches, 4);
        for (int p = 0; p < L.npatches; p++)
            fails += sq_check_rel("annulus", "patch area", L.patches[p].area, 0.21 * M_PI, 1e-6);
        sq_layout_free(&L);
        close_shape(&an);
    }
    return fails != 0;
}
