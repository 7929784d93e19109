/* semquad — route 1b of periodic pairs (docs/domains.md): on the face's
 * own layout, the vertices of each pair's image curve set to the images
 * of its master's, one to one in order, so the image's layout corners
 * slide along it; the relaxation then holds both curves (held_edges). */
#include "identified_edges.h"
#include "quad_mesher_private.h"

#include <math.h>
#include <stdlib.h>

/* The vertices of v on CAD edge t in the order of its arc length
 * (order[*n], allocated): the sides on t form a path whose end nearer the
 * curve's start comes first.  SQ_ERR_LAYOUT if they do not (a closed
 * curve). */
static sq_status curve_path(const cad_face *face, const qm_vmesh *v, int t, int **order, int *n,
                            sq_error *err)
{
    int *nb = malloc(sizeof(int) * 2 * ((size_t)v->nv + 1));
    *order = malloc(sizeof(int) * ((size_t)v->nv + 1));
    *n = 0;
    if (!nb || !*order) {
        free(nb);
        return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    }
    for (int i = 0; i < 2 * v->nv; i++) nb[i] = -1;
    int nodes = 0;
    for (int q = 0; q < v->nq; q++)
        for (int k = 0; k < 4; k++) {
            if (v->side_tag[4 * q + k] != t) continue;
            const int ends[2] = {v->quad[4 * q + k], v->quad[4 * q + (k + 1) % 4]};
            for (int r = 0; r < 2; r++) {
                const int x = ends[r];
                nodes += nb[2 * x] < 0;
                nb[2 * x + (nb[2 * x] >= 0)] = ends[1 - r];
            }
        }
    double s0[2];
    sq_status st = qm_curve_point(face, t, 0.0, s0, err);
    int start = -1;
    double dmin = HUGE_VAL;
    for (int x = 0; x < v->nv && st == SQ_OK; x++) {
        if (nb[2 * x] < 0 || nb[2 * x + 1] >= 0) continue; /* not an end */
        double d = hypot(v->xy[2 * x] - s0[0], v->xy[2 * x + 1] - s0[1]);
        if (d < dmin) dmin = d, start = x;
    }
    for (int prev = -1, x = start; x >= 0 && *n < nodes;) {
        (*order)[(*n)++] = x;
        int next = nb[2 * x] != prev ? nb[2 * x] : nb[2 * x + 1];
        prev = x, x = next;
    }
    if (st == SQ_OK && (start < 0 || *n != nodes))
        st = SQ_FAIL(err, SQ_ERR_LAYOUT, "periodic edge %d: its mesh is not one open path", t);
    free(nb);
    return st;
}

sq_status qm_slide_periodic(const cad_face *face, const sq_mesher_options *opt, qm_vmesh *v,
                            sq_error *err)
{
    sq_status st = SQ_OK;
    for (int k = 0; k < opt->slid.npairs && st == SQ_OK; k++) {
        const sq_identified_pair *p = &opt->slid.pairs[k];
        int *A = NULL, *B = NULL, na = 0, nb = 0;
        st = curve_path(face, v, p->a, &A, &na, err);
        if (st == SQ_OK) st = curve_path(face, v, p->b, &B, &nb, err);
        if (st == SQ_OK && na != nb)
            st = SQ_FAIL(err, SQ_ERR_INTERNAL, "periodic edges %d and %d carry %d and %d vertices",
                         p->a, p->b, na, nb);
        /* b at arc L - s is T(a at s): b's order reversed */
        for (int j = 0; j < na && st == SQ_OK; j++)
            sq_affine_map(p->affine, &v->xy[2 * (size_t)A[j]], &v->xy[2 * (size_t)B[nb - 1 - j]]);
        free(A), free(B);
    }
    return st;
}
