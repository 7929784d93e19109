/* semquad — boundary layers (Marcon 2019 §3.4): the chords leaving a wall
 * graded geometrically, the layers' vertices put exactly at their heights,
 * the sides along a curved wall curved like it. */
#include "quad_mesher_private.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Boundary layers (Marcon 2019 §3.4): an edge leaving a boundary-layer
 * curve is graded from that end, first segment bl_first, growing by
 * bl_ratio over bl_layers segments, then uniform.  grade[e]: bit 1 graded
 * from n0, bit 2 from n1. */
static int on_bl_curve(const sq_layout *L, const sq_face_info *info, const sq_mesher_options *o,
                       int node)
{
    const sq_layout_node *v = &L->nodes[node];
    for (int b = 0; b < o->nbl; b++) {
        if (v->kind == SQ_LNODE_FOOT && v->id == o->bl_edges[b]) return 1;
        if (v->kind == SQ_LNODE_CORNER && (info->vertices[v->id].edge_in == o->bl_edges[b] ||
                                           info->vertices[v->id].edge_out == o->bl_edges[b]))
            return 1;
    }
    return 0;
}

static int is_bl_edge(const sq_layout *L, const sq_mesher_options *o, int e)
{
    for (int b = 0; b < o->nbl; b++)
        if (L->edges[e].cad_edge == o->bl_edges[b]) return 1;
    return 0;
}

void qm_bl_grading(const sq_layout *L, const sq_face_info *info, const sq_mesher_options *o,
                   int *grade)
{
    for (int e = 0; e < L->nedges; e++) {
        grade[e] = 0;
        if (o->nbl == 0 || is_bl_edge(L, o, e)) continue;
        grade[e] = on_bl_curve(L, info, o, L->edges[e].n0) | 2 * on_bl_curve(L, info, o, L->edges[e].n1);
    }
}

/* Thickness of nb geometric layers. */
double qm_bl_thickness(const sq_mesher_options *o, int nb)
{
    return o->bl_ratio == 1.0 ? o->bl_first * nb
                              : o->bl_first * (pow(o->bl_ratio, nb) - 1.0) / (o->bl_ratio - 1.0);
}

/* Arc-length fractions f[0..n] of an edge with n segments. */
void qm_edge_fractions(double len, int n, int grade, const sq_mesher_options *o, double *f)
{
    int ends = (grade & 1) + ((grade & 2) >> 1), nb = 0;
    while (ends && nb < o->bl_layers && ends * (nb + 1) < n &&
           ends * qm_bl_thickness(o, nb + 1) < len)
        nb++;
    double T = qm_bl_thickness(o, nb) / len; /* one end's layers, as a fraction */
    int mid = n - ends * nb;
    for (int k = 0; k <= n; k++) f[k] = (double)k / n;
    if (!nb) return;
    int lo = grade & 1 ? nb : 0, hi = grade & 2 ? n - nb : n;
    double a = grade & 1 ? T : 0.0, b = grade & 2 ? 1.0 - T : 1.0;
    for (int k = 0; k <= n; k++) {
        if (k <= lo && (grade & 1)) f[k] = qm_bl_thickness(o, k) / len;
        else if (k >= hi && (grade & 2)) f[k] = 1.0 - qm_bl_thickness(o, n - k) / len;
        else f[k] = a + (b - a) * (double)(k - lo) / mid;
    }
}

/* The other quad on side (a, b) of quad q, or -1; *k its local side. */
static int across(const qm_vmesh *v, const int *vstart, const int *vquads, int q, int a, int b,
                  int *k)
{
    for (int t = vstart[a]; t < vstart[a + 1]; t++) {
        int p = vquads[t];
        if (p == q) continue;
        for (int l = 0; l < 4; l++)
            if (v->quad[4 * p + l] == b && v->quad[4 * p + (l + 1) % 4] == a) {
                *k = l;
                return p;
            }
    }
    return -1;
}

/* Boundary layers, exactly: from every vertex of a wall (a boundary-layer
 * CAD edge), march outwards through the quads' columns and put the vertex
 * of layer j at qm_bl_thickness(j) along the wall's normal — the graded edges
 * only approximate that between them.  The march stops where the graded
 * mesh had no more layers (a vertex further than 1.25 times the asked
 * thickness). */
