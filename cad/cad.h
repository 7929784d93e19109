/* semquad cad/ — the only layer that sees OpenCASCADE and CGAL.
 *
 * A C contract over a C++ shim: opaque handles, plain C types, every
 * OpenCASCADE/CGAL exception caught and turned into an sq_status + message.
 * Nothing here prints to stdout or stderr.
 *
 * Frames and orientation (docs/conventions.md, "Geometry"): a planar face
 * is described in a 2D frame (origin O, axes X, Y) of its plane chosen so that
 * the face normal is +Z = X x Y.  When the face lies in a plane z = const,
 * X and Y are the global x and y axes and O is on the z axis, so coordinates
 * read as in the file (even if the face's normal is -z: its loops are then
 * walked in the opposite sense to keep the orientation below).
 * In that frame the outer loop runs counter-clockwise and holes clockwise:
 * the face is always on the left of the direction of travel.
 *
 * Lengths are in the file's own unit (no conversion to millimetres). */
#ifndef SQ_CAD_H
#define SQ_CAD_H

#include "sq_status.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ---- a CAD file ---------------------------------------------------------- */

typedef struct cad_model cad_model; /* opaque: the shape read from a file */

/* Read a STEP (.step/.stp), IGES (.iges/.igs) or BREP (.brep/.brp) file,
 * chosen by extension (case-insensitive) and checked by content.
 * Returns SQ_ERR_INPUT (missing, unreadable, empty, not valid CAD, no face)
 * with a one-line message.  *out stays NULL on failure. */
sq_status cad_model_read(const char *path, cad_model **out, sq_error *err);
void cad_model_free(cad_model **model); /* NULL-safe, NULLs *model */

/* Let OpenCASCADE turn access violations inside its code into exceptions
 * (OSD::SetSignal, process-wide, floating-point traps left off): a file
 * with a dangling reference is then refused instead of crashing.  Call
 * once at program start, before any cad_ function. */
void cad_catch_signals(void);

/* How cad_model_read_with reads: healing (docs/healing.md). */
typedef struct {
    int heal;              /* 1 (default): heal planar faces within the tolerance */
    double heal_tolerance; /* > 0: the tolerance (file unit); <= 0 (default): the
                              file's own for each face: the largest of the file's
                              uncertainty and the face's vertex and edge tolerances */
} cad_read_options;

void cad_read_options_default(cad_read_options *o);

/* cad_model_read with options.  Every OpenCASCADE failure, NaN or infinite
 * coordinates included, is SQ_ERR_INPUT with one line; a face that cannot
 * be healed does not fail the read: it is CAD_FACE_BROKEN. */
sq_status cad_model_read_with(const char *path, const cad_read_options *opts, cad_model **out,
                              sq_error *err);

typedef enum {
    CAD_FACE_OK = 0,     /* planar, taken as read */
    CAD_FACE_HEALED,     /* planar, defects healed within the tolerance */
    CAD_FACE_NOT_PLANAR, /* not meshable by semquad */
    CAD_FACE_BROKEN      /* planar with a defect beyond the tolerance */
} cad_face_status;

/* Status of face `index`; *reason (may be NULL) gets a one-line reason for a
 * broken face, else NULL. */
cad_face_status cad_model_face_status(const cad_model *model, int index, const char **reason);

/* The file's healing tolerance (file unit; the largest of the file's
 * uncertainty and its vertex and edge tolerances: no face heals beyond it,
 * or the given one), 0 when healing is off. */
double cad_model_heal_tolerance(const cad_model *model);

/* Cusps: two edges tangent at their common vertex with the face between
 * them.  Any quad with a corner there has a zero angle, hence a zero
 * Jacobian: healing blunts them.  Tangent means tangent as far as the face
 * is resolved: cad_face_create closes its junctions to CAD_CUSP_REL_TOL of
 * the boundary's length (delta), so an edge's direction over its length L
 * is known to delta/L; edges at an angle a with a L_min < delta (L_min the
 * shorter one's length) lie within delta of each other all along the
 * shorter one.  A real angle above that, however small (a sliver's 0.0004
 * degrees), is a corner: a quad there has scaled Jacobian sin(a) > 0.
 * (Tangencies in CAD files hold to 1e-10 rad or better: the real parts'
 * cusps read 5e-11 degrees or 0.) */
#define CAD_CUSP_REL_TOL 1e-7

/* A cusp is blunted only by a segment (the healing tolerance) at least this
 * fraction of the face's size: the meshers take such a face in under a
 * minute (36 s at 1e-5 on tests/t336's face), not one far smaller. */
#define CAD_CUSP_MIN_SEGMENT 1e-5

