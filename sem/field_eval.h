/* semquad sem/ — value and physical gradient of a field anywhere.
 *
 * An evaluator binds a field (borrowed; its coefficients are read at each
 * call, so a field re-solved in place needs no new evaluator) to the modal
 * geometry of its mesh and a locator.  At (element, r, s) one Dubiner
 * recurrence of order max(P, geometry order) gives both the field's modes
 * and the geometry Jacobian; nothing is allocated, and the evaluator is
 * read-only, so threads may share it. */
#ifndef SEM_FIELD_EVAL_H
#define SEM_FIELD_EVAL_H

#include "field.h"
#include "locate.h"
#include "sq_status.h"

typedef struct sem_field_evaluator sem_field_evaluator; /* opaque */

/* loc: a locator of the field's mesh, borrowed, its modal geometry
 * shared; or NULL to build one (owned by the evaluator). */
sq_status sem_field_evaluator_create(const sem_field *f, const sem_locator *loc,
                                     sem_field_evaluator **out, sq_error *err);
void sem_field_evaluator_free(sem_field_evaluator **ev); /* NULL-safe, NULLs *ev */
const sem_locator *sem_field_evaluator_locator(const sem_field_evaluator *ev);

/* Value val[ncomp] and physical gradient grad[2*ncomp] ({d/dx, d/dy} per
 * component; may be NULL) at reference point (r,s) of element e; also the
 * physical point x[2] (may be NULL). */
void sem_field_evaluator_eval_ref(const sem_field_evaluator *ev, int e, double r, double s,
                                  double *val, double *grad, double x[2]);

/* The same at a physical point: *elem is a hint on input (-1: none) and the
 * containing element on output.  Returns 0, or 1 if xy is outside the mesh
 * (val, grad untouched). */
int sem_field_evaluator_eval(const sem_field_evaluator *ev, const double xy[2], int *elem,
                             double *val, double *grad);

#endif
