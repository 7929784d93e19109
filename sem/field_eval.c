/* semquad sem/ — value and physical gradient of a field anywhere (see
 * field_eval.h).  The gradient is J^{-T} (d/dr, d/ds) with J from the
 * modal geometry, which is exact for the isoparametric map of tri_mesh.h. */
#include "field_eval.h"

#include "dg_modal.h"
#include "tri_nodes.h"

#include <stdlib.h>

struct sem_field_evaluator {
    const sem_field *f;
    const sem_locator *loc;
    sem_locator *own;
    sem_dubiner_tab tab; /* order max(P, geometry order) */
    int nf, ng;          /* field and geometry modes */
    int same;            /* tab order == P: field modes in place */
    int fidx[SEM_MAX_MODES], gidx[SEM_MAX_MODES]; /* positions in the tab numbering */
    const double *gm;    /* 2*ng*ntris modal geometry: the locator's */
};

void sem_field_evaluator_free(sem_field_evaluator **ev)
{
    if (!ev || !*ev) return;
    sem_locator_free(&(*ev)->own);
    free(*ev);
    *ev = NULL;
}

const sem_locator *sem_field_evaluator_locator(const sem_field_evaluator *ev) { return ev->loc; }

sq_status sem_field_evaluator_create(const sem_field *f, const sem_locator *loc,
                                     sem_field_evaluator **out, sq_error *err)
{
    if (!out) return SQ_FAIL(err, SQ_ERR_USAGE, "field_evaluator_create: NULL output");
    *out = NULL;
    if (!f || !f->mesh || f->P < 0 || f->P > SEM_MAX_ORDER)
        return SQ_FAIL(err, SQ_ERR_USAGE, "field_evaluator_create: bad field");
    if (loc && sem_locator_mesh(loc) != f->mesh)
        return SQ_FAIL(err, SQ_ERR_USAGE, "field_evaluator_create: locator of another mesh");
    sem_field_evaluator *E = calloc(1, sizeof *E);
    if (!E) return SQ_FAIL(err, SQ_ERR_INTERNAL, "field_evaluator_create: out of memory");
    sq_status st;
    E->f = f;
    const int go = f->mesh->order, P = f->P, T = P > go ? P : go;
    sem_dubiner_tab_init(&E->tab, T);
    E->nf = sem_tri_num_nodes(P);
    E->ng = sem_tri_num_nodes(go);
    E->same = T == P;
    for (int q = 0; q <= T; ++q)
        for (int p = 0; p + q <= T; ++p) {
            if (p + q <= P) E->fidx[sem_tri_node_index(P, p, q)] = sem_tri_node_index(T, p, q);
            if (p + q <= go) E->gidx[sem_tri_node_index(go, p, q)] = sem_tri_node_index(T, p, q);
        }
    if (!loc) {
        if ((st = sem_locator_create(f->mesh, &E->own, err)) != SQ_OK) {
            sem_field_evaluator_free(&E);
            return st;
        }
        loc = E->own;
    }
    E->loc = loc;
    E->gm = sem_locator_modal_geometry(loc);
    *out = E;
    return SQ_OK;
}

void sem_field_evaluator_eval_ref(const sem_field_evaluator *E, int e, double r, double s,
                                  double *val, double *grad, double x[2])
{
    double phi[SEM_MAX_MODES], dr[SEM_MAX_MODES], ds[SEM_MAX_MODES];
    const int nf = E->nf, ng = E->ng, nc = E->f->ncomp;
    const int need_d = grad != NULL;
    sem_dubiner_tab_eval(&E->tab, r, s, phi, need_d ? dr : NULL, need_d ? ds : NULL);
    double rx = 0, ry = 0, sx = 0, sy = 0;
    if (need_d || x) {
        const double *g = E->gm + 2 * (size_t)ng * e;
        double px = 0, py = 0, xr = 0, xs = 0, yr = 0, ys = 0;
        for (int m = 0; m < ng; ++m) {
            const int k = E->gidx[m];
            const double gx = g[2 * m], gy = g[2 * m + 1];
            if (x) {
                px += gx * phi[k];
                py += gy * phi[k];
            }
            if (need_d) {
                xr += gx * dr[k];
                xs += gx * ds[k];
                yr += gy * dr[k];
                ys += gy * ds[k];
            }
        }
        if (x) {
            x[0] = px;
            x[1] = py;
        }
        if (need_d) {
            const double det = xr * ys - xs * yr;
            rx = ys / det;
            ry = -xs / det;
            sx = -yr / det;
            sy = xr / det;
        }
    }
    const double *c = E->f->coef + (size_t)e * nf * nc;
    if (nc == 1 && E->same) { /* the common case: straight dot products */
        double v = 0, a = 0, b = 0;
        if (need_d) {
            for (int m = 0; m < nf; ++m) {
                v += c[m] * phi[m];
                a += c[m] * dr[m];
                b += c[m] * ds[m];
            }
            grad[0] = rx * a + sx * b;
            grad[1] = ry * a + sy * b;
        } else {
            for (int m = 0; m < nf; ++m) v += c[m] * phi[m];
        }
        val[0] = v;
        return;
    }
    for (int k = 0; k < nc; ++k) {
        double v = 0, a = 0, b = 0;
        for (int m = 0; m < nf; ++m) {
            const int i = E->fidx[m];
            const double cm = c[(size_t)m * nc + k];
            v += cm * phi[i];
            if (need_d) {
                a += cm * dr[i];
                b += cm * ds[i];
            }
        }
        val[k] = v;
        if (need_d) {
            grad[2 * k] = rx * a + sx * b;
            grad[2 * k + 1] = ry * a + sy * b;
        }
    }
}

int sem_field_evaluator_eval(const sem_field_evaluator *E, const double xy[2], int *elem,
                             double *val, double *grad)
{
    int e = -1;
    double r, s;
    const int hint = elem ? *elem : -1;
    if (sem_locator_find(E->loc, xy, hint, &e, &r, &s) != 0) return 1;
    if (elem) *elem = e;
    sem_field_evaluator_eval_ref(E, e, r, s, val, grad, NULL);
    return 0;
}
