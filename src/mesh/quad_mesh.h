/* semquad — a conforming high-order quadrilateral mesh (plain data), what
 * `semquad mesh` produces and the writers consume.
 *
 * Element (i, j) lattice: each quad of order Q has (Q+1)^2 nodes, node
 * (i, j), 0 <= i, j <= Q, at local index j*(Q+1) + i; (i, j) = (0,0),
 * (Q,0), (Q,Q), (0,Q) are its corners, counter-clockwise.  Local side k
 * joins corner k to corner (k+1)%4.  Nodes are shared between elements
 * (global indices), so the mesh is conforming by construction.  The node
 * positions along each side are Gauss–Lobatto–Legendre (nodes = "gll") or
 * equispaced ("equispaced") in the element's parameter; writers resample to
 * what their format expects when needed. */
#ifndef SQ_QUAD_MESH_H
#define SQ_QUAD_MESH_H

#include "sq_status.h"

#include <stddef.h>

typedef enum { SQ_NODES_GLL = 0, SQ_NODES_EQUISPACED = 1 } sq_node_kind;

/* A periodic link (docs/domains.md): the nodes of curve `tag` are the
 * images of curve `master`'s under one rigid motion, node[k] =
 * T(master_node[k]) exactly (sq_quad_mesh_apply_periodic). */
typedef struct {
    int tag, master;   /* boundary tags (CAD edges) */
    double affine[6];  /* T(x, y) = (a0 x + a1 y + a2, a3 x + a4 y + a5) */
    int nnodes;
    int *node, *master_node;
} sq_quad_periodic;

typedef struct {
    int order;           /* Q, 1..10 */
    sq_node_kind nodes;  /* placement of the nodes along each element side */
    int nnodes;
    double *xy;          /* 2*nnodes */
    int nquads;
    int *conn;           /* (Q+1)^2 * nquads global node indices, lattice order */
    int *patch;          /* nquads: layout patch of each quad (or -1) */
    int nbnd;            /* boundary element sides */
    int *bnd_quad;       /* nbnd: the quad */
    int *bnd_side;       /* nbnd: its local side 0..3 */
    int *bnd_tag;        /* nbnd: CAD edge index (the boundary curve, physical group) */
    int ntags;           /* boundary curves: tags are 0..ntags-1 */
    char **tag_name;     /* ntags names (NULL: boundary_<tag>), or NULL: none named */
    /* faces of a domain (docs/domains.md): nregions > 0 faces, region[q]
     * the face (0..nregions-1) of quad q, region_face[r] that face's number
     * in the CAD file, region_name[r] its name (NULL: face_<number>; the
     * array NULL: none named); nregions = 0, all NULL: one face */
    int nregions;
    int *region;
    int *region_face;
    char **region_name;
    /* periodic pairs (quad_periodic.c): nperiodic links; the identified
     * domain's Euler characteristic, the net index sum (4 - valence) its
     * interior vertices need by Gauss–Bonnet, and this mesh's irregular
     * vertices in it and their net index */
    int nperiodic;
    sq_quad_periodic *periodic;
    int periodic_chi, periodic_index, periodic_irregular, periodic_mesh_index;
    /* a large mesh relaxed coarser (quad_mesher.h design 5): the quads of
     * the mesh relaxed, this one its 2^k x 2^k refinement; 0: this one */
    int relaxed_quads;
} sq_quad_mesh;

/* Periodic links (quad_periodic.c): every link's nodes set to the images
 * of its master's; dst's links a copy of src's (same node numbering);
 * link appended (its arrays taken); all freed. */
void sq_quad_mesh_apply_periodic(sq_quad_mesh *m);
sq_status sq_quad_mesh_copy_periodic(sq_quad_mesh *dst, const sq_quad_mesh *src, sq_error *err);
sq_status sq_quad_mesh_add_periodic(sq_quad_mesh *m, const sq_quad_periodic *link, sq_error *err);
void sq_quad_mesh_free_periodic(sq_quad_mesh *m);

