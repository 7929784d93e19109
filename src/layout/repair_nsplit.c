/* semquad — the n-quad split of a patch with n corners (Marcon 2019 §3.4's
 * midpoint division for n = 3): a node joined to the midpoints of the n
 * sides, at the centroid or on the patch's medial axis, with spokes bent
 * along the patch's constrained Delaunay triangulation where straight ones
 * would leave it. */
#include "repair_private.h"

#include <math.h>
#include <stdlib.h>

/* Distance from p to the closed polygon ring[n]. */
static double ring_dist(const double *ring, int n, const double p[2])
{
    double best = HUGE_VAL;
    for (int i = 0; i < n; i++) {
        const double *a = &ring[2 * i], *b = &ring[2 * ((i + 1) % n)];
        double v[2] = {b[0] - a[0], b[1] - a[1]}, l2 = v[0] * v[0] + v[1] * v[1];
        double t = l2 > 0 ? ((p[0] - a[0]) * v[0] + (p[1] - a[1]) * v[1]) / l2 : 0.0;
        t = fmin(fmax(t, 0.0), 1.0);
        best = fmin(best, hypot(a[0] + t * v[0] - p[0], a[1] + t * v[1] - p[1]));
    }
    return best;
}

/* Does segment a-b meet the closed polygon ring[n] farther than tol from b? */
static int seg_leaves(const double *ring, int n, const double a[2], const double b[2], double tol)
{
    for (int i = 0; i < n; i++) {
        const double *p = &ring[2 * i], *q = &ring[2 * ((i + 1) % n)];
        double t, u;
        if (!lay_seg_seg(a, b, p, q, &t, &u)) continue;
        double x = a[0] + t * (b[0] - a[0]), y = a[1] + t * (b[1] - a[1]);
        if (hypot(x - b[0], y - b[1]) > tol) return 1;
    }
    return 0;
}

/* Polylines a[na] and b[nb] meet other than at their common first point? */
static int paths_cross(const double *a, int na, const double *b, int nb, double tol)
{
    for (int i = 0; i + 1 < na; i++)
        for (int j = 0; j + 1 < nb; j++) {
            double t, u;
            if (!lay_seg_seg(&a[2 * i], &a[2 * i + 2], &b[2 * j], &b[2 * j + 2], &t, &u)) continue;
            double x = a[2 * i] + t * (a[2 * i + 2] - a[2 * i]);
            double y = a[2 * i + 1] + t * (a[2 * i + 3] - a[2 * i + 1]);
            if (hypot(x - a[0], y - a[1]) > tol) return 1;
        }
    return 0;
}

sq_status lay_ring_with_points(const sq_layout *L, const sq_layout_patch *P, const double *sp,
                               int n, double **ring, int *nring, sq_error *err)
{
    int m;
    double *poly = lay_cycle_polygon(L, P->half, P->cycle_start[1], &m);
    double *out = malloc(2 * (size_t)(m + n) * sizeof *out);
    int *seg = malloc((size_t)(n > 0 ? n : 1) * sizeof *seg);
    double *par = malloc((size_t)(n > 0 ? n : 1) * sizeof *par);
    if (!poly || !out || !seg || !par) {
        free(poly), free(out), free(seg), free(par);
        return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    }
    for (int k = 0; k < n; k++) {
        double best = HUGE_VAL;
        for (int i = 0; i < m; i++) {
            const double *a = &poly[2 * i], *b = &poly[2 * ((i + 1) % m)];
            double v[2] = {b[0] - a[0], b[1] - a[1]}, l2 = v[0] * v[0] + v[1] * v[1];
            double t = l2 > 0 ? ((sp[2 * k] - a[0]) * v[0] + (sp[2 * k + 1] - a[1]) * v[1]) / l2
                              : 0.0;
            t = fmin(fmax(t, 0.0), 1.0);
            double d = hypot(a[0] + t * v[0] - sp[2 * k], a[1] + t * v[1] - sp[2 * k + 1]);
            if (d < best) best = d, seg[k] = i, par[k] = t;
        }
    }
    int c = 0;
    for (int i = 0; i < m; i++) {
        out[2 * c] = poly[2 * i];
        out[2 * c + 1] = poly[2 * i + 1];
        c++;
        /* the points on segment i, by their parameter (n is small) */
        double last = -1.0;
        for (;;) {
            int pick = -1;
            for (int k = 0; k < n; k++)
                if (seg[k] == i && par[k] > last && (pick < 0 || par[k] < par[pick])) pick = k;
            if (pick < 0) break;
            last = par[pick];
            out[2 * c] = sp[2 * pick];
            out[2 * c + 1] = sp[2 * pick + 1];
            c++;
        }
    }
    free(poly), free(seg), free(par);
    *ring = out;
    *nring = c;
    return SQ_OK;
}

