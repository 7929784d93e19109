#include "htheta_field.h"

#include "critical_points.h"
#include "field_analysis.h"
#include "tri_quad.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

void sq_htheta_options_default(sq_htheta_options *opt)
{
    memset(opt, 0, sizeof *opt);
    opt->order = 8;
    sq_tri_options_default(&opt->tri);
    opt->tri.order = 8;
    opt->grading = 1e-3;
    opt->align_tol_deg = 0.01;
}

void sq_htheta_free(sq_htheta *f)
{
    if (!f) return;
    sq_theta_field_free(&f->theta);
    sq_h_field_free(&f->h);
    sem_locator_free(&f->loc);
    sq_triangulation_free(&f->tri);
    sq_pattern_balance_free(&f->balance);
    sq_face_info_free(&f->info);
    free(f->points);
    free(f->vloops);
    free(f->trace_size);
    free(f->loops);
    memset(f, 0, sizeof *f);
}

/* d reduced modulo π/2 into (−π/4, π/4] */
static double wrap_quarter(double d)
{
    return d - M_PI_2 * round(d / M_PI_2);
}

/* ∫ κ ds along a CAD edge: the unwrapped change of its tangent angle */
static sq_status edge_turning(const cad_face *face, int e, double *turn, sq_error *err)
{
    const int ns = 512;
    const double L = cad_face_edge_length(face, e);
    double t0[2], t1[2];
    *turn = 0.0;
    SQ_TRY(cad_face_edge_eval(face, e, 0.0, NULL, t0, NULL, err));
    for (int k = 1; k <= ns; k++) {
        SQ_TRY(cad_face_edge_eval(face, e, L * k / ns, NULL, t1, NULL, err));
        *turn += atan2(t0[0] * t1[1] - t0[1] * t1[0], t0[0] * t1[0] + t0[1] * t1[1]);
        t0[0] = t1[0], t0[1] = t1[1];
    }
    return SQ_OK;
}

static void edge_point(int k, double u, double rs[2])
{
    if (k == 0) rs[0] = u, rs[1] = 0.0;
    else if (k == 1) rs[0] = 1.0 - u, rs[1] = u;
    else rs[0] = 0.0, rs[1] = 1.0 - u;
}

/* θ minus the CAD edge's tangent angle at the points u = 1/4, 1/2, 3/4 of
 * every boundary element edge on loop l, in d (*nd of them) */
static sq_status boundary_deviations(const cad_face *face, const sq_htheta *f, int l, double *d,
                                     int *nd, sq_error *err)
{
    const sem_tri_mesh *m = f->tri.mesh;
    *nd = 0;
    for (int h = 0; h < 3 * m->ntris; h++) {
        if (m->neigh[h] >= 0 || cad_face_edge_loop(face, m->btag[h]) != l) continue;
        for (int q = 1; q <= 3; q++) {
            double rs[2], x[2], s, tan[2];
            edge_point(h % 3, 0.25 * q, rs);
            const double th = sq_theta_field_eval_ref(&f->theta, h / 3, rs[0], rs[1], NULL);
            sem_locator_map(f->loc, h / 3, rs[0], rs[1], x, NULL);
            SQ_TRY(cad_face_edge_project(face, m->btag[h], x, &s, NULL, NULL, err));
            SQ_TRY(cad_face_edge_eval(face, m->btag[h], s, NULL, tan, NULL, err));
            d[(*nd)++] = th - atan2(tan[1], tan[0]);
        }
    }
    return SQ_OK;
}

