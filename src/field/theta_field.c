#include "theta_field.h"

#include "poisson.h"
#include "sq_segment.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

void sq_theta_field_free(sq_theta_field *t)
{
    if (!t) return;
    sem_field_evaluator_free(&t->ev);
    sem_field_free(&t->tr);
    sq_branch_cut_free(&t->cut);
    free(t->axy);
    free(t->aref);
    memset(t, 0, sizeof *t);
}

/* angle nearest to ref among a + 2πk */
static double near_branch(double a, double ref)
{
    return a + 2.0 * M_PI * round((ref - a) / (2.0 * M_PI));
}

/* The arg terms, θ_s and the holes' (steps 1 and 2), and their gradient
 * at x in element e */
static double theta_singular(const sq_theta_field *t, int e, const double x[2], double grad[2])
{
    double v = 0.0;
    if (grad) grad[0] = grad[1] = 0.0;
    for (int j = 0; j < t->narg; j++) {
        const double dx = x[0] - t->axy[2 * j], dy = x[1] - t->axy[2 * j + 1];
        const double a = t->acoef[j], r2 = dx * dx + dy * dy;
        v += a * near_branch(atan2(dy, dx), t->aref[(size_t)j * t->mesh->ntris + e]);
        if (grad) {
            grad[0] -= a * dy / r2;
            grad[1] += a * dx / r2;
        }
    }
    return v;
}

double sq_theta_field_eval_ref(const sq_theta_field *t, int e, double r, double s, double grad[2])
{
    /* the derivatives only when asked for: the tracer needs θ alone */
    double v, g[2], x[2], gs[2];
    sem_field_evaluator_eval_ref(t->ev, e, r, s, &v, grad ? g : NULL, x);
    v += theta_singular(t, e, x, grad ? gs : NULL) + t->theta0;
    if (grad) grad[0] = g[0] + gs[0], grad[1] = g[1] + gs[1];
    return v;
}

typedef struct {
    const sq_theta_field *t;
    const sem_locator *loc;
    int fail;
} tdata;

/* ∂θ_r'/∂ν on boundary edge tag = 3 e + k (sem_poisson_data.g_by_edge):
 * (n × ∇H_r)·ν, the tangential derivative of H_r in the edge's own element
 * (its integral along the boundary telescopes to zero), minus the normal
 * derivative of the holes' arg terms */
static double tr_flux(const double x[2], const double n[2], int tag, void *ctx)
{
    tdata *d = ctx;
    const sq_theta_field *t = d->t;
    double rs[2], v, g[2];
    if (sem_locator_invert(d->loc, tag / 3, x, rs)) {
        d->fail = 1;
        return 0.0;
    }
    sem_field_evaluator_eval_ref(t->h->ev, tag / 3, rs[0], rs[1], &v, g, NULL);
    double flux = -g[1] * n[0] + g[0] * n[1];
    for (int j = t->h->npoints; j < t->narg; j++) {
        const double dx = x[0] - t->axy[2 * j], dy = x[1] - t->axy[2 * j + 1];
        flux -= t->acoef[j] * (-dy * n[0] + dx * n[1]) / (dx * dx + dy * dy);
    }
    return flux;
}

/* reference coordinates of the point at u in [0,1] along edge k */
static void edge_point(int k, double u, double rs[2])
{
    if (k == 0) rs[0] = u, rs[1] = 0.0;
    else if (k == 1) rs[0] = 1.0 - u, rs[1] = u;
    else rs[0] = 0.0, rs[1] = 1.0 - u;
}

/* Distance from p to the mesh's boundary edges on loop l (as chords), and
 * whether p is on the far side of them from the face (even-odd crossings
 * of the chords: inside the hole). */
static double hole_distance(const sem_tri_mesh *m, const int *loops, int l, const double p[2],
                            int *inside)
{
    double d2 = HUGE_VAL;
    int cross = 0;
    for (int q = 0; q < 3 * m->ntris; q++) {
        if (m->neigh[q] >= 0) continue;
        const int va = m->tri[q], vb = m->tri[3 * (q / 3) + (q % 3 + 1) % 3];
        if (loops[va] != l || loops[vb] != l) continue;
        const double *a = &m->vxy[2 * va], *b = &m->vxy[2 * vb];
        const double u = sq_segment_foot(p, a, b);
        const double dx = p[0] - a[0] - u * (b[0] - a[0]), dy = p[1] - a[1] - u * (b[1] - a[1]);
        d2 = fmin(d2, dx * dx + dy * dy);
        cross ^= sq_segment_crosses_ray(p, a, b);
    }
    *inside = cross;
    return sqrt(d2);
}