/* One defect healed on a face: kind "gap" (between the ends of edges
 * edge_a and edge_b of a wire, size its width), "connection" (consecutive
 * edges not sharing their vertex, size the vertices' distance), "small
 * edge" (edge_a, size its length), "degenerated edge" (edge_a),
 * "self-intersection" (the wire's), or "cusp" (between edges edge_a and
 * edge_b, blunted: cut[0] and cut[1] cut off them, joined by a segment of
 * length size), or "as read" (the face kept as read: the fix would leave a
 * defect of kind `defect`, "no face" or one of the above, with its wire,
 * edges, size and place); at: where, in the file's 3D coordinates.  Wires
 * and edges are numbered as in the file. */
typedef struct {
    const char *kind;
    const char *defect; /* "as read": the defect the fix would leave; else "" */
    int wire, edge_a, edge_b; /* -1: none */
    double size;
    double at[3];
    double cut[2];
} cad_heal;

int cad_model_face_num_heals(const cad_model *model, int index);
/* Record k of face `index`; 0 on success, -1 if out of range. */
int cad_model_face_heal(const cad_model *model, int index, int k, cad_heal *out);

/* Length unit of the file as written: "mm", "m", "cm", "inch", "foot",
 * "micrometre" or "unknown" (BREP files carry no unit). */
const char *cad_model_unit(const cad_model *model);

int cad_model_num_faces(const cad_model *model);

/* Surface type name of face `index`: "plane", "cylinder", "cone", "sphere",
 * "torus", "bezier", "bspline", "revolution", "extrusion", "offset",
 * "other".  NULL if the index is out of range. */
const char *cad_model_face_surface(const cad_model *model, int index);

/* 1 if face `index` lies in a plane (within 1e-7 of its size: a B-spline
 * surface may), else 0. */
int cad_model_face_planar(const cad_model *model, int index);

/* Index of the default face: the only planar face if there is exactly one,
 * else 0 (and *note is set to a one-line explanation, else to NULL). */
int cad_model_default_face(const cad_model *model, const char **note);

/* Move the model rigidly and scale it: x -> scale * R(axis, angle) x + t,
 * R the rotation by angle (radians) about the unit axis[3] through the
 * origin.  Faces extracted afterwards see the moved geometry (robustness
 * tests: singular points must move with the shape). */
sq_status cad_model_transform(cad_model *model, const double axis[3], double angle, double scale,
                              const double t[3], sq_error *err);

/* ---- a planar face in its 2D frame --------------------------------------- */

typedef struct cad_face cad_face; /* opaque */

typedef enum {
    CAD_EDGE_LINE = 0,
    CAD_EDGE_CIRCLE,
    CAD_EDGE_ELLIPSE,
    CAD_EDGE_HYPERBOLA,
    CAD_EDGE_PARABOLA,
    CAD_EDGE_BEZIER,
    CAD_EDGE_BSPLINE,
    CAD_EDGE_OFFSET,
    CAD_EDGE_OTHER
} cad_edge_type;

const char *cad_edge_type_name(cad_edge_type type); /* "line", "circle", ... */

/* Extract face `index` of the model.  SQ_ERR_USAGE if the index is out of
 * range; SQ_ERR_GEOMETRY if the face is not planar (the message names its
 * surface type), is broken (the healing's reason) or has a degenerate
 * boundary. */
sq_status cad_face_create(const cad_model *model, int index, cad_face **out, sq_error *err);
void cad_face_free(cad_face **face); /* NULL-safe, NULLs *face */

/* The 2D frame: origin[3], xdir[3], ydir[3] in the file's 3D coordinates. */
void cad_face_frame(const cad_face *face, double origin[3], double xdir[3], double ydir[3]);

/* Loops: loop 0 is the outer loop, loops 1.. are holes.  Edges are numbered
 * globally 0..num_edges-1, loop by loop, each loop's edges in the order of
 * travel; edge e of loop l is loop_first_edge(l) + k, k < loop_num_edges(l).
 * The end of each edge is the start of the next one in its loop, and the
 * last edge of a loop ends where its first begins. */
int cad_face_num_loops(const cad_face *face);
int cad_face_loop_first_edge(const cad_face *face, int loop);
int cad_face_loop_num_edges(const cad_face *face, int loop);
int cad_face_num_edges(const cad_face *face);

/* Names the file gives its faces and edges (STEP: the names of its
 * ADVANCED_FACE / FACE_SURFACE and EDGE_CURVE items, as OCCT's XDE reader
 * reads them for sub-shapes; docs/formats.md "Named boundaries"), made
 * group names: characters other than [A-Za-z0-9_-] as '_', at most 63;
 * "" and "NONE" are none.  NULL: no name (IGES and BREP files: never).
 * An edge of a face keeps its name through healing: it is the named edge
 * of the file's face whose middle point is within the face's junction
 * tolerance of its own. */
