/* semquad sem/ — piecewise-polynomial fields in the orthonormal Dubiner
 * basis (coefficients per element, see field.h). */
#include "field.h"

#include "gauss.h"
#include "tri_basis.h"

#include <stdlib.h>

#define FIELD_NMAX ((SEM_MAX_ORDER + 1) * (SEM_MAX_ORDER + 2) / 2)

sq_status sem_field_create(const sem_tri_mesh *mesh, int P, int ncomp, sem_field **out,
                           sq_error *err)
{
    if (!out) return SQ_FAIL(err, SQ_ERR_USAGE, "field_create: NULL output");
    *out = NULL;
    if (!mesh) return SQ_FAIL(err, SQ_ERR_USAGE, "field_create: NULL mesh");
    if (P < 0 || P > SEM_MAX_ORDER || ncomp < 1)
        return SQ_FAIL(err, SQ_ERR_USAGE, "field_create: order %d outside 0..%d or %d components",
                       P, SEM_MAX_ORDER, ncomp);
    sem_field *f = calloc(1, sizeof *f);
    if (!f) return SQ_FAIL(err, SQ_ERR_INTERNAL, "field_create: out of memory");
    f->mesh = mesh;
    f->P = P;
    f->nmodes = (P + 1) * (P + 2) / 2;
    f->ncomp = ncomp;
    f->coef = calloc((size_t)mesh->ntris * (size_t)f->nmodes * (size_t)ncomp + 1, sizeof(double));
    if (!f->coef) {
        free(f);
        return SQ_FAIL(err, SQ_ERR_INTERNAL, "field_create: out of memory (%d elements)",
                       mesh->ntris);
    }
    *out = f;
    return SQ_OK;
}

void sem_field_free(sem_field **f)
{
    if (!f || !*f) return;
    free((*f)->coef);
    free(*f);
    *f = NULL;
}

void sem_field_eval_modes(const sem_field *f, int e, const double *phi, const double *pr,
                          const double *ps, double *val, double *dr, double *ds)
{
    const int nm = f->nmodes, nc = f->ncomp;
    const double *c = f->coef + (size_t)e * nm * nc;
    for (int k = 0; k < nc; ++k) {
        double v = 0.0, a = 0.0, b = 0.0;
        for (int m = 0; m < nm; ++m) {
            const double cm = c[m * nc + k];
            v += cm * phi[m];
            if (dr) a += cm * pr[m];
            if (ds) b += cm * ps[m];
        }
        val[k] = v;
        if (dr) dr[k] = a;
        if (ds) ds[k] = b;
    }
}

void sem_field_eval_ref(const sem_field *f, int e, double r, double s, double *val, double *dr,
                        double *ds)
{
    double phi[FIELD_NMAX], pr[FIELD_NMAX], ps[FIELD_NMAX];
    sem_tri_dubiner(f->P, r, s, phi, dr ? pr : NULL, ds ? ps : NULL);
    sem_field_eval_modes(f, e, phi, pr, ps, val, dr, ds);
}