/* An index list (nodes, edges, patches) a[n] sorted ascending, each
 * index kept once: the count kept. */
int sq_sort_unique(int *a, int n);

/* Named boundaries (docs/formats.md): the group of curve t, the least
 * tag with its name (t itself when unnamed), and its name, buf
 * ("boundary_<t>") when unnamed. */
int sq_quad_mesh_tag_group(const sq_quad_mesh *m, int t);
/* The name of face r of a domain: its name, or buf ("face_<number>"). */
const char *sq_quad_mesh_region_name(const sq_quad_mesh *m, int r, char *buf, size_t n);
const char *sq_quad_mesh_tag_name(const sq_quad_mesh *m, int t, char *buf, size_t n);

/* src's curve and face names given to dst (a mesh made from it with the
 * same tags and regions: a family's refined mesh); dst has none yet. */
sq_status sq_quad_mesh_copy_names(sq_quad_mesh *dst, const sq_quad_mesh *src, sq_error *err);

/* Give m nregions regions (region[] and region_face[] allocated, zeroed). */
sq_status sq_quad_mesh_set_regions(sq_quad_mesh *m, int nregions, sq_error *err);

sq_status sq_quad_mesh_create(int order, sq_node_kind nodes, int nnodes, int nquads, int nbnd,
                              sq_quad_mesh **out, sq_error *err);
void sq_quad_mesh_free(sq_quad_mesh **m); /* NULL-safe, NULLs *m */

/* Lattice index of node (i, j) of a quad of order Q. */
static inline int sq_quad_node(int Q, int i, int j) { return j * (Q + 1) + i; }

/* Lattice index of the s-th node along local side k of a quad of order Q,
 * from corner k to corner k+1 (counter-clockwise, the quad on the left). */
static inline int sq_quad_side_node(int Q, int k, int s)
{
    switch (k) {
    case 0: return sq_quad_node(Q, s, 0);
    case 1: return sq_quad_node(Q, Q, s);
    case 2: return sq_quad_node(Q, Q - s, Q);
    default: return sq_quad_node(Q, 0, Q - s);
    }
}

/* Quality (docs/conventions.md, Jezdimirović 2021 Table 1): per quad,
 * eta = 1 - max_k |alpha_k - π/2| / (π/2) over the four corner angles, and
 * the scaled Jacobian min det J / max |det J| over the whole element, a
 * proven lower bound from the Bézier coefficients of det J
 * (jacobian_bezier.h, Johnen 2013). */
typedef struct {
    double eta_mean, eta_min, tau_percent; /* tau: % of quads with eta > 0.9 */
    double min_scaled_jacobian;            /* least per-quad bound (sq_jac_ratio) */
    double min_scaled_jacobian_nodes;      /* the same ratio of det J at the nodes only */
    int worst_quad;                        /* the quad of min_scaled_jacobian */
    double worst_xy[2];                    /* its centre, x(1/2, 1/2) */
    int jacobian_capped;                   /* quads whose bounds a cap left unsharp */
    int irregular_interior; /* interior vertices with valence != 4 */
    int irregular_boundary; /* boundary vertices with valence != 2 other than corners */
    /* eta_mean, eta_min and tau_percent (and the per-quad eta) are measured
     * on the straight corner polygon (docs/conventions.md "Quality"), so a
     * measure of the MSH file (tests/t611) agrees with the report; the same
     * statistics with the angles between the curved sides' tangents at the
     * corners (from the element's Lagrange map) are these (docs/formats.md): */
    double eta_curved_mean, eta_curved_min, tau_curved_percent;
    double area;         /* sum over quads of the integral of det J (Gauss, exact) */
    int inverted;        /* quads not proven valid: Bézier lower bound of det J <= 0 */
    int vertices;        /* distinct corner vertices */
    int boundary_vertices;
} sq_quad_quality;

