/* semquad — vertices slid along a curve onto points given elsewhere
 * (docs/domains.md): route 1b of periodic pairs (on the face's own
 * layout, the vertices of each pair's image curve set to the images of its
 * master's, one to one in order) and the layout road over a domain's faces
 * (the vertices on a shared curve set to those of the face across), so the
 * layout corners on the curve slide along it; the relaxation then holds
 * the curves (held_edges). */
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
        st = SQ_FAIL(err, SQ_ERR_LAYOUT, "edge %d: its mesh is not one open path", t);
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

typedef struct {
    double s;
    int v;
} arc_vertex;

static int cmp_arc_vertex(const void *a, const void *b)
{
    const arc_vertex *x = a, *y = b;
    return (x->s > y->s) - (x->s < y->s);
}

/* The vertices of v on the closed CAD edge t (the whole loop) by their
 * arc length: into c[*n] (allocated). */
static sq_status loop_vertices(const cad_face *face, const qm_vmesh *v, int t, arc_vertex **c,
                               int *n, sq_error *err)
{
    char *on = calloc((size_t)v->nv + 1, 1);
    *c = malloc(sizeof **c * ((size_t)v->nv + 1));
    *n = 0;
    sq_status st = on && *c ? SQ_OK : SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    for (int q = 0; q < v->nq && st == SQ_OK; q++)
        for (int k = 0; k < 4; k++)
            if (v->side_tag[4 * q + k] == t) on[v->quad[4 * q + k]] = on[v->quad[4 * q + (k + 1) % 4]] = 1;
    for (int x = 0; x < v->nv && st == SQ_OK; x++) {
        if (!on[x]) continue;
        (*c)[*n].v = x;
        st = cad_face_edge_project(face, t, &v->xy[2 * (size_t)x], &(*c)[*n].s, NULL, NULL, err);
        ++*n;
    }
    if (st == SQ_OK) qsort(*c, (size_t)*n, sizeof **c, cmp_arc_vertex);
    free(on);
    return st;
}

/* A closed shared curve: its n vertices onto the n points of the face
 * across, in cyclic order, turned by the shift that moves them least
 * (the sum of their arc distances round the loop). */
static sq_status slide_loop(const cad_face *face, int t, const sq_edge_points *ep, qm_vmesh *v,
                            sq_error *err)
{
    arc_vertex *c = NULL;
    int n = 0;
    sq_status st = loop_vertices(face, v, t, &c, &n, err);
    if (st == SQ_OK && n != ep->n)
        st = SQ_FAIL(err, SQ_ERR_LAYOUT, "shared edge %d: %d segments here and %d on the face across",
                     t, n, ep->n);
    double L = cad_face_edge_length(face, t), best = HUGE_VAL;
    int shift = 0;
    for (int r = 0; r < n && st == SQ_OK; r++) {
        double sum = 0.0;
        for (int k = 0; k < n; k++) {
            double d = fabs(c[k].s - ep->s[(k + r) % n]);
            sum += fmin(d, L - d);
        }
        if (sum < best) best = sum, shift = r;
    }
    for (int k = 0; k < n && st == SQ_OK; k++)
        st = qm_curve_point(face, t, ep->s[(k + shift) % n], &v->xy[2 * (size_t)c[k].v], err);
    free(c);
    return st;
}

sq_status qm_slide_shared(const cad_face *face, const sq_mesher_options *opt, qm_vmesh *v,
                          sq_error *err)
{
    sq_status st = SQ_OK;
    for (int e = 0; e < cad_face_num_edges(face) && st == SQ_OK; e++) {
        const sq_edge_points *ep = &opt->edge_points[e];
        if (ep->n == 0) continue;
        if (cad_face_edge_closed(face, e)) {
            st = slide_loop(face, e, ep, v, err);
            continue;
        }
        int *A = NULL, na = 0;
        st = curve_path(face, v, e, &A, &na, err);
        if (st == SQ_OK && na != ep->n + 1)
            st = SQ_FAIL(err, SQ_ERR_LAYOUT,
                         "shared edge %d: %d segments here and %d on the face across", e, na - 1,
                         ep->n);
        /* ep->s[0] = 0 and the curve's end are its ends, not moved */
        for (int j = 1; j < ep->n && st == SQ_OK; j++)
            st = qm_curve_point(face, e, ep->s[j], &v->xy[2 * (size_t)A[j]], err);
        free(A);
    }
    return st;
}