const char *cad_model_face_name(const cad_model *model, int index);
const char *cad_face_edge_name(const cad_face *face, int edge);
int cad_face_edge_loop(const cad_face *face, int edge);
/* 1 when edge `edge` is a whole loop by itself (a closed curve: a full
 * circle, its start its end), else 0. */
int cad_face_edge_closed(const cad_face *face, int edge);
cad_edge_type cad_face_edge_type(const cad_face *face, int edge);
double cad_face_edge_length(const cad_face *face, int edge);

/* Evaluate edge `edge` at arc length s in [0, length], measured in the
 * direction of travel.  Any of xy[2], tangent[2] (unit, direction of travel)
 * and curvature (signed: > 0 where the boundary turns left, i.e. towards the
 * face) may be NULL.  At s = 0 and s = length xy is the corner the edge shares
 * with its neighbour; where the curve's own end misses it (within the
 * closure tolerance) the gap is blended in along the edge, so that xy is
 * continuous in s (tangent and curvature are the curve's). */
sq_status cad_face_edge_eval(const cad_face *face, int edge, double s, double xy[2],
                             double tangent[2], double *curvature, sq_error *err);

/* *val = the integral of x dy - y dx (twice the signed area swept about the
 * frame's origin) along edge `edge` from arc length s0 to s1 >= s0, both
 * measured in the direction of travel; 0 if s1 <= s0. */
sq_status cad_face_edge_green(const cad_face *face, int edge, double s0, double s1, double *val,
                              sq_error *err);

/* Closest point of edge `edge` to p: arc length *s and foot[2] (either may
 * be NULL); *dist its distance (may be NULL). */
sq_status cad_face_edge_project(const cad_face *face, int edge, const double p[2], double *s,
                                double foot[2], double *dist, sq_error *err);

/* The unit tangent (direction of travel) of edge `edge` at its closest
 * point to p: cad_face_edge_project then cad_face_edge_eval, without the
 * two arc-length conversions (boundary data at many points). */
sq_status cad_face_edge_tangent_near(const cad_face *face, int edge, const double p[2],
                                     double tangent[2], sq_error *err);

/* ---- edges faces share (cad_shared.cpp; docs/domains.md) ----------------- */
typedef enum {
    CAD_SHARED_NONE = 0,
    CAD_SHARED_SAME = 1,      /* one OCCT edge of both faces (a sewn or fragmented file) */
    CAD_SHARED_COINCIDENT = 2 /* two edges that coincide within the tolerance (faces not sewn) */
} cad_shared_kind;
/* Whether edge ea of face a and edge eb of face b are one boundary curve of
 * a 2D domain: the same OCCT edge, or two edges of equal length whose points
 * at 0, 1/4, 1/2, 3/4 and all of their arc length coincide in 3D within tol
 * (either way round).  *reversed: b travels it against a (faces side by side
 * travel a shared edge in opposite senses). */
sq_status cad_edges_shared(const cad_face *a, int ea, const cad_face *b, int eb, double tol,
                           cad_shared_kind *kind, int *reversed, sq_error *err);

/* ---- constrained Delaunay refinement (CGAL) ------------------------------ */

/* Local target size at a point; return <= 0 for "no bound here". */
typedef double (*cad_size_fn)(const double xy[2], void *ctx);

typedef struct {
    int npoints;                /* input points, 2*npoints in xy */
    const double *xy;
    int nsegments;              /* constrained segments, 2*nsegments in seg */
    const int *seg;             /* point indices */
    int nholes;                 /* one seed point inside each hole, 2*nholes */
    const double *holes;
    double min_angle_deg;       /* minimum angle bound, <= 30 (CGAL's guarantee) */
    double max_size;            /* longest edge bound, <= 0: none */
    cad_size_fn size;           /* optional local size bound (NULL: none) */
    void *size_ctx;
    int max_vertices;           /* work bound: refuse beyond it (<= 0: 20 million) */
    int keep_segments;          /* 1: refine triangles only, never split a segment
                                   (no Gabriel refinement: a corner far sharper than
                                   any angle bound then costs nothing) */
} cad_cdt_input;

typedef struct {
    int nverts;
    double *xy;      /* 2*nverts */
    int *source;     /* per vertex: index of the input point, or -1 (Steiner) */
    int *on_segment; /* per vertex: for a Steiner vertex on a constrained segment,
                        that input segment's index; else -1 */
    int ntris;
    int *tri;        /* 3*ntris vertex indices, counter-clockwise */
} cad_cdt_output;

