/* semquad sem/ — point location on a curved triangle mesh.
 *
 * A bucket grid over the elements' bounding boxes (each box bounds the
 * curved element, sampled on a fine lattice of its map and enlarged) gives
 * candidate elements; each candidate is tested by inverting its map x(r,s)
 * with Newton's method, accepting a converged (r,s)
 * inside the reference triangle (within SEM_LOCATE_TOL).  With a hint
 * element the search first walks from element to neighbour across the edge
 * the inverse map points through, which costs a few Newton solves when the
 * point is near the hint (critical-point search, streamline tracing) and
 * allocates nothing.  The locator is read-only once built: threads may
 * share it. */
#ifndef SEM_LOCATE_H
#define SEM_LOCATE_H

#include "sq_status.h"
#include "tri_mesh.h"

/* Reference-coordinate tolerance for "inside the element". */
#define SEM_LOCATE_TOL 1e-10

typedef struct sem_locator sem_locator; /* opaque */

/* Build the grid for mesh (borrowed: must outlive the locator). */
sq_status sem_locator_create(const sem_tri_mesh *mesh, sem_locator **out, sq_error *err);
void sem_locator_free(sem_locator **loc); /* NULL-safe, NULLs *loc */
const sem_tri_mesh *sem_locator_mesh(const sem_locator *loc);
/* The modal geometry of the mesh's elements (sem_modal_geometry, dg_modal.h),
 * owned by the locator. */
const double *sem_locator_modal_geometry(const sem_locator *loc);

/* Locate xy: returns 0 and sets *elem, *r, *s if the point is in the mesh,
 * 1 if it is outside (outputs untouched).  hint: an element near xy (the
 * previous answer) or -1.  No allocation. */
int sem_locator_find(const sem_locator *loc, const double xy[2], int hint, int *elem, double *r,
                     double *s);

/* Newton inversion of element e's map at xy (see locate.c): returns 0
 * if it converged, with (r,s) in rs (inside the reference triangle or not:
 * test with sem_locator_inside), 1 if it did not converge. */
int sem_locator_invert(const sem_locator *loc, int e, const double xy[2], double rs[2]);

/* Whether (r,s) lies in the reference triangle within SEM_LOCATE_TOL. */
static inline int sem_locator_inside(double r, double s)
{
    return r >= -SEM_LOCATE_TOL && s >= -SEM_LOCATE_TOL && r + s <= 1.0 + SEM_LOCATE_TOL;
}

/* Map of element e at (r,s): x (may be NULL), J = {x_r, x_s, y_r, y_s}
 * (may be NULL); returns det J.  Uses the modal geometry (cheaper than the
 * Lagrange form of tri_geom.h), equal to it to round-off. */
double sem_locator_map(const sem_locator *loc, int e, double r, double s, double x[2],
                       double jac[4]);

#endif
