/* semquad — the all-quad last resort (layout.h sq_layout_all_quad): where the
 * correction is stuck, crossings become nodes, dangling pieces go, and every
 * non-quad patch is split (a lens cut across, n quads around a centre, a
 * chord from a corner); the splits' ends on neighbouring patches are left as
 * T-junctions.  A T-junction lies on a straight part of the neighbour's side
 * (no corner there), so the neighbour stays a four-sided patch whose side is
 * two layout edges; the chord quantization matches sides edge by edge
 * (src/mesh/quad_chords.c), so the mesh stays conforming, and its vertex at
 * the T-junction is regular (the spoke goes on as a grid line of the
 * neighbour).  The layout's quad patches keep their corners. */
#include "repair_private.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The first patch that is not a quad: n != 4 corners, or several cycles
 * (annular); -1 when every patch is a quad. */
static int first_non_quad(const sq_layout *L)
{
    for (int p = 0; p < L->npatches; p++)
        if (L->patches[p].ncycles != 1 || L->patches[p].ncorners != 4) return p;
    return -1;
}

/* What the mesh needs of the layout: four-sided patches of one cycle,
 * areas summing to the face's, no crossing and no dangling end.  The
 * corner counts at singular points, face vertices and feet, and the
 * T-junctions, are the pattern's concern, not the mesh's: the mesh's
 * irregular vertices are counted on the mesh.  Returns the number of
 * defects left; the first in *why. */
static int all_quad_defects(const sq_layout *L, char *why, size_t n)
{
    sq_layout_defects d;
    sq_layout_check(L, &d);
    int left = 0;
    for (int k = 0; k < d.n; k++) {
        sq_defect_kind kind = d.d[k].kind;
        if (kind == SQ_DEFECT_SINGULAR || kind == SQ_DEFECT_VERTEX || kind == SQ_DEFECT_FOOT ||
            kind == SQ_DEFECT_TJUNCTION)
            continue;
        if (left++ == 0) snprintf(why, n, "%s", d.d[k].msg);
    }
    sq_layout_defects_free(&d);
    return left;
}

/* Where patch p is, for the message of a failure: its area centroid. */
static void patch_where(const sq_layout *L, int p, char *buf, size_t n)
{
    double c[2];
    if (lay_patch_centroid(L, &L->patches[p], c))
        snprintf(buf, n, "patch %d (centroid (%.6g, %.6g), %d corners, %d cycles)", p, c[0], c[1],
                 L->patches[p].ncorners, L->patches[p].ncycles);
    else
        snprintf(buf, n, "patch %d (%d corners, %d cycles)", p, L->patches[p].ncorners,
                 L->patches[p].ncycles);
}

/* Does segment a-b stay inside the closed polygon ring[n] (touching it
 * only within tol of its ends, its midpoint inside)? */
static int chord_inside(const double *ring, int n, const double a[2], const double b[2],
                        double tol)
{
    for (int i = 0; i < n; i++) {
        double t, u;
        if (!lay_seg_seg(a, b, &ring[2 * i], &ring[2 * ((i + 1) % n)], &t, &u)) continue;
        double x = a[0] + t * (b[0] - a[0]), y = a[1] + t * (b[1] - a[1]);
        if (hypot(x - a[0], y - a[1]) > tol && hypot(x - b[0], y - b[1]) > tol) return 0;
    }
    double m[2] = {0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1])};
    return lay_poly_contains(ring, n, m);
}

/* The levels of imbalance a chord may have: the corners' split tried
 * from the most even one outwards, this many levels (the test is linear in
 * the ring's points, a patch of traced lines has thousands). */
#define CHORD_LEVELS 3

/* Bent spokes only in a patch of at most this many ring points: their
 * triangulation's medial-axis search is quadratic in them (a patch along a
 * face of many holes had 2e5, minutes). */
#define ALLQUAD_BENT_RING_MAX 2000

