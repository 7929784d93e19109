/* semquad — separatrices: polylines traced through a cross field from the
 * singular points and the corners that take two or more quads (Marcon 2019
 * §2.4, §3.3). */
#ifndef SQ_SEPARATRIX_H
#define SQ_SEPARATRIX_H

#include "sq_status.h"

typedef enum {
    SQ_END_OPEN = 0,  /* not finished (length bound reached: a limit cycle?) */
    SQ_END_SINGULAR,  /* at singular point `id` (exactly its position) */
    SQ_END_CORNER,    /* at face vertex `id` (sq_face_info.vertices, exactly) */
    SQ_END_BOUNDARY,  /* on CAD edge `id` at arc length `s` (exactly on it) */
    SQ_END_SEPARATRIX /* on separatrix `id` of the set at arc length `s` along it
                         (exactly on its polyline; only from sq_trace_continue) */
} sq_end_kind;

typedef struct {
    sq_end_kind kind;
    int id;
    double s;         /* SQ_END_BOUNDARY: arc length on edge id */
} sq_sep_end;

typedef struct {
    int npts;
    double *xy;        /* 2*npts, from start to end */
    sq_sep_end start, end;
    double start_angle; /* direction at the start (radians) */
    double end_angle;   /* direction of travel at the end (radians; for a merged
                           separatrix: the other start angle + π) */
    int merged;        /* 1: the result of merging two separatrices that met */
} sq_separatrix;

typedef struct {
    int n, cap;
    sq_separatrix *s;
} sq_separatrix_set;

void sq_separatrix_set_free(sq_separatrix_set *set); /* frees, zeroes the struct */

/* Append *s to the set, which takes ownership of s->xy (s is zeroed). */
sq_status sq_separatrix_set_append(sq_separatrix_set *set, sq_separatrix *s, sq_error *err);

/* Polyline length. */
double sq_separatrix_length(const sq_separatrix *s);

#endif