typedef struct {
    long key;
    int e; /* 3 * triangle + edge */
} edge_key;

static int cmp_edge_key(const void *a, const void *b)
{
    const edge_key *x = a, *y = b;
    if (x->key != y->key) return x->key < y->key ? -1 : 1;
    return x->e - y->e;
}

/* nb[3t + j]: the triangle across edge j (vertices j, j+1) of triangle t,
 * -1 on the rim; malloc'ed, NULL when out of memory. */
static int *tri_neighbours(const cad_cdt_output *o)
{
    size_t n3 = 3 * (size_t)(o->ntris > 0 ? o->ntris : 1);
    int *nb = malloc(n3 * sizeof *nb);
    edge_key *k = malloc(n3 * sizeof *k);
    if (!nb || !k) {
        free(nb), free(k);
        return NULL;
    }
    long nv = o->nverts;
    for (int e = 0; e < 3 * o->ntris; e++) {
        long a = o->tri[e], b = o->tri[3 * (e / 3) + (e % 3 + 1) % 3];
        k[e] = (edge_key){a < b ? a * nv + b : b * nv + a, e};
        nb[e] = -1;
    }
    qsort(k, (size_t)(3 * o->ntris), sizeof *k, cmp_edge_key);
    for (int i = 0; i + 1 < 3 * o->ntris; i++)
        if (k[i].key == k[i + 1].key) {
            nb[k[i].e] = k[i + 1].e / 3;
            nb[k[i + 1].e] = k[i].e / 3;
        }
    free(k);
    return nb;
}

/* A path inside the ring from c (in triangle t0) to triangulation vertex
 * v: through the midpoints of the edges the breadth-first triangle walk
 * crosses, then shortened wherever a straight piece stays inside.  *path
 * malloc'ed (*np points, c first, v last). */
