/* semquad — coarse curved triangulation of a planar face.
 *
 * design:
 *  1. discretize each boundary edge, equidistributing
 *     rho(s) = 1/size + |curvature(s)|/max_turn (every segment turns by at
 *     most max_turn, and is at most `size` long), points exactly on the curve;
 *     chords that cross (loops closer than a chord's sagitta: a near-tangent
 *     hole) are halved on their curves until none do (cad_segments_crossing);
 *  2. CGAL constrained Delaunay refinement (min angle, size, graded size
 *     around the extra points) of that polygon;
 *  3. where the refinement split a boundary segment, put the split point on
 *     the curve (by arc length) into the discretization and redo 2, so every
 *     boundary vertex lies on the CAD curve;
 *  4. raise to order P: nodes of boundary edges at Gauss–Lobatto–Legendre
 *     arc-length positions on the curve, interior nodes by blending the edge
 *     displacements into the element (Szabó & Babuška's blending map), and
 *     check every element's scaled Jacobian. */
#ifndef SQ_TRIANGULATE_H
#define SQ_TRIANGULATE_H

#include "cad.h"
#include "tri_mesh.h"

/* Arc lengths of points on one CAD edge. */
typedef struct {
    int n;
    const double *s;
} sq_edge_points;

/* The highest order of the curved triangles (their nodal sets stop there). */
#define SQ_TRI_MAX_ORDER 12

typedef struct {
    int order;            /* P, 1..SQ_TRI_MAX_ORDER */
    double size;          /* longest edge; <= 0: automatic (sqrt(area)/3) */
    double min_angle_deg; /* CGAL's angle bound, default 20; 0: none (size only) */
    double max_turn_deg;  /* largest boundary turning per segment, default 30 */
    int nextra;           /* points to insert as vertices, 2*nextra in extra_xy */
    const double *extra_xy;
    double extra_size;    /* size at the extra points (<= 0: size/8); grows
                             with distance at rate extra_growth up to size */
    const double *extra_sizes; /* per extra point instead of extra_size (NULL:
                                  extra_size at all of them) */
    double extra_growth;  /* <= 0: 1/2 */
    int max_vertices;     /* work bound (default SQ_TRI_MAX_VERTICES): beyond
                             it the face is refused (SQ_ERR_GEOMETRY) */
    int keep_segments;    /* 1: never split a boundary segment in the refinement
                             (cad_cdt_input's: for order 1 with no angle bound) */
    /* NULL, or per CAD edge of the face: where .n > 0, the edge's boundary
     * points to start from are exactly s[0..n-1] (arc lengths along its
     * direction of travel, s[0] = 0, increasing, below its length) instead
     * of the equidistributed ones: faces of a domain sharing an edge start
     * from one discretization of it (docs/domains.md) */
    const sq_edge_points *edge_points;
    /* NULL, or a size bound of the caller's at xy (ctx its data): the
     * refinement's and the boundary's size is at most it there (a size
     * field of a stage above this one, which this one cannot name) */
    double (*user_size)(const double xy[2], void *ctx);
    void *user_ctx;
} sq_tri_options;

/* The coarse triangulation carries a field of order up to 12 on every
 * triangle: 20000 vertices (about 40000 triangles) is already far beyond
 * any face whose features the size resolves, and CGAL reaches it in about a
 * second; a face that needs more (aspect 1e6, a needle corner graded to
 * 1e-7 of the size) is refused rather than left running. */
#define SQ_TRI_MAX_VERTICES 20000

void sq_tri_options_default(sq_tri_options *opt);

/* The order of the triangles a field of order p is solved on:
 * isoparametric, up to SQ_TRI_MAX_ORDER (the one clamp of a field's order). */
int sq_tri_order_for(int p);

/* The size bound opt resolves to on a face of area `area`: opt->size, or
 * sqrt(|area|) / 3 where that is <= 0.  Callers that know the area set
 * opt->size with it, and sq_triangulate need not compute it. */
double sq_tri_size(const sq_tri_options *opt, double area);

/* The edge length the refinement aims at at xy: the resolved size bound
 * `size`, graded towards opt's extra points (extra_size there, growing at
 * extra_growth with the distance), at most opt's user_size. */
double sq_tri_graded_size(const sq_tri_options *opt, double size, const double xy[2]);

typedef struct {
    sem_tri_mesh *mesh;  /* btag = CAD edge index of boundary element edges */
    double *bs;          /* 6*ntris: arc lengths (start, end) of each element
                            edge on its CAD edge, along the edge's direction;
                            unused (0) for interior edges */
    double *jac;         /* ntris: scaled Jacobian of each element */
    double size;         /* size bound used */
    double min_angle_deg;       /* smallest angle of the straight triangles */
    double min_scaled_jacobian; /* over all elements */
    double area;                /* sum over elements of the integral of det J */
} sq_triangulation;

sq_status sq_triangulate(const cad_face *face, const sq_tri_options *opt, sq_triangulation *out,
                         sq_error *err);
void sq_triangulation_free(sq_triangulation *tri); /* frees, zeroes the struct */

#endif