/* Constrained Delaunay triangulation of the region bounded by the segments
 * (minus the holes' regions), refined by CGAL's Delaunay mesher to the angle
 * and size bounds.  Refinement may split constrained segments (on_segment
 * says which).  SQ_ERR_GEOMETRY, without running on, when the bounds need
 * more than max_vertices vertices (features far smaller than the size: a
 * thin part, near-touching boundaries, a needle corner).  The caller frees
 * the output with cad_cdt_output_free. */
sq_status cad_cdt_mesh(const cad_cdt_input *in, cad_cdt_output *out, sq_error *err);
void cad_cdt_output_free(cad_cdt_output *out); /* frees the arrays, zeroes the struct */

/* The pairs of segments (2*nsegments point indices into xy) that meet other
 * than at an end point they share (the same index or the same coordinates),
 * decided by CGAL's exact predicates: what cad_cdt_mesh would refuse as
 * crossing constraints, and segments that overlap along a line.  *pairs
 * (malloc'd, the caller frees it; NULL on failure) gets 2 * *npairs segment
 * indices, each pair (k < l), sorted; at most max_pairs pairs (<= 0: all). */
sq_status cad_segments_crossing(int npoints, const double *xy, int nsegments, const int *seg,
                                int max_pairs, int **pairs, int *npairs, sq_error *err);


/* ---- cutting a face into sub-faces (cad_split.cpp) ------------------------ */

typedef struct cad_split cad_split; /* opaque: a face cut into sub-faces */

/* Cut face `face_index` of `model` along ncurves curves.  Curve k has
 * npts[k] >= 2 points, xy[k][2*i], xy[k][2*i+1], in the face's 2D frame;
 * `face` is that face made by cad_face_create (its frame is used; NULL: made
 * here).  Each curve becomes one B-spline edge: the segment for 2 points,
 * else the cubic interpolating its points.  Its first and last points must
 * lie on the face boundary (within 1e-7 x the face's size: they are snapped
 * onto it, corners exactly), or coincide with another curve's end point (the
 * same coordinates within that tolerance: several curves ending at one
 * singular point share one vertex), or lie on another curve (a T-junction);
 * its other points must lie in the face.  Curves may cross one another: they
 * are cut where they meet.  The face is split by OpenCASCADE's Boolean
 * splitter; the sub-faces' areas add up to the face's (checked, 1e-8).
 * Errors: SQ_ERR_USAGE (bad arguments, `face` not that face), SQ_ERR_LAYOUT
 * (a dangling end point or curve piece, a point outside the face, a
 * degenerate curve: the message names the curve), SQ_ERR_INTERNAL (the
 * split failed).  *out stays NULL on failure. */
sq_status cad_face_split(const cad_model *model, int face_index, const cad_face *face,
                         int ncurves, const int *npts, const double *const *xy, cad_split **out,
                         sq_error *err);
void cad_split_free(cad_split **s); /* NULL-safe, NULLs *s */

int cad_split_num_faces(const cad_split *s);

/* Area of sub-face i (Green's theorem on its edges, adaptive Gauss-Legendre:
 * exact to rounding on the B-spline edges); 0 if i is out of range. */
double cad_split_face_area(const cad_split *s, int i);

/* Area of the face before the split, computed the same way. */
double cad_split_total_area(const cad_split *s);

/* Corners of sub-face i: the vertices of its boundary where the edges before
 * and after meet at an angle differing from 180 degrees by more than tol_deg
 * (smooth joins, e.g. where a curve's foot splits an arc, are not corners).
 * Returns their number (-1 if i is out of range) and, if xy is not NULL,
 * the first min(number, max) of them in xy[2*j] in the 2D frame, wire by
 * wire in the order of travel along each. */
int cad_split_face_corners(const cad_split *s, int i, double tol_deg, double *xy, int max);
int cad_split_face_num_corners(const cad_split *s, int i, double tol_deg);

/* Index of the sub-face containing point xy (2D frame; a point on a shared
 * edge gives one of its faces), -1 if none. */
int cad_split_locate(const cad_split *s, const double xy[2]);

/* Write the sub-faces as one STEP shell, in the file's 3D frame and length
 * unit (no scaling), so that cad_model_read gives them back as
 * cad_split_num_faces faces.  Atomic: written to a temporary file beside
 * `path`, then renamed.  SQ_ERR_OUTPUT on failure (no file left behind). */
sq_status cad_split_write_step(const cad_split *s, const char *path, sq_error *err);

#ifdef __cplusplus
}
#endif
#endif