static sq_status cdt_path(const cad_cdt_output *o, const int *nb, const double *ring, int nring,
                          const double c[2], int t0, int v, double tol, double **path, int *np,
                          sq_error *err)
{
    int nt = o->ntris;
    int *from = malloc((size_t)nt * sizeof *from), *queue = malloc((size_t)nt * sizeof *queue);
    double *raw = malloc(2 * (size_t)(nt + 2) * sizeof *raw);
    if (!from || !queue || !raw) {
        free(from), free(queue), free(raw);
        return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    }
    for (int t = 0; t < nt; t++) from[t] = -2;
    int head = 0, tail = 0, goal = -1;
    from[t0] = -1;
    queue[tail++] = t0;
    while (head < tail && goal < 0) {
        int t = queue[head++];
        for (int j = 0; j < 3; j++) {
            if (o->tri[3 * t + j] == v) goal = t;
            int u = nb[3 * t + j];
            if (u >= 0 && from[u] == -2) {
                from[u] = t;
                queue[tail++] = u;
            }
        }
    }
    int n = 0;
    if (goal >= 0) { /* v, the crossed edges' midpoints back to t0, c */
        raw[2 * n] = o->xy[2 * v], raw[2 * n + 1] = o->xy[2 * v + 1], n++;
        for (int t = goal; from[t] >= 0; t = from[t]) {
            int s = from[t];
            for (int j = 0; j < 3; j++)
                if (nb[3 * s + j] == t) {
                    int a = o->tri[3 * s + j], b = o->tri[3 * s + (j + 1) % 3];
                    raw[2 * n] = 0.5 * (o->xy[2 * a] + o->xy[2 * b]);
                    raw[2 * n + 1] = 0.5 * (o->xy[2 * a + 1] + o->xy[2 * b + 1]);
                    n++;
                    break;
                }
        }
        raw[2 * n] = c[0], raw[2 * n + 1] = c[1], n++;
    }
    free(from), free(queue);
    if (goal < 0) {
        free(raw);
        return SQ_FAIL(err, SQ_ERR_LAYOUT, "no path inside the patch to a side");
    }
    /* reverse to c ... v, keeping only the points a straight piece needs */
    double *out = malloc(2 * (size_t)n * sizeof *out);
    if (!out) {
        free(raw);
        return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    }
    int m = 0, i = n - 1;
    out[2 * m] = raw[2 * i], out[2 * m + 1] = raw[2 * i + 1], m++;
    while (i > 0) {
        int j = i - 1;
        while (j > 0 && !seg_leaves(ring, nring, &raw[2 * i], &raw[2 * (j - 1)],
                                    j - 1 == 0 ? tol : 0.0))
            j--;
        out[2 * m] = raw[2 * j], out[2 * m + 1] = raw[2 * j + 1], m++;
        i = j;
    }
    free(raw);
    *path = out;
    *np = m;
    return SQ_OK;
}

/* The triangle holding p (the nearest centroid's when none does). */
static int tri_holding(const cad_cdt_output *o, const double p[2])
{
    int best = 0;
    double bd = HUGE_VAL;
    for (int t = 0; t < o->ntris; t++) {
        const double *a = &o->xy[2 * o->tri[3 * t]], *b = &o->xy[2 * o->tri[3 * t + 1]],
                     *c = &o->xy[2 * o->tri[3 * t + 2]];
        double d1 = (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0]);
        double d2 = (c[0] - b[0]) * (p[1] - b[1]) - (c[1] - b[1]) * (p[0] - b[0]);
        double d3 = (a[0] - c[0]) * (p[1] - c[1]) - (a[1] - c[1]) * (p[0] - c[0]);
        if (d1 >= 0 && d2 >= 0 && d3 >= 0) return t;
        double d = hypot((a[0] + b[0] + c[0]) / 3 - p[0], (a[1] + b[1] + c[1]) / 3 - p[1]);
        if (d < bd) bd = d, best = t;
    }
    return best;
}

/* The centre of an n-quad split when the centroid will not do: among the
 * triangles' circumcentres (Voronoi vertices of the ring's points, on its
 * medial axis) inside the ring, else their centroids, the one that sees
 * the most side points sp[n] along straight spokes, the farthest from the
 * ring among those (the largest empty circle when it sees them all). */
