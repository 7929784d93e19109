/* semquad — the last resort for a patch with n != 4 corners: an extra
 * separatrix from a corner, else the n-quad split, each tried on a snapshot
 * of the layout and undone unless it leaves fewer defects. */
#include "repair_private.h"

#include <limits.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Unit direction of half-edge h of patch P at its start. */
static void half_start_dir(const sq_layout *L, const sq_layout_half *h, double d[2])
{
    const sq_layout_edge *E = &L->edges[h->edge];
    sq_separatrix s = {.npts = E->npts, .xy = E->xy};
    lay_leave_dir(&s, h->reversed, d, L->scale);
}

/* The cross branches at corner k of patch P that point into the patch at
 * least EXTRA_MARGIN_DEG away from both its sides there (dir[2 * j]);
 * returns how many (at most 4). */
#define EXTRA_MARGIN_DEG 20.0
static int wedge_branches(const lay_repair *r, const sq_layout_patch *P, int k, double *dir)
{
    const sq_layout *L = r->L;
    const sq_layout_node *c = &L->nodes[P->corners[k]];
    double out[2], ang = P->corner_angle[k], margin = EXTRA_MARGIN_DEG * M_PI / 180.0;
    half_start_dir(L, &P->half[P->corner_half[k]], out);
    if (!r->field || ang < 2.0 * margin) return 0;
    /* the field a little inside, along the bisector (the corner may be a
     * singular point) */
    double a0 = atan2(out[1], out[0]), bis = a0 + 0.5 * ang, th;
    double q[2] = {c->x + 1e-3 * r->step * cos(bis), c->y + 1e-3 * r->step * sin(bis)};
    int elem = -1, n = 0;
    if (r->field->direction(r->field->ctx, q, &elem, &th)) return 0;
    for (int j = 0; j < 4; j++) {
        double phi = remainder(th + j * M_PI / 2 - a0, 2.0 * M_PI);
        if (phi < 0) phi += 2.0 * M_PI;
        if (phi > margin && phi < ang - margin) {
            dir[2 * n] = cos(a0 + phi);
            dir[2 * n + 1] = sin(a0 + phi);
            n++;
        }
    }
    return n;
}

/* An extra separatrix from corner k of patch p along direction dir, traced
 * in the field to the patch's other side (Marcon's streamlines from the
 * offending corner): a pentagon with a corner whose angle holds a cross
 * branch becomes a quad and a triangle or two quads; where the line ends
 * on a separatrix it leaves a T-junction, continued next.  The step is
 * bounded by a tenth of the patch's shortest side so that thin patches
 * are crossed, not jumped. */
static sq_status extra_separatrix(lay_repair *r, int p, int k, const double dir[2], sq_error *err)
{
    sq_layout *L = r->L;
    const sq_layout_patch *P = &L->patches[p];
    const sq_layout_node *c = &L->nodes[P->corners[k]];
    sq_sep_end start;
    if (c->kind == SQ_LNODE_SINGULAR && L->role[c->id] == SQ_LROLE_TJUNCTION)
        return SQ_FAIL(err, SQ_ERR_LAYOUT, "corner is a T-junction");
    if (!lay_node_end(L, P->corners[k], &start))
        return SQ_FAIL(err, SQ_ERR_LAYOUT, "corner is not a node of the set");
    double shortest = HUGE_VAL;
    for (int j = 0; j < P->ncorners; j++) {
        int a = P->corner_half[j], b = P->corner_half[(j + 1) % P->ncorners];
        if (b <= a) b += P->nhalf;
        double len = 0.0;
        for (int h = a; h < b; h++) len += L->edges[P->half[h % P->nhalf].edge].length;
        shortest = fmin(shortest, len);
    }
    double step = r->step, xy[2] = {c->x, c->y};
    r->step = fmin(step, 0.1 * shortest);
    lay_line ln;
    sq_status st = lay_trace_line(r, xy, dir, 1e-6 * L->scale, &ln, err);
    r->step = step;
    if (st == SQ_OK) st = lay_add_line(r, &ln, start, err);
    free(ln.xy);
    if (st != SQ_OK) return st;
    if (c->kind == SQ_LNODE_CORNER) L->vertex_quads[c->id]++;
    if (c->kind == SQ_LNODE_SINGULAR) L->sing[c->id].valence++;
    return SQ_OK;
}

