/* semquad — validation of a layout (layout.h; issue "Must show"): four
 * corners per patch, each singular point of valence V a corner of V
 * patches, each face vertex with n quads a corner of n patches, areas
 * summing to the face area, no crossing, no dangling end, no T-junction. */
#include "layout_internal.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static void add(sq_layout_defects *d, sq_defect_kind kind, int index, const char *fmt, ...)
{
    d->count[kind]++;
    if (d->n == d->cap) {
        int c = d->cap ? 2 * d->cap : 16;
        sq_layout_defect *q = realloc(d->d, (size_t)c * sizeof *q);
        if (!q) return; /* counted, not described */
        d->d = q;
        d->cap = c;
    }
    sq_layout_defect *x = &d->d[d->n++];
    x->kind = kind;
    x->index = index;
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(x->msg, sizeof x->msg, fmt, ap);
    va_end(ap);
}

void sq_layout_defects_free(sq_layout_defects *d)
{
    if (!d) return;
    free(d->d);
    memset(d, 0, sizeof *d);
}

int sq_layout_check(const sq_layout *L, sq_layout_defects *d)
{
    memset(d, 0, sizeof *d);
    int *corners = calloc((size_t)(L->nnodes > 0 ? L->nnodes : 1), sizeof *corners);
    int *nsep = calloc((size_t)(L->nnodes > 0 ? L->nnodes : 1), sizeof *nsep);
    if (!corners || !nsep) {
        free(corners);
        free(nsep);
        add(d, SQ_DEFECT_AREA, -1, "out of memory while checking");
        return d->n;
    }
    double sum = 0.0;
    for (int p = 0; p < L->npatches; p++) {
        const sq_layout_patch *P = &L->patches[p];
        sum += P->area;
        for (int k = 0; k < P->ncorners; k++) corners[P->corners[k]]++;
        if (P->ncycles > 1)
            add(d, SQ_DEFECT_ANNULAR, p, "patch %d has %d boundary cycles (annular)", p,
                P->ncycles);
        if (P->ncorners != 4)
            add(d, SQ_DEFECT_CORNERS, p, "patch %d has %d corners", p, P->ncorners);
    }
    for (int e = 0; e < L->nedges; e++)
        if (L->edges[e].sep >= 0) {
            nsep[L->edges[e].n0]++;
            nsep[L->edges[e].n1]++;
        }
    for (int v = 0; v < L->nnodes; v++) {
        const sq_layout_node *n = &L->nodes[v];
        switch (n->kind) {
        case SQ_LNODE_SINGULAR:
            if (L->role[n->id] == SQ_LROLE_TJUNCTION) {
                add(d, SQ_DEFECT_TJUNCTION, v, "T-junction at (%.6g, %.6g)", n->x, n->y);
            } else if (corners[v] != n->valence) {
                add(d, SQ_DEFECT_SINGULAR, v,
                    "singular point %d of valence %d at (%.6g, %.6g) is a corner of %d patches",
                    n->id, n->valence, n->x, n->y, corners[v]);
            }
            break;
        case SQ_LNODE_CORNER: {
            const int q = n->valence;
            int want = q;
            /* a smooth junction no separatrix leaves is no corner at all */
            if (nsep[v] == 0 && q == 2) want = 0;
            if (q == 0) {
                if (corners[v] > 0)
                    add(d, SQ_DEFECT_VERTEX, v,
                        "face vertex %d at (%.6g, %.6g) takes 0 quads (degenerate block)", n->id,
                        n->x, n->y);
            } else if (corners[v] != want) {
                add(d, SQ_DEFECT_VERTEX, v,
                    "face vertex %d at (%.6g, %.6g) with %d quads is a corner of %d patches",
                    n->id, n->x, n->y, q, corners[v]);
            }
            break;
        }
        case SQ_LNODE_FOOT:
            if (corners[v] != nsep[v] + 1)
                add(d, SQ_DEFECT_FOOT, v,
                    "foot of %d separatrices on edge %d at (%.6g, %.6g) is a corner of %d patches",
                    nsep[v], n->id, n->x, n->y, corners[v]);
            break;
        case SQ_LNODE_CROSSING:
            add(d, SQ_DEFECT_CROSSING, v, "separatrices cross at (%.6g, %.6g)", n->x, n->y);
            break;
        case SQ_LNODE_OPEN:
            if (n->degree <= 1)
                add(d, SQ_DEFECT_OPEN, v, "separatrix %d ends open at (%.6g, %.6g)", n->id, n->x,
                    n->y);
            else
                add(d, SQ_DEFECT_TJUNCTION, v, "separatrix %d ends on another at (%.6g, %.6g)",
                    n->id, n->x, n->y);
            break;
        }
    }
    if (fabs(sum - L->face_area) > 1e-9 * fabs(L->face_area))
        add(d, SQ_DEFECT_AREA, -1, "patch areas sum to %.12g, the face's area is %.12g", sum,
            L->face_area);
    free(corners);
    free(nsep);
    return d->n;
}

void sq_layout_defects_summary(const sq_layout_defects *d, char *buf, int n)
{
    if (n <= 0) return;
    buf[0] = '\0';
    if (d->n == 0) {
        snprintf(buf, (size_t)n, "valid");
        return;
    }
    /* patches by corner count */
    int len = 0;
    const char *sep = "";
    int bycorner[9] = {0};
    for (int k = 0; k < d->n; k++)
        if (d->d[k].kind == SQ_DEFECT_CORNERS) {
            int c = 0;
            sscanf(d->d[k].msg, "patch %*d has %d corners", &c);
            bycorner[c < 8 ? c : 8]++;
        }
    for (int c = 0; c <= 8 && len < n; c++)
        if (bycorner[c]) {
            len += snprintf(buf + len, (size_t)(n - len), "%s%d patch%s with %s%d corners", sep,
                            bycorner[c], bycorner[c] > 1 ? "es" : "", c == 8 ? ">= " : "", c);
            sep = ", ";
        }
    static const char *names[SQ_DEFECT_NKINDS] = {
        NULL, "annular patch", "singular point with wrong corner count",
        "face vertex with wrong corner count", "foot with wrong corner count",
        "area mismatch", "crossing", "open separatrix", "T-junction"};
    for (int k = 1; k < SQ_DEFECT_NKINDS && len < n; k++)
        if (d->count[k]) {
            len += snprintf(buf + len, (size_t)(n - len), "%s%d %s%s", sep, d->count[k], names[k],
                            d->count[k] > 1 ? "s" : "");
            sep = ", ";
        }
}
