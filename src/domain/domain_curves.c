/* semquad — the curves of a domain (domain.h, design 1). */
#include "domain.h"

#include <stdlib.h>
#include <string.h>

void sq_domain_free(sq_domain *d)
{
    if (d->curve_of)
        for (int f = 0; f < d->nfaces; f++) free(d->curve_of[f]);
    free(d->curve_of);
    free(d->curves);
    memset(d, 0, sizeof *d);
}

/* The earlier face's edge that is the same curve as edge e of face f
 * (*cf, *ce), or *cf = -1. */
static sq_status find_partner(const sq_domain *d, int f, int e, double tol, int *cf, int *ce,
                              int *kind, int *rev, sq_error *err)
{
    *cf = -1;
    for (int g = 0; g < f; g++)
        for (int k = 0; k < cad_face_num_edges(d->faces[g]); k++) {
            cad_shared_kind sk;
            SQ_TRY(cad_edges_shared(d->faces[g], k, d->faces[f], e, tol, &sk, rev, err));
            if (sk == CAD_SHARED_NONE) continue;
            *cf = g, *ce = k, *kind = (int)sk;
            return SQ_OK;
        }
    return SQ_OK;
}

sq_status sq_domain_build(int nfaces, const cad_face *const *faces, const sq_face_info *info,
                          double tol, sq_domain *d, sq_error *err)
{
    memset(d, 0, sizeof *d);
    d->nfaces = nfaces;
    d->faces = faces;
    d->info = info;
    int total = 0;
    for (int f = 0; f < nfaces; f++) total += cad_face_num_edges(faces[f]);
    d->curves = calloc((size_t)total + 1, sizeof *d->curves);
    d->curve_of = calloc((size_t)nfaces + 1, sizeof *d->curve_of);
    if (!d->curves || !d->curve_of) return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    sq_status st = SQ_OK;
    for (int f = 0; f < nfaces && st == SQ_OK; f++) {
        int ne = cad_face_num_edges(faces[f]);
        if (!(d->curve_of[f] = malloc(sizeof(int) * ((size_t)ne + 1))))
            return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
        for (int e = 0; e < ne && st == SQ_OK; e++) {
            int g, k, kind = 0, rev = 0;
            st = find_partner(d, f, e, tol, &g, &k, &kind, &rev, err);
            if (st != SQ_OK) break;
            int c = g >= 0 ? d->curve_of[g][k] : d->ncurves;
            if (g >= 0 && d->curves[c].face[1] >= 0)
                return SQ_FAIL(err, SQ_ERR_GEOMETRY,
                               "edge %d of face %d is shared by three faces (a 2D domain has at "
                               "most two on each curve)",
                               k, g);
            if (g < 0) d->curves[d->ncurves++] = (sq_domain_curve){{f, -1}, {e, -1}, 0, 0, -1};
            else d->curves[c].face[1] = f, d->curves[c].edge[1] = e, d->curves[c].reversed = rev,
                 d->curves[c].kind = kind;
            d->curve_of[f][e] = c;
        }
    }
    /* boundary tags in the order of the curves: faces, then their edges */
    for (int c = 0; c < d->ncurves; c++) {
        if (d->curves[c].face[1] >= 0) d->ninterfaces++;
        else d->curves[c].tag = d->ntags++;
    }
    return st;
}

int sq_domain_face_shares(const sq_domain *d, int f)
{
    for (int e = 0; e < cad_face_num_edges(d->faces[f]); e++)
        if (d->curves[d->curve_of[f][e]].face[1] >= 0) return 1;
    return 0;
}
