/* semquad — a block-structured high-order quad mesh of a valid layout
 * (Jezdimirović 2021 §5.3 and §7; Marcon 2019 §3.4).
 *
 * design:
 *  1. chord quantization: every layout edge gets n_e >= 1 segments, first
 *     round(length / size) — the length measured in units of e^H when the
 *     field carries a size; then, patch by patch, opposite sides are made
 *     equal by adding segments to the smaller side (to its edge with the
 *     largest length per segment), repeated until every patch matches — the
 *     additions travel along the layout's chords;
 *  2. each edge's nodes are placed once, by arc length (sub-segment nodes
 *     at Gauss–Lobatto–Legendre or equispaced fractions), exactly on the CAD
 *     curve for boundary edges: the patches sharing an edge share its nodes,
 *     so the mesh is conforming by construction;
 *  3. each patch is filled by discrete transfinite interpolation of its four
 *     sides (blending parameters from the sides' arc-length fractions); the
 *     glued vertex mesh is Laplace-smoothed (untangling), then relaxed to
 *     the minimum of Winslow's energy with the boundary vertices sliding on
 *     their curves (quad_relax.h, Marcon §3.4's suggestion): grid lines
 *     cross at right angles and meet the boundary orthogonally.  Singular
 *     points may move in that relaxation to even out their angles; if a
 *     curved quad then has a non-positive Jacobian they are held, and
 *     failing that the relaxation is skipped;
 *  4. quads of order Q take their (Q+1)^2 nodes from that grid;
 *  5. large meshes: where the quantization gives more than relax_max_quads
 *     quads (and no boundary layers, held edges or periodic pairs), the
 *     chords are quantized again (design 1) at 2^k times the size, k the
 *     least giving at most relax_max_quads quads; 2-4 run on that coarse
 *     mesh, whose quads are then split 2 x 2 k times along their own maps
 *     (quad_refine.h: nested, new boundary nodes on the CAD curves, on
 *     opt->threads threads).  The relaxation's result is a smooth map, so
 *     its sub-maps are as good as relaxing the fine grid, at linear cost
 *     and a fraction of the memory (CHOLMOD's factor, about 2.3 kB a
 *     quad, is the largest part of a relaxation). */
#ifndef SQ_QUAD_MESHER_H
#define SQ_QUAD_MESHER_H

#include "cross_field.h"
#include "layout.h"
#include "size_field.h"
#include "quad_mesh.h"
#include "sq_progress.h"
#include "triangulate.h"

typedef struct {
    int order;          /* Q, 1..10 (default 4) */
    double size;        /* target element size; <= 0: sqrt(area)/8 */
    sq_node_kind nodes; /* default GLL */
    /* boundary layers on the CAD edges bl_edges[nbl]: the first cells of
     * the blocks on them, first height bl_first growing by bl_ratio over
     * bl_layers cells, then by bl_gradation (<= 1: SQ_SIZE_GRADATION) up
     * to the isotropic size (docs/sizes.md) */
    int nbl;
    const int *bl_edges;
    double bl_first, bl_ratio, bl_gradation;
    int bl_layers;
    /* the field traced, or NULL: where it carries a size (the H/θ field's
     * e^H, Jezdimirović 2021 eq. 21) the target size is size * e^H, so the
     * chords follow the per-patch parametrization's scale */
    const sq_cross_field *field;
    /* the user's size field h(x) (src/size), or NULL: the uniform size;
     * where set, the target size is h(x) with `size` as its far size */
    const sq_size_field *sizes;
    /* refuse (SQ_ERR_USAGE) a quantization with more quads than this,
     * before the quads are allocated (default SQ_MAX_QUADS) */
    double max_quads;
    /* "mesh" (patches filled of all) and the relaxation's "relax" */
    sq_progress progress;
    /* faces of a domain (docs/domains.md), NULL for one face: per CAD edge
     * of the face, the split road's triangulation starts from these points
     * (sq_tri_options.edge_points) and the layout road's vertices on the
     * edge are slid onto them (n 0: an edge left as it is), and where held_edges[e] is 1 the
     * vertices on edge e stay where they are placed (smoothing and
     * relaxation move them on no face, so the faces sharing e agree) */
    const sq_edge_points *edge_points;
    const int *held_edges;
    /* faces of a domain whose layouts agree (docs/domains.md), NULL: none:
     * per CAD edge, at least min_chords[e] chords where edge e is one
     * layout edge (the count the face across a shared curve or a periodic
     * pair needs; the quantization raises the opposite sides to match) */
    const int *min_chords;
    /* threads for the refinement and the quality (0: the processors online) */
    int threads;
    /* a quantization of more quads is relaxed coarser and refined (design
     * 5); 0: never */
    double relax_max_quads;
    /* identified edges (periodic, identified_edges.h; none: npairs 0): the
     * layout road gives a boundary piece on a and its image on b the same
     * chords */
    sq_identification periodic;
    /* periodic pairs on the face's own layout (route 1b, docs/domains.md;
     * none: npairs 0): the two curves of a pair get one total chord count
     * (their pieces need not correspond), and after the patches the
     * vertices on b are set to the images of a's in order, b's layout
     * corners sliding along b, then held there by the relaxation */
    sq_identification slid;
} sq_mesher_options;

/* 2e7 quads of order 4 take about 10 GB (25 nodes of 16 bytes each, the
 * vertex grid, the relaxation's arrays and the writers' copies). */
#define SQ_MAX_QUADS 2e7

void sq_mesher_options_default(sq_mesher_options *opt);

/* The target size where sq_mesher_options.size is not set, on a face of
 * area `area` (both roads): sqrt(area)/8. */
double sq_mesher_default_size(double area);
/* The size the mesher works at: opt->size where set, else the default. */
double sq_mesher_size(const sq_mesher_options *opt, double area);

/* Refuse (SQ_ERR_USAGE) a size whose quads, about area / size^2, are more
 * than max_quads, naming the smallest size that fits: a check before any
 * work, from the face's area alone. */
sq_status sq_mesher_check_size(double area, double size, double max_quads, sq_error *err);

/* info: the face (its vertices tell which edges a corner joins). */
sq_status sq_mesh_layout(const cad_face *face, const sq_face_info *info, const sq_layout *L,
                         const sq_mesher_options *opt, sq_quad_mesh **out, sq_error *err);

/* A straight-sided quad mesh of the face, corners only, whose boundary
 * vertices lie on the CAD curves: what a road other than the layout's
 * (quad_split.h) hands to the mesher. */
typedef struct {
    int nv, nq;
    const double *xy;     /* 2*nv */
    const int *quad;      /* 4*nq corner vertices, counter-clockwise */
    const int *block;     /* nq: the block each quad belongs to (sq_quad_mesh.patch) */
    const int *side_tag;  /* 4*nq: CAD edge under side k (corner k to k+1), or -1 */
} sq_linear_quads;

/* Design 3 (untangling, relaxation) and 4 (order opt->order, sides on the
 * CAD curves) on a given straight-sided mesh; opt's size is not used and
 * boundary layers are not made (SQ_ERR_USAGE if opt->nbl > 0). */
sq_status sq_mesh_linear_quads(const cad_face *face, const sq_face_info *info,
                               const sq_linear_quads *lq, const sq_mesher_options *opt,
                               sq_quad_mesh **out, sq_error *err);

#endif
