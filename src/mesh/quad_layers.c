/* semquad — boundary layers (Marcon 2019 §3.4): their thickness, and the
 * sides along a curved wall curved like it (the layers themselves are the
 * walls' sizes, sq_size_field_walls). */
#include "quad_mesher_private.h"

#include <math.h>

/* Thickness of nb geometric layers. */
double qm_bl_thickness(const sq_mesher_options *o, int nb)
{
    return o->bl_ratio == 1.0 ? o->bl_first * nb
                              : o->bl_first * (pow(o->bl_ratio, nb) - 1.0) / (o->bl_ratio - 1.0);
}

/* Design 4: the order-Q quads.  Element sides on the boundary follow the
 * CAD curve between their vertices' arc lengths; other sides are straight;
 * element interiors by transfinite interpolation of their four sides. */
/* A side inside a boundary layer that runs along its wall is curved like
 * the wall: its nodes at arc length and distance interpolated between its
 * vertices', offset from the wall along the inward normal, so thin layer
 * elements follow a curved wall instead of being cut by it.  Returns 1 and
 * fills c, s0, s1, d0, d1 for such a side. */
int qm_layer_side(const cad_face *face, const sq_mesher_options *o, double thick,
                  const double A[2], const double B[2], int *c, double *s0, double *s1,
                  double *d0, double *d1)
{
    for (int b = 0; b < o->nbl; b++) {
        int e = o->bl_edges[b];
        if (cad_face_edge_project(face, e, A, s0, NULL, d0, NULL) != SQ_OK ||
            cad_face_edge_project(face, e, B, s1, NULL, d1, NULL) != SQ_OK)
            return 0;
        if (*d0 > thick || *d1 > thick) continue;
        double Lc = cad_face_edge_length(face, e);
        if (fabs(*s1 - *s0) > 0.5 * Lc) { /* a closed edge: the shorter way round */
            if (*s1 > *s0) *s0 += Lc;
            else *s1 += Lc;
        }
        /* along the wall, not across it */
        if (fabs(*s1 - *s0) <= fabs(*d1 - *d0)) return 0;
        *c = e;
        return 1;
    }
    return 0;
}