/* Length of the polyline path[np]. */
static double path_length(const double *path, int np)
{
    double len = 0.0;
    for (int i = 0; i + 1 < np; i++)
        len += hypot(path[2 * i + 2] - path[2 * i], path[2 * i + 3] - path[2 * i + 1]);
    return len;
}

/* The chord from corner k of patch P to the midpoint of its side j. */
typedef struct {
    int k, edge;
    double frac, mid[2], len;
    double *path; /* bent: malloc'ed polyline (np points), NULL when straight */
    int np;
} allquad_chord;

/* The best chord of level `lev` (the corners' split |2o - (n - 1)| = lev):
 * straight when one stays inside (the shortest), else, with `cdt`, bent
 * along the ring's triangulation (the shortest path).  c->k < 0: none. */
static sq_status best_chord(lay_repair *r, const sq_layout_patch *P, const double *mids,
                            const int *medge, const double *mfrac, const double *ring, int nring,
                            const lay_ring_cdt *cdt, int lev, allquad_chord *c, sq_error *err)
{
    const sq_layout *L = r->L;
    const int n = P->ncorners;
    const double tol = 1e3 * r->tol;
    for (int k = 0; k < n; k++)
        for (int sgn = -1; sgn <= 1; sgn += 2) {
            int twice = n - 1 + sgn * lev; /* 2o: the parts have o + 2 and n - o + 1 corners */
            if (twice % 2 || (lev == 0 && sgn > 0)) continue;
            int o = twice / 2, j = (k + o) % n;
            if (n > 1 && (o < 1 || o > n - 2)) continue;
            const sq_layout_node *v = &L->nodes[P->corners[k]];
            const double a[2] = {v->x, v->y}, *mid = &mids[2 * j];
            sq_sep_end start;
            if (!lay_node_end(L, P->corners[k], &start)) continue;
            double *path = NULL, len;
            int np = 0;
            if (!cdt) {
                len = hypot(mid[0] - a[0], mid[1] - a[1]);
                if (len >= c->len || !chord_inside(ring, nring, a, mid, tol)) continue;
            } else {
                sq_error e;
                sq_status st = lay_ring_cdt_path(cdt, ring, nring, a, mid, r->tol, &path, &np, &e);
                if (st == SQ_ERR_INTERNAL) return SQ_FAIL(err, st, "%s", e.msg);
                if (st != SQ_OK) continue;
                len = path_length(path, np);
                if (len >= c->len) {
                    free(path);
                    continue;
                }
            }
            free(c->path);
            *c = (allquad_chord){k, medge[j], mfrac[j], {mid[0], mid[1]}, len, path, np};
        }
    return SQ_OK;
}

/* Patch p (one cycle, n corners) cut by a separatrix from a corner to the
 * midpoint of a side not at that corner (for n = 1 its only side): the cut
 * that parts the corners most evenly, straight where one stays inside (the
 * shortest), else bent along the patch's triangulation, as the n-quad
 * split's spokes are.  For the patches the n-quad split cannot take
 * (spokes that would cross, n = 1) and those of many corners, whose centre
 * would be a vertex of high valence. */