sq_status qm_bl_march(const cad_face *face, const sq_mesher_options *o, qm_vmesh *v, sq_error *err)
{
    int *vstart = calloc((size_t)v->nv + 1, sizeof(int)), *vquads = malloc(sizeof(int) * 4 * (size_t)v->nq);
    int *fill = calloc((size_t)v->nv + 1, sizeof(int));
    double *orig = malloc(sizeof(double) * 2 * (size_t)v->nv + 1);
    sq_status st = vstart && vquads && fill && orig ? SQ_OK : SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    if (st == SQ_OK) {
        memcpy(orig, v->xy, sizeof(double) * 2 * (size_t)v->nv);
        for (int t = 0; t < 4 * v->nq; t++) vstart[v->quad[t] + 1]++;
        for (int i = 0; i < v->nv; i++) vstart[i + 1] += vstart[i];
        for (int q = 0; q < v->nq; q++)
            for (int l = 0; l < 4; l++) {
                int a = v->quad[4 * q + l];
                vquads[vstart[a] + fill[a]++] = q;
            }
    }
    double limit = 1.25 * qm_bl_thickness(o, o->bl_layers);
    for (int q0 = 0; q0 < v->nq && st == SQ_OK; q0++)
        for (int k0 = 0; k0 < 4 && st == SQ_OK; k0++) {
            int tag = v->side_tag[4 * q0 + k0], is = 0;
            for (int b = 0; b < o->nbl; b++) is |= tag == o->bl_edges[b];
            if (!is) continue;
            for (int end = 0; end < 2 && st == SQ_OK; end++) {
                /* the column from wall vertex w: through q0, then across */
                int q = q0, k = k0, w = v->quad[4 * q0 + (k0 + end) % 4];
                double s, X[2], tg[2];
                st = cad_face_edge_project(face, tag, &v->xy[2 * w], &s, NULL, NULL, err);
                if (st == SQ_OK) st = cad_face_edge_eval(face, tag, s, X, tg, NULL, err);
                for (int j = 1; j <= o->bl_layers && q >= 0 && st == SQ_OK; j++) {
                    /* in quad q with wall-side k, the vertex above the column */
                    int up = v->quad[4 * q + (end ? (k + 2) % 4 : (k + 3) % 4)];
                    double dist, dx = orig[2 * up] - X[0], dy = orig[2 * up + 1] - X[1];
                    st = cad_face_edge_project(face, tag, &orig[2 * up], NULL, NULL, &dist, err);
                    if (st != SQ_OK || dist > limit) break;
                    /* a column that leaves the wall obliquely (a fan at a
                     * corner of the wall) keeps its graded vertices */
                    if (-dx * tg[1] + dy * tg[0] < 0.5 * hypot(dx, dy)) break;
                    double h = qm_bl_thickness(o, j);
                    /* the face is on the left of the wall's direction */
                    v->xy[2 * up] = X[0] - h * tg[1];
                    v->xy[2 * up + 1] = X[1] + h * tg[0];
                    /* next quad outwards: across the side opposite the wall side */
                    int a = v->quad[4 * q + (k + 2) % 4], b = v->quad[4 * q + (k + 3) % 4], kk;
                    q = across(v, vstart, vquads, q, a, b, &kk);
                    k = q >= 0 ? kk : k;
                }
            }
        }
    free(vstart);
    free(vquads);
    free(fill);
    free(orig);
    return st;
}

/* Design 4: the order-Q quads.  Element sides on the boundary follow the
 * CAD curve between their vertices' arc lengths; other sides are straight;
 * element interiors by transfinite interpolation of their four sides. */
/* A side inside a boundary layer that runs along its wall is curved like
 * the wall: its nodes at arc length and distance interpolated between its
 * vertices', offset from the wall along the inward normal, so thin layer
 * elements follow a curved wall instead of being cut by it.  Returns 1 and
 * fills c, s0, s1, d0, d1 for such a side. */
int qm_layer_side(const cad_face *face, const sq_mesher_options *o, double thick,
                  const double A[2], const double B[2], int *c, double *s0, double *s1,
                  double *d0, double *d1)
{
    for (int b = 0; b < o->nbl; b++) {
        int e = o->bl_edges[b];
        if (cad_face_edge_project(face, e, A, s0, NULL, d0, NULL) != SQ_OK ||
            cad_face_edge_project(face, e, B, s1, NULL, d1, NULL) != SQ_OK)
            return 0;
        if (*d0 > thick || *d1 > thick) continue;
        double Lc = cad_face_edge_length(face, e);
        if (fabs(*s1 - *s0) > 0.5 * Lc) { /* a closed edge: the shorter way round */
            if (*s1 > *s0) *s0 += Lc;
            else *s1 += Lc;
        }
        /* along the wall, not across it */
        if (fabs(*s1 - *s0) <= fabs(*d1 - *d0)) return 0;
        *c = e;
        return 1;
    }
    return 0;
}

sq_status qm_bl_keep(const cad_face *face, const sq_mesher_options *opt, const qm_vmesh *v,
                     int **keep, sq_error *err)
{
    *keep = NULL;
    if (opt->nbl <= 0) return SQ_OK;
    double T = 1.5 * qm_bl_thickness(opt, opt->bl_layers);
    int *k = calloc((size_t)v->nv + 1, sizeof(int));
    if (!k) return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    sq_status st = SQ_OK;
    for (int i = 0; i < v->nv && st == SQ_OK; i++)
        for (int b = 0; b < opt->nbl && st == SQ_OK && !k[i]; b++) {
            double d;
            st = cad_face_edge_project(face, opt->bl_edges[b], &v->xy[2 * i], NULL, NULL, &d, err);
            k[i] = d < T;
        }
    *keep = k;
    return st;
}
