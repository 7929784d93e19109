/* semquad — one discretization of every interface of a domain: the split
 * road's rounds over the faces (domain.h, designs 2 and 3) and the points
 * the layout road slides a face's vertices onto. */
#include "domain.h"
#include "quad_edges.h"
#include "quad_split.h"
#include "sq_parallel.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Rounds of design 2: each adds only the splits the refinement made near
 * an interface in one face to the other, and a split is never undone, so
 * the lists settle in two or three rounds (docs/domains.md). */
#define MAX_ROUNDS 8
/* arc lengths closer than this part of a curve are one point: the faces
 * place the same points to rounding (their arc lengths run in opposite
 * senses) */
#define SAME_ARC 1e-9

typedef struct {
    int n, cap;
    double *s;
} arc_list;

static sq_status arc_add(arc_list *a, double s, sq_error *err)
{
    if (a->n == a->cap) {
        int cap = 2 * a->cap + 16;
        double *p = realloc(a->s, sizeof(double) * (size_t)cap);
        if (!p) return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
        a->s = p, a->cap = cap;
    }
    a->s[a->n++] = s;
    return SQ_OK;
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* Sorted, points within tol of the one before dropped. */
static void arc_unique(arc_list *a, double tol)
{
    if (a->n < 2) return;
    qsort(a->s, (size_t)a->n, sizeof(double), cmp_double);
    int m = 1;
    for (int k = 1; k < a->n; k++)
        if (a->s[k] - a->s[m - 1] > tol) a->s[m++] = a->s[k];
    a->n = m;
}

/* Which side of curve c edge e of face f is, and whether it runs against
 * the curve's sense (the curve's is its first face's). */
static int runs_against(const sq_domain_curve *c, int f, int e)
{
    return !(c->face[0] == f && c->edge[0] == e) && c->reversed;
}

/* The interior vertices face f's triangulation put on its interfaces, in
 * their curves' arc length: into own[2c + side] (cleared first; side 0 for
 * the curve's first face) and all[c]. */
static sq_status collect(const sq_domain *d, int f, const sq_triangulation *tri, arc_list *own,
                         arc_list *all, sq_error *err)
{
    const cad_face *face = d->faces[f];
    const sem_tri_mesh *m = tri->mesh;
    for (int e = 0; e < cad_face_num_edges(face); e++) {
        int c = d->curve_of[f][e];
        const sq_domain_curve *cv = &d->curves[c];
        if (cv->face[1] < 0) continue;
        arc_list *mine = &own[2 * c + !(cv->face[0] == f && cv->edge[0] == e)];
        mine->n = 0;
        double L = cad_face_edge_length(face, e), eps = SAME_ARC * L;
        int rev = runs_against(cv, f, e);
        for (int t = 0; t < m->ntris; t++)
            for (int k = 0; k < 3; k++) {
                if (m->neigh[3 * t + k] >= 0 || m->btag[3 * t + k] != e) continue;
                for (int j = 0; j < 2; j++) {
                    double s = tri->bs[6 * t + 2 * k + j], sg = rev ? L - s : s;
                    if (sg > eps && sg < L - eps) {
                        SQ_TRY(arc_add(mine, sg, err));
                        SQ_TRY(arc_add(&all[c], sg, err));
                    }
                }
            }
        arc_unique(mine, eps);
    }
    return SQ_OK;
}

/* Face f's edge points from the curves' lists: its start, then the
 * interior points in its own sense. */
static sq_status face_points(const sq_domain *d, int f, const arc_list *all, arc_list *fp,
                             sq_edge_points *ep, sq_error *err)
{
    const cad_face *face = d->faces[f];
    for (int e = 0; e < cad_face_num_edges(face); e++) {
        int c = d->curve_of[f][e];
        const sq_domain_curve *cv = &d->curves[c];
        fp[e].n = 0;
        ep[e] = (sq_edge_points){0, NULL};
        if (cv->face[1] < 0) continue;
        double L = cad_face_edge_length(face, e);
        int rev = runs_against(cv, f, e);
        SQ_TRY(arc_add(&fp[e], 0.0, err));
        for (int k = 0; k < all[c].n; k++) SQ_TRY(arc_add(&fp[e], rev ? L - all[c].s[k] : all[c].s[k], err));
        qsort(fp[e].s, (size_t)fp[e].n, sizeof(double), cmp_double);
        ep[e] = (sq_edge_points){fp[e].n, fp[e].s};
    }
    return SQ_OK;
}

typedef struct {
    arc_list *own, *all;          /* per curve side (2c, 2c+1), per curve */
    arc_list **fp;                /* per face, per edge */
    sq_edge_points **ep;          /* per face, per edge */
    int **held;                   /* per face, per edge */
    sq_triangulation *tri;        /* per face */
} split_work;

static void work_free(const sq_domain *d, split_work *w)
{
    for (int c = 0; c < d->ncurves && w->own; c++)
        free(w->own[2 * c].s), free(w->own[2 * c + 1].s), free(w->all[c].s);
    for (int f = 0; f < d->nfaces && w->fp; f++) {
        for (int e = 0; w->fp[f] && e < cad_face_num_edges(d->faces[f]); e++) free(w->fp[f][e].s);
        free(w->fp[f]);
        free(w->ep[f]);
        free(w->held[f]);
        sq_triangulation_free(&w->tri[f]);
    }
    free(w->own), free(w->all), free(w->fp), free(w->ep), free(w->held), free(w->tri);
}

static sq_status work_alloc(const sq_domain *d, split_work *w, sq_error *err)
{
    size_t nc = (size_t)d->ncurves + 1, nf = (size_t)d->nfaces + 1;
    w->own = calloc(2 * nc, sizeof *w->own), w->all = calloc(nc, sizeof *w->all);
    w->fp = calloc(nf, sizeof *w->fp), w->ep = calloc(nf, sizeof *w->ep);
    w->held = calloc(nf, sizeof *w->held), w->tri = calloc(nf, sizeof *w->tri);
    if (!w->own || !w->all || !w->fp || !w->ep || !w->held || !w->tri)
        return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    for (int f = 0; f < d->nfaces; f++) {
        size_t ne = (size_t)cad_face_num_edges(d->faces[f]) + 1;
        w->fp[f] = calloc(ne, sizeof **w->fp), w->ep[f] = calloc(ne, sizeof **w->ep);
        w->held[f] = calloc(ne, sizeof **w->held);
        if (!w->fp[f] || !w->ep[f] || !w->held[f]) return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
        for (int e = 0; e + 1 < (int)ne; e++) w->held[f][e] = d->curves[d->curve_of[f][e]].face[1] >= 0;
    }
    return SQ_OK;
}

/* One step over the sharing faces on threads (sq_parallel_for): each face
 * triangulated (from the lists of the last round unless it is the first)
 * or meshed on its triangulation, writing only its own result, so that
 * both are the serial run's for every thread count. */
typedef struct {
    const sq_domain *d;
    sq_mesher_options o; /* the caller's, the faces' own loops on their share of the threads */
    split_work *w;
    int first;
    sq_quad_mesh **out; /* NULL: triangulate */
} faces_step;

static sq_status step_range(void *ctx, long begin, long end, sq_error *err)
{
    const faces_step *s = ctx;
    for (long f = begin; f < end; f++) {
        if (!sq_domain_face_shares(s->d, (int)f)) continue;
        sq_mesher_options o = s->o;
        const cad_face *face = s->d->faces[f];
        const sq_face_info *info = &s->d->info[f];
        if (s->out) {
            o.held_edges = s->w->held[f];
            SQ_TRY(sq_mesh_split_triangulation(face, info, &s->w->tri[f], &o, &s->out[f], err));
            continue;
        }
        o.edge_points = s->first ? NULL : s->w->ep[f];
        sq_triangulation_free(&s->w->tri[f]);
        SQ_TRY(sq_split_triangulate(face, info, &o, &s->w->tri[f], err));
    }
    return SQ_OK;
}

static sq_status faces_step_run(const sq_domain *d, const sq_mesher_options *mo, split_work *w,
                                int first, sq_quad_mesh **out, sq_error *err)
{
    int inner, outer = sq_threads_nested(mo->threads, d->nfaces, &inner);
    faces_step s = {d, *mo, w, first, out};
    s.o.threads = inner;
    if (outer > 1) s.o.progress.fn = NULL; /* the faces' events would interleave */
    return sq_parallel_for(outer, d->nfaces, 1, step_range, &s, err);
}

/* One round of design 2: every sharing face triangulated; *agreed when
 * every face put exactly the joined list's points on each of its
 * interfaces. */
static sq_status round_once(const sq_domain *d, const sq_mesher_options *mo, split_work *w,
                            int first, int *agreed, sq_error *err)
{
    for (int c = 0; c < d->ncurves; c++) w->all[c].n = 0;
    SQ_TRY(faces_step_run(d, mo, w, first, NULL, err));
    for (int f = 0; f < d->nfaces; f++)
        if (sq_domain_face_shares(d, f)) SQ_TRY(collect(d, f, &w->tri[f], w->own, w->all, err));
    *agreed = 1;
    for (int c = 0; c < d->ncurves; c++) {
        const sq_domain_curve *cv = &d->curves[c];
        if (cv->face[1] < 0) continue;
        arc_unique(&w->all[c], SAME_ARC * cad_face_edge_length(d->faces[cv->face[0]], cv->edge[0]));
        /* the union has as many points as each face's list only if each is it */
        *agreed &= w->own[2 * c].n == w->all[c].n && w->own[2 * c + 1].n == w->all[c].n;
    }
    return SQ_OK;
}

sq_status sq_domain_mesh_split(const sq_domain *d, const sq_mesher_options *mo, sq_quad_mesh **out,
                               int *rounds, sq_error *err)
{
    split_work w = {0};
    sq_status st = work_alloc(d, &w, err);
    int agreed = 0, r = 0;
    for (; st == SQ_OK && !agreed && r < MAX_ROUNDS; r++) {
        st = round_once(d, mo, &w, r == 0, &agreed, err);
        for (int f = 0; f < d->nfaces && st == SQ_OK && !agreed; f++)
            if (sq_domain_face_shares(d, f)) st = face_points(d, f, w.all, w.fp[f], w.ep[f], err);
    }
    *rounds = r;
    if (st == SQ_OK && !agreed)
        st = SQ_FAIL(err, SQ_ERR_LAYOUT,
                     "the faces' triangulations did not agree on their shared edges after %d "
                     "rounds; try another --size",
                     MAX_ROUNDS);
    if (st == SQ_OK) st = faces_step_run(d, mo, &w, 0, out, err);
    if (st != SQ_OK)
        for (int f = 0; f < d->nfaces; f++)
            if (sq_domain_face_shares(d, f)) sq_quad_mesh_free(&out[f]);
    work_free(d, &w);
    return st;
}

/* Face g's vertices on its edge eg (corners of its boundary sides there)
 * into a, as arc lengths on face f's edge e across (the same curve, both
 * senses). */
static sq_status vertices_across(const sq_domain *d, const sq_quad_mesh *q, int g, int eg, int f,
                                 int e, int reversed, arc_list *a, sq_error *err)
{
    double Lg = cad_face_edge_length(d->faces[g], eg), Lf = cad_face_edge_length(d->faces[f], e);
    for (int b = 0; b < q->nbnd; b++) {
        if (q->bnd_tag[b] != eg) continue;
        for (int j = 0; j < 2; j++) {
            int v = sq_quad_corner_node(q, q->bnd_quad[b], (q->bnd_side[b] + j) % 4);
            double sg;
            SQ_TRY(cad_face_edge_project(d->faces[g], eg, &q->xy[2 * (size_t)v], &sg, NULL, NULL,
                                         err));
            SQ_TRY(arc_add(a, (reversed ? Lg - sg : sg) * Lf / Lg, err));
        }
    }
    return SQ_OK;
}

sq_status sq_domain_layout_points(const sq_domain *d, int f, sq_quad_mesh *const *q,
                                  sq_edge_points *ep, int *any, sq_error *err)
{
    *any = 0;
    int ne = cad_face_num_edges(d->faces[f]);
    for (int e = 0; e < ne; e++) ep[e] = (sq_edge_points){0, NULL};
    sq_status st = SQ_OK;
    for (int e = 0; e < ne && st == SQ_OK; e++) {
        const sq_domain_curve *cv = &d->curves[d->curve_of[f][e]];
        int side = cv->face[0] == f && cv->edge[0] == e, g = cv->face[side], eg = cv->edge[side];
        /* a periodic pair within f: its image side (side 1) slides onto the
         * master's vertices of f's own mesh (held there, so kept when f is
         * meshed again) */
        if (cv->face[1] < 0 || g > f || (g == f && side) || !q[g]) continue;
        double L = cad_face_edge_length(d->faces[f], e), tol = SAME_ARC * L;
        /* a closed curve (a whole loop): its vertices wherever they are;
         * else its start, then the interior vertices */
        int closed = cad_face_edge_closed(d->faces[f], e);
        arc_list a = {0};
        st = closed ? SQ_OK : arc_add(&a, 0.0, err);
        if (st == SQ_OK) st = vertices_across(d, q[g], g, eg, f, e, cv->reversed, &a, err);
        for (int k = 0; closed && k < a.n; k++)
            if (a.s[k] > L - tol) a.s[k] = 0.0; /* the closing point is the start */
        arc_unique(&a, tol);
        while (!closed && a.n > 1 && a.s[a.n - 1] > L - tol) a.n--; /* the end: not a point */
        ep[e] = (sq_edge_points){a.n, a.s};
        *any = 1;
    }
    if (st != SQ_OK) sq_domain_layout_points_free(ep, ne);
    return st;
}

void sq_domain_layout_points_free(sq_edge_points *ep, int ne)
{
    for (int e = 0; ep && e < ne; e++) {
        free((double *)ep[e].s);
        ep[e] = (sq_edge_points){0, NULL};
    }
}