static sq_status split_chord(lay_repair *r, int p, sq_error *err)
{
    sq_layout *L = r->L;
    const sq_layout_patch *P = &L->patches[p];
    const int n = P->ncorners;
    double *mids = malloc(2 * (size_t)n * sizeof *mids), *mfrac = malloc((size_t)n * sizeof *mfrac);
    int *medge = malloc((size_t)n * sizeof *medge), nring = 0;
    double *ring = NULL;
    lay_ring_cdt cdt = {0};
    allquad_chord c = {.k = -1, .len = HUGE_VAL};
    sq_status st = mids && mfrac && medge ? SQ_OK
                                                : SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    for (int j = 0; j < n && st == SQ_OK; j++)
        st = lay_side_point(r, P, j, 0.5, &medge[j], &mfrac[j], &mids[2 * j], err);
    if (st == SQ_OK) st = lay_ring_with_points(L, P, mids, n, &ring, &nring, err);
    for (int lev = 0; lev < CHORD_LEVELS && c.k < 0 && st == SQ_OK; lev++)
        st = best_chord(r, P, mids, medge, mfrac, ring, nring, NULL, lev, &c, err);
    if (st == SQ_OK && c.k < 0 && nring <= ALLQUAD_BENT_RING_MAX) {
        sq_error e;
        if (lay_ring_cdt_build(r, ring, nring, &cdt, &e) == SQ_OK)
            for (int lev = 0; lev < CHORD_LEVELS && c.k < 0 && st == SQ_OK; lev++)
                st = best_chord(r, P, mids, medge, mfrac, ring, nring, &cdt, lev, &c, err);
    }
    if (st == SQ_OK && c.k < 0)
        st = SQ_FAIL(err, SQ_ERR_LAYOUT, "no cut from a corner stays inside");
    if (st == SQ_OK) {
        const sq_layout_node *v = &L->nodes[P->corners[c.k]];
        double a[2] = {v->x, v->y};
        sq_sep_end start;
        lay_node_end(L, P->corners[c.k], &start);
        if (v->kind == SQ_LNODE_CORNER) L->vertex_quads[v->id]++;
        if (v->kind == SQ_LNODE_SINGULAR) L->sing[v->id].valence++;
        st = lay_add_spoke(r, start, a, c.path, c.np, c.edge, c.frac, c.mid, err);
    }
    free(c.path), free(mids), free(mfrac), free(medge), free(ring);
    lay_ring_cdt_free(&cdt);
    return st;
}

/* The separatrices that end at an inner node of degree 1 (a singular point
 * left with one separatrix, an end the untangling cut loose) removed, until
 * none: a dangling piece is no side of any patch. */
#define ALLQUAD_DANGLING_PASSES 64
static sq_status remove_dangling(lay_repair *r, sq_error *err)
{
    sq_layout *L = r->L;
    for (int pass = 0; pass < ALLQUAD_DANGLING_PASSES; pass++) {
        SQ_TRY(lay_graph_build(L, r->face, r->info, err));
        int removed = 0;
        for (int k = L->seps.n - 1; k >= 0; k--) {
            int dangles = 0;
            for (int e = 0; e < L->nedges && !dangles; e++) {
                const sq_layout_edge *E = &L->edges[e];
                if (E->sep != k) continue;
                const sq_layout_node *a = &L->nodes[E->n0], *b = &L->nodes[E->n1];
                dangles = (a->degree == 1 && a->kind != SQ_LNODE_CORNER && a->kind != SQ_LNODE_FOOT) ||
                          (b->degree == 1 && b->kind != SQ_LNODE_CORNER && b->kind != SQ_LNODE_FOOT);
            }
            if (!dangles) continue;
            lay_sep_remove(&L->seps, k);
            L->stats.separatrices_removed++;
            removed = 1;
        }
        if (!removed) return SQ_OK;
    }
    return SQ_OK;
}

/* Patch p cut across from the point at fraction t[0] of side side[0] to
 * the point at t[1] of side side[1]: straight where the cut stays inside,
 * else bent along the patch's triangulation. */
