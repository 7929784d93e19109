/* semquad — the edges of a quad mesh (quad_edges.h), found by sorting the
 * quads' sides by their two corner vertices. */
#include "quad_edges.h"

#include "sq_parallel_sort.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

int sq_quad_corner_node(const sq_quad_mesh *m, int q, int k)
{
    int Q = m->order;
    static const int ci[4] = {0, 1, 1, 0}, cj[4] = {0, 0, 1, 1};
    return m->conn[(size_t)q * (Q + 1) * (Q + 1) + sq_quad_node(Q, ci[k] * Q, cj[k] * Q)];
}

typedef struct {
    int lo, hi, side; /* corner vertices (lo < hi) and 4q + k */
} side_key;

static int key_cmp(const void *pa, const void *pb)
{
    const side_key *a = pa, *b = pb;
    if (a->lo != b->lo) return a->lo < b->lo ? -1 : 1;
    if (a->hi != b->hi) return a->hi < b->hi ? -1 : 1;
    return (a->side > b->side) - (a->side < b->side);
}

sq_status sq_quad_edges_build(const sq_quad_mesh *m, int threads, sq_quad_edges *e,
                              sq_error *err)
{
    memset(e, 0, sizeof *e);
    size_t ns = 4 * (size_t)m->nquads;
    side_key *key = malloc((ns ? ns : 1) * sizeof *key);
    e->side_edge = malloc((ns ? ns : 1) * sizeof *e->side_edge);
    e->owner = malloc((ns ? ns : 1) * sizeof *e->owner);
    e->tag = malloc((ns ? ns : 1) * sizeof *e->tag);
    if (!key || !e->side_edge || !e->owner || !e->tag) {
        free(key);
        sq_quad_edges_free(e);
        return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    }
    for (int q = 0; q < m->nquads; q++)
        for (int k = 0; k < 4; k++) {
            int a = sq_quad_corner_node(m, q, k), b = sq_quad_corner_node(m, q, (k + 1) % 4);
            key[4 * q + k] = (side_key){a < b ? a : b, a < b ? b : a, 4 * q + k};
        }
    /* a total order (the side decides ties) */
    sq_status st = sq_parallel_sort(threads, key, ns, sizeof *key, key_cmp, err);
    if (st != SQ_OK) {
        free(key);
        sq_quad_edges_free(e);
        return st;
    }
    for (size_t s = 0; s < ns; s++) {
        if (s == 0 || key[s].lo != key[s - 1].lo || key[s].hi != key[s - 1].hi) {
            e->owner[e->nedges] = key[s].side;
            e->tag[e->nedges] = -1;
            e->nedges++;
        }
        e->side_edge[key[s].side] = e->nedges - 1;
    }
    for (int s = 0; s < m->nbnd; s++)
        e->tag[e->side_edge[4 * m->bnd_quad[s] + m->bnd_side[s]]] = m->bnd_tag[s];
    free(key);
    return SQ_OK;
}

void sq_quad_edges_free(sq_quad_edges *e)
{
    if (!e) return;
    free(e->side_edge);
    free(e->owner);
    free(e->tag);
    memset(e, 0, sizeof *e);
}

void sq_quad_edges_lengths(const sq_quad_mesh *m, const sq_quad_edges *e, double *mean,
                           double *max)
{
    double sum = 0.0, big = 0.0;
    for (int f = 0; f < e->nedges; f++) {
        int q = e->owner[f] / 4, k = e->owner[f] % 4;
        const double *a = &m->xy[2 * (size_t)sq_quad_corner_node(m, q, k)];
        const double *b = &m->xy[2 * (size_t)sq_quad_corner_node(m, q, (k + 1) % 4)];
        double len = hypot(b[0] - a[0], b[1] - a[1]);
        sum += len;
        if (len > big) big = len;
    }
    *mean = e->nedges ? sum / e->nedges : 0.0;
    *max = big;
}
