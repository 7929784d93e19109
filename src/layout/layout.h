/* semquad — the quad layout: the boundary loops and the separatrices as a
 * planar graph, its faces (patches), validation and correction
 * (Marcon 2019 §3.3–3.4; Jezdimirović 2021 journal §6).
 *
 * design:
 *  1. nodes: face vertices, singular points (the caller's, plus nodes that
 *     repairs insert), separatrix feet on the boundary (CAD edge + arc
 *     length), open (dangling) ends and crossings.  Separatrices are cut
 *     at every intersection with one another or with themselves (exact
 *     segment-segment intersection of their polylines); the boundary is cut
 *     at the face vertices and the feet.
 *  2. patches are the faces of the planar graph: at every node the
 *     half-edges are sorted by the angle of their tangent there, and a face
 *     is walked by turning to the clockwise neighbour of the twin (the face
 *     stays on the left).  Cycles that use a boundary edge against its
 *     direction of travel bound the outside (or a hole's inside) and are
 *     dropped; a clockwise cycle (a separate component, e.g. an untouched
 *     hole loop) is an inner boundary of the smallest counter-clockwise
 *     cycle that contains it, so a patch may have several cycles (annular).
 *  3. a node is a corner of a patch when the patch's interior angle there
 *     (between the tangents of its two edges) is off π by more than
 *     SQ_LAYOUT_CORNER_TOL_DEG; patch areas are exact (Green's theorem: the
 *     CAD curves integrated adaptively, the polylines by the shoelace
 *     formula), so they sum to the face area whatever the separatrices.
 *  4. correction (sq_layout_build), repeated until valid or stuck:
 *     duplicated separatrices removed (Jezdimirović §6.1, Fig. 15); limit
 *     cycles (open ends, separatrices crossing one another twice or
 *     themselves) cut at their first near-orthogonal crossing (§6.1,
 *     Fig. 16), leaving a T-junction; T-junctions repaired by continuing the
 *     cut separatrix across along the field (Heun steps, §6.1) to the
 *     boundary or the next separatrix (§6.3, Fig. 17); near-orthogonal
 *     crossings of two separatrices become regular valence-4 nodes (both
 *     split there); a triangular patch with a boundary valence-2 point on
 *     a side (a face vertex taking one quad where the boundary is within
 *     SQ_LAYOUT_CORNER_TOL_DEG of straight: a quad in topology, a triangle
 *     in geometry) split as Jezdimirović §6.3, Fig. 18: the point becomes
 *     two valence-3 points, a node imposed at the patch's barycentre joined
 *     to the point (now a regular boundary point of two quads) and to the
 *     midpoints of the two other sides; other triangular patches split by
 *     midpoint division (Marcon §3.4, Fig. 13: a valence-3 node at the
 *     patch centroid joined to the midpoints of the three sides; a
 *     valence-0 corner then takes one quad).  A spoke's end on a separatrix
 *     is a T-junction for the neighbouring patch, repaired in turn.
 *     Annular patches (no corner on any cycle) cut along field lines from
 *     the outer loop to the inner one, at points where the field is best
 *     aligned with the inward normal.
 *  5. the all-quad last resort (sq_layout_all_quad, for `mesh` where 4
 *     leaves the layout invalid): crossings made nodes, dangling pieces
 *     removed, every non-quad patch split (a lens cut across, the n-quad
 *     split, a chord from a corner), the spokes' ends left as T-junctions:
 *     four-sided patches whose sides may be several layout edges, which
 *     the chord quantization matches edge by edge.
 *
 * All coordinates are in the face's 2D frame (cad.h). */
#ifndef SQ_LAYOUT_H
#define SQ_LAYOUT_H

#include "cross_field.h"
#include "face_info.h"
#include "separatrix.h"
#include "singularity.h"
#include "trace.h"

/* Interior angles within this of π are not corners (degrees). */
#define SQ_LAYOUT_CORNER_TOL_DEG 30.0
/* The all-quad last resort's tolerance at inserted nodes (degrees): a
 * spoke that leaves a side at 160° still makes a corner of its quad there
 * (a wide angle, not a triangle split again and again), while a T-junction
 * on a straight spoke or a smooth separatrix stays no corner. */
#define SQ_LAYOUT_ALLQUAD_CORNER_TOL_DEG 10.0
/* A face vertex taking 2 quads (the field's rounding of angle / 90 deg: an
 * angle in about 135-225 deg) within this of π starts no separatrix and is
 * no patch corner: a bend of a patch side with two quads at it, as a smooth
 * junction (degrees; trace.c, layout_patches.c). */