/* jumps, turning and alignment of every loop */
static sq_status loop_checks(const cad_face *face, sq_htheta *f, sq_error *err)
{
    /* the deviations once per loop for both the mean and the spread */
    double *d = malloc(sizeof(double) * (9 * (size_t)f->tri.mesh->ntris + 1));
    if (!d) return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    sq_status st = SQ_OK;
    for (int l = 0; l < f->nloops && st == SQ_OK; l++) {
        sq_htheta_loop *L = &f->loops[l];
        L->loop = l;
        double kappa = 0.0, corner_turn = 0.0, corner_s = 0.0;
        for (int k = 0; k < cad_face_loop_num_edges(face, l) && st == SQ_OK; k++) {
            double t;
            st = edge_turning(face, cad_face_loop_first_edge(face, l) + k, &t, err);
            kappa += t;
        }
        int nd = 0;
        if (st == SQ_OK) st = boundary_deviations(face, f, l, d, &nd, err);
        if (st != SQ_OK) break;
        for (int i = 0; i < f->info.nvertices; i++) {
            const sq_vertex *v = &f->info.vertices[i];
            if (v->loop != l) continue;
            const double a = v->angle_deg * M_PI / 180.0;
            corner_turn += M_PI - a;
            corner_s += f->balance.quads[i] * M_PI_2 - a;
        }
        /* the face is on the left: holes are walked clockwise */
        L->turning = (l == 0 ? 1.0 : -1.0) * (kappa + corner_turn);
        if (l > 0) {
            L->expected_jump = -(kappa + corner_s);
            L->jump = sq_theta_jump_around_loop(&f->theta, f->vloops, l);
        }
        double s4 = 0.0, c4 = 0.0;
        for (int i = 0; i < nd; i++) {
            s4 += sin(4.0 * d[i]);
            c4 += cos(4.0 * d[i]);
        }
        L->misalignment = 0.25 * atan2(s4, c4); /* circular mean of 4δ */
        for (int i = 0; i < nd; i++)
            L->spread = fmax(L->spread, fabs(wrap_quarter(d[i] - L->misalignment)));
        L->aligned = fabs(L->misalignment) <= f->align_tol;
    }
    free(d);
    return st;
}

/* e^H bounded to a factor SIZE_BOUND either way: it vanishes at a
 * valence-3 point and blows up at a valence-5 one. */
#define SIZE_BOUND 4.0
static double bounded_size(double H) { return fmin(fmax(exp(H), 1.0 / SIZE_BOUND), SIZE_BOUND); }

/* The sizes' scale c: the root mean square of the bounded e^-H over the
 * face, so that sizes e^H c give about area / size^2 quads, as a uniform
 * size does.  By a rule of degree 3 on each element (4 points): the bound
 * leaves kinks in the integrand, and a scale of counts needs no more than
 * a few thousandths (the disc: 0.2 % from rules of degree 12 and 20, which
 * agree to 1e-4; the 32 x 32 grid of the face's box that the rule replaces,
 * with a point location each, cost the disc 0.7 ms of its 14). */
static sq_status size_scale(sq_htheta *f, sq_error *err)
{
    sem_tri_quad *q = NULL;
    SQ_TRY(sem_tri_quad_create(3, &q, err));
    double sum = 0.0, area = 0.0;
    for (int e = 0; e < f->tri.mesh->ntris; e++)
        for (int k = 0; k < q->npts; k++) {
            const double r = q->rs[2 * k], t = q->rs[2 * k + 1];
            const double w = q->w[k] * sem_locator_map(f->loc, e, r, t, NULL, NULL);
            const double sz = bounded_size(sq_h_field_eval_ref(&f->h, e, r, t, NULL, NULL));
            sum += w / (sz * sz);
            area += w;
        }
    sem_tri_quad_free(&q);
    f->size_scale = area > 0.0 && sum > 0.0 ? sqrt(sum / area) : 1.0;
    return SQ_OK;
}

/* Element sizes with the grading at the first np extra points (the imposed
 * points) undone: sqrt(area) scaled by the refinement's target size without
 * those points over the target size with them, at the centroid (the
 * grading at singular corners is kept: the guiding field has it too). */
static sq_status trace_sizes(const sem_tri_mesh *m, const sq_tri_options *tri, double size, int np,
                             double **out, sq_error *err)
{
    double *t = malloc(sizeof *t * ((size_t)m->ntris + 1));
    if (!t) return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    sq_tri_options corners = *tri;
    corners.nextra = tri->nextra - np;
    corners.extra_xy = tri->extra_xy + 2 * np;
    if (tri->extra_sizes) corners.extra_sizes = tri->extra_sizes + np;
    for (int e = 0; e < m->ntris; e++) {
        const double *a = &m->vxy[2 * m->tri[3 * e]], *b = &m->vxy[2 * m->tri[3 * e + 1]],
                     *c = &m->vxy[2 * m->tri[3 * e + 2]];
        const double g[2] = {(a[0] + b[0] + c[0]) / 3.0, (a[1] + b[1] + c[1]) / 3.0};
        const double area =
            0.5 * fabs((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]));
        t[e] =
            sqrt(area) * sq_tri_graded_size(&corners, size, g) / sq_tri_graded_size(tri, size, g);
    }
    *out = t;
    return SQ_OK;
}

