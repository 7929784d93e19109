/* semquad — the guiding-field stage end to end: triangulate, solve, find
 * the critical points, give corners their valences, check Poincaré–Hopf. */
#ifndef SQ_FIELD_ANALYSIS_H
#define SQ_FIELD_ANALYSIS_H

#include "corner_valence.h"
#include "critical_points.h"
#include "identified_edges.h"
#include "triangulate.h"

typedef struct {
    int order;          /* P of the field */
    sq_method method;   /* auto, cg, dg */
    sq_tri_options tri; /* the triangulation (its order: min(P, 12)) */
    double grading;     /* > 0: element size at singular boundary vertices,
                           relative to the triangulation size (hp grading,
                           see sq_singular_vertices); 0: no grading */
    sq_identification periodic; /* pairs of identified edges (none: npairs 0):
                                   the field solved on the identified domain
                                   (identified_edges.h) */
    const sq_bend *bends; /* nbends face vertices the data turns through
                             (guiding_field.h; may be NULL): they take 2
                             quads, sq_vertex.bent */
    int nbends;
} sq_field_options;

/* Corners turning by less than this (degrees) are near-straight: the
 * field's boundary direction jumps there by 4 times the turn, under 40
 * degrees, so next to the jump |(u, v)| stays above cos 20 deg = 0.94: no
 * zero of the field can sit there unresolved; such a corner takes 2 quads
 * and starts no separatrix.  They are not graded: a polygon of hundreds of
 * such corners (a circle drawn as a polygon) would otherwise get a graded
 * ring of elements at each (21k triangles, 86 s on a 155-gon). */
#define SQ_NEAR_STRAIGHT_TOL_DEG 10.0

/* 1 if the vertex is not smooth but turns by less than
 * SQ_NEAR_STRAIGHT_TOL_DEG (either way). */
int sq_vertex_near_straight(const sq_vertex *v);

/* Boundary vertices where the guiding field is singular and limits
 * convergence to algebraic rates: corners whose angle is not a multiple of
 * 90 degrees (the boundary data jumps), re-entrant corners, and smooth
 * junctions where the curvature jumps; near-straight corners are left out.
 * xy[2*nvertices]; returns the count. */
sq_status sq_singular_vertices(const cad_face *face, const sq_face_info *info, double *xy, int *n,
                               sq_error *err);

void sq_field_options_default(sq_field_options *opt);

typedef struct {
    sq_face_info info;
    sq_triangulation tri;
    sq_guiding_field field;
    int npoints;
    sq_critical_point *points;
    sq_corner_valence *corners; /* one per info.vertices */
    /* Σ_interior (4 - V) + Σ_vertices (2 - n) against 4χ */
    int ph_lhs, ph_rhs;
    double t_triangulate, t_solve, t_critical; /* seconds */
    int identified_rounds; /* triangulations until the pairs agreed (0: no pairs) */
} sq_field_analysis;

sq_status sq_field_analyse(const cad_face *face, const sq_field_options *opt,
                           sq_field_analysis *out, sq_error *err);
void sq_field_analysis_free(sq_field_analysis *a); /* frees, zeroes the struct */

/* Wall-clock seconds (monotonic). */
double sq_now(void);

#endif