/* A point well inside hole l, where its arg term's centre goes: the
 * point of a 12 × 12 lattice over the hole's bounding box farthest from
 * its boundary, refined twice on lattices a cell wide around the best.
 * Any point of the hole makes the remainder single-valued; the farther
 * from the boundary, the smoother the arg term is on the face and the less
 * of it θ_r' has to resolve (a circle's centre: none). */
static void hole_centre(const sem_tri_mesh *m, const int *loops, int l, double c[2])
{
    enum { N = 12 };
    double lo[2] = {HUGE_VAL, HUGE_VAL}, hi[2] = {-HUGE_VAL, -HUGE_VAL};
    for (int v = 0; v < m->nverts; v++)
        if (loops[v] == l)
            for (int i = 0; i < 2; i++) {
                lo[i] = fmin(lo[i], m->vxy[2 * v + i]);
                hi[i] = fmax(hi[i], m->vxy[2 * v + i]);
            }
    double best = -1.0;
    c[0] = 0.5 * (lo[0] + hi[0]), c[1] = 0.5 * (lo[1] + hi[1]);
    double h[2] = {(hi[0] - lo[0]) / N, (hi[1] - lo[1]) / N};
    for (int pass = 0; pass < 3; pass++) {
        const double o[2] = {pass ? c[0] - h[0] : lo[0], pass ? c[1] - h[1] : lo[1]};
        if (pass) h[0] *= 2.0 / N, h[1] *= 2.0 / N;
        for (int i = 0; i < N; i++)
            for (int k = 0; k < N; k++) {
                const double p[2] = {o[0] + (i + 0.5) * h[0], o[1] + (k + 0.5) * h[1]};
                int in;
                const double d = hole_distance(m, loops, l, p, &in);
                if (in && d > best) best = d, c[0] = p[0], c[1] = p[1];
            }
    }
}

/* The arg terms: centres, coefficients, and per element the branch at its
 * centroid, continuous across the edges not on L (a breadth-first walk
 * over the face minus L from element 0). */
static sq_status arg_terms(sq_theta_field *out, const sem_locator *loc, const int *loops,
                           int nloops, sq_error *err)
{
    const sem_tri_mesh *m = out->mesh;
    const sq_h_field *h = out->h;
    const int nt = m->ntris, np = h->npoints, na = np + nloops - 1;
    out->narg = na;
    out->axy = malloc(sizeof(double) * (3 * (size_t)na + 1));
    out->aref = malloc(sizeof(double) * ((size_t)na * nt + 1));
    int *queue = malloc(sizeof(int) * ((size_t)nt + 1));
    unsigned char *seen = calloc((size_t)nt + 1, 1);
    if (!out->axy || !out->aref || !queue || !seen) {
        free(queue);
        free(seen);
        return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    }
    out->acoef = out->axy + 2 * na;
    for (int j = 0; j < np; j++) {
        out->axy[2 * j] = h->xy[2 * j], out->axy[2 * j + 1] = h->xy[2 * j + 1];
        out->acoef[j] = h->c[j] / (2.0 * M_PI);
    }
    /* H_r is harmonic in the face: its conjugate's only periods are around
     * the holes, each minus the flux of H_r out of the face through the
     * hole (∮ ∇H_r·(t_y, −t_x) ds walking counter-clockwise round it) */
    for (int l = 1; l < nloops; l++) {
        hole_centre(m, loops, l, &out->axy[2 * (np + l - 1)]);
        out->acoef[np + l - 1] = -h->loop_flux[l] / (2.0 * M_PI);
    }
    int head = 0, tail = 0;
    queue[tail++] = 0;
    seen[0] = 1;
    while (head < tail) {
        const int e = queue[head++];
        double xc[2];
        sem_locator_map(loc, e, 1.0 / 3.0, 1.0 / 3.0, xc, NULL);
        int from = -1; /* a visited neighbour across an edge not on L */
        for (int k = 0; k < 3 && e != 0; k++) {
            const int nb = m->neigh[3 * e + k];
            if (nb >= 0 && !out->cut.cut[3 * e + k] && seen[nb] == 2) from = nb;
        }
        for (int j = 0; j < na; j++) {
            const double a = atan2(xc[1] - out->axy[2 * j + 1], xc[0] - out->axy[2 * j]);
            out->aref[(size_t)j * nt + e] =
                from < 0 ? a : near_branch(a, out->aref[(size_t)j * nt + from]);
        }
        seen[e] = 2;
        for (int k = 0; k < 3; k++) {
            const int nb = m->neigh[3 * e + k];
            if (nb >= 0 && !out->cut.cut[3 * e + k] && !seen[nb]) seen[nb] = 1, queue[tail++] = nb;
        }
    }
    free(queue);
    free(seen);
    if (tail != nt) return SQ_FAIL(err, SQ_ERR_INTERNAL, "theta: the face minus L is not connected");
    return SQ_OK;
}