sq_status sq_htheta_compute(const cad_face *face, const sq_pattern *pattern,
                            const sq_htheta_options *opt, sq_htheta *out, sq_error *err)
{
    memset(out, 0, sizeof *out);
    double t0 = sq_now();
    double *extra = NULL, *pxy = NULL, *hextra = NULL;
    int *val = NULL, *sing = NULL;
    sq_status st = sq_face_info_compute(face, &out->info, err);
    if (st == SQ_OK) st = sq_pattern_check(face, &out->info, pattern, &out->balance, err);
    if (st != SQ_OK) goto done;
    const int np = pattern->npoints, nv = out->info.nvertices;
    out->npoints = np;
    out->nloops = out->info.nloops;
    out->align_tol = opt->align_tol_deg * M_PI / 180.0;
    out->points = calloc((size_t)np + 1, sizeof *out->points);
    out->loops = calloc((size_t)out->nloops + 1, sizeof *out->loops);
    extra = malloc(sizeof(double) * 2 * ((size_t)np + 2 * (size_t)nv + 1));
    hextra = malloc(sizeof(double) * ((size_t)np + 2 * (size_t)nv + 1));
    pxy = malloc(sizeof(double) * (2 * (size_t)np + 1));
    val = malloc(sizeof(int) * ((size_t)np + 1));
    sing = malloc(sizeof(int) * ((size_t)np + 1));
    if (!out->points || !out->loops || !extra || !hextra || !pxy || !val || !sing) {
        st = SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
        goto done;
    }
    /* the points and the singular corners as graded vertices (§4, Fig. 6) */
    int nextra = 0;
    for (int j = 0; j < np; j++) {
        pxy[2 * j] = extra[2 * j] = pattern->points[j].x;
        pxy[2 * j + 1] = extra[2 * j + 1] = pattern->points[j].y;
        val[j] = pattern->points[j].valence;
    }
    nextra = np;
    int ncorner = 0;
    if ((st = sq_singular_vertices(face, &out->info, extra + 2 * np, &ncorner, err)) != SQ_OK)
        goto done;
    nextra += ncorner;
    for (int i = 0; i < nv; i++) {
        const sq_vertex *v = &out->info.vertices[i];
        if (fabs(out->balance.quads[i] * M_PI_2 - v->angle_deg * M_PI / 180.0) < 1e-12) continue;
        if (out->balance.quads[i] == 2 && sq_vertex_near_straight(v)) continue;
        int dup = 0;
        for (int q = np; q < nextra; q++)
            dup |= hypot(extra[2 * q] - v->x, extra[2 * q + 1] - v->y) < 1e-12;
        if (dup) continue;
        extra[2 * nextra] = v->x;
        extra[2 * nextra + 1] = v->y;
        nextra++;
    }
    sq_tri_options tri = opt->tri;
    tri.order = opt->tri.order > 0 ? opt->tri.order : sq_tri_order_for(opt->order);
    tri.nextra = nextra;
    tri.extra_xy = extra;
    tri.size = sq_tri_size(&tri, out->info.area);
    for (int q = 0; q < nextra; q++)
        hextra[q] =
            (q < np && opt->point_grading > 0.0 ? opt->point_grading : opt->grading) * tri.size;
    tri.extra_sizes = hextra;
    tri.extra_growth = 1.0;
    if ((st = sq_triangulate(face, &tri, &out->tri, err)) != SQ_OK) goto done;
    const sem_tri_mesh *m = out->tri.mesh;
    if ((st = sem_locator_create(m, &out->loc, err)) != SQ_OK) goto done;
    if ((st = trace_sizes(m, &tri, tri.size, np, &out->trace_size, err)) != SQ_OK) goto done;
    if ((st = sq_mesh_vertex_loops(face, m, &out->vloops, err)) != SQ_OK) goto done;
    const double diag = hypot(out->info.bbox[2] - out->info.bbox[0],
                              out->info.bbox[3] - out->info.bbox[1]);
    for (int j = 0; j < np; j++) {
        int best = -1;
        double bd = HUGE_VAL;
        for (int v = 0; v < m->nverts; v++) {
            double d = hypot(m->vxy[2 * v] - pxy[2 * j], m->vxy[2 * v + 1] - pxy[2 * j + 1]);
            if (d < bd) bd = d, best = v;
        }
        if (bd > 1e-9 * diag) {
            st = SQ_FAIL(err, SQ_ERR_INTERNAL,
                         "singular point (%g, %g) did not become a mesh vertex (nearest %.3g away)",
                         pxy[2 * j], pxy[2 * j + 1], bd);
            goto done;
        }
        /* solve with the vertex's own coordinates: the point is exactly on it */
        pxy[2 * j] = m->vxy[2 * best];
        pxy[2 * j + 1] = m->vxy[2 * best + 1];
        sing[j] = best;
        sq_htheta_point *p = &out->points[j];
        p->x = pattern->points[j].x;
        p->y = pattern->points[j].y;
        p->valence = val[j];
        p->origin = pattern->points[j].origin;
        p->vertex = best;
        p->c = M_PI_2 * (4 - val[j]);
    }
    double t1 = sq_now();
    if ((st = sq_h_field_solve(face, &out->info, m, out->loc, opt->order, np, pxy, val,
                               out->balance.quads, &out->h, err)) != SQ_OK)
        goto done;
    out->work = sem_poisson_work_done(out->h.solver);
    if ((st = size_scale(out, err)) != SQ_OK) goto done;
    /* θ solves with H's factor */
    st = sq_theta_field_solve(face, m, out->loc, &out->h, out->vloops, out->nloops, sing,
                              &out->theta, err);
    sem_poisson_free(&out->h.solver);
    if (st != SQ_OK) goto done;
    for (int j = 0; j < np; j++)
        out->points[j].jump = sq_theta_jump_around_vertex(&out->theta, sing[j]);
    st = loop_checks(face, out, err);
    out->t_triangulate = t1 - t0;
    out->t_solve = sq_now() - t1;
done:
    free(extra);
    free(hextra);
    free(pxy);
    free(val);
    free(sing);
    if (st != SQ_OK) sq_htheta_free(out);
    return st;
}

