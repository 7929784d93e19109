#include "separatrix.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

void sq_separatrix_set_free(sq_separatrix_set *set)
{
    if (!set) return;
    for (int k = 0; k < set->n; k++) free(set->s[k].xy);
    free(set->s);
    memset(set, 0, sizeof *set);
}

sq_status sq_separatrix_set_append(sq_separatrix_set *set, sq_separatrix *s, sq_error *err)
{
    if (set->n == set->cap) {
        int cap = set->cap ? 2 * set->cap : 16;
        sq_separatrix *ns = realloc(set->s, (size_t)cap * sizeof *ns);
        if (!ns) return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory (%d separatrices)", cap);
        set->s = ns;
        set->cap = cap;
    }
    set->s[set->n++] = *s;
    memset(s, 0, sizeof *s);
    return SQ_OK;
}

double sq_separatrix_length(const sq_separatrix *s)
{
    double l = 0.0;
    for (int i = 1; i < s->npts; i++)
        l += hypot(s->xy[2 * i] - s->xy[2 * i - 2], s->xy[2 * i + 1] - s->xy[2 * i - 1]);
    return l;
}