/* step 4: θ equal to the tangent angle at the midpoint of the first
 * boundary element edge on the first edge of the outer loop */
static sq_status anchor(const cad_face *face, const sem_locator *loc, sq_theta_field *t,
                        sq_error *err)
{
    const sem_tri_mesh *mesh = t->mesh;
    const int edge0 = cad_face_loop_first_edge(face, 0);
    int hb = -1;
    for (int q = 0; q < 3 * mesh->ntris && hb < 0; q++)
        if (mesh->neigh[q] < 0 && mesh->btag[q] == edge0) hb = q;
    if (hb < 0) return SQ_FAIL(err, SQ_ERR_INTERNAL, "theta: no element on edge %d", edge0);
    double rs[2], tan[2], sp;
    edge_point(hb % 3, 0.5, rs);
    const double raw = sq_theta_field_eval_ref(t, hb / 3, rs[0], rs[1], NULL);
    sem_locator_map(loc, hb / 3, rs[0], rs[1], t->anchor, NULL);
    SQ_TRY(cad_face_edge_project(face, edge0, t->anchor, &sp, NULL, NULL, err));
    SQ_TRY(cad_face_edge_eval(face, edge0, sp, NULL, tan, NULL, err));
    t->theta0 = atan2(tan[1], tan[0]) - raw;
    return SQ_OK;
}

sq_status sq_theta_field_solve(const cad_face *face, const sem_tri_mesh *mesh,
                               const sem_locator *loc, const sq_h_field *h, const int *loops,
                               int nloops, const int *sing, sq_theta_field *out, sq_error *err)
{
    memset(out, 0, sizeof *out);
    out->mesh = mesh;
    out->h = h;
    sq_status st = sq_branch_cut_build(mesh, loops, nloops, h->npoints, sing, &out->cut, err);
    if (st == SQ_OK) st = arg_terms(out, loc, loops, nloops, err);
    if (st != SQ_OK) goto done;
    /* step 3: θ_r' with H's factor (the same operator, the same space) */
    out->ndofs = sem_poisson_ndofs(h->solver);
    if ((st = sem_field_create(mesh, h->order, 1, &out->tr, err)) != SQ_OK) goto done;
    tdata d = {out, loc, 0};
    sem_poisson_data data = {NULL, NULL, tr_flux, &d, 0, NULL, 1};
    if ((st = sem_poisson_solve(h->solver, &data, out->tr, err)) != SQ_OK) goto done;
    if (d.fail) {
        st = SQ_FAIL(err, SQ_ERR_INTERNAL, "theta: a boundary point left its element");
        goto done;
    }
    if ((st = sem_field_evaluator_create(out->tr, loc, &out->ev, err)) != SQ_OK) goto done;
    st = anchor(face, loc, out, err);
done:
    if (st != SQ_OK) sq_theta_field_free(out);
    return st;
}

/* θ(right) − θ(left) of cut edge i, directed as stored (edges[2i] →
 * edges[2i+1]; the element of the stored half-edge is on its left): the
 * growth of θ along a counter-clockwise loop around edges[2i] in the face
 * minus L, from the left side of the edge round to its right side */
static double edge_jump(const sq_theta_field *t, int i)
{
    const int q = t->cut.half[i], e = q / 3, k = q % 3, nb = t->mesh->neigh[q];
    int j = 0;
    while (j < 3 && t->mesh->neigh[3 * nb + j] != e) j++;
    double a[2], b[2];
    edge_point(k, 0.5, a);
    edge_point(j, 0.5, b);
    return sq_theta_field_eval_ref(t, nb, b[0], b[1], NULL) -
           sq_theta_field_eval_ref(t, e, a[0], a[1], NULL);
}

double sq_theta_jump_around_vertex(const sq_theta_field *t, int v)
{
    double J = 0.0;
    for (int i = 0; i < t->cut.nedges; i++) {
        if (t->cut.edges[2 * i] == v) J += edge_jump(t, i);
        else if (t->cut.edges[2 * i + 1] == v) J -= edge_jump(t, i);
    }
    return J;
}

double sq_theta_jump_around_loop(const sq_theta_field *t, const int *loops, int loop)
{
    double J = 0.0;
    for (int i = 0; i < t->cut.nedges; i++) {
        const int a = loops[t->cut.edges[2 * i]] == loop, b = loops[t->cut.edges[2 * i + 1]] == loop;
        if (a && !b) J += edge_jump(t, i);
        else if (b && !a) J -= edge_jump(t, i);
    }
    return J;
}
