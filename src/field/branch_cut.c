#include "branch_cut.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

void sq_branch_cut_free(sq_branch_cut *c)
{
    if (!c) return;
    free(c->edges);
    free(c->half);
    free(c->cut);
    memset(c, 0, sizeof *c);
}

sq_status sq_mesh_vertex_loops(const cad_face *face, const sem_tri_mesh *m, int **loops,
                               sq_error *err)
{
    int *l = malloc(sizeof(int) * ((size_t)m->nverts + 1));
    if (!l) return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    for (int v = 0; v < m->nverts; v++) l[v] = -1;
    for (int h = 0; h < 3 * m->ntris; h++) {
        if (m->neigh[h] >= 0 || m->btag[h] < 0) continue;
        const int loop = cad_face_edge_loop(face, m->btag[h]), t = h / 3, k = h % 3;
        l[m->tri[3 * t + k]] = loop;
        l[m->tri[3 * t + (k + 1) % 3]] = loop;
    }
    *loops = l;
    return SQ_OK;
}

/* binary min-heap of (distance, node) */
typedef struct {
    double d;
    int n;
} heap_item;

static void heap_push(heap_item *h, int *n, heap_item it)
{
    int i = (*n)++;
    while (i > 0 && h[(i - 1) / 2].d > it.d) {
        h[i] = h[(i - 1) / 2];
        i = (i - 1) / 2;
    }
    h[i] = it;
}

static heap_item heap_pop(heap_item *h, int *n)
{
    heap_item top = h[0], last = h[--(*n)];
    int i = 0;
    for (;;) {
        int c = 2 * i + 1;
        if (c >= *n) break;
        if (c + 1 < *n && h[c + 1].d < h[c].d) c++;
        if (h[c].d >= last.d) break;
        h[i] = h[c];
        i = c;
    }
    h[i] = last;
    return top;
}

sq_status sq_branch_cut_build(const sem_tri_mesh *m, const int *loops, int nloops, int nsing,
                              const int *sing, sq_branch_cut *out, sq_error *err)
{
    memset(out, 0, sizeof *out);
    const int nv = m->nverts, nn = nv + nloops, nh = 3 * m->ntris;
    /* graph node of a vertex: itself inside, its loop's node on the boundary */
#define NODE(v) (loops[v] >= 0 ? nv + loops[v] : (v))
    int *deg = calloc((size_t)nn + 1, sizeof(int));
    int *start = malloc(sizeof(int) * ((size_t)nn + 2));
    int *adj = malloc(sizeof(int) * (2 * (size_t)nh + 1)); /* half-edges */
    int *parent = malloc(sizeof(int) * ((size_t)nn + 1));  /* half-edge to the parent */
    double *dist = malloc(sizeof(double) * ((size_t)nn + 1));
    unsigned char *done = calloc((size_t)nn + 1, 1);
    heap_item *heap = malloc(sizeof(heap_item) * (2 * (size_t)nh + (size_t)nn + 1));
    out->cut = calloc((size_t)nh + 1, 1);
    out->edges = malloc(sizeof(int) * (2 * (size_t)nn + 2));
    out->half = malloc(sizeof(int) * ((size_t)nn + 1));
    sq_status st = SQ_OK;
    if (!deg || !start || !adj || !parent || !dist || !done || !heap || !out->cut ||
        !out->edges || !out->half) {
        st = SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
        goto done;
    }
    /* each interior edge once (from its lower-numbered element), both ways */
    for (int h = 0; h < nh; h++) {
        const int nb = m->neigh[h];
        if (nb < 0 || nb < h / 3) continue;
        const int a = NODE(m->tri[h]), b = NODE(m->tri[3 * (h / 3) + (h % 3 + 1) % 3]);
        if (a == b) continue;
        deg[a]++;
        deg[b]++;
    }
    start[0] = 0;
    for (int i = 0; i < nn; i++) start[i + 1] = start[i] + deg[i], deg[i] = 0;
    for (int h = 0; h < nh; h++) {
        const int nb = m->neigh[h];
        if (nb < 0 || nb < h / 3) continue;
        const int a = NODE(m->tri[h]), b = NODE(m->tri[3 * (h / 3) + (h % 3 + 1) % 3]);
        if (a == b) continue;
        adj[start[a] + deg[a]++] = h;
        adj[start[b] + deg[b]++] = h;
    }
    for (int i = 0; i < nn; i++) parent[i] = -1, dist[i] = HUGE_VAL;
    int hn = 0;
    dist[nv] = 0.0;
    heap_push(heap, &hn, (heap_item){0.0, nv});
    while (hn > 0) {
        heap_item it = heap_pop(heap, &hn);
        if (done[it.n]) continue;
        done[it.n] = 1;
        for (int q = start[it.n]; q < start[it.n + 1]; q++) {
            const int h = adj[q], va = m->tri[h], vb = m->tri[3 * (h / 3) + (h % 3 + 1) % 3];
            const int a = NODE(va), b = NODE(vb), o = a == it.n ? b : a;
            if (done[o]) continue;
            const double d = it.d + hypot(m->vxy[2 * va] - m->vxy[2 * vb],
                                          m->vxy[2 * va + 1] - m->vxy[2 * vb + 1]);
            if (d < dist[o]) {
                dist[o] = d;
                parent[o] = h;
                heap_push(heap, &hn, (heap_item){d, o});
            }
        }
    }
    /* keep the tree paths from the terminals to the root: the tree with
     * its hanging edges pruned */
    memset(done, 0, (size_t)nn + 1);
    done[nv] = 1;
    for (int k = 0; k < nsing + nloops - 1; k++) {
        int node = k < nsing ? sing[k] : nv + 1 + (k - nsing);
        if (node < nv && loops[node] >= 0) {
            st = SQ_FAIL(err, SQ_ERR_USAGE, "branch cut: singular vertex %d is on the boundary",
                         node);
            goto done;
        }
        while (!done[node]) {
            done[node] = 1;
            const int h = parent[node];
            if (h < 0) {
                st = SQ_FAIL(err, SQ_ERR_INTERNAL,
                             "branch cut: the triangulation is not connected");
                goto done;
            }
            const int va = m->tri[h], vb = m->tri[3 * (h / 3) + (h % 3 + 1) % 3];
            out->edges[2 * out->nedges] = va;
            out->edges[2 * out->nedges + 1] = vb;
            out->half[out->nedges++] = h;
            out->cut[h] = 1;
            const int nb = m->neigh[h];
            for (int j = 0; j < 3; j++)
                if (m->neigh[3 * nb + j] == h / 3) out->cut[3 * nb + j] = 1;
            node = NODE(va) == node ? NODE(vb) : NODE(va);
        }
    }
#undef NODE
done:
    free(deg);
    free(start);
    free(adj);
    free(parent);
    free(dist);
    free(done);
    free(heap);
    if (st != SQ_OK) sq_branch_cut_free(out);
    return st;
}