static void far_point(const cad_cdt_output *o, const double *ring, int nring, const double *sp,
                      int n, double tol, double cen[2])
{
    double best = -1.0;
    int bestseen = -1;
    for (int t = 0; t < o->ntris; t++) {
        const double *a = &o->xy[2 * o->tri[3 * t]], *b = &o->xy[2 * o->tri[3 * t + 1]],
                     *c = &o->xy[2 * o->tri[3 * t + 2]];
        double bx = b[0] - a[0], by = b[1] - a[1], cx = c[0] - a[0], cy = c[1] - a[1];
        double d = 2.0 * (bx * cy - by * cx), q[2];
        q[0] = a[0] + (cy * (bx * bx + by * by) - by * (cx * cx + cy * cy)) / d;
        q[1] = a[1] + (bx * (cx * cx + cy * cy) - cx * (bx * bx + by * by)) / d;
        if (!(fabs(d) > 0) || !lay_poly_contains(ring, nring, q)) {
            q[0] = (a[0] + b[0] + c[0]) / 3.0;
            q[1] = (a[1] + b[1] + c[1]) / 3.0;
        }
        /* straight spokes seen, and all of them when no two consecutive
         * ones are within SQ_LAYOUT_CORNER_TOL_DEG of straight (else the
         * centre is no corner of the quad between them) */
        int seen = 0;
        double ang[16];
        for (int k = 0; k < n; k++) {
            seen += !seg_leaves(ring, nring, q, &sp[2 * k], tol);
            if (k < 16) ang[k] = atan2(sp[2 * k + 1] - q[1], sp[2 * k] - q[0]);
        }
        for (int k = 0; k < n && k < 16 && seen == n; k++) {
            double gap = remainder(ang[(k + 1) % n] - ang[k], 2.0 * M_PI);
            if (gap < 0) gap += 2.0 * M_PI;
            if (gap > M_PI - SQ_LAYOUT_CORNER_TOL_DEG * M_PI / 180.0) seen = n - 1;
        }
        if (seen < bestseen) continue;
        double dist = ring_dist(ring, nring, q);
        if (seen > bestseen || dist > best) {
            best = dist;
            bestseen = seen;
            cen[0] = q[0];
            cen[1] = q[1];
        }
    }
}

/* the n-quad split's triangulation: at most this many points per point of
 * the patch's ring (its own points and CGAL's splits of encroached sides) */
#define SPLIT_CDT_POINTS_PER_RING_POINT 8

sq_status lay_ring_cdt_build(const lay_repair *r, const double *ring, int nring, lay_ring_cdt *t,
                             sq_error *err)
{
    int *seg = malloc(2 * (size_t)nring * sizeof *seg);
    if (!seg) return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    for (int i = 0; i < nring; i++) seg[2 * i] = i, seg[2 * i + 1] = (i + 1) % nring;
    cad_cdt_input in = {0};
    in.npoints = nring, in.xy = ring, in.nsegments = nring, in.seg = seg;
    /* spokes need a triangulation, not a fine one: CGAL's conforming
     * splits of encroached sides multiply without end near tiny sides,
     * so a split that needs more than a few points per ring point is
     * given up (the trial is undone) */
    in.max_vertices = SPLIT_CDT_POINTS_PER_RING_POINT * nring;
    in.keep_segments = r->all_quad;
    sq_status st = cad_cdt_mesh(&in, &t->o, err);
    free(seg);
    if (st == SQ_OK && !(t->nb = tri_neighbours(&t->o)))
        st = SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    return st;
}

sq_status lay_ring_cdt_path(const lay_ring_cdt *t, const double *ring, int nring,
                            const double from[2], const double to[2], double tol, double **path,
                            int *np, sq_error *err)
{
    const cad_cdt_output *o = &t->o;
    int v = 0; /* the triangulation's vertex at `to` */
    for (int i = 1; i < o->nverts; i++)
        if (hypot(o->xy[2 * i] - to[0], o->xy[2 * i + 1] - to[1]) <
            hypot(o->xy[2 * v] - to[0], o->xy[2 * v + 1] - to[1]))
            v = i;
    SQ_TRY(cdt_path(o, t->nb, ring, nring, from, tri_holding(o, from), v, tol, path, np, err));
    (*path)[2 * *np - 2] = to[0]; /* end exactly on the side point */
    (*path)[2 * *np - 1] = to[1];
    return SQ_OK;
}

void lay_ring_cdt_free(lay_ring_cdt *t)
{
    cad_cdt_output_free(&t->o);
    free(t->nb);
    t->nb = NULL;
}

/* n-quad split of patch p (one cycle, n corners; Marcon §3.4's midpoint
 * division for n = 3): a node of valence n joined to the arc-length
 * midpoints of the n sides, so that the patch becomes n quads.  The node
 * is the area centroid when straight spokes from it stay inside the
 * patch, else a point of the patch's medial axis (far_point); a spoke that
 * cannot be straight follows the patch's constrained Delaunay
 * triangulation (only if `bent`: else SQ_ERR_LAYOUT, as when the spokes
 * would cross). */
