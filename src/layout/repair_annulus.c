/* semquad — annular patches (several cycles, no corner) cut along field
 * lines from the outer cycle. */
#include "repair_private.h"

#include <math.h>
#include <stdlib.h>

/* Annular patch (several cycles, no corner): cut along field lines from its
 * outer cycle, at four points (one per quarter of its length) where the
 * field is best aligned with the inward normal. */
sq_status lay_cut_annulus(lay_repair *r, int *done, sq_error *err)
{
    sq_layout *L = r->L;
    for (int p = 0; p < L->npatches && !*done; p++) {
        const sq_layout_patch *P = &L->patches[p];
        if (P->ncycles < 2 || P->ncorners != 0) continue;
        int nh = P->cycle_start[1];
        double tot = 0.0;
        for (int k = 0; k < nh; k++) tot += L->edges[P->half[k].edge].length;
        enum { NCUT = 4, NS = 64 };
        int ncut = 0;
        for (int q = 0; q < NCUT; q++) {
            double bestal = -2.0, bp[2] = {0, 0}, bd[2] = {0, 0};
            sq_sep_end bstart = {SQ_END_OPEN, -1, 0.0};
            for (int i = 0; i < NS; i++) {
                double target = tot * (q + (i + 0.5) / NS) / NCUT, acc = 0.0;
                for (int k = 0; k < nh; k++) {
                    const sq_layout_edge *E = &L->edges[P->half[k].edge];
                    if (acc + E->length < target && k < nh - 1) {
                        acc += E->length;
                        continue;
                    }
                    if (E->cad_edge < 0) break; /* only boundary starts */
                    double f = (target - acc) / E->length;
                    if (P->half[k].reversed) f = 1.0 - f;
                    double s = E->s0 + f * (E->s1 - E->s0), x[2], t[2];
                    SQ_TRY(cad_face_edge_eval(r->face, E->cad_edge, s, x, t, NULL, err));
                    double nrm[2] = {-t[1], t[0]}, b[2]; /* the face is on the left */
                    if (P->half[k].reversed) nrm[0] = -nrm[0], nrm[1] = -nrm[1];
                    double xin[2] = {x[0] + 1e-3 * r->step * nrm[0],
                                     x[1] + 1e-3 * r->step * nrm[1]};
                    int el = -1;
                    if (lay_branch(r, xin, &el, nrm, b)) break;
                    /* alignment, ties going to the middle of the quarter */
                    double al = b[0] * nrm[0] + b[1] * nrm[1] -
                                1e-3 * fabs(i + 0.5 - 0.5 * NS) / NS;
                    if (al > bestal) {
                        bestal = al;
                        bp[0] = x[0];
                        bp[1] = x[1];
                        bd[0] = nrm[0];
                        bd[1] = nrm[1];
                        bstart = (sq_sep_end){SQ_END_BOUNDARY, E->cad_edge, s};
                    }
                    break;
                }
            }
            if (bstart.kind != SQ_END_BOUNDARY) continue;
            lay_line ln;
            sq_status st = lay_trace_line(r, bp, bd, 1e-6 * L->scale, &ln, err);
            if (st == SQ_OK) st = lay_add_line(r, &ln, bstart, err);
            free(ln.xy);
            if (st != SQ_OK) return st;
            ncut++;
        }
        if (ncut > 0) {
            L->stats.annuli_cut++;
            *done = 1;
        }
    }
    return SQ_OK;
}
