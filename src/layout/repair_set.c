/* semquad — the repairs of the separatrix set (Jezdimirović 2021 journal
 * §6.1, §6.3), which need no patches: duplicates removed, ends on another
 * separatrix made T-junctions, limit cycles cut, single crossings made
 * valence-4 nodes, T-junctions continued across; for the all-quad last
 * resort, every crossing made a node at once and open pieces removed. */
#include "repair_private.h"

#include <math.h>
#include <stdlib.h>

long lay_set_points(const sq_separatrix_set *S)
{
    long n = 0;
    for (int i = 0; i < S->n; i++) n += S->s[i].npts;
    return n;
}

/* The crossings of the separatrix set, found once per state of the set
 * (the repairs tried in turn on an unchanged set share them). */
static sq_status crossings(lay_repair *r, sq_error *err)
{
    if (r->hit_ok) return SQ_OK;
    free(r->hit);
    r->hit = NULL;
    r->nhit = 0;
    SQ_TRY(lay_intersections(&r->L->seps, r->tol, &r->hit, &r->nhit, err));
    r->hit_ok = 1;
    return SQ_OK;
}

static int same_end(const sq_sep_end *a, const sq_sep_end *b, double tol)
{
    if (a->kind != b->kind || a->id != b->id) return 0;
    if (a->kind == SQ_END_BOUNDARY) return fabs(a->s - b->s) <= tol;
    return a->kind != SQ_END_OPEN;
}

/* Duplicated separatrices: same ends, every point of one within 2 % of the
 * face size of the other (Jezdimirović §6.1, Fig. 15). */
static sq_status remove_duplicate(lay_repair *r, int *done, sq_error *err)
{
    (void)err;
    sq_separatrix_set *S = &r->L->seps;
    double close = 0.02 * r->L->scale, tol = 1e-6 * r->L->scale;
    for (int a = 0; a < S->n; a++)
        for (int b = a + 1; b < S->n; b++) {
            const sq_separatrix *A = &S->s[a], *B = &S->s[b];
            int same = (same_end(&A->start, &B->start, tol) && same_end(&A->end, &B->end, tol)) ||
                       (same_end(&A->start, &B->end, tol) && same_end(&A->end, &B->start, tol));
            if (!same) continue;
            /* stop at the first point farther than `close` (most pairs
             * with the same ends are not duplicates) */
            double worst = 0.0, d;
            for (int j = 0; j < A->npts && worst <= close; j++) {
                lay_nearest_pos(B, &A->xy[2 * j], &d);
                worst = fmax(worst, d);
            }
            for (int j = 0; j < B->npts && worst <= close; j++) {
                lay_nearest_pos(A, &B->xy[2 * j], &d);
                worst = fmax(worst, d);
            }
            if (worst > close) continue;
            /* keep a merged one if there is one */
            lay_sep_remove(S, A->merged && !B->merged ? b : a);
            r->L->stats.duplicates_removed++;
            *done = 1;
            return SQ_OK;
        }
    return SQ_OK;
}

/* Ends that stop on another separatrix (open ends the graph finds on a
 * curve, the tracer's SQ_END_SEPARATRIX) become T-junction nodes. */
static sq_status make_tjunction(lay_repair *r, int *done, sq_error *err)
{
    sq_layout *L = r->L;
    SQ_TRY(crossings(r, err));
    const lay_hit *h = r->hit;
    const int nh = r->nhit;
    sq_status st = SQ_OK;
    for (int k = 0; k < nh && !*done; k++) {
        int stem = -1, other = -1, end = -1;
        double pos = 0;
        if (h[k].enda >= 0 && h[k].endb < 0) {
            stem = h[k].a, other = h[k].b, end = h[k].enda, pos = h[k].pb;
        } else if (h[k].endb >= 0 && h[k].enda < 0) {
            stem = h[k].b, other = h[k].a, end = h[k].endb, pos = h[k].pa;
        } else {
            continue;
        }
        sq_separatrix *s = &L->seps.s[stem];
        sq_sep_end *e = end ? &s->end : &s->start;
        if (e->kind != SQ_END_OPEN && e->kind != SQ_END_SEPARATRIX) continue;
        double p[2] = {h[k].x, h[k].y};
        st = lay_sing_push(L, p[0], p[1], 3, SQ_LROLE_TJUNCTION, err);
        if (st != SQ_OK) break;
        e->kind = SQ_END_SINGULAR;
        e->id = L->nsing - 1;
        st = lay_split_sep(L, other, pos, p, L->nsing - 1, err);
        *done = 1;
    }
    return st;
}

/* Limit cycles: an open separatrix, or one crossing itself or another one
 * twice; cut at its first near-orthogonal crossing (else the most
 * orthogonal one), leaving a T-junction (Jezdimirović §6.1, Fig. 16). */
