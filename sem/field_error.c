/* semquad sem/ — errors of a field against an exact solution: quadrature of
 * (u_h - u)^2 and |grad u_h - grad u|^2 with weights w det J on each curved
 * element; grad u_h = J^{-T} (d/dr, d/ds). */
#include "field_error.h"

#include "dg_modal.h"
#include "tri_nodes.h"
#include "tri_quad.h"

#include <math.h>
#include <stdlib.h>

sq_status sem_field_error(const sem_field *f, int comp, sem_exact_fn exact, void *ctx, int degree,
                          double *l2, double *h1, sq_error *err)
{
    if (!f || !f->mesh || !exact || !l2)
        return SQ_FAIL(err, SQ_ERR_USAGE, "field_error: NULL argument");
    if (comp < 0 || comp >= f->ncomp)
        return SQ_FAIL(err, SQ_ERR_USAGE, "field_error: component %d outside 0..%d", comp,
                       f->ncomp - 1);
    const sem_tri_mesh *M = f->mesh;
    const int go = M->order, P = f->P, nf = f->nmodes, nc = f->ncomp, ng = sem_tri_num_nodes(go);
    if (degree <= 0) degree = 2 * P + 2 * go + 4;
    sem_tri_quad *q = NULL;
    double *gm = NULL, *tf = NULL, *tg = NULL;
    sq_status st;
    if ((st = sem_tri_quad_create(degree, &q, err)) != SQ_OK) return st;
    if ((st = sem_modal_geometry(M, &gm, err)) != SQ_OK) goto done;
    /* tabulate field modes (phi, dr, ds) and geometry modes at the points */
    const int nq = q->npts;
    tf = malloc(sizeof(double) * 3 * (size_t)nq * nf);
    tg = malloc(sizeof(double) * 3 * (size_t)nq * ng);
    if (!tf || !tg) {
        st = SQ_FAIL(err, SQ_ERR_INTERNAL, "field_error: out of memory");
        goto done;
    }
    sem_dubiner_tab T;
    sem_dubiner_tab_init(&T, P);
    for (int k = 0; k < nq; ++k) {
        double *a = tf + 3 * (size_t)k * nf;
        sem_dubiner_tab_eval(&T, q->rs[2 * k], q->rs[2 * k + 1], a, a + nf, a + 2 * nf);
    }
    sem_dubiner_tab_init(&T, go);
    for (int k = 0; k < nq; ++k) {
        double *a = tg + 3 * (size_t)k * ng;
        sem_dubiner_tab_eval(&T, q->rs[2 * k], q->rs[2 * k + 1], a, a + ng, a + 2 * ng);
    }
    double e0 = 0.0, e1 = 0.0;
    for (int e = 0; e < M->ntris; ++e) {
        const double *g = gm + 2 * (size_t)ng * e;
        const double *c = f->coef + (size_t)e * nf * nc + comp;
        for (int k = 0; k < nq; ++k) {
            const double *a = tg + 3 * (size_t)k * ng;
            double x[2], J[4];
            const double det = sem_modal_map(ng, g, a, a + ng, a + 2 * ng, x, J);
            const double *b = tf + 3 * (size_t)k * nf;
            double v = 0, vr = 0, vs = 0;
            for (int m = 0; m < nf; ++m) {
                const double cm = c[(size_t)m * nc];
                v += cm * b[m];
                vr += cm * b[nf + m];
                vs += cm * b[2 * nf + m];
            }
            const double gx = (J[3] * vr - J[2] * vs) / det, gy = (-J[1] * vr + J[0] * vs) / det;
            double ue, ge[2] = {0.0, 0.0};
            exact(x, ctx, &ue, ge);
            const double w = q->w[k] * fabs(det);
            e0 += w * (v - ue) * (v - ue);
            e1 += w * ((gx - ge[0]) * (gx - ge[0]) + (gy - ge[1]) * (gy - ge[1]));
        }
    }
    *l2 = sqrt(e0);
    if (h1) *h1 = sqrt(e1);
done:
    free(tf);
    free(tg);
    free(gm);
    sem_tri_quad_free(&q);
    return st;
}