sq_status lay_split_centre(lay_repair *r, int p, int bent, sq_error *err)
{
    sq_layout *L = r->L;
    const sq_layout_patch *P = &L->patches[p];
    const int n = P->ncorners;
    if (n < 2 || P->ncycles != 1) return SQ_FAIL(err, SQ_ERR_LAYOUT, "patch %d: no sides", p);
    double *mid = malloc(2 * (size_t)n * sizeof *mid), *mfrac = malloc((size_t)n * sizeof *mfrac);
    int *medge = malloc((size_t)n * sizeof *medge);
    double **path = calloc((size_t)n, sizeof *path), *ring = NULL;
    int *np = calloc((size_t)n, sizeof *np), nring = 0;
    lay_ring_cdt t = {0};
    sq_status st = SQ_OK;
    if (!mid || !mfrac || !medge || !path || !np)
        st = SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    for (int k = 0; k < n && st == SQ_OK; k++)
        st = lay_side_point(r, P, k, 0.5, &medge[k], &mfrac[k], &mid[2 * k], err);
    if (st == SQ_OK) st = lay_ring_with_points(L, P, mid, n, &ring, &nring, err);
    double cen[2] = {0, 0};
    int straight = st == SQ_OK && lay_patch_centroid(L, P, cen) &&
                   lay_poly_contains(ring, nring, cen);
    for (int k = 0; k < n && straight; k++)
        straight = !seg_leaves(ring, nring, cen, &mid[2 * k], r->tol);
    if (st == SQ_OK && !straight && !bent)
        st = SQ_FAIL(err, SQ_ERR_LAYOUT, "patch %d: straight spokes would leave it", p);
    if (st == SQ_OK && !straight) st = lay_ring_cdt_build(r, ring, nring, &t, err);
    if (st == SQ_OK && !straight) {
        far_point(&t.o, ring, nring, mid, n, r->tol, cen);
        for (int k = 0; k < n && st == SQ_OK; k++)
            if (seg_leaves(ring, nring, cen, &mid[2 * k], r->tol))
                st = lay_ring_cdt_path(&t, ring, nring, cen, &mid[2 * k], r->tol, &path[k], &np[k],
                                       err);
    }
    /* spokes must not meet but at the centre */
    for (int a = 0; a < n && st == SQ_OK; a++)
        for (int b = a + 1; b < n && st == SQ_OK; b++) {
            double sa[4] = {cen[0], cen[1], mid[2 * a], mid[2 * a + 1]};
            double sb[4] = {cen[0], cen[1], mid[2 * b], mid[2 * b + 1]};
            const double *pa = path[a] ? path[a] : sa, *pb = path[b] ? path[b] : sb;
            if (paths_cross(pa, path[a] ? np[a] : 2, pb, path[b] ? np[b] : 2, r->tol))
                st = SQ_FAIL(err, SQ_ERR_LAYOUT, "patch %d: spokes from (%g, %g) cross", p,
                             cen[0], cen[1]);
        }
    if (st == SQ_OK) st = lay_sing_push(L, cen[0], cen[1], n, SQ_LROLE_MIDPOINT, err);
    int M = L->nsing - 1;
    for (int k = 0; k < n && st == SQ_OK; k++)
        st = lay_add_spoke(r, (sq_sep_end){SQ_END_SINGULAR, M, 0.0}, cen, path[k], np[k],
                           medge[k], mfrac[k], &mid[2 * k], err);
    /* a valence-0 face vertex of the patch now takes one quad */
    for (int k = 0; k < n && st == SQ_OK; k++) {
        const sq_layout_node *v = &L->nodes[P->corners[k]];
        if (v->kind == SQ_LNODE_CORNER && L->vertex_quads[v->id] == 0) L->vertex_quads[v->id] = 1;
    }
    for (int k = 0; path && k < n; k++) free(path[k]);
    free(path), free(np), free(mid), free(mfrac), free(medge), free(ring);
    lay_ring_cdt_free(&t);
    return st;
}
