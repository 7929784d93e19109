/* semquad — the boundary-aligned guiding field (Marcon 2019, eqs. 3-4):
 * Δu = Δv = 0 in the face, (u, v) = (cos 4θ_b, sin 4θ_b) on its boundary,
 * θ_b the tangent angle of the CAD curve, solved with CG or DG spectral/hp
 * elements of order P on the curved triangulation.
 *
 * Degenerate data: when every edge runs at a multiple of 45° in some frame
 * (a square with a hole turned by 45°, chamfers), the data takes two values
 * ±e^{iφ} only, and u + iv is e^{iφ} times a real harmonic function: it
 * vanishes on whole curves, across which the cross turns by 45° in no
 * particular sense, and a critical point's index cannot be read there.
 * Such data is solved again with the crosses of one family of edges (those
 * whose data is −e^{iφ}, φ that of the first boundary point) turned by
 * SQ_GUIDING_TWIST_DEG: the generic nearby field, that of the face with
 * those edges turned by as much, whose zeros are isolated. */
#ifndef SQ_GUIDING_FIELD_H
#define SQ_GUIDING_FIELD_H

#include "cad.h"
#include "face_info.h"
#include "field_eval.h"
#include "poisson.h"

/* Corner angles within this of a multiple of 90 degrees keep the boundary
 * data continuous (CG is used by --method auto). */
#define SQ_RIGHT_ANGLE_TOL_DEG 1e-3

/* |Im(w e^{−iφ})| under which boundary data counts as degenerate: the
 * data is cos/sin of exact tangent angles, good to round-off. */
#define SQ_DEGENERATE_DATA_TOL 1e-9
/* Small against the 45° between the two families (the layout stays the
 * face's), large against the field's discretization error so that the
 * turn across the former zero curves is resolved by the elements: the
 * same face with the hole turned by 44° instead of 45° meshes with the
 * same layout. */
#define SQ_GUIDING_TWIST_DEG 1.0

typedef enum { SQ_METHOD_AUTO = -1, SQ_METHOD_CG = SEM_CG, SQ_METHOD_DG = SEM_DG } sq_method;

/* A bend: a face vertex the data turns through along its two edges, with
 * the tangent's own turn, instead of jumping at it (a kink of a periodic
 * pair that is one regular point of the identified domain,
 * docs/domains.md).  Marcon's data jumps at a corner, and the field takes
 * the shorter way round (the chord between the two values of w), so a 245
 * deg kink gets 3 quads; turning with the bend, the long way, it gets 2.
 * The data's angle is θ_b plus a correction rising linearly in arc length
 * over len_in of edge_in and len_out of edge_out, continuous at the vertex
 * (θ_in + turn len_in / (len_in + len_out) from both sides). */
typedef struct {
    int vertex;            /* sq_face_info.vertices */
    int edge_in, edge_out; /* its edges (sq_vertex) */
    double turn;           /* the tangent's turn there, π − the interior angle (radians) */
    double len_in, len_out;
} sq_bend;

typedef struct {
    const sem_tri_mesh *mesh; /* borrowed */
    sem_method method;        /* what was used */
    int order;
    long ndofs;               /* per component */
    sem_field *uv;            /* two components: u, v */
    sem_field_evaluator *ev;  /* on uv */
    double twist;             /* != 0: degenerate data, solved twisted (above); radians of w */
    double twist_phase;       /* φ */
    int nbends;
    sq_bend *bends;           /* owned copy: the data turns through them */
} sq_guiding_field;

/* The method --method auto picks: CG when every corner angle is a multiple
 * of 90 degrees (within SQ_RIGHT_ANGLE_TOL_DEG), else DG. */
sem_method sq_guiding_method_auto(const sq_face_info *info);

/* The boundary data g was solved with at a point of CAD edge `edge`:
 * (cos 4θ_b, sin 4θ_b) from the edge's exact tangent at the point nearest
 * to x, turned through g's bends, twisted as g was. */
sq_status sq_guiding_field_data(const sq_guiding_field *g, const cad_face *face, int edge,
                                const double x[2], double uv[2], sq_error *err);

/* The bends' correction of the data's angle at arc length s of edge
 * (radians of θ, 0 away from g's bends). */
double sq_guiding_field_bend(const sq_guiding_field *g, const cad_face *face, int edge, double s);

/* glued: NULL, or mesh glued along identified edges (sem_tri_mesh_glue):
 * the field is solved on it, the pairs' unknowns one (identified_edges.h),
 * and lives on mesh as ever.  bends: nbends of them (may be 0, NULL). */
sq_status sq_guiding_field_solve(const cad_face *face, const sq_face_info *info,
                                 const sem_tri_mesh *mesh, const sem_tri_mesh *glued,
                                 const sq_bend *bends, int nbends, int order, sq_method method,
                                 sq_guiding_field *out, sq_error *err);
void sq_guiding_field_free(sq_guiding_field *g); /* frees, zeroes the struct */

/* The L2 norms of u and v over the face (reports; not needed to mesh). */
sq_status sq_guiding_field_norms(const sq_guiding_field *g, double *l2_u, double *l2_v,
                                 sq_error *err);

/* (u, v) and their physical gradients (grad[4] = {u_x, u_y, v_x, v_y}, may
 * be NULL) at a physical point; *elem is a hint in, the element out.
 * Returns 0, or 1 if x is outside the triangulation. */
int sq_guiding_field_eval(const sq_guiding_field *g, const double x[2], int *elem, double uv[2],
                          double grad[4]);

#endif
