#include "guiding_field.h"

#include "field_error.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

sem_method sq_guiding_method_auto(const sq_face_info *info)
{
    for (int v = 0; v < info->nvertices; v++) {
        double q = info->vertices[v].angle_deg / 90.0;
        if (fabs(q - round(q)) * 90.0 > SQ_RIGHT_ANGLE_TOL_DEG) return SEM_DG;
    }
    return SEM_CG;
}

/* The correction of the data's angle at arc length s of edge (sq_bend). */
static double bend_turn(const sq_bend *b, int n, const cad_face *face, int edge, double s)
{
    double c = 0.0;
    for (int k = 0; k < n; k++) {
        const double span = b[k].len_in + b[k].len_out;
        if (edge == b[k].edge_in) {
            const double d = cad_face_edge_length(face, edge) - s; /* to the vertex */
            if (d < b[k].len_in) c += b[k].turn * (b[k].len_in - d) / span;
        }
        if (edge == b[k].edge_out && s < b[k].len_out)
            c -= b[k].turn * (b[k].len_out - s) / span;
    }
    return c;
}

static int bends_edge(const sq_bend *b, int n, int edge)
{
    for (int k = 0; k < n; k++)
        if (edge == b[k].edge_in || edge == b[k].edge_out) return 1;
    return 0;
}

/* Marcon 2019, eq. (3): (cos 4θ_b, sin 4θ_b), θ_b the tangent angle,
 * turned through the bends of the edge. */
static sq_status boundary_value(const cad_face *face, const sq_bend *bends, int nbends, int edge,
                                const double x[2], double uv[2], sq_error *err)
{
    double t[2];
    SQ_TRY(cad_face_edge_tangent_near(face, edge, x, t, err));
    double theta = atan2(t[1], t[0]);
    if (bends_edge(bends, nbends, edge)) {
        double s;
        SQ_TRY(cad_face_edge_project(face, edge, x, &s, NULL, NULL, err));
        theta += bend_turn(bends, nbends, face, edge, s);
    }
    uv[0] = cos(4.0 * theta);
    uv[1] = sin(4.0 * theta);
    return SQ_OK;
}

double sq_guiding_field_bend(const sq_guiding_field *g, const cad_face *face, int edge, double s)
{
    return bend_turn(g->bends, g->nbends, face, edge, s);
}

/* w = u + iv turned by twist x (1 − Re(w e^{−iφ}))/2: the family of
 * edges whose data is e^{iφ} keeps it, the other (−e^{iφ}) turns by the
 * whole twist (guiding_field.h). */
static void twist_data(double uv[2], double twist, double phase)
{
    const double a = twist * 0.5 * (1.0 - (uv[0] * cos(phase) + uv[1] * sin(phase)));
    const double u = uv[0] * cos(a) - uv[1] * sin(a), v = uv[0] * sin(a) + uv[1] * cos(a);
    uv[0] = u;
    uv[1] = v;
}

sq_status sq_guiding_field_data(const sq_guiding_field *g, const cad_face *face, int edge,
                                const double x[2], double uv[2], sq_error *err)
{
    SQ_TRY(boundary_value(face, g->bends, g->nbends, edge, x, uv, err));
    if (g->twist != 0.0) twist_data(uv, g->twist, g->twist_phase);
    return SQ_OK;
}

/* Boundary data of one component.  Every solve visits the same boundary
 * points in the same order, so the first pass keeps (x, u, v) of each point
 * and the others reuse them (one CAD projection per point); a point that
 * does not match is projected again. */
typedef struct {
    const cad_face *face;
    const sq_bend *bends;
    int nbends;
    int comp;
    long k, n, cap;      /* position in this pass; points kept by the first */
    double *memo;        /* 4 n: x, y, u, v (untwisted) */
    double twist, phase; /* sq_guiding_field */
    sq_status status;    /* first failure, latched: the solver's callback has no error path */
    sq_error *err;
} bdata_ctx;

static double boundary_data(const double x[2], const double n[2], int tag, void *p)
{
    (void)n;
    bdata_ctx *c = p;
    double uv[2] = {0.0, 0.0};
    const long k = c->k++;
    if (k < c->n && c->memo[4 * k] == x[0] && c->memo[4 * k + 1] == x[1]) {
        uv[0] = c->memo[4 * k + 2];
        uv[1] = c->memo[4 * k + 3];
    } else {
        if (c->status == SQ_OK) c->status = boundary_value(c->face, c->bends, c->nbends, tag, x, uv, c->err);
        if (k == c->n && c->status == SQ_OK) {
            if (c->n == c->cap) {
                const long cap = c->cap ? 2 * c->cap : 256;
                double *m = realloc(c->memo, sizeof(double) * 4 * (size_t)cap);
                if (!m) {
                    c->status = SQ_FAIL(c->err, SQ_ERR_INTERNAL, "out of memory");
                    return 0.0;
                }
                c->memo = m;
                c->cap = cap;
            }
            double *m = c->memo + 4 * c->n++;
            m[0] = x[0], m[1] = x[1], m[2] = uv[0], m[3] = uv[1];
        }
    }
    if (c->twist != 0.0) twist_data(uv, c->twist, c->phase);
    return uv[c->comp];
}