/* ---- repairs tried and undone when they do not help --------------------- */

typedef struct {
    sq_separatrix_set seps;
    int nsing;
    sq_singularity *sing;
    sq_lrole *role;
    int *vertex_quads;
    sq_layout_stats stats;
} snapshot;

static void snapshot_free(snapshot *s)
{
    lay_sepset_free(&s->seps);
    free(s->sing), free(s->role), free(s->vertex_quads);
    memset(s, 0, sizeof *s);
}

static sq_status snapshot_take(const sq_layout *L, snapshot *s, sq_error *err)
{
    memset(s, 0, sizeof *s);
    size_t ns = (size_t)(L->nsing > 0 ? L->nsing : 1), nv = (size_t)(L->nvertices > 0 ? L->nvertices : 1);
    s->sing = malloc(ns * sizeof *s->sing);
    s->role = malloc(ns * sizeof *s->role);
    s->vertex_quads = malloc(nv * sizeof *s->vertex_quads);
    if (!s->sing || !s->role || !s->vertex_quads) {
        snapshot_free(s);
        return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    }
    if (L->nsing > 0) { /* a layout without singular points has no arrays */
        memcpy(s->sing, L->sing, (size_t)L->nsing * sizeof *s->sing);
        memcpy(s->role, L->role, (size_t)L->nsing * sizeof *s->role);
    }
    if (L->nvertices > 0)
        memcpy(s->vertex_quads, L->vertex_quads, (size_t)L->nvertices * sizeof *s->vertex_quads);
    s->nsing = L->nsing;
    s->stats = L->stats;
    for (int k = 0; k < L->seps.n; k++) {
        const sq_separatrix *a = &L->seps.s[k];
        sq_status st = lay_sep_push(&s->seps, a->xy, a->npts, a->start, a->end, err);
        if (st != SQ_OK) {
            snapshot_free(s);
            return st;
        }
        sq_separatrix *b = &s->seps.s[k];
        b->start_angle = a->start_angle;
        b->end_angle = a->end_angle;
        b->merged = a->merged;
    }
    return SQ_OK;
}

/* Put the snapshot back into L (whose own state is freed); s is emptied. */
static void snapshot_restore(sq_layout *L, snapshot *s)
{
    lay_sepset_free(&L->seps);
    free(L->sing), free(L->role), free(L->vertex_quads);
    L->seps = s->seps;
    L->sing = s->sing;
    L->role = s->role;
    L->nsing = s->nsing;
    L->vertex_quads = s->vertex_quads;
    L->stats = s->stats;
    memset(s, 0, sizeof *s);
}

/* After a patch repair: the set-level repairs until none applies, the
 * graph rebuilt and its defects counted (*ndef; INT_MAX when the repairs
 * do not settle within SETTLE_MAX). */
#define SETTLE_MAX 200
static sq_status settle(lay_repair *r, int *ndef, sq_error *err)
{
    int done = 1, it = 0;
    *ndef = INT_MAX;
    while (done && it++ < SETTLE_MAX && r->work <= WORK_MAX) SQ_TRY(lay_set_repair(r, &done, err));
    if (done) return SQ_OK;
    SQ_TRY(lay_graph_build(r->L, r->face, r->info, err));
    sq_layout_defects d;
    *ndef = sq_layout_check(r->L, &d);
    sq_layout_defects_free(&d);
    return SQ_OK;
}

/* Each trial settles the whole set: a bound on them bounds the time a face
 * with many non-quad patches takes to be declared invalid. */
#define MAX_TRIALS 16

typedef struct {
    int patch, corner; /* corner -1: the n-quad split, -2: removing separatrix sep */
    int sep;
    double dir[2];
} candidate;

