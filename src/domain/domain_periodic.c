/* semquad — periodic pairs of a domain of several faces (domain.h
 * design 5, docs/domains.md): the pairs among the domain's boundary
 * curves, the domain whose interfaces also are the pairs (for the split
 * road's exchange), the identified domain's Gauss–Bonnet count on the mesh. */
#include "domain.h"
#include "periodic.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

sq_status sq_domain_periodic_find(const sq_domain *d, const char *spec, sq_periodic *p,
                                  sq_error *err)
{
    sq_periodic_curve *c = malloc(sizeof *c * ((size_t)d->ntags + 1));
    if (!c) return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    double bbox[4] = {HUGE_VAL, HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
    for (int f = 0; f < d->nfaces; f++) {
        double A[6];
        int flip;
        sq_domain_frame(d, f, A, &flip);
        for (int k = 0; k < 4; k++) { /* the face's box corners in the domain's frame */
            const double *b = d->info[f].bbox, x[2] = {b[2 * (k & 1)], b[1 + 2 * (k >> 1)]};
            double y[2];
            sq_affine_map(A, x, y);
            bbox[0] = fmin(bbox[0], y[0]), bbox[1] = fmin(bbox[1], y[1]);
            bbox[2] = fmax(bbox[2], y[0]), bbox[3] = fmax(bbox[3], y[1]);
        }
        for (int e = 0; e < cad_face_num_edges(d->faces[f]); e++) {
            const sq_domain_curve *cv = &d->curves[d->curve_of[f][e]];
            if (cv->tag >= 0) sq_periodic_curve_of(d->faces[f], &d->info[f], e, A, flip, &c[cv->tag]);
        }
    }
    sq_status st = sq_periodic_find_curves(c, d->ntags, bbox, spec, p, err);
    free(c);
    return st;
}

static int curve_of_tag(const sq_domain *d, int t)
{
    for (int c = 0; c < d->ncurves; c++)
        if (d->curves[c].tag == t) return c;
    return -1;
}

sq_status sq_domain_periodic_split(const sq_domain *d, const sq_periodic *p, sq_domain *s,
                                   sq_error *err)
{
    *s = *d;
    s->curves = malloc(sizeof *s->curves * ((size_t)d->ncurves + 1));
    s->curve_of = calloc((size_t)d->nfaces + 1, sizeof *s->curve_of);
    if (!s->curves || !s->curve_of) {
        free(s->curves), free(s->curve_of);
        memset(s, 0, sizeof *s);
        return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    }
    memcpy(s->curves, d->curves, sizeof *s->curves * (size_t)d->ncurves);
    for (int f = 0; f < d->nfaces; f++) {
        size_t ne = (size_t)cad_face_num_edges(d->faces[f]);
        if (!(s->curve_of[f] = malloc(sizeof(int) * (ne + 1)))) {
            sq_domain_free(s);
            return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
        }
        memcpy(s->curve_of[f], d->curve_of[f], sizeof(int) * ne);
    }
    /* pair k: b's curve becomes a's second side; a's arc s is b's L - s
     * when both faces (or neither) are mirrored into the domain's frame */
    for (int k = 0; k < p->npairs; k++) {
        int ca = curve_of_tag(d, p->pairs[k].a), cb = curve_of_tag(d, p->pairs[k].b), fa, fb;
        double A[6];
        sq_domain_curve *a = &s->curves[ca];
        const sq_domain_curve *b = &d->curves[cb];
        sq_domain_frame(d, a->face[0], A, &fa);
        sq_domain_frame(d, b->face[0], A, &fb);
        a->face[1] = b->face[0], a->edge[1] = b->edge[0], a->reversed = fa == fb, a->tag = -1;
        s->curve_of[b->face[0]][b->edge[0]] = ca;
        s->ninterfaces++;
    }
    return SQ_OK;
}

/* The interior angle of quad q at its corner c: from its side towards the
 * next corner to its side towards the previous one, counter-clockwise
 * (the nodes next to the corner give the sides' directions there). */
static double corner_angle(const sq_quad_mesh *m, int q, int c)
{
    int Q = m->order, npe = (Q + 1) * (Q + 1);
    const int *n = &m->conn[(size_t)q * npe];
    const double *v = &m->xy[2 * (size_t)n[sq_quad_side_node(Q, c, 0)]];
    const double *a = &m->xy[2 * (size_t)n[sq_quad_side_node(Q, c, 1)]];
    const double *b = &m->xy[2 * (size_t)n[sq_quad_side_node(Q, (c + 3) % 4, Q - 1)]];
    double d1[2] = {a[0] - v[0], a[1] - v[1]}, d2[2] = {b[0] - v[0], b[1] - v[1]};
    double t = atan2(d1[0] * d2[1] - d1[1] * d2[0], d1[0] * d2[0] + d1[1] * d2[1]);
    return t < 0.0 ? t + 2.0 * M_PI : t;
}

/* Keys of three ints (a side's end classes, then its middle's), in
 * lexicographic order. */
static int cmp_key(const void *x, const void *y)
{
    const int *p = x, *q = y;
    for (int k = 0; k < 3; k++)
        if (p[k] != q[k]) return (p[k] > q[k]) - (p[k] < q[k]);
    return 0;
}

/* Edges of the identified mesh: quad sides keyed by their ends' classes
 * and (from Q = 2) the lesser class of the nodes next to them. */
static sq_status count_edges(const sq_quad_mesh *m, const int *cls, int *ne, sq_error *err)
{
    int Q = m->order, npe = (Q + 1) * (Q + 1), n = 4 * m->nquads;
    int *k = malloc(sizeof *k * 3 * ((size_t)n + 1));
    if (!k) return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    for (int q = 0; q < m->nquads; q++)
        for (int s = 0; s < 4; s++) {
            const int *c = &m->conn[(size_t)q * npe];
            int a = cls[c[sq_quad_side_node(Q, s, 0)]], b = cls[c[sq_quad_side_node(Q, s, Q)]];
            int u = Q > 1 ? cls[c[sq_quad_side_node(Q, s, 1)]] : -1;
            int w = Q > 1 ? cls[c[sq_quad_side_node(Q, s, Q - 1)]] : -1;
            int *key = &k[3 * (4 * q + s)];
            key[0] = a < b ? a : b, key[1] = a < b ? b : a, key[2] = u < w ? u : w;
        }
    qsort(k, (size_t)n, 3 * sizeof *k, cmp_key);
    *ne = 0;
    for (int i = 0; i < n; i++) *ne += i == 0 || cmp_key(&k[3 * i], &k[3 * (i - 1)]) != 0;
    free(k);
    return SQ_OK;
}

/* 1 if boundary tag t is an edge of a pair. */
static int paired(const sq_periodic *p, int t)
{
    for (int k = 0; k < p->npairs; k++)
        if (p->pairs[k].a == t || p->pairs[k].b == t) return 1;
    return 0;
}

sq_status sq_domain_periodic_identified(const sq_periodic *p, const sq_quad_mesh *m, int *chi,
                                        int *index, int *irregular, int *mesh_index, sq_error *err)
{
    int nn = m->nnodes, Q = m->order, npe = (Q + 1) * (Q + 1), *cls = NULL, ne = 0;
    SQ_TRY(sq_periodic_node_classes(m, &cls, err));
    double *angle = calloc((size_t)nn + 1, sizeof *angle);
    char *corner = calloc((size_t)nn + 1, 1), *open = calloc((size_t)nn + 1, 1);
    sq_status st = angle && corner && open ? count_edges(m, cls, &ne, err)
                                           : SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    for (int q = 0; q < m->nquads && st == SQ_OK; q++)
        for (int c = 0; c < 4; c++) {
            int v = cls[m->conn[(size_t)q * npe + sq_quad_side_node(Q, c, 0)]];
            corner[v] = 1, angle[v] += corner_angle(m, q, c);
        }
    for (int s = 0; s < m->nbnd && st == SQ_OK; s++) {
        if (paired(p, m->bnd_tag[s])) continue;
        const int *c = &m->conn[(size_t)m->bnd_quad[s] * npe];
        open[cls[c[sq_quad_side_node(Q, m->bnd_side[s], 0)]]] = 1;
        open[cls[c[sq_quad_side_node(Q, m->bnd_side[s], Q)]]] = 1;
    }
    /* chi = V - E + F of the identified mesh; each class's index from its
     * angle: a boundary vertex 2 - round(angle / 90 deg), an interior one
     * 4 - round(angle / 90 deg) (0 at a straight or full angle) */
    int nv = 0, sum = 0;
    for (int v = 0; v < nn && st == SQ_OK; v++)
        if (corner[v]) nv++, sum += (open[v] ? 2 : 4) - (int)lround(angle[v] / (0.5 * M_PI));
    *chi = nv - ne + m->nquads;
    *index = 4 * *chi - sum;
    free(cls), free(angle), free(corner), free(open);
    if (st == SQ_OK) st = sq_periodic_irregular(p, m, irregular, mesh_index, err);
    return st;
}
