#include "h_field.h"

#include "gauss.h"
#include "poisson.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

void sq_h_field_free(sq_h_field *h)
{
    if (!h) return;
    free(h->xy);
    free(h->c);
    free(h->loop_flux);
    sem_field_evaluator_free(&h->ev);
    sem_poisson_free(&h->solver);
    sem_field_free(&h->hr);
    memset(h, 0, sizeof *h);
}

double sq_h_singular(const sq_h_field *h, const double x[2], double grad[2])
{
    double v = 0.0;
    if (grad) grad[0] = grad[1] = 0.0;
    for (int j = 0; j < h->npoints; j++) {
        const double dx = x[0] - h->xy[2 * j], dy = x[1] - h->xy[2 * j + 1];
        const double r2 = dx * dx + dy * dy, a = h->c[j] / (2.0 * M_PI);
        v += 0.5 * a * log(r2);
        if (grad) {
            grad[0] += a * dx / r2;
            grad[1] += a * dy / r2;
        }
    }
    return v;
}

double sq_h_field_eval_ref(const sq_h_field *h, int e, double r, double s, double x[2],
                           double grad[2])
{
    double v, g[2], xx[2], gs[2];
    sem_field_evaluator_eval_ref(h->ev, e, r, s, &v, g, xx);
    v += sq_h_singular(h, xx, gs) + h->shift;
    if (grad) {
        grad[0] = g[0] + gs[0];
        grad[1] = g[1] + gs[1];
    }
    if (x) x[0] = xx[0], x[1] = xx[1];
    return v;
}

/* The curvature data on one boundary element edge of a CAD edge of
 * varying curvature: the arc lengths it spans, [s0, s0 + ds] in the
 * direction of travel, and, where the field's rule does not resolve κ
 * there, its flux density: the exact turning of the tangent over the span
 * divided by the element edge's length (curvature_spans). */
typedef struct {
    int tag;
    int pointwise; /* the rule resolves κ here: κ itself */
    double s0, ds, g;
} turn_span;

typedef struct {
    const cad_face *face;
    const sq_h_field *h;
    turn_span *span; /* every boundary element edge, by CAD edge and s0 */
    int *first;      /* num_edges + 1: each CAD edge's spans in span[] */
    double gshift;   /* constant removed from the flux */
    sq_status st;
    sq_error *err;
} bdata;

static sem_bc_kind all_neumann(int tag, void *ctx)
{
    (void)tag;
    (void)ctx;
    return SEM_BC_NEUMANN;
}

/* The span of CAD edge tag holding arc length s (the last span with s0 <=
 * s; before the first, the last one, which on a closed edge wraps past its
 * closing point), NULL on an edge without spans. */
static const turn_span *span_at(const bdata *b, int tag, double s)
{
    int lo = b->first[tag], hi = b->first[tag + 1] - 1;
    if (hi < lo) return NULL;
    if (s < b->span[lo].s0) return &b->span[hi];
    while (lo < hi) {
        const int mid = (lo + hi + 1) / 2;
        if (b->span[mid].s0 <= s) lo = mid;
        else hi = mid - 1;
    }
    return &b->span[lo];
}

/* ∂H_r/∂ν = κ_g − ∂H_s/∂ν (eq. 12 with the singular part moved over), κ_g
 * where the rule does not resolve it as its span's mean (curvature_spans) */
static double hr_flux(const double x[2], const double n[2], int tag, void *ctx)
{
    bdata *b = ctx;
    double s = 0.0, kappa = 0.0, gs[2];
    if (b->st == SQ_OK) b->st = cad_face_edge_project(b->face, tag, x, &s, NULL, NULL, b->err);
    const turn_span *sp = span_at(b, tag, s);
    if (sp && !sp->pointwise)
        kappa = sp->g;
    else if (b->st == SQ_OK)
        b->st = cad_face_edge_eval(b->face, tag, s, NULL, NULL, &kappa, b->err);
    sq_h_singular(b->h, x, gs);
    return kappa - (gs[0] * n[0] + gs[1] * n[1]) - b->gshift;
}

/* Point u in [0, 1] of boundary element edge h (edge h % 3 of element
 * h / 3, from its vertex h % 3 to the next): x, the outward unit normal n
 * and the length element *ds (per unit of u). */
static void edge_point(const sem_locator *loc, int h, double u, double x[2], double n[2],
                       double *ds)
{
    const int e = h / 3, k = h % 3;
    double rs[2], d[2], J[4];
    if (k == 0) rs[0] = u, rs[1] = 0, d[0] = 1, d[1] = 0;
    else if (k == 1) rs[0] = 1 - u, rs[1] = u, d[0] = -1, d[1] = 1;
    else rs[0] = 0, rs[1] = 1 - u, d[0] = 0, d[1] = -1;
    sem_locator_map(loc, e, rs[0], rs[1], x, J);
    const double tx = J[0] * d[0] + J[1] * d[1], ty = J[2] * d[0] + J[3] * d[1];
    *ds = hypot(tx, ty);
    n[0] = ty / *ds;
    n[1] = -tx / *ds;
}

