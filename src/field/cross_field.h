/* semquad — the one small interface through which layout stages see a
 * cross field, whatever computed it (guiding field (u, v) of Marcon 2019, or
 * the H/θ field of Jezdimirović 2021): the cross direction modulo π/2 at a
 * point and, where known, the target size there. */
#ifndef SQ_CROSS_FIELD_H
#define SQ_CROSS_FIELD_H

#include "guiding_field.h"

typedef struct {
    void *ctx;
    /* An angle theta with the cross {theta + k π/2} at x.  *elem: hint in
     * (-1: none), containing element of the triangulation out.  Returns 0,
     * or 1 if x is outside the face (outputs untouched). */
    int (*direction)(void *ctx, const double x[2], int *elem, double *theta);
    /* Size of element elem of the triangulation the field lives on (the
     * tracer ties its step to it). */
    double (*element_size)(void *ctx, int elem);
    /* Target mesh size at x relative to the face's (e^H, scaled so that the
     * root mean square of its inverse over the face is 1), or 0 when the
     * field carries no size (the guiding field) or x is outside. May be
     * NULL. */
    double (*size)(void *ctx, const double x[2], int *elem);
} sq_cross_field;

/* The guiding field as a cross field: theta = atan2(v, u)/4 (eq. 2). */
sq_cross_field sq_guiding_cross_field(const sq_guiding_field *g);

#endif