static sq_status cut_across(lay_repair *r, int p, const int side[2], const double t[2],
                            sq_error *err)
{
    sq_layout *L = r->L;
    const sq_layout_patch *P = &L->patches[p];
    int edge[2], nring = 0, np = 0;
    double frac[2], pt[4], *ring = NULL, *path = NULL;
    for (int k = 0; k < 2; k++)
        SQ_TRY(lay_side_point(r, P, side[k], t[k], &edge[k], &frac[k], &pt[2 * k], err));
    SQ_TRY(lay_ring_with_points(L, P, pt, 2, &ring, &nring, err));
    sq_status st = SQ_OK;
    if (!chord_inside(ring, nring, &pt[0], &pt[2], 1e3 * r->tol)) {
        lay_ring_cdt cdt = {0};
        if (nring > ALLQUAD_BENT_RING_MAX)
            st = SQ_FAIL(err, SQ_ERR_LAYOUT, "the cut across leaves it (%d ring points)", nring);
        if (st == SQ_OK) st = lay_ring_cdt_build(r, ring, nring, &cdt, err);
        if (st == SQ_OK)
            st = lay_ring_cdt_path(&cdt, ring, nring, &pt[0], &pt[2], r->tol, &path, &np, err);
        lay_ring_cdt_free(&cdt);
    }
    free(ring);
    sq_sep_end a;
    if (st == SQ_OK) st = lay_edge_end(r, edge[0], frac[0], &pt[0], &a, err);
    if (st == SQ_OK) st = lay_add_spoke(r, a, &pt[0], path, np, edge[1], frac[1], &pt[2], err);
    free(path);
    return st;
}

/* A patch of two corners (a lens) cut across between its two sides'
 * midpoints: two triangles, split next, which share the cut's midpoint.
 * (An n-quad split of a lens puts its centre on a straight line between
 * the spokes: two triangles whose splits meet at that centre.) */
static sq_status split_lens(lay_repair *r, int p, sq_error *err)
{
    return cut_across(r, p, (const int[2]){0, 1}, (const double[2]){0.5, 0.5}, err);
}

/* A patch of one corner (a teardrop) whose corner no chord can leave (a
 * crossing of separatrices) cut across its side between the thirds of its
 * arc length: a lens and a triangle, split next. */
static sq_status split_teardrop(lay_repair *r, int p, sq_error *err)
{
    return cut_across(r, p, (const int[2]){0, 0}, (const double[2]){1.0 / 3.0, 2.0 / 3.0}, err);
}

/* A patch of many corners is cut first: an n-quad split's centre of
 * valence n >= this is a vertex of high valence with thin quads. */
#define ALLQUAD_CHORD_FIRST 7

/* Patch p split once: a lens cut across (bent where a straight cut leaves
 * it), else its n-quad split; a teardrop by a chord from its corner, else
 * cut across its side; the n-quad split (3 <= n < ALLQUAD_CHORD_FIRST) or
 * the chord, the other one where the first cannot be made. */
static sq_status split_once(lay_repair *r, int p, sq_error *err)
{
    const sq_layout_patch *P = &r->L->patches[p];
    const int n = P->ncorners;
    const int chord_first = n < 2 || n >= ALLQUAD_CHORD_FIRST;
    long npts = 0;
    for (int h = 0; h < P->nhalf; h++) npts += r->L->edges[P->half[h].edge].npts;
    const int bent = npts <= ALLQUAD_BENT_RING_MAX;
    sq_error e1;
    sq_status st = n == 2        ? split_lens(r, p, &e1)
                   : chord_first ? split_chord(r, p, &e1)
                                 : lay_split_centre(r, p, bent, &e1);
    if (st == SQ_OK || st == SQ_ERR_INTERNAL) {
        if (st != SQ_OK && err) *err = e1;
        return st;
    }
    sq_error e2;
    st = n == 1                      ? split_teardrop(r, p, &e2)
         : chord_first || n == 2 ? lay_split_centre(r, p, bent, &e2)
                                 : split_chord(r, p, &e2);
    if (st == SQ_OK || st == SQ_ERR_INTERNAL) {
        if (st != SQ_OK && err) *err = e2;
        return st;
    }
    return SQ_FAIL(err, SQ_ERR_LAYOUT, "%s; %s", e1.msg, e2.msg);
}

/* Splits bound: every split of an n-gon leaves quads, or triangles and
 * smaller polygons that a few more splits take; a patch whose splits go on
 * (a sliver whose parts stay triangles) ends the last resort. */
#define ALLQUAD_SPLITS_PER_PATCH 4
#define ALLQUAD_SPLITS_MIN 8