/* Apply candidate c and settle; keep it (*kept) when fewer than `before`
 * defects are left, else restore the set and its graph. */
static sq_status try_candidate(lay_repair *r, const candidate *c, int before, int *kept,
                               sq_error *err)
{
    *kept = 0;
    if (r->trials++ >= MAX_TRIALS) return SQ_OK;
    snapshot s;
    SQ_TRY(snapshot_take(r->L, &s, err));
    sq_error e2;
    int ndef = INT_MAX;
    sq_status st = c->corner >= 0    ? extra_separatrix(r, c->patch, c->corner, c->dir, &e2)
                   : c->corner == -1 ? lay_split_centre(r, c->patch, 1, &e2)
                                     : lay_remove_sep(r, c->sep, &e2);
    if (st == SQ_OK) st = settle(r, &ndef, &e2);
    if (st == SQ_ERR_INTERNAL) {
        snapshot_free(&s);
        if (err) *err = e2;
        return st;
    }
    *kept = st == SQ_OK && ndef < before;
    if (*kept) {
        snapshot_free(&s);
        return SQ_OK;
    }
    snapshot_restore(r->L, &s);
    r->hit_ok = 0;
    return lay_graph_build(r->L, r->face, r->info, err);
}

/* A patch of at most 3 corners: the separatrices bounding it removed, one
 * at a time (a sliver along the boundary, a triangle beside a singular
 * point that captured one separatrix too many); *done when one is kept. */
static sq_status remove_bounding(lay_repair *r, int p, int before, int *done, sq_error *err)
{
    sq_layout *L = r->L;
    const sq_layout_patch *P = &L->patches[p];
    int nh = P->nhalf, *seps = malloc((size_t)(nh > 0 ? nh : 1) * sizeof *seps), m = 0;
    if (!seps) return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    for (int h = 0; h < nh; h++) { /* P is rebuilt by every trial: copy first */
        int k = L->edges[P->half[h].edge].sep, seen = 0;
        for (int j = 0; j < m; j++) seen |= seps[j] == k;
        if (k >= 0 && !seen) seps[m++] = k;
    }
    sq_status st = SQ_OK;
    for (int j = 0; j < m && !*done && st == SQ_OK; j++) {
        candidate c = {p, -2, seps[j], {0.0, 0.0}};
        st = try_candidate(r, &c, before, done, err);
        if (*done) L->stats.separatrices_removed++;
    }
    free(seps);
    return st;
}

/* A patch with n != 4 corners that the triangle repairs leave (a sliver, a
 * pentagon, a hexagon, a triangle they could not mend): for n <= 3 first a
 * separatrix bounding it removed, then an extra separatrix from a corner
 * whose angle holds a cross branch, else the n-quad split; the first that
 * leaves fewer defects than `before` is kept. */
sq_status lay_repair_polygon(lay_repair *r, int before, int *done, sq_error *err)
{
    sq_layout *L = r->L;
    for (int p = 0; p < L->npatches && !*done; p++) {
        if (L->patches[p].ncycles != 1 || L->patches[p].ncorners == 4) continue;
        if (L->patches[p].ncorners <= 3) SQ_TRY(remove_bounding(r, p, before, done, err));
        if (*done) break;
        for (int k = 0; k < L->patches[p].ncorners && !*done; k++) {
            double dir[8];
            int nd = wedge_branches(r, &L->patches[p], k, dir);
            for (int j = 0; j < nd && !*done; j++) {
                candidate c = {p, k, -1, {dir[2 * j], dir[2 * j + 1]}};
                SQ_TRY(try_candidate(r, &c, before, done, err));
                if (*done) L->stats.extra_separatrices++;
            }
        }
        if (*done || L->patches[p].ncorners < 2) continue;
        candidate c = {p, -1, -1, {0.0, 0.0}};
        SQ_TRY(try_candidate(r, &c, before, done, err));
        if (*done) L->stats.polygons_split++;
    }
    return SQ_OK;
}