#define SQ_LAYOUT_BEND_TOL_DEG 45.0

typedef enum {
    SQ_LNODE_CORNER = 0, /* face vertex `id` (sq_face_info.vertices) */
    SQ_LNODE_SINGULAR,   /* singular point `id` of sq_layout.sing */
    SQ_LNODE_FOOT,       /* on CAD edge `id` at arc length `s` */
    SQ_LNODE_CROSSING,   /* separatrices cross here (not at their ends) */
    SQ_LNODE_OPEN        /* dangling end of separatrix `id` */
} sq_lnode_kind;

typedef struct {
    double x, y;
    sq_lnode_kind kind;
    int id;
    double s;    /* SQ_LNODE_FOOT: arc length on CAD edge id */
    int valence; /* patches expected to have it as a corner: V at a singular
                    point, n at a face vertex, 2 at a foot, 4 at a crossing,
                    0 at an open end */
    int degree;  /* edge ends at the node */
    int bend;    /* SQ_LNODE_CORNER: sq_vertex.bent, a bend of a patch side at
                    any angle when it takes 2 quads */
} sq_layout_node;

typedef struct {
    int n0, n1;    /* from node n0 to node n1 */
    int cad_edge;  /* >= 0: boundary piece, CAD edge cad_edge from arc length
                      s0 to s1 > s0 (its direction of travel: face on the left) */
    double s0, s1;
    int sep;       /* >= 0: piece of separatrix sep of sq_layout.seps */
    int npts;      /* polyline from n0 to n1, ends exactly at the nodes; for a
                      boundary piece a sample of the CAD curve (for drawing) */
    double *xy;    /* 2*npts */
    double length;
} sq_layout_edge;

typedef struct {
    int edge;
    int reversed; /* 1: walked from n1 to n0 */
} sq_layout_half;

typedef struct {
    int ncycles;
    int *cycle_start;    /* ncycles+1 offsets into half; cycle 0 is the outer
                            (counter-clockwise) one, the others are holes */
    int nhalf;
    sq_layout_half *half; /* each cycle walked with the patch on the left */
    int ncorners;        /* over all cycles */
    int *corners;        /* node ids, in walking order */
    int *corner_half;    /* index into half of the half-edge leaving corner k */
    double *corner_angle; /* interior angle at corner k (radians) */
    double area;         /* exact (Green), > 0 */
    /* Quad patches (ncorners == 4, one cycle): half is rotated to start at
     * corner 0, and side k (k = 0..3, from corners[k] to corners[(k+1)%4])
     * is half[side_start[k] .. side_start[k+1]-1]; side_start[4] = nhalf.
     * Other patches: all -1. */
    int side_start[5];
} sq_layout_patch;

/* Why a node was added to the caller's singular points. */
typedef enum {
    SQ_LROLE_INPUT = 0,  /* given by the caller */
    SQ_LROLE_CROSSING,   /* two separatrices crossing (regular, valence 4) */
    SQ_LROLE_TJUNCTION,  /* end of a cut separatrix on another (to repair) */
    SQ_LROLE_MIDPOINT,   /* midpoint division (Marcon §3.4), valence 3 */
    SQ_LROLE_VALENCE2    /* barycentre node of a boundary valence-2 split
                            (Jezdimirović §6.3), valence 3 */
} sq_lrole;

typedef struct {
    int separatrices, patches, quad_patches;
    int t_junctions, limit_cycles_cut, triangles_repaired, annuli_cut, duplicates_removed;
    int crossings_split; /* near-orthogonal crossings made regular nodes */
    int valence2_split;  /* boundary valence-2 points split (Jezdimirović
                            Fig. 18); triangles_repaired counts the midpoint
                            divisions only */
    int extra_separatrices; /* traced from a corner of a pentagon or hexagon */
    int polygons_split;  /* n-quad splits of patches with n != 3, 4 corners */
    int separatrices_removed; /* bounding slivers or triangles (repair_remove.c) */
    int straight_stems;  /* T-junction stems continued by a straight ray where
                            the field line found no end */
    int iterations;      /* correction passes */
    int all_quad_splits; /* patches split by the all-quad last resort
                            (sq_layout_all_quad); 0 on a valid layout */
} sq_layout_stats;