static int cmp_span(const void *pa, const void *pb)
{
    const turn_span *a = pa, *b = pb;
    if (a->tag != b->tag) return (a->tag > b->tag) - (a->tag < b->tag);
    return (a->s0 > b->s0) - (a->s0 < b->s0);
}

/* ∫κ, ∫|κ| over boundary element edge h of CAD edge tag by the nq-point
 * Gauss–Legendre rule t, w on the mesh's geometry (κ at the points' feet on
 * the edge), and the element edge's length. */
static sq_status edge_turning(const cad_face *face, const sem_locator *loc, int h, int tag, int nq,
                              const double *t, const double *w, double *ik, double *iabs,
                              double *len, sq_error *err)
{
    *ik = *iabs = *len = 0.0;
    for (int q = 0; q < nq; q++) {
        double x[2], n[2], dsu, sq, kappa;
        edge_point(loc, h, 0.5 * (1.0 + t[q]), x, n, &dsu);
        SQ_TRY(cad_face_edge_project(face, tag, x, &sq, NULL, NULL, err));
        SQ_TRY(cad_face_edge_eval(face, tag, sq, NULL, NULL, &kappa, err));
        *ik += 0.5 * w[q] * dsu * kappa;
        *iabs += 0.5 * w[q] * dsu * fabs(kappa);
        *len += 0.5 * w[q] * dsu;
    }
    return SQ_OK;
}

/* The span of boundary element edge h (from mesh vertex va to vb) on CAD
 * edge tag: its ends' arc lengths ordered along the direction of travel,
 * and the turning of the CAD tangent between them, exact up to a multiple
 * of 2π, which the rule's ∫κ ik (within far less than π of it) decides. */
static sq_status edge_span(const cad_face *face, const sem_tri_mesh *m, int h, int tag, double ik,
                           double len, turn_span *sp, sq_error *err)
{
    const int va = m->tri[h], vb = m->tri[3 * (h / 3) + (h % 3 + 1) % 3];
    const double L = cad_face_edge_length(face, tag);
    double s[2], tan[2][2], p0[2], p1[2];
    SQ_TRY(cad_face_edge_project(face, tag, &m->vxy[2 * va], &s[0], NULL, NULL, err));
    SQ_TRY(cad_face_edge_project(face, tag, &m->vxy[2 * vb], &s[1], NULL, NULL, err));
    SQ_TRY(cad_face_edge_eval(face, tag, 0.0, p0, NULL, NULL, err));
    SQ_TRY(cad_face_edge_eval(face, tag, L, p1, NULL, NULL, err));
    const int closed = hypot(p1[0] - p0[0], p1[1] - p0[1]) < 1e-9 * L;
    double ds = s[1] - s[0];
    if (closed) ds -= L * round(ds / L); /* the short way round */
    double s0 = ds < 0.0 ? s[0] + ds : s[0];
    if (closed) s0 -= L * floor(s0 / L);
    double s1 = s0 + fabs(ds);
    if (closed && s1 > L) s1 -= L; /* past the closing point */
    SQ_TRY(cad_face_edge_eval(face, tag, s0, NULL, tan[0], NULL, err));
    SQ_TRY(cad_face_edge_eval(face, tag, fmin(s1, L), NULL, tan[1], NULL, err));
    const double a = atan2(tan[0][0] * tan[1][1] - tan[0][1] * tan[1][0],
                           tan[0][0] * tan[1][0] + tan[0][1] * tan[1][1]);
    const double turn = a + 2.0 * M_PI * round((ik - a) / (2.0 * M_PI));
    *sp = (turn_span){tag, 0, s0, fabs(ds), turn / len};
    return SQ_OK;
}

/* A rule of nq points resolves κ on a span when it agrees with the rule of
 * nq / 2 points (the usual estimate of the finer rule's error) to this
 * fraction of the span's ∫|κ|: the spans that keep pointwise κ then leave
 * an imbalance below 1e-6 of the data, a hundredth of what the solver
 * accepts (CG_COMPAT_RTOL, poisson_cg.c). */
#define KAPPA_RESOLVED 1e-6

/* One span per boundary element edge on a CAD edge of varying curvature
 * (a line's or circle's κ is constant: every rule integrates it exactly up
 * to the element edge's length, as it does the span means).  Where the
 * rule does not resolve κ, the span's mean makes ∮κ over those spans their
 * exact total turning (Gauss–Bonnet) for any rule that integrates a
 * constant over an element edge, the solver's included: pointwise κ, on a
 * B-spline edge whose curvature varies within one element (T106's blade),
 * missed it by 1e-3 of the data, the field's rule and the solver's by
 * different amounts. */