static sq_status cut_limit_cycle(lay_repair *r, int *done, sq_error *err)
{
    sq_layout *L = r->L;
    SQ_TRY(crossings(r, err));
    const lay_hit *h = r->hit;
    const int nh = r->nhit;
    sq_status st = SQ_OK;
    int n = L->seps.n;
    /* seen[o] == k + 1: k already crosses o (one pass over the crossings
     * per separatrix, not one per pair of them: faces with many holes have
     * 10^4 crossings before the repairs) */
    int *seen = calloc((size_t)n + 1, sizeof *seen);
    if (!seen) return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    for (int k = 0; k < n && !*done && st == SQ_OK; k++) {
        const sq_separatrix *s = &L->seps.s[k];
        int lc = s->end.kind == SQ_END_OPEN;
        for (int a = 0; a < nh && !lc; a++) {
            if (h[a].enda >= 0 || h[a].endb >= 0 || (h[a].a != k && h[a].b != k)) continue;
            int o = h[a].a == k ? h[a].b : h[a].a;
            lc = o == k || seen[o] == k + 1;
            seen[o] = k + 1;
        }
        if (!lc) continue;
        /* the cut: first crossing along k with |cos| < 0.5, else the most
         * orthogonal; the cut point's position on k and on the other */
        int best = -1, good = -1;
        double bestpos = HUGE_VAL, goodpos = HUGE_VAL, bestcos = 2.0;
        for (int a = 0; a < nh; a++) {
            if (h[a].enda >= 0 || h[a].endb >= 0) continue;
            if (h[a].a != k && h[a].b != k) continue;
            double posk = h[a].a == k ? h[a].pa : h[a].pb;
            if (h[a].a == k && h[a].b == k) posk = fmax(h[a].pa, h[a].pb);
            if (h[a].cosang < 0.5 && posk < goodpos) {
                goodpos = posk;
                good = a;
            }
            if (h[a].cosang < bestcos) {
                bestcos = h[a].cosang;
                best = a;
                bestpos = posk;
            }
        }
        int c = good >= 0 ? good : best;
        double posk = good >= 0 ? goodpos : bestpos;
        if (c < 0) continue; /* open but crossing nothing: left for the report */
        int other = h[c].a == k ? h[c].b : h[c].a;
        double poso = h[c].a == k ? h[c].pb : h[c].pa;
        if (other == k) poso = fmin(h[c].pa, h[c].pb);
        double p[2] = {h[c].x, h[c].y};
        st = lay_sing_push(L, p[0], p[1], 3, SQ_LROLE_TJUNCTION, err);
        if (st != SQ_OK) break;
        int node = L->nsing - 1;
        /* truncate k at posk */
        sq_separatrix *sk = &L->seps.s[k];
        int j = (int)floor(posk);
        if (j >= sk->npts - 1) j = sk->npts - 2;
        sk->npts = j + 2;
        sk->xy[2 * (j + 1)] = p[0];
        sk->xy[2 * (j + 1) + 1] = p[1];
        sk->end = (sq_sep_end){SQ_END_SINGULAR, node, 0.0};
        st = lay_split_sep(L, other, poso, p, node, err);
        L->stats.limit_cycles_cut++;
        *done = 1;
    }
    free(seen);
    return st;
}

/* Two separatrices crossing once: a regular node of valence 4 where both
 * are split (the patches around it are checked by their angles). */
static sq_status split_crossing(lay_repair *r, int *done, sq_error *err)
{
    sq_layout *L = r->L;
    SQ_TRY(crossings(r, err));
    const lay_hit *h = r->hit;
    const int nh = r->nhit;
    sq_status st = SQ_OK;
    for (int k = 0; k < nh && !*done; k++) {
        if (h[k].enda >= 0 || h[k].endb >= 0 || h[k].a == h[k].b) continue;
        double p[2] = {h[k].x, h[k].y};
        st = lay_sing_push(L, p[0], p[1], 4, SQ_LROLE_CROSSING, err);
        if (st != SQ_OK) break;
        int node = L->nsing - 1;
        int a = h[k].a, b = h[k].b;
        double pa = h[k].pa, pb = h[k].pb;
        st = lay_split_sep(L, a, pa, p, node, err);
        if (st == SQ_OK) st = lay_split_sep(L, b, pb, p, node, err);
        L->stats.crossings_split++;
        *done = 1;
    }
    return st;
}

/* T-junction repair: continue the stem across the separatrix it ends on,
 * along the field, to the boundary or the next separatrix (Jezdimirović
 * §6.3, Fig. 17); the T becomes a regular valence-4 node. */