sq_status sq_htheta_check_alignment(const sq_htheta *f, int allow_misaligned, sq_error *err)
{
    if (allow_misaligned) return SQ_OK;
    /* θ is fixed on the outer loop and ∂θ/∂s = κ_g with the corner fluxes
     * keeps it there: its misalignment is discretization error (0.02° on a
     * seven-pointed star, graded as for `mesh`), not holonomy, which only
     * holes can break */
    for (int l = 1; l < f->nloops; l++)
        if (!f->loops[l].aligned)
            return SQ_FAIL(err, SQ_ERR_PATTERN,
                           "the pattern breaks holonomy: the cross field is misaligned by %.4f "
                           "deg with boundary loop %d (%s); move the singular points or use "
                           "--allow-misaligned",
                           f->loops[l].misalignment * 180.0 / M_PI, l, l ? "a hole" : "outer");
    return SQ_OK;
}

int sq_htheta_eval(const sq_htheta *f, const double x[2], int *elem, double *H, double gH[2],
                   double *theta, double gtheta[2])
{
    int e;
    double r, s;
    if (sem_locator_find(f->loc, x, elem ? *elem : -1, &e, &r, &s)) return 1;
    if (elem) *elem = e;
    /* each of H and θ (with their singular log and arg terms) only when
     * asked for: the tracer needs θ alone, the sizes e^H alone */
    if (H || gH) {
        const double h = sq_h_field_eval_ref(&f->h, e, r, s, NULL, gH);
        if (H) *H = h;
    }
    if (theta || gtheta) {
        const double t = sq_theta_field_eval_ref(&f->theta, e, r, s, gtheta);
        if (theta) *theta = t;
    }
    return 0;
}

static int ht_direction(void *ctx, const double x[2], int *elem, double *theta)
{
    return sq_htheta_eval(ctx, x, elem, NULL, NULL, theta, NULL);
}

static double ht_element_size(void *ctx, int e) { return ((const sq_htheta *)ctx)->trace_size[e]; }

static double ht_size(void *ctx, const double x[2], int *elem)
{
    const sq_htheta *f = ctx;
    double H;
    if (sq_htheta_eval(f, x, elem, &H, NULL, NULL, NULL)) return 0.0;
    return bounded_size(H) * f->size_scale; /* eq. (21) */
}

sq_cross_field sq_htheta_cross_field(const sq_htheta *f)
{
    sq_cross_field c = {(void *)f, ht_direction, ht_element_size, ht_size};
    return c;
}

int sq_htheta_param_gradients(const sq_htheta *f, const double x[2], int *elem, double gu[2],
                              double gv[2], double curl[2])
{
    double H, gH[2], th, gt[2];
    if (sq_htheta_eval(f, x, elem, &H, gH, &th, gt)) return 1;
    const double w = exp(-H), c = cos(th), s = sin(th);
    gu[0] = w * c, gu[1] = w * s;   /* eq. (18) */
    gv[0] = -w * s, gv[1] = w * c;
    if (curl) {
        const double a = gt[0] + gH[1], b = gt[1] - gH[0]; /* Cauchy–Riemann residuals */
        curl[0] = w * (c * a + s * b);
        curl[1] = w * (c * b - s * a);
    }
    return 0;
}