/* eta of the straight quad with counter-clockwise corners c[4]. */
double sq_quad_corner_eta(const double *const c[4]);

/* Per-quad eta[nquads] and sjac[nquads] (either may be NULL) and the
 * summary, the quads shared among `threads` threads (0: the processors
 * online); the same numbers for every count (sums in quad order). */
sq_status sq_quad_mesh_quality(const sq_quad_mesh *m, double *eta, double *sjac, int threads,
                               sq_quad_quality *q, sq_error *err);

/* ---- Added with the writers: element maps, resampling, report ---- */

/* Per-quad eta measured between the tangents of the curved sides at the
 * corners (the eta_curved_* statistics of sq_quad_mesh_quality). */
sq_status sq_quad_mesh_eta_curved(const sq_quad_mesh *m, double *eta_curved, sq_error *err);

/* The element map of quad q: x(u, v) = sum_ij x_ij l_i(u) l_j(v), (u, v)
 * in [0,1]^2, l_i the Lagrange polynomials of the node parameters t_i
 * (GLL points mapped to [0,1], or i/Q). */
typedef struct {
    int order;
    double t[11]; /* node parameters in [0,1] */
    double w[11]; /* barycentric weights */
} sq_quad_basis;

sq_status sq_quad_basis_init(sq_quad_basis *b, int order, sq_node_kind nodes, sq_error *err);
/* l[Q+1] and (if dl) dl[Q+1] at u. */
void sq_quad_basis_eval(const sq_quad_basis *b, double u, double *l, double *dl);
/* x[2] of quad q where the basis takes the values lu[Q+1] in u and lv[Q+1]
 * in v (sq_quad_basis_eval's, once for many quads): sq_quad_mesh_map's x,
 * bit for bit. */
void sq_quad_mesh_point(const sq_quad_mesh *m, int q, const double *lu, const double *lv,
                        double x[2]);
/* x[2] and (if d) d[4] = {x_u, x_v, y_u, y_v} of quad q at (u, v). */
void sq_quad_mesh_map(const sq_quad_mesh *m, const sq_quad_basis *b, int q, double u, double v,
                      double x[2], double d[4]);

/* A copy of m with the nodes moved to the other placement (each node
 * re-evaluated from the element's own Lagrange interpolant at the
 * corresponding lattice point; connectivity and boundary unchanged). */
sq_status sq_quad_mesh_resample(const sq_quad_mesh *m, sq_node_kind nodes, sq_quad_mesh **out,
                                sq_error *err);

/* Order elevation of a linear quad mesh (also: synthetic meshes for tests
 * and benchmarks).  Coarse vertices vxy[2*nverts], quads[4*nquads] corner
 * vertices counter-clockwise.  Node (i, j) of quad q is the bilinear point
 * of its corners at the parameters (t_i, t_j) of `nodes`, then moved by
 * warp (NULL: identity), so a warp applied to a parameter-space grid gives
 * nodes exactly on the warped curves (e.g. circles for a polar warp).
 * Sides used by one quad are the boundary, tagged side_tag[4q+k] (NULL:
 * all 0, ntags = 1).  Mesh nodes: the coarse vertices first (same
 * indices), then Q-1 per coarse edge, then (Q-1)^2 per quad. */
typedef void (*sq_quad_warp_fn)(void *ctx, const double in[2], double out[2]);
sq_status sq_quad_mesh_elevate(int nverts, const double *vxy, int nquads, const int *quads,
                               const int *side_tag, int ntags, int order, sq_node_kind nodes,
                               sq_quad_warp_fn warp, void *ctx, sq_quad_mesh **out,
                               sq_error *err);

/* One summary line ("320 quads, order 4, ...") into buf. */
void sq_quad_quality_line(const sq_quad_mesh *m, const sq_quad_quality *q, char *buf, size_t n);

#endif
