/* semquad — what a planar face is: corners, area, Euler characteristic.
 *
 * Built on the cad/ evaluation API only (no OpenCASCADE types).  Area by
 * Green's theorem along the exact boundary curves, so it does not depend on
 * any triangulation (OpenCASCADE's own mass properties are off by up to 1 %
 * on B-spline faces: T106's is 0.9 % off).
 *
 * GSL reports through its error handler: programs using this layer call
 * gsl_set_error_handler_off() once at start-up so that failures come back
 * as status codes instead of aborting. */
#ifndef SQ_FACE_INFO_H
#define SQ_FACE_INFO_H

#include "cad.h"
#include "json_writer.h"

#include <stddef.h>

/* Vertices whose turning angle is below this are smooth junctions, not
 * corners (degrees). */
#define SQ_SMOOTH_TOL_DEG 0.5

typedef struct {
    double x, y;
    double angle_deg; /* interior angle seen from the face, in (0, 360) */
    int loop;
    int edge_in, edge_out; /* edge ending here, edge starting here */
    int smooth;            /* 1: smooth junction (|180 - angle| < tol) */
    int bent;              /* 1: a bend (guiding_field.h sq_bend): 2 quads, no
                              separatrix, no patch corner, at any angle; set by
                              the field analysis, 0 from sq_face_info_compute */
    double cusp_tol_deg;   /* interior angles below this are cusps here */
} sq_vertex;

typedef struct {
    int nloops, nholes, chi; /* chi = 1 - holes */
    double area;
    double bbox[4]; /* xmin, ymin, xmax, ymax of the boundary */
    int nvertices;
    sq_vertex *vertices; /* every junction of two edges, loop by loop */
    int ncorners;        /* vertices that are not smooth */
} sq_face_info;

sq_status sq_face_info_compute(const cad_face *face, sq_face_info *info, sq_error *err);

/* Cusps (cad.h, CAD_CUSP_REL_TOL): healing blunts them within the
 * tolerance; those left are refused (sq_face_check_cusps). */
#define SQ_CUSP_REL_TOL CAD_CUSP_REL_TOL

/* SQ_ERR_LAYOUT, naming where and why, if the face has a cusp. */
sq_status sq_face_check_cusps(const sq_face_info *info, sq_error *err);
void sq_face_info_free(sq_face_info *info); /* frees arrays, zeroes the struct */

/* Total absolute turning of an edge, integral of |curvature| ds (radians). */
sq_status sq_edge_turning(const cad_face *face, int edge, double *turning, sq_error *err);

/* "ok", "healed", "not planar" or "broken" (semquad info's status). */
const char *sq_face_status_name(cad_face_status s);

/* What healing did, as a sentence: "closed a 1.2e-05 mm gap between edges
 * 0 and 1 of wire 0 at (1, 0, 0)". */
void sq_heal_text(const cad_heal *h, const char *unit, char *buf, size_t n);

/* The "healing" key of face `face` into an open JSON object: {"tolerance":
 * T, "fixes": [{"kind", "wire", "edges", "size", "at"}]}; tolerance 0 when
 * healing is off. */
void sq_json_healing(sq_json *j, const cad_model *m, int face);

#endif