static sq_status curvature_spans(const sem_locator *loc, const sem_tri_mesh *m, int nq, bdata *b,
                                 sq_error *err)
{
    const int ne = cad_face_num_edges(b->face);
    double t[64], w[64], t2[64], w2[64];
    SQ_TRY(sem_gauss_jacobi(nq, 0.0, 0.0, t, w, err));
    SQ_TRY(sem_gauss_jacobi(nq / 2, 0.0, 0.0, t2, w2, err));
    b->span = malloc(sizeof(turn_span) * (3 * (size_t)m->ntris + 1));
    b->first = calloc((size_t)ne + 2, sizeof(int));
    if (!b->span || !b->first) return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    int nb = 0;
    for (int h = 0; h < 3 * m->ntris; h++) {
        const int tag = m->btag[h];
        if (m->neigh[h] >= 0) continue;
        const cad_edge_type type = cad_face_edge_type(b->face, tag);
        if (type == CAD_EDGE_LINE || type == CAD_EDGE_CIRCLE) continue;
        double ik, iabs, len, ik2, iabs2, len2;
        SQ_TRY(edge_turning(b->face, loc, h, tag, nq, t, w, &ik, &iabs, &len, err));
        SQ_TRY(edge_turning(b->face, loc, h, tag, nq / 2, t2, w2, &ik2, &iabs2, &len2, err));
        SQ_TRY(edge_span(b->face, m, h, tag, ik, len, &b->span[nb], err));
        b->span[nb].pointwise = fabs(ik - ik2) <= KAPPA_RESOLVED * iabs;
        nb++;
        b->first[tag + 2]++;
    }
    qsort(b->span, (size_t)nb, sizeof(turn_span), cmp_span);
    for (int e = 0; e < ne; e++) b->first[e + 2] += b->first[e + 1];
    for (int e = 0; e <= ne; e++) b->first[e] = b->first[e + 1];
    return SQ_OK;
}

/* Integrals over the mesh boundary (Gauss–Legendre on every boundary
 * element edge, exact geometry of the mesh): of the data g, |g| and 1, of
 * g and 1 per boundary loop (lg, llen: nloops each), and the face's
 * integrals of H_s and 1 by the divergence theorem (Δ ln r = 0 away from
 * the points): ∫ ln|x − X| dA = ∮ (2 ln r − 1)/4 (x − X)·ν ds, the field
 * r (2 ln r − 1)/4 e_r vanishing at X, and ∫ 1 dA = ∮ (x − o)·ν / 2 ds.
 * The integrands are smooth on the boundary (the points are inside, the
 * triangulation graded towards them), where a volume rule meets ln r's
 * singularity at the vertex X. */
typedef struct {
    double ig, iabs, len, ihs, area;
    double *lg, *llen;
} bsums;

static sq_status boundary_integral(const sem_locator *loc, const sem_tri_mesh *m, int nq, bdata *b,
                                   bsums *S, sq_error *err)
{
    const sq_h_field *hf = b->h;
    double t[64], w[64];
    SQ_TRY(sem_gauss_jacobi(nq, 0.0, 0.0, t, w, err));
    S->ig = S->iabs = S->len = S->ihs = S->area = 0.0;
    for (int l = 0; l < cad_face_num_loops(b->face); l++) S->lg[l] = S->llen[l] = 0.0;
    const double o[2] = {m->vxy[0], m->vxy[1]}; /* the area's origin: on the face */
    for (int h = 0; h < 3 * m->ntris; h++) {
        if (m->neigh[h] >= 0) continue;
        const int l = cad_face_edge_loop(b->face, m->btag[h]);
        for (int q = 0; q < nq; q++) {
            double x[2], n[2], ds;
            edge_point(loc, h, 0.5 * (1.0 + t[q]), x, n, &ds);
            const double g = hr_flux(x, n, m->btag[h], b), wq = 0.5 * w[q] * ds;
            S->ig += wq * g;
            S->iabs += wq * fabs(g);
            S->len += wq;
            S->lg[l] += wq * g;
            S->llen[l] += wq;
            S->area += 0.5 * wq * ((x[0] - o[0]) * n[0] + (x[1] - o[1]) * n[1]);
            for (int j = 0; j < hf->npoints; j++) {
                const double dx = x[0] - hf->xy[2 * j], dy = x[1] - hf->xy[2 * j + 1];
                S->ihs += wq * hf->c[j] / (2.0 * M_PI) * 0.25 * (log(dx * dx + dy * dy) - 1.0) *
                          (dx * n[0] + dy * n[1]);
            }
        }
        SQ_TRY(b->st);
    }
    return SQ_OK;
}

