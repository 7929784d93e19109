/* semquad — the guiding field's triangulation on a face with identified
 * edges (identified_edges.h, designs 1 and 2). */
#include "identified_edges.h"

#include "tri_mesh_glue.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* arc lengths closer than this part of an edge are one point: the two
 * edges of a pair carry the same points to rounding (as domain_split.c) */
#define SAME_ARC 1e-9

void sq_affine_map(const double T[6], const double p[2], double q[2])
{
    const double q0 = T[0] * p[0] + T[1] * p[1] + T[2], q1 = T[3] * p[0] + T[4] * p[1] + T[5];
    q[0] = q0, q[1] = q1;
}

void sq_affine_inverse(const double T[6], double Ti[6])
{
    const double det = T[0] * T[4] - T[1] * T[3];
    Ti[0] = T[4] / det, Ti[1] = -T[1] / det, Ti[3] = -T[3] / det, Ti[4] = T[0] / det;
    Ti[2] = -(Ti[0] * T[2] + Ti[1] * T[5]);
    Ti[5] = -(Ti[3] * T[2] + Ti[4] * T[5]);
}

void sq_identified_points_free(sq_identified_points *p)
{
    for (int e = 0; e < p->nedges && p->s; e++) free(p->s[e]);
    free(p->s);
    free(p->ep);
    memset(p, 0, sizeof *p);
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* Sorted, points within tol of the one before dropped: the count kept. */
static int unique_arcs(double *s, int n, double tol)
{
    if (n < 2) return n;
    qsort(s, (size_t)n, sizeof(double), cmp_double);
    int m = 1;
    for (int k = 1; k < n; k++)
        if (s[k] - s[m - 1] > tol) s[m++] = s[k];
    return m;
}

/* b's arc length as a's: b at L_b − s is T(a at s) */
static double on_a(double sb, double La, double Lb) { return La * (1.0 - sb / Lb); }

/* The ends of tri's element edges on CAD edge e, in a's arc length (the
 * partner's mapped), appended to s[*n]; s has room for 2 per element edge. */
static void edge_vertices(const sq_triangulation *tri, int e, int mapped, double La, double Lb,
                          double *s, int *n)
{
    const sem_tri_mesh *m = tri->mesh;
    for (int h = 0; h < 3 * m->ntris; h++) {
        if (m->neigh[h] >= 0 || m->btag[h] != e) continue;
        for (int j = 0; j < 2; j++) {
            const double x = tri->bs[2 * h + j];
            s[(*n)++] = mapped ? on_a(x, La, Lb) : x;
        }
    }
}

static sq_status points_alloc(const cad_face *face, sq_identified_points *p, sq_error *err)
{
    p->nedges = cad_face_num_edges(face);
    p->ep = calloc((size_t)p->nedges + 1, sizeof *p->ep);
    p->s = calloc((size_t)p->nedges + 1, sizeof *p->s);
    if (!p->ep || !p->s) return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    return SQ_OK;
}

/* edge e's list from the joined one u[n] (a's arc length, interior points):
 * its start, then the points in its own sense */
static sq_status set_list(sq_identified_points *p, int e, const double *u, int n, int mapped,
                          double La, double Lb, sq_error *err)
{
    double *s = realloc(p->s[e], sizeof(double) * ((size_t)n + 1));
    if (!s) return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    p->s[e] = s;
    s[0] = 0.0;
    for (int k = 0; k < n; k++) s[k + 1] = mapped ? on_a(u[n - 1 - k], Lb, La) : u[k];
    p->ep[e] = (sq_edge_points){n + 1, s};
    return SQ_OK;
}

sq_status sq_identified_points_update(const cad_face *face, const sq_identification *id,
                                      const sq_triangulation *tri, sq_identified_points *p,
                                      int *agreed, sq_error *err)
{
    if (!p->ep) SQ_TRY(points_alloc(face, p, err));
    const long cap = 4 * 3 * (long)tri->mesh->ntris + 1;
    double *all = malloc(sizeof(double) * (size_t)cap);
    double *own = malloc(sizeof(double) * (size_t)cap);
    if (!all || !own) {
        free(all);
        free(own);
        return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    }
    sq_status st = SQ_OK;
    *agreed = 1;
    for (int k = 0; k < id->npairs && st == SQ_OK; k++) {
        const int a = id->pairs[k].a, b = id->pairs[k].b;
        const double La = cad_face_edge_length(face, a), Lb = cad_face_edge_length(face, b);
        const double tol = SAME_ARC * La;
        int n = 0, na = 0, nb = 0;
        edge_vertices(tri, a, 0, La, Lb, own, &na);
        na = unique_arcs(own, na, tol);
        memcpy(all, own, sizeof(double) * (size_t)na);
        edge_vertices(tri, b, 1, La, Lb, own, &nb);
        nb = unique_arcs(own, nb, tol);
        memcpy(all + na, own, sizeof(double) * (size_t)nb);
        n = unique_arcs(all, na + nb, tol);
        *agreed &= n == na && n == nb;
        /* the interior points: the ends are the edges' own */
        int lo = 0, hi = n;
        while (lo < hi && all[lo] <= tol) lo++;
        while (hi > lo && all[hi - 1] >= La - tol) hi--;
        st = set_list(p, a, all + lo, hi - lo, 0, La, Lb, err);
        if (st == SQ_OK) st = set_list(p, b, all + lo, hi - lo, 1, La, Lb, err);
    }
    free(all);
    free(own);
    return st;
}

typedef struct {
    double s0, s1; /* in a's arc length, s0 < s1 */
    int h;         /* element edge 3t + k */
} side;

static int cmp_side(const void *x, const void *y)
{
    const side *p = x, *q = y;
    return (p->s0 > q->s0) - (p->s0 < q->s0);
}

/* tri's element edges on e, in a's arc length, sorted: the count */
static int sides_of(const sq_triangulation *tri, int e, int mapped, double La, double Lb, side *out)
{
    const sem_tri_mesh *m = tri->mesh;
    int n = 0;
    for (int h = 0; h < 3 * m->ntris; h++) {
        if (m->neigh[h] >= 0 || m->btag[h] != e) continue;
        const double x0 = tri->bs[2 * h], x1 = tri->bs[2 * h + 1];
        out[n++] = mapped ? (side){on_a(x1, La, Lb), on_a(x0, La, Lb), h} : (side){x0, x1, h};
    }
    qsort(out, (size_t)n, sizeof *out, cmp_side);
    return n;
}

sq_status sq_identified_glue(const cad_face *face, const sq_identification *id,
                             const sq_triangulation *tri, sem_tri_mesh **glued, sq_error *err)
{
    const sem_tri_mesh *m = tri->mesh;
    side *sa = malloc(sizeof *sa * (3 * (size_t)m->ntris + 1));
    side *sb = malloc(sizeof *sb * (3 * (size_t)m->ntris + 1));
    int *pairs = malloc(sizeof(int) * (6 * (size_t)m->ntris + 1));
    sq_status st = SQ_OK;
    if (!sa || !sb || !pairs) st = SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    int np = 0;
    for (int k = 0; k < id->npairs && st == SQ_OK; k++) {
        const int a = id->pairs[k].a, b = id->pairs[k].b;
        const double La = cad_face_edge_length(face, a), Lb = cad_face_edge_length(face, b);
        const double tol = SAME_ARC * La;
        const int na = sides_of(tri, a, 0, La, Lb, sa), nb = sides_of(tri, b, 1, La, Lb, sb);
        int ok = na == nb;
        for (int i = 0; i < na && ok; i++) {
            ok = fabs(sa[i].s0 - sb[i].s0) <= tol && fabs(sa[i].s1 - sb[i].s1) <= tol;
            pairs[2 * np] = sa[i].h;
            pairs[2 * np++ + 1] = sb[i].h;
        }
        if (!ok)
            st = SQ_FAIL(err, SQ_ERR_INTERNAL,
                         "the triangulation's vertices on edges %d and %d do not match (%d and %d "
                         "segments)",
                         a, b, na, nb);
    }
    if (st == SQ_OK) st = sem_tri_mesh_glue(m, np, pairs, glued, err);
    free(sa);
    free(sb);
    free(pairs);
    return st;
}