typedef struct {
    /* the pattern the graph is built on (copies; repairs extend them) */
    int nsing;
    sq_singularity *sing;
    sq_lrole *role;       /* per singular point */
    int nvertices;
    int *vertex_quads;    /* n per face vertex (0 set to 1 once its triangle
                             is repaired, 1 to 2 once a valence-2 point is
                             split) */
    sq_separatrix_set seps;
    /* the planar graph */
    int nnodes;
    sq_layout_node *nodes;
    int nedges;
    sq_layout_edge *edges;
    int npatches;
    sq_layout_patch *patches;
    double face_area; /* from sq_face_info */
    double scale;     /* bounding-box diagonal */
    double inserted_corner_tol; /* > 0: at the nodes repairs inserted, sectors
                                   off π by more than this (radians) are
                                   corners (the all-quad last resort); else
                                   SQ_LAYOUT_CORNER_TOL_DEG as everywhere */
    sq_layout_stats stats;
} sq_layout;

typedef enum {
    SQ_DEFECT_CORNERS = 0, /* a patch without exactly four corners */
    SQ_DEFECT_ANNULAR,     /* a patch with several boundary cycles */
    SQ_DEFECT_SINGULAR,    /* singular point of valence V not a corner of V patches */
    SQ_DEFECT_VERTEX,      /* face vertex with n quads not a corner of n patches */
    SQ_DEFECT_FOOT,        /* foot on the boundary not a corner of 2 patches */
    SQ_DEFECT_AREA,        /* patch areas do not sum to the face area */
    SQ_DEFECT_CROSSING,    /* separatrices crossing other than at their ends */
    SQ_DEFECT_OPEN,        /* dangling (open) separatrix end */
    SQ_DEFECT_TJUNCTION,   /* a separatrix ending on another one */
    SQ_DEFECT_NKINDS
} sq_defect_kind;

typedef struct {
    sq_defect_kind kind;
    int index;     /* patch (CORNERS, ANNULAR) or node (others; -1 for AREA) */
    char msg[160]; /* one line */
} sq_layout_defect;

typedef struct {
    int n, cap;
    sq_layout_defect *d;
    int count[SQ_DEFECT_NKINDS];
} sq_layout_defects;

/* Build the layout graph of the face from a singularity pattern and a set of
 * separatrices, without repairs.  vertex_quads[info->nvertices]: n per face
 * vertex.  The set is copied.  *out is zeroed on failure. */
sq_status sq_layout_graph(const cad_face *face, const sq_face_info *info, const int *vertex_quads,
                          int nsing, const sq_singularity *sing, const sq_separatrix_set *seps,
                          sq_layout *out, sq_error *err);

/* Build and correct the layout (design 4).  field (may be NULL: repairs then
 * continue straight) and opt (may be NULL: defaults) drive the repairs'
 * tracing.  Returns SQ_OK with a valid layout, or SQ_ERR_LAYOUT with what is
 * left in err ("2 patches with 3 corners, 1 T-junction") and the last
 * layout in *out (the caller frees it either way); other codes: *out zeroed. */
sq_status sq_layout_build(const cad_face *face, const sq_face_info *info, const int *vertex_quads,
                          int nsing, const sq_singularity *sing, const sq_separatrix_set *seps,
                          const sq_cross_field *field, const sq_trace_options *opt,
                          sq_layout *out, sq_error *err);

/* The all-quad last resort for a layout sq_layout_build left invalid:
 * every patch that is not a quad split into n quads around a centre
 * (n >= 2 corners; layout_allquad.c), the spokes' ends on neighbouring
 * patches left as T-junctions (no corner there: the neighbour stays a quad).
 * SQ_OK when every patch then has four corners and one cycle, with no
 * crossing and no dangling end (valences and T-junctions are not checked:
 * the mesh's irregular vertices are counted on the mesh); else
 * SQ_ERR_LAYOUT saying which patch and why, L as far as it got. */
sq_status sq_layout_all_quad(const cad_face *face, const sq_face_info *info, sq_layout *L,
                             sq_error *err);

void sq_layout_free(sq_layout *layout); /* frees, zeroes the struct; NULL-safe */

/* Validate (design 3; DESIGN.md must-show checks).  Fills *defects (freed
 * with sq_layout_defects_free); returns the number of defects. */
int sq_layout_check(const sq_layout *layout, sq_layout_defects *defects);
void sq_layout_defects_free(sq_layout_defects *d);

/* One line: "2 patches with 3 corners, 1 T-junction" (or "valid"). */
void sq_layout_defects_summary(const sq_layout_defects *d, char *buf, int n);

/* Point of edge e at fraction t in [0, 1] of its length, walked from n0
 * (exact CAD evaluation for boundary pieces). */
sq_status sq_layout_edge_point(const sq_layout *layout, const cad_face *face, int e, double t,
                               double xy[2], sq_error *err);

#endif
