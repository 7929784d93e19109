/* semquad — triangular patches: the boundary valence-2 split (Jezdimirović
 * 2021 §6.3, Fig. 18) and midpoint division (Marcon 2019 §3.4, Fig. 13). */
#include "repair_private.h"

/* Triangular patch: midpoint division (Marcon §3.4, Fig. 13), the n-quad
 * split with n = 3; a midpoint on a separatrix is a T-junction repaired
 * next. */
sq_status lay_split_triangle(lay_repair *r, int *done, sq_error *err)
{
    sq_layout *L = r->L;
    for (int p = 0; p < L->npatches && !*done; p++) {
        const sq_layout_patch *P = &L->patches[p];
        if (P->ncorners != 3 || P->ncycles != 1) continue;
        sq_error e2;
        sq_status st = lay_split_centre(r, p, 0, &e2);
        if (st == SQ_ERR_LAYOUT) continue; /* left to lay_repair_polygon */
        if (st != SQ_OK) {
            if (err) *err = e2;
            return st;
        }
        L->stats.triangles_repaired++;
        *done = 1;
    }
    return SQ_OK;
}

/* The half-edge (index into P->half) leaving a boundary valence-2 point on
 * P's cycle that is not a corner of P, or -1: a face vertex taking one quad
 * with no separatrix at it. */
static int valence2_half(const sq_layout *L, const sq_layout_patch *P)
{
    for (int h = 0; h < P->nhalf; h++) {
        const sq_layout_edge *E = &L->edges[P->half[h].edge];
        int v = P->half[h].reversed ? E->n1 : E->n0;
        const sq_layout_node *n = &L->nodes[v];
        if (n->kind != SQ_LNODE_CORNER || L->vertex_quads[n->id] != 1 || n->degree != 2) continue;
        int corner = 0;
        for (int k = 0; k < P->ncorners; k++) corner |= P->corners[k] == v;
        if (!corner) return h;
    }
    return -1;
}

/* Boundary valence-2 point (Jezdimirović 2021 §6.2–6.3, Fig. 18): a face
 * vertex taking one quad (two mesh edges) where the boundary is nearly
 * straight, so that its patch, a quadrilateral in topology, has only three
 * geometric corners.  It is split into two valence-3 points: a valence-3
 * node imposed at the barycentre of the patch, joined by a spoke to the
 * vertex (which then has three edges and takes two quads, a regular
 * boundary point) and by spokes to the midpoints of the two sides away from
 * it, so that the triangle becomes three quads; the index is kept (1/4 at
 * the vertex before, 1/4 at the node after).  Marcon's midpoint division
 * would put a foot beside the vertex instead and leave it a corner of no
 * patch. */
sq_status lay_split_valence2(lay_repair *r, int *done, sq_error *err)
{
    sq_layout *L = r->L;
    for (int p = 0; p < L->npatches && !*done; p++) {
        const sq_layout_patch *P = &L->patches[p];
        if (P->ncorners != 3 || P->ncycles != 1) continue;
        int h = valence2_half(L, P);
        if (h < 0) continue;
        /* side k (corner k to corner k+1) holding the vertex */
        int side = 0;
        for (int k = 0; k < 3; k++) {
            int a = P->corner_half[k], b = P->corner_half[(k + 1) % 3];
            if (b <= a) b += P->nhalf;
            if ((h > a && h < b) || (h + P->nhalf > a && h + P->nhalf < b)) side = k;
        }
        const sq_layout_edge *E = &L->edges[P->half[h].edge];
        const sq_layout_node *V = &L->nodes[P->half[h].reversed ? E->n1 : E->n0];
        int vid = V->id;
        double vxy[2] = {V->x, V->y}, mid[2][2], cen[2];
        int medge[2];
        double mfrac[2];
        for (int j = 0; j < 2; j++)
            SQ_TRY(lay_side_point(r, P, (side + 1 + j) % 3, 0.5, &medge[j], &mfrac[j], mid[j], err));
        if (!lay_patch_centroid(L, P, cen)) {
            cen[0] = (vxy[0] + mid[0][0] + mid[1][0]) / 3.0;
            cen[1] = (vxy[1] + mid[0][1] + mid[1][1]) / 3.0;
        }
        SQ_TRY(lay_sing_push(L, cen[0], cen[1], 3, SQ_LROLE_VALENCE2, err));
        int M = L->nsing - 1;
        const sq_sep_end from_m = {SQ_END_SINGULAR, M, 0.0};
        SQ_TRY(lay_straight_sep(L, from_m, cen, vxy, (sq_sep_end){SQ_END_CORNER, vid, 0.0}, err));
        for (int j = 0; j < 2; j++)
            SQ_TRY(lay_add_spoke(r, from_m, cen, NULL, 0, medge[j], mfrac[j], mid[j], err));
        L->vertex_quads[vid] = 2;
        L->stats.valence2_split++;
        *done = 1;
    }
    return SQ_OK;
}
