/* semquad — removing a separatrix that bounds a non-quad patch (Jezdimirović
 * 2021 §6: separatrices are added and removed until the layout is valid):
 * one that runs along the boundary and leaves a 1- or 2-corner sliver, or
 * one captured by a singular point that already has its valence of them. */
#include "repair_private.h"

#include <stdlib.h>
#include <string.h>

int lay_ends_at(const sq_layout *L, int t, int *ids, int *ends, int max)
{
    int m = 0;
    for (int k = 0; k < L->seps.n; k++)
        for (int w = 0; w < 2; w++) {
            const sq_sep_end *e = w ? &L->seps.s[k].end : &L->seps.s[k].start;
            if (e->kind != SQ_END_SINGULAR || e->id != t) continue;
            if (m < max) ids[m] = k, ends[m] = w;
            m++;
        }
    return m;
}

/* The two separatrices left at inserted node t joined into one through t
 * (t then ends none). */
static sq_status join_at(sq_layout *L, int t, sq_error *err)
{
    int ids[2], ends[2];
    if (lay_ends_at(L, t, ids, ends, 2) != 2 || ids[0] == ids[1]) return SQ_OK;
    const sq_separatrix *a = &L->seps.s[ids[0]], *b = &L->seps.s[ids[1]];
    int n = a->npts + b->npts - 1;
    double *xy = malloc(2 * (size_t)n * sizeof *xy);
    if (!xy) return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    /* a towards t (reversed if it starts there), then b away from t */
    for (int i = 0; i < a->npts; i++) {
        int j = ends[0] ? i : a->npts - 1 - i;
        xy[2 * i] = a->xy[2 * j], xy[2 * i + 1] = a->xy[2 * j + 1];
    }
    for (int i = 1; i < b->npts; i++) {
        int j = ends[1] ? b->npts - 1 - i : i;
        xy[2 * (a->npts - 1 + i)] = b->xy[2 * j], xy[2 * (a->npts - 1 + i) + 1] = b->xy[2 * j + 1];
    }
    sq_sep_end s0 = ends[0] ? a->start : a->end, s1 = ends[1] ? b->start : b->end;
    sq_status st = lay_sep_push(&L->seps, xy, n, s0, s1, err);
    free(xy);
    if (st != SQ_OK) return st;
    lay_sep_remove(&L->seps, ids[0] > ids[1] ? ids[0] : ids[1]);
    lay_sep_remove(&L->seps, ids[0] > ids[1] ? ids[1] : ids[0]);
    return SQ_OK;
}

sq_status lay_remove_sep(lay_repair *r, int k, sq_error *err)
{
    sq_layout *L = r->L;
    const sq_sep_end e[2] = {L->seps.s[k].start, L->seps.s[k].end};
    if (e[0].kind == SQ_END_SINGULAR && e[1].kind == SQ_END_SINGULAR && e[0].id == e[1].id)
        return SQ_FAIL(err, SQ_ERR_LAYOUT, "separatrix %d is a loop", k);
    /* admissible only if every node it ends at stays what it is: a singular
     * point keeps its valence of separatrices, an inserted node (T-junction,
     * crossing, midpoint) of three ends keeps two, joined through it */
    for (int w = 0; w < 2; w++) {
        if (e[w].kind != SQ_END_SINGULAR) continue;
        int ids[8], ends[8], m = lay_ends_at(L, e[w].id, ids, ends, 8);
        if (L->role[e[w].id] == SQ_LROLE_INPUT ? m <= L->sing[e[w].id].valence : m != 3)
            return SQ_FAIL(err, SQ_ERR_LAYOUT, "separatrix %d is needed at its end %d", k, w);
    }
    lay_sep_remove(&L->seps, k);
    for (int w = 0; w < 2; w++) {
        if (e[w].kind == SQ_END_CORNER && L->vertex_quads[e[w].id] > 1) L->vertex_quads[e[w].id]--;
        if (e[w].kind == SQ_END_SINGULAR && L->role[e[w].id] != SQ_LROLE_INPUT)
            SQ_TRY(join_at(L, e[w].id, err));
    }
    r->hit_ok = 0;
    return SQ_OK;
}