static sq_status repair_tjunction(lay_repair *r, int *done, sq_error *err)
{
    sq_layout *L = r->L;
    for (int t = 0; t < L->nsing && !*done; t++) {
        if (L->role[t] != SQ_LROLE_TJUNCTION) continue;
        /* the three separatrix ends at t; the stem is the one not in the most
         * opposite pair */
        int ids[3], ends[3];
        if (lay_ends_at(L, t, ids, ends, 3) != 3) continue;
        double d[3][2];
        for (int k = 0; k < 3; k++) lay_leave_dir(&L->seps.s[ids[k]], ends[k], d[k], L->scale);
        int stem = 0;
        double best = 2.0;
        for (int k = 0; k < 3; k++) {
            const double *a = d[(k + 1) % 3], *b = d[(k + 2) % 3];
            double dot = a[0] * b[0] + a[1] * b[1];
            if (dot < best) {
                best = dot;
                stem = k;
            }
        }
        double dir[2] = {-d[stem][0], -d[stem][1]}, p[2] = {L->sing[t].x, L->sing[t].y};
        /* where the field line runs out of its length (a thin patch's
         * tiny steps, a line circling without meeting anything), the
         * straight ray: the shortest connection to the opposite side; not
         * past the repair lines' work bound, which ends the repairs */
        lay_line ln;
        sq_error e2, e3;
        sq_status st = lay_trace_line(r, p, dir, 1e-6 * L->scale, &ln, &e2), st2 = st;
        if (st == SQ_ERR_LAYOUT && r->lwork <= LINE_WORK_MAX) { /* else e2 is the error */
            free(ln.xy);
            st2 = lay_ray_line(r, p, dir, 1e-6 * L->scale, &ln, &e3);
            if (st2 == SQ_OK) L->stats.straight_stems++;
            if (st2 == SQ_ERR_INTERNAL) st = st2, e2 = e3; /* else the field line's reason */
        }
        if (st2 != SQ_OK && err) *err = e2;
        st = st2 == SQ_OK ? SQ_OK : st;
        if (st == SQ_OK) st = lay_add_line(r, &ln, (sq_sep_end){SQ_END_SINGULAR, t, 0.0}, err);
        free(ln.xy);
        if (st != SQ_OK) return st;
        L->role[t] = SQ_LROLE_CROSSING;
        L->sing[t].valence = 4;
        L->stats.t_junctions++;
        *done = 1;
    }
    return SQ_OK;
}

/* One set-level repair, the first that applies (*done). */
sq_status lay_set_repair(lay_repair *r, int *done, sq_error *err)
{
    *done = 0;
    r->hit_ok = 0;
    r->work += (double)lay_set_points(&r->L->seps);
    SQ_TRY(remove_duplicate(r, done, err));
    if (!*done) SQ_TRY(make_tjunction(r, done, err));
    if (!*done) SQ_TRY(cut_limit_cycle(r, done, err));
    if (!*done) SQ_TRY(split_crossing(r, done, err));
    if (!*done) SQ_TRY(repair_tjunction(r, done, err));
    return SQ_OK;
}

/* The piece of the set that came from separatrix `orig` (from[]) and holds
 * p inside it (not at an end), and p's position on it; -1 if none. */
static int piece_through(const sq_layout *L, const int *from, int orig, const double p[2],
                         double tol, double *pos)
{
    int best = -1;
    double bd = tol;
    for (int k = 0; k < L->seps.n; k++) {
        if (from[k] != orig) continue;
        double d, q = lay_nearest_pos(&L->seps.s[k], p, &d);
        if (d <= bd && q > 1e-9 && q < L->seps.s[k].npts - 1 - 1e-9) best = k, bd = d, *pos = q;
    }
    return best;
}

sq_status lay_set_untangle(lay_repair *r, sq_error *err)
{
    sq_layout *L = r->L;
    r->hit_ok = 0;
    SQ_TRY(crossings(r, err));
    int *from = malloc((size_t)(L->seps.n + 2 * r->nhit + 1) * sizeof *from);
    if (!from) return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    for (int k = 0; k < L->seps.n; k++) from[k] = k;
    sq_status st = SQ_OK;
    for (int c = 0; c < r->nhit && st == SQ_OK; c++) {
        const lay_hit *h = &r->hit[c];
        if (h->enda >= 0 || h->endb >= 0) continue;
        double p[2] = {h->x, h->y}, pa = 0.0, pb = 0.0;
        int ka = piece_through(L, from, h->a, p, 1e3 * r->tol, &pa);
        if (ka < 0) continue;
        st = lay_sing_push(L, p[0], p[1], 4, SQ_LROLE_CROSSING, err);
        int node = L->nsing - 1;
        if (st == SQ_OK) st = lay_split_sep(L, ka, pa, p, node, err);
        if (st != SQ_OK) break;
        from[L->seps.n - 1] = h->a;
        /* a self-crossing's second passage is inside another piece now */
        int kb = piece_through(L, from, h->b, p, 1e3 * r->tol, &pb);
        if (kb >= 0) st = lay_split_sep(L, kb, pb, p, node, err);
        if (kb >= 0 && st == SQ_OK) from[L->seps.n - 1] = h->b;
        L->stats.crossings_split++;
    }
    free(from);
    /* a piece that ends open dangles into a patch: no side of any */
    for (int k = L->seps.n - 1; k >= 0 && st == SQ_OK; k--)
        if (L->seps.s[k].start.kind == SQ_END_OPEN || L->seps.s[k].end.kind == SQ_END_OPEN) {
            lay_sep_remove(&L->seps, k);
            L->stats.separatrices_removed++;
        }
    r->hit_ok = 0;
    return st;
}
