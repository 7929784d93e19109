/* semquad sem/ — a (possibly discontinuous) piecewise-polynomial field on a
 * curved triangle mesh: the common output of the CG and DG solvers and the
 * input of everything that evaluates solutions.
 *
 * Storage: per element, coefficients in the orthonormal Dubiner basis of
 * tri_basis.h (order P, nmodes = (P+1)(P+2)/2 modes), ncomp components:
 *   coef[((size_t)e * nmodes + m) * ncomp + c].
 * A CG solution is stored the same way (its continuity is a property of the
 * values, not of the storage). */
#ifndef SEM_FIELD_H
#define SEM_FIELD_H

#include "sq_status.h"
#include "tri_mesh.h"

typedef struct {
    const sem_tri_mesh *mesh; /* borrowed: must outlive the field */
    int P;
    int nmodes;
    int ncomp;
    double *coef;
} sem_field;

/* Zero field of order P (0..SEM_MAX_ORDER) with ncomp >= 1 components. */
sq_status sem_field_create(const sem_tri_mesh *mesh, int P, int ncomp, sem_field **out,
                           sq_error *err);
void sem_field_free(sem_field **f); /* NULL-safe, NULLs *f */

/* Value (val[ncomp]) and reference-coordinate derivatives (dr, ds:
 * [ncomp], may be NULL) of the field on element e at (r,s).  No
 * allocation; P <= SEM_MAX_ORDER. */
void sem_field_eval_ref(const sem_field *f, int e, double r, double s, double *val, double *dr,
                        double *ds);
/* The same from the Dubiner modes at (r,s), phi (and pr, ps where dr,
 * ds are asked for) as sem_tri_dubiner(f->P, r, s, ...) gives them: the
 * same sums, so the same bits as sem_field_eval_ref, for points at which
 * many elements are evaluated (the modes computed once). */
void sem_field_eval_modes(const sem_field *f, int e, const double *phi, const double *pr,
                          const double *ps, double *val, double *dr, double *ds);

#endif
