#include "theta_field.h"

#include "poisson.h"
#include "tri_mesh_cut.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

void sq_theta_field_free(sq_theta_field *t)
{
    if (!t) return;
    sem_field_evaluator_free(&t->ev);
    sem_field_free(&t->tr);
    sem_tri_mesh_free(&t->cut_mesh);
    sq_branch_cut_free(&t->cut);
    free(t->aref);
    memset(t, 0, sizeof *t);
}

/* angle nearest to ref among a + 2πk */
static double near_branch(double a, double ref)
{
    return a + 2.0 * M_PI * round((ref - a) / (2.0 * M_PI));
}

/* θ_s and its gradient at x in element e (step 1) */
static double theta_singular(const sq_theta_field *t, int e, const double x[2], double grad[2])
{
    const sq_h_field *h = t->h;
    double v = 0.0;
    if (grad) grad[0] = grad[1] = 0.0;
    for (int j = 0; j < h->npoints; j++) {
        const double dx = x[0] - h->xy[2 * j], dy = x[1] - h->xy[2 * j + 1];
        const double a = h->c[j] / (2.0 * M_PI), r2 = dx * dx + dy * dy;
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

static sem_bc_kind all_neumann(int tag, void *ctx)
{
    (void)tag;
    (void)ctx;
    return SEM_BC_NEUMANN;
}

/* (n × ∇H_r)·ν on the cut mesh's boundary edge tag = 3 e + k: the
 * tangential derivative of H_r along the edge, the same from both sides */
static double tr_flux(const double x[2], const double n[2], int tag, void *ctx)
{
    tdata *d = ctx;
    const int e = tag / 3;
    double rs[2], v, g[2];
    if (sem_locator_invert(d->loc, e, x, rs)) {
        d->fail = 1;
        return 0.0;
    }
    sem_field_evaluator_eval_ref(d->t->h->ev, e, rs[0], rs[1], &v, g, NULL);
    return -g[1] * n[0] + g[0] * n[1];
}

/* reference coordinates of the point at u in [0,1] along edge k */
static void edge_point(int k, double u, double rs[2])
{
    if (k == 0) rs[0] = u, rs[1] = 0.0;
    else if (k == 1) rs[0] = 1.0 - u, rs[1] = u;
    else rs[0] = 0.0, rs[1] = 1.0 - u;
}

sq_status sq_theta_field_solve(const cad_face *face, const sem_tri_mesh *mesh,
                               const sem_locator *loc, sq_h_field *h, const int *loops,
                               int nloops, const int *sing, sq_theta_field *out, sq_error *err)
{
    memset(out, 0, sizeof *out);
    out->mesh = mesh;
    out->h = h;
    const int nt = mesh->ntris, np = h->npoints;
    sem_poisson *solver = NULL;
    int *queue = NULL;
    sq_status st = sq_branch_cut_build(mesh, loops, nloops, np, sing, &out->cut, err);
    if (st == SQ_OK) st = sem_tri_mesh_cut(mesh, out->cut.cut, 0, &out->cut_mesh, NULL, err);
    if (st != SQ_OK) goto done;
    sem_tri_mesh *cm = out->cut_mesh;
    for (int q = 0; q < 3 * nt; q++)
        if (cm->neigh[q] < 0) cm->btag[q] = q; /* the element is in the tag */
    /* step 1: branches of arg(x − X_j) continuous across uncut edges */
    out->aref = malloc(sizeof(double) * ((size_t)np * nt + 1));
    queue = malloc(sizeof(int) * ((size_t)nt + 1));
    unsigned char *seen = calloc((size_t)nt + 1, 1);
    if (!out->aref || !queue || !seen) {
        free(seen);
        st = SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
        goto done;
    }
    int head = 0, tail = 0;
    queue[tail++] = 0;
    seen[0] = 1;
    while (head < tail) {
        const int e = queue[head++];
        double xc[2];
        sem_locator_map(loc, e, 1.0 / 3.0, 1.0 / 3.0, xc, NULL);
        int from = -1; /* a visited neighbour across an uncut edge */
        for (int k = 0; k < 3 && e != 0; k++)
            if (cm->neigh[3 * e + k] >= 0 && seen[cm->neigh[3 * e + k]] == 2) from = cm->neigh[3 * e + k];
        for (int j = 0; j < np; j++) {
            const double a = atan2(xc[1] - h->xy[2 * j + 1], xc[0] - h->xy[2 * j]);
            out->aref[(size_t)j * nt + e] = from < 0 ? a : near_branch(a, out->aref[(size_t)j * nt + from]);
        }
        seen[e] = 2;
        for (int k = 0; k < 3; k++) {
            const int nb = cm->neigh[3 * e + k];
            if (nb >= 0 && !seen[nb]) seen[nb] = 1, queue[tail++] = nb;
        }
    }
    free(seen);
    if (tail != nt) {
        st = SQ_FAIL(err, SQ_ERR_INTERNAL, "theta: the cut mesh is not connected");
        goto done;
    }
    /* step 2, with H_r's element matrices: the cut mesh has its elements */
    if ((st = sem_poisson_create_like(&h->solver, cm, all_neumann, NULL, &solver, err)) != SQ_OK)
        goto done;
    out->ndofs = sem_poisson_ndofs(solver);
    out->work = sem_poisson_work_done(solver);
    if ((st = sem_field_create(cm, h->order, 1, &out->tr, err)) != SQ_OK) goto done;
    tdata d = {out, loc, 0};
    sem_poisson_data data = {NULL, NULL, tr_flux, &d, 0, NULL};
    if ((st = sem_poisson_solve(solver, &data, out->tr, err)) != SQ_OK) goto done;
    if (d.fail) {
        st = SQ_FAIL(err, SQ_ERR_INTERNAL, "theta: a boundary point left its element");
        goto done;
    }
    if ((st = sem_field_evaluator_create(out->tr, loc, &out->ev, err)) != SQ_OK) goto done;
    /* step 3: anchor on the first edge of the outer loop */
    const int edge0 = cad_face_loop_first_edge(face, 0);
    int hb = -1;
    for (int q = 0; q < 3 * nt && hb < 0; q++)
        if (mesh->neigh[q] < 0 && mesh->btag[q] == edge0) hb = q;
    if (hb < 0) {
        st = SQ_FAIL(err, SQ_ERR_INTERNAL, "theta: no element on edge %d", edge0);
        goto done;
    }
    double rs[2], tan[2], sp;
    edge_point(hb % 3, 0.5, rs);
    const double raw = sq_theta_field_eval_ref(out, hb / 3, rs[0], rs[1], NULL);
    sem_locator_map(loc, hb / 3, rs[0], rs[1], out->anchor, NULL);
    if ((st = cad_face_edge_project(face, edge0, out->anchor, &sp, NULL, NULL, err)) != SQ_OK ||
        (st = cad_face_edge_eval(face, edge0, sp, NULL, tan, NULL, err)) != SQ_OK)
        goto done;
    out->theta0 = atan2(tan[1], tan[0]) - raw;
done:
    free(queue);
    sem_poisson_free(&solver);
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