/* Does the data take both values ±e^{iφ} (φ that of the first point) and
 * no other?  Then the field is real up to that phase and changes sign.
 * (Data e^{iφ} alone gives the constant field: no zeros.) */
static int data_is_degenerate(const bdata_ctx *c, double *phase)
{
    if (c->n == 0) return 0;
    *phase = atan2(c->memo[3], c->memo[2]);
    int opposite = 0;
    for (long k = 0; k < c->n; k++) {
        const double *m = c->memo + 4 * k;
        if (fabs(m[3] * cos(*phase) - m[2] * sin(*phase)) > SQ_DEGENERATE_DATA_TOL) return 0;
        opposite |= m[2] * cos(*phase) + m[3] * sin(*phase) < 0.0;
    }
    return opposite;
}

static void zero_exact(const double x[2], void *ctx, double *u, double grad[2])
{
    (void)x;
    (void)ctx;
    *u = 0.0;
    grad[0] = grad[1] = 0.0;
}

sq_status sq_guiding_field_norms(const sq_guiding_field *g, double *l2_u, double *l2_v,
                                 sq_error *err)
{
    SQ_TRY(sem_field_error(g->uv, 0, zero_exact, NULL, 0, l2_u, NULL, err));
    return sem_field_error(g->uv, 1, zero_exact, NULL, 0, l2_v, NULL, err);
}

void sq_guiding_field_free(sq_guiding_field *g)
{
    if (!g) return;
    sem_field_evaluator_free(&g->ev);
    sem_field_free(&g->uv);
    free(g->bends);
    memset(g, 0, sizeof *g);
}

sq_status sq_guiding_field_solve(const cad_face *face, const sq_face_info *info,
                                 const sem_tri_mesh *mesh, const sem_tri_mesh *glued,
                                 const sq_bend *bends, int nbends, int order, sq_method method,
                                 sq_guiding_field *out, sq_error *err)
{
    const sem_tri_mesh *sm = glued ? glued : mesh; /* the elements are mesh's either way */
    memset(out, 0, sizeof *out);
    sem_method m = method == SQ_METHOD_AUTO ? sq_guiding_method_auto(info) : (sem_method)method;
    sem_poisson *solver = NULL;
    sem_field *comp[2] = {NULL, NULL};
    SQ_TRY(sem_poisson_create(sm, order, m, NULL, NULL, &solver, err));
    sq_status st = sem_field_create(mesh, order, 2, &out->uv, err);
    /* u and v share the matrix: one factorization, two right-hand sides */
    bdata_ctx ctx = {.face = face, .bends = bends, .nbends = nbends, .status = SQ_OK, .err = err};
    if (st == SQ_OK && nbends > 0) {
        out->bends = malloc(sizeof *out->bends * (size_t)nbends);
        if (!out->bends) st = SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
        else memcpy(out->bends, bends, sizeof *out->bends * (size_t)nbends), out->nbends = nbends;
    }
    for (int c = 0; c < 2 && st == SQ_OK; c++)
        st = sem_field_create(sm, order, 1, &comp[c], err);
    /* a degenerate field is solved again with the twisted data */
    for (int pass = 0; pass < 2 && st == SQ_OK; pass++) {
        if (pass == 1 && !data_is_degenerate(&ctx, &ctx.phase)) break;
        ctx.twist = pass == 1 ? SQ_GUIDING_TWIST_DEG * M_PI / 45.0 : 0.0;
        for (int c = 0; c < 2 && st == SQ_OK; c++) {
            ctx.comp = c;
            ctx.k = 0;
            sem_poisson_data data = {.g = boundary_data, .g_ctx = &ctx};
            st = sem_poisson_solve(solver, &data, comp[c], err);
            if (st == SQ_OK) st = ctx.status;
        }
    }
    if (st == SQ_OK) {
        int nm = out->uv->nmodes;
        for (long k = 0; k < (long)mesh->ntris * nm; k++) {
            out->uv->coef[2 * k] = comp[0]->coef[k];
            out->uv->coef[2 * k + 1] = comp[1]->coef[k];
        }
        out->mesh = mesh;
        out->method = m;
        out->order = order;
        out->twist = ctx.twist;
        out->twist_phase = ctx.phase;
        out->ndofs = sem_poisson_ndofs(solver);
        st = sem_field_evaluator_create(out->uv, NULL, &out->ev, err);
    }
    free(ctx.memo);
    sem_field_free(&comp[0]);
    sem_field_free(&comp[1]);
    sem_poisson_free(&solver);
    if (st != SQ_OK) sq_guiding_field_free(out);
    return st;
}

int sq_guiding_field_eval(const sq_guiding_field *g, const double x[2], int *elem, double uv[2],
                          double grad[4])
{
    return sem_field_evaluator_eval(g->ev, x, elem, uv, grad);
}