/* Patch p split as the last resort; *why says where on failure. */
static sq_status split_patch(lay_repair *r, int p, sq_error *err)
{
    const sq_layout_patch *P = &r->L->patches[p];
    char where[160];
    patch_where(r->L, p, where, sizeof where);
    if (P->ncycles != 1)
        return SQ_FAIL(err, SQ_ERR_LAYOUT, "%s: an annular patch the repairs could not cut", where);
    if (P->ncorners < 1)
        return SQ_FAIL(err, SQ_ERR_LAYOUT, "%s: a patch without corners has no sides to split",
                       where);
    sq_error e2;
    sq_status st = split_once(r, p, &e2);
    if (st == SQ_OK) r->L->stats.all_quad_splits++;
    if (st == SQ_ERR_INTERNAL && err) *err = e2;
    if (st == SQ_OK || st == SQ_ERR_INTERNAL) return st;
    return SQ_FAIL(err, st, "%s: %s", where, e2.msg);
}

/* Passes: in each, the non-quad patches that share no layout edge with
 * one another are split (a spoke's end changes only the sides it ends
 * on), then the graph is rebuilt, its work counted against WORK_MAX. */
static sq_status split_all(lay_repair *r, sq_error *err)
{
    sq_layout *L = r->L;
    int nonquad = 0;
    for (int p = 0; p < L->npatches; p++)
        nonquad += L->patches[p].ncycles != 1 || L->patches[p].ncorners != 4;
    const int max_splits = ALLQUAD_SPLITS_PER_PATCH * nonquad + ALLQUAD_SPLITS_MIN;
    sq_status st = SQ_OK;
    while (st == SQ_OK) {
        int p0 = first_non_quad(L);
        if (p0 < 0) return SQ_OK;
        if (L->stats.all_quad_splits >= max_splits || r->work > WORK_MAX) {
            char where[160];
            patch_where(L, p0, where, sizeof where);
            return SQ_FAIL(err, SQ_ERR_LAYOUT, "%s still not a quad after %d splits%s", where,
                           L->stats.all_quad_splits,
                           r->work > WORK_MAX ? " (the splits' work bound)" : "");
        }
        char *used = calloc((size_t)L->nedges + 1, 1);
        if (!used) return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
        for (int p = p0; p < L->npatches && st == SQ_OK; p++) {
            const sq_layout_patch *P = &L->patches[p];
            int free_sides = P->ncycles != 1 || P->ncorners != 4;
            for (int h = 0; h < P->nhalf && free_sides; h++) free_sides = !used[P->half[h].edge];
            if (!free_sides) continue;
            for (int h = 0; h < P->nhalf; h++) used[P->half[h].edge] = 1;
            st = split_patch(r, p, err);
        }
        free(used);
        r->work += (double)lay_set_points(&L->seps);
        if (st == SQ_OK) st = lay_graph_build(L, r->face, r->info, err);
    }
    return st;
}

sq_status sq_layout_all_quad(const cad_face *face, const sq_face_info *info, sq_layout *L,
                             sq_error *err)
{
    lay_repair r;
    sq_status st = lay_repair_begin(&r, L, face, info, NULL, NULL, err);
    r.all_quad = 1;
    L->inserted_corner_tol = SQ_LAYOUT_ALLQUAD_CORNER_TOL_DEG * M_PI / 180.0;
    if (st == SQ_OK) st = lay_set_untangle(&r, err);
    if (st == SQ_OK) st = remove_dangling(&r, err);
    if (st == SQ_OK) st = split_all(&r, err);
    lay_repair_end(&r);
    char why[200];
    if (st == SQ_OK && all_quad_defects(L, why, sizeof why) > 0)
        st = SQ_FAIL(err, SQ_ERR_LAYOUT, "%s", why);
    if (st != SQ_OK) return st;
    L->stats.separatrices = L->seps.n;
    L->stats.patches = L->npatches;
    L->stats.quad_patches = L->npatches;
    return SQ_OK;
}