sq_status sq_h_field_solve(const cad_face *face, const sq_face_info *info,
                           const sem_tri_mesh *mesh, const sem_locator *loc, int order,
                           int npoints, const double *xy, const int *valence, const int *quads,
                           sq_h_field *out, sq_error *err)
{
    memset(out, 0, sizeof *out);
    out->mesh = mesh;
    out->order = order;
    out->npoints = npoints;
    out->xy = malloc(sizeof(double) * (2 * (size_t)npoints + 1));
    out->c = malloc(sizeof(double) * ((size_t)npoints + 1));
    const int nl = cad_face_num_loops(face);
    out->loop_flux = calloc((size_t)nl + 1, sizeof(double));
    double *lg = malloc(sizeof(double) * (2 * (size_t)nl + 1)), *llen = lg ? lg + nl : NULL;
    sem_point_source *ps = malloc(sizeof *ps * ((size_t)info->nvertices + 1));
    sq_status st = SQ_OK;
    bdata b = {face, out, NULL, NULL, 0.0, SQ_OK, err};
    if (!out->xy || !out->c || !out->loop_flux || !lg || !ps) {
        st = SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
        goto done;
    }
    for (int j = 0; j < npoints; j++) {
        out->xy[2 * j] = xy[2 * j];
        out->xy[2 * j + 1] = xy[2 * j + 1];
        out->c[j] = M_PI_2 * (4 - valence[j]); /* c_j = (π/2)(4 − V_j) */
    }
    /* corner point fluxes s_i = n_i π/2 − α_i at the mesh vertex there */
    int nps = 0;
    double ssum = 0.0, sabs = 0.0;
    for (int i = 0; i < info->nvertices; i++) {
        const sq_vertex *v = &info->vertices[i];
        const double s = quads[i] * M_PI_2 - v->angle_deg * M_PI / 180.0;
        if (fabs(s) < 1e-12) continue;
        int found = 0;
        for (int h = 0; h < 3 * mesh->ntris && !found; h++) {
            const int mv = mesh->tri[h];
            if (hypot(mesh->vxy[2 * mv] - v->x, mesh->vxy[2 * mv + 1] - v->y) > 1e-9 *
                    (1.0 + fabs(v->x) + fabs(v->y)))
                continue;
            const int k = h % 3;
            ps[nps] = (sem_point_source){h / 3, k == 1 ? 1.0 : 0.0, k == 2 ? 1.0 : 0.0, s};
            out->loop_flux[v->loop] += s;
            nps++;
            found = 1;
        }
        if (!found) {
            st = SQ_FAIL(err, SQ_ERR_INTERNAL, "corner (%g, %g) is not a mesh vertex", v->x, v->y);
            goto done;
        }
        ssum += s;
        sabs += fabs(s);
    }
    out->ncorner_sources = nps;
    bsums S = {0.0, 0.0, 0.0, 0.0, 0.0, lg, llen};
    if ((st = curvature_spans(loc, mesh, order + 8, &b, err)) != SQ_OK ||
        (st = boundary_integral(loc, mesh, order + 8, &b, &S, err)) != SQ_OK)
        goto done;
    out->imbalance = S.ig + ssum;
    out->data_size = S.iabs + sabs;
    b.gshift = out->imbalance / S.len; /* the quadrature residue, spread evenly */
    for (int l = 0; l < nl; l++) out->loop_flux[l] += lg[l] - b.gshift * llen[l];
    if ((st = sem_poisson_create(mesh, order, SEM_CG, all_neumann, NULL, &out->solver, err)) !=
        SQ_OK)
        goto done;
    out->ndofs = sem_poisson_ndofs(out->solver);
    if ((st = sem_field_create(mesh, order, 1, &out->hr, err)) != SQ_OK) goto done;
    sem_poisson_data data = {NULL, NULL, hr_flux, &b, nps, ps, 0};
    if ((st = sem_poisson_solve(out->solver, &data, out->hr, err)) != SQ_OK) {
        /* the solver's own quadrature of the data found them unbalanced:
         * a property of this pattern on this face, not a usage error */
        if (st == SQ_ERR_USAGE && err) {
            char why[sizeof err->msg];
            snprintf(why, sizeof why, "%s", err->msg);
            st = SQ_FAIL(err, SQ_ERR_PATTERN,
                         "the H field of this pattern cannot be solved: %s (the field's "
                         "quadrature does not resolve the boundary data)",
                         why);
        }
        goto done;
    }
    if ((st = b.st) != SQ_OK) goto done;
    if ((st = sem_field_evaluator_create(out->hr, loc, &out->ev, err)) != SQ_OK) goto done;
    /* zero mean of H = H_s + H_r (H_r has zero mean already) */
    out->shift = -S.ihs / S.area;
done:
    free(ps);
    free(lg);
    free(b.span);
    free(b.first);
    if (st != SQ_OK) sq_h_field_free(out);
    return st;
}
