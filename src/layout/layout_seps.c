/* semquad — the layout's own copies of the separatrix set and of the
 * singular points, which the repairs extend: push, remove, free; the
 * amortized growth of the layout's arrays. */
#include "layout_internal.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

void *lay_grow(void *p, int *cap, int need, size_t size)
{
    if (need <= *cap) return p;
    int c = *cap > 0 ? *cap : 8;
    while (c < need) c *= 2;
    void *q = realloc(p, (size_t)c * size);
    if (q) *cap = c;
    return q;
}

sq_status lay_sep_push(sq_separatrix_set *set, const double *xy, int npts, sq_sep_end start,
                       sq_sep_end end, sq_error *err)
{
    sq_separatrix *s = lay_grow(set->s, &set->cap, set->n + 1, sizeof *s);
    if (!s) return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    set->s = s;
    sq_separatrix *t = &s[set->n];
    memset(t, 0, sizeof *t);
    t->xy = malloc(2 * (size_t)(npts > 0 ? npts : 1) * sizeof *t->xy);
    if (!t->xy) return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    memcpy(t->xy, xy, 2 * (size_t)npts * sizeof *xy);
    t->npts = npts;
    t->start = start;
    t->end = end;
    t->start_angle = npts > 1 ? atan2(xy[3] - xy[1], xy[2] - xy[0]) : 0.0;
    set->n++;
    return SQ_OK;
}

void lay_sep_remove(sq_separatrix_set *set, int k)
{
    free(set->s[k].xy);
    memmove(&set->s[k], &set->s[k + 1], (size_t)(set->n - k - 1) * sizeof *set->s);
    set->n--;
}

void lay_sepset_free(sq_separatrix_set *set)
{
    if (!set) return;
    for (int k = 0; k < set->n; k++) free(set->s[k].xy);
    free(set->s);
    memset(set, 0, sizeof *set);
}

sq_status lay_sing_push(sq_layout *L, double x, double y, int valence, sq_lrole role,
                        sq_error *err)
{
    sq_singularity *s = realloc(L->sing, (size_t)(L->nsing + 1) * sizeof *s);
    if (!s) return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    L->sing = s;
    sq_lrole *r = realloc(L->role, (size_t)(L->nsing + 1) * sizeof *r);
    if (!r) return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    L->role = r;
    s[L->nsing] = (sq_singularity){x, y, valence, SQ_ORIGIN_MIDPOINT};
    r[L->nsing] = role;
    L->nsing++;
    return SQ_OK;
}
