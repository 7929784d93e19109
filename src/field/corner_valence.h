/* semquad — number of quads at each boundary vertex from the guiding field
 * (Marcon 2019, eq. 15): n = Δθ/(π/2) - I(θ0, θf), with Δθ the interior
 * angle and I the change of ψ = atan2(v, u)/4, in units of π/2, along a small
 * arc inside the face from the outgoing to the incoming edge.  The arc's
 * ends are boundary points, where (u, v) is the boundary data itself, so a
 * jump of the data at the corner (angles that are not multiples of 90°) is
 * accounted for exactly.  n = 0 is a degenerate (triangular) block. */
#ifndef SQ_CORNER_VALENCE_H
#define SQ_CORNER_VALENCE_H

#include "guiding_field.h"

typedef struct {
    int vertex;       /* index into sq_face_info.vertices */
    int valence;      /* n: quads at the vertex */
    double raw;       /* Δθ/(π/2) - I before rounding */
    double angle_deg; /* interior angle */
} sq_corner_valence;

/* One entry per vertex of info (smooth junctions included: n = 2). */
sq_status sq_corner_valences(const sq_guiding_field *g, const cad_face *face,
                             const sq_face_info *info, sq_corner_valence **out, sq_error *err);

#endif
