/* semquad — a face whose pairs of edges are identified (periodic
 * boundaries, docs/domains.md): the guiding field is solved on the
 * identified domain, its unknowns on edge a those on edge b (Marcon 2019's
 * field, eqs. 3–4, with no boundary data on the pairs).
 *
 * design:
 *  1. the coarse triangulation puts the same vertices on both edges of a
 *     pair: it is triangulated, the arc lengths of the vertices on a and
 *     on b (mapped onto a: L − s) joined into one list, and triangulated
 *     again from it (sq_tri_options.edge_points) until both edges carry
 *     exactly the list (a refinement that splits a segment on one edge
 *     reaches the other in the next round; never undone, so it settles);
 *  2. the element edges on a are paired with those on b at the same arc
 *     lengths and the mesh is glued along them (sem_tri_mesh_glue): one
 *     unknown per pair of matching vertices and edge modes, so the field
 *     is continuous across the pair and nothing is imposed there;
 *  3. only transforms that leave w = u + iv unchanged are identified this
 *     way: translations (w(T x) = w(x)).  A rotation by φ turns w by 4φ
 *     (w(T x) = e^{4iφ} w(x)); its pairs are not identified (the caller
 *     leaves them out; docs/domains.md says what is left).
 *
 * The transform is kept with the pair for the separatrices that leave
 * through one edge and re-enter through the other (src/layout/trace.c). */
#ifndef SQ_IDENTIFIED_EDGES_H
#define SQ_IDENTIFIED_EDGES_H

#include "cad.h"
#include "triangulate.h"

typedef struct {
    int a, b;          /* CAD edges: b at arc L − s is T(a at s) */
    double affine[6];  /* T(x, y) = (a0 x + a1 y + a2, a3 x + a4 y + a5), a to b */
} sq_identified_pair;

typedef struct {
    int npairs;
    const sq_identified_pair *pairs; /* borrowed */
} sq_identification;

/* A separatrix that left through a and re-entered through b crosses them
 * at images of each other, up to the offset of lines merged across the cut
 * (two arms of a singular point traced round the identified domain meet
 * within a few steps, trace.h): the layout's pieces of a and b, and the
 * mesh's nodes there, are partners within this part of the mesh size (far
 * above the offset, far below a piece's length), and the image's nodes are
 * then set to the master's images. */
#define SQ_IDENTIFIED_CROSSING_REL_TOL 0.25

/* Rounds of design 1 before giving up (SQ_ERR_GEOMETRY): measured, one or
 * two (the refinement rarely splits a boundary segment). */
#define SQ_IDENTIFIED_MAX_ROUNDS 8

/* Design 1's lists, one per CAD edge of the face (only the pairs' used). */
typedef struct {
    int nedges;
    sq_edge_points *ep; /* what sq_tri_options.edge_points takes */
    double **s;         /* their storage */
} sq_identified_points;

void sq_identified_points_free(sq_identified_points *p); /* frees, zeroes */

/* Design 1, one round: the joined lists of tri's vertices on each pair
 * into p (allocated on first use); *agreed: tri already put exactly them
 * on both edges of every pair. */
sq_status sq_identified_points_update(const cad_face *face, const sq_identification *id,
                                      const sq_triangulation *tri, sq_identified_points *p,
                                      int *agreed, sq_error *err);

/* Design 2: tri's mesh glued along every pair (tri agreed on them). */
sq_status sq_identified_glue(const cad_face *face, const sq_identification *id,
                             const sq_triangulation *tri, sem_tri_mesh **glued, sq_error *err);

/* q = T(p), T an affine map as sq_identified_pair.affine holds it (q may
 * be p). */
void sq_affine_map(const double T[6], const double p[2], double q[2]);
/* Ti = T^-1 (T a rigid motion, or any invertible affine map). */
void sq_affine_inverse(const double T[6], double Ti[6]);

#endif
