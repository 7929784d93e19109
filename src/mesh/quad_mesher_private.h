/* semquad — internals shared by the files of the layout road and the
 * mesher's second half (quad_mesher.c, quad_chords.c, quad_layers.c,
 * quad_transfinite.c, quad_assemble.c, quad_untangle.c, quad_raise.c; not a
 * public contract).  The designs cited are those of quad_mesher.h. */
#ifndef SQ_QUAD_MESHER_PRIVATE_H
#define SQ_QUAD_MESHER_PRIVATE_H

#include "quad_mesher.h"
#include "quad_relax.h"

/* Samples of an edge's size measure (qm_size_measure); with boundary
 * layers more, so that the first cell (a few thousandths of the edge) is
 * read from the cumulative measure, not interpolated across it. */
#define SIZE_SAMPLES 32
#define SIZE_SAMPLES_BL 128

/* The nodes of every layout edge, placed once (design 2). */
typedef struct {
    const int *n;  /* segments per edge */
    long *base;    /* first global id of each edge's interior points */
    double **pts;  /* per edge: n*Q+1 points from n0 to n1 */
} qm_edge_nodes;

/* One patch's grid of vertices (design 3). */
typedef struct {
    int NU, NV;      /* grid points - 1 along u and v */
    double *xy;      /* 2*(NU+1)*(NV+1), index j*(NU+1)+i */
    long *gid;
    int *tag[4];     /* CAD edge under each boundary segment of side k, in grid order */
} qm_patch_grid;

/* Vertex-level mesh: patch grids of corner vertices glued along edges. */
typedef struct {
    int nv, nq;
    double *xy;     /* 2*nv */
    int *foot;      /* nv: 1 where a separatrix ends on the boundary */
    int *quad;      /* 4*nq corner vertices, counter-clockwise */
    int *patch;     /* nq */
    int *side_tag;  /* 4*nq: CAD edge under side k, or -1 */
} qm_vmesh;

/* ---- quad_chords.c: design 1 ---- */

/* Segments on side k of quad patch p, n segments per edge. */
long qm_side_count(const sq_layout_patch *p, int k, const int *n);
/* Quads of a quantization: the product of each patch's two side counts. */
double qm_quantized_quads(const sq_layout *L, const int *n);
/* Samples S of each edge's cumulative measure under options o. */
int qm_size_samples(const sq_mesher_options *o);
/* Each edge's measure m[e] (in units of the field's size where it carries
 * one), which counts its segments, and the cumulative values cum[e * (S +
 * 1) + k] of its measure without the field's size, which place its
 * vertices; S = qm_size_samples(o). */
sq_status qm_size_measure(const sq_layout *L, const cad_face *face,
                          const sq_mesher_options *o, double *m, double *cum, sq_error *err);
/* Arc-length fraction where the cumulative measure cum[S + 1] reaches
 * fraction u. */
double qm_measure_fraction(const double *cum, int S, double u);
/* Segments per edge n[e], opposite sides of every patch matched; with
 * need (NULL: none), no fewer on sides k and k + 2 of patch q than
 * round(need[2 q + k] / size). */
/* partner (NULL: none): layout edges whose counts are one (qm_periodic_partners);
 * o->slid: each pair's two curves one total (SQ_ERR_LAYOUT where the
 * layout's sheets cannot give it). */
sq_status qm_quantize(const sq_layout *L, const double *len, double size, const double *need,
                      const int *partner, const sq_mesher_options *o, int *n, sq_error *err);
/* With identified edges (o->periodic): partner[e] the boundary piece on b
 * whose ends are the images of piece e's on a (and back) within a quarter
 * of the size, else -1. */
void qm_periodic_partners(const sq_layout *L, const cad_face *face, const sq_mesher_options *o,
                          double size, int *partner);

/* ---- quad_interior.c ---- */

/* With the user's sizes: need[2 q + k], the largest integral of size / h
 * along the lines inside quad patch q that run like its side k (k = 0, 1),
 * in the units of the edges' measure (qm_size_measure). */
sq_status qm_interior_measure(const sq_layout *L, const cad_face *face,
                              const sq_mesher_options *o, double size, double *need,
                              sq_error *err);

/* ---- quad_layers.c: boundary layers ---- */

/* Thickness of nb geometric layers. */
double qm_bl_thickness(const sq_mesher_options *o, int nb);
/* A side from A to B along a wall inside its layer (1: c, s0, s1, d0, d1 filled). */
int qm_layer_side(const cad_face *face, const sq_mesher_options *o, double thick,
                  const double A[2], const double B[2], int *c, double *s0, double *s1,
                  double *d0, double *d1);

/* ---- quad_transfinite.c, quad_assemble.c: designs 2 and 3 ---- */

/* Transfinite (Coons) interpolation at (u, v) in [0, 1]^2 of the side
 * points B(u) (v = 0), T(u) (v = 1), Lf(v) (u = 0), R(v) (u = 1) and the
 * corners P00, P10, P11, P01: x. */
static inline void qm_coons(const double *B, const double *T, const double *Lf, const double *R,
                            const double *P00, const double *P10, const double *P11,
                            const double *P01, double u, double v, double x[2])
{
    for (int c = 0; c < 2; c++)
        x[c] = (1 - v) * B[c] + v * T[c] + (1 - u) * Lf[c] + u * R[c] -
               ((1 - u) * (1 - v) * P00[c] + u * (1 - v) * P10[c] + u * v * P11[c] +
                (1 - u) * v * P01[c]);
}

void qm_patch_grid_free(qm_patch_grid *g);
/* The grids of the layout's patches (grids[npatches]), from the edges'
 * nodes; their interior vertices numbered from *next_id on; "mesh"
 * progress per patch. */
sq_status qm_fill_patches(const sq_layout *L, const qm_edge_nodes *en, const sq_progress *progress,
                          long *next_id, qm_patch_grid *grids, sq_error *err);
/* The vertex mesh of layout L with nseg[e] segments per edge, placed by
 * the cumulative measures cum of qm_size_measure. */
sq_status qm_assemble(const sq_layout *L, const cad_face *face, const sq_mesher_options *opt,
                      const int *nseg, const double *cum, qm_vmesh *v, sq_error *err);
void qm_vmesh_free(qm_vmesh *v);

/* ---- quad_regrade.c: boundary layers exact on every grid line ---- */

/* With boundary layers (o->nbl, o->sizes the walls' field, read with the
 * far size far): every grid line of v leaving a wall, followed straight
 * on through regular interior vertices to the boundary or an irregular
 * vertex (reach > 0: to `reach` vertices past the first where the size
 * along it is isotropic), its nodes moved along it so that its first
 * o->bl_layers cells are the metric's and the rest keep its count; a
 * line whose move would fold a quad is left as it was.  ends (NULL: not
 * wanted): *ends allocated, 1 at the irregular interior vertices where
 * such a line ends. */
sq_status qm_regrade_walls(const sq_mesher_options *o, double far, int reach, qm_vmesh *v,
                           int **ends, sq_error *err);

/* ---- quad_slide.c: vertices slid along curves ---- */

/* The vertices of each pair of opt->slid on b set to the images of a's,
 * one to one in order of arc length (b at L - s the image of a at s): b's
 * layout corners slide along b.  The quantization gave both one total
 * (SQ_ERR_INTERNAL otherwise). */
sq_status qm_slide_periodic(const cad_face *face, const sq_mesher_options *opt, qm_vmesh *v,
                            sq_error *err);
/* Faces of a domain on the layout road: the vertices on each edge e with
 * opt->edge_points[e].n > 0 set, in order of arc length, to those points
 * (the face across put its vertices there), its layout corners sliding
 * along e; on a closed edge (a whole loop) the points are all its
 * vertices, matched in cyclic order.  SQ_ERR_LAYOUT if the counts differ. */
sq_status qm_slide_shared(const cad_face *face, const sq_mesher_options *opt, qm_vmesh *v,
                          sq_error *err);

/* ---- quad_untangle.c ---- */

/* Every corner triangle of quad q has positive area. */
int qm_quad_valid(const qm_vmesh *v, int q);
/* Laplace untangling of the free vertices (keep: vertices held, or NULL). */
sq_status qm_smooth(const cad_face *face, const sq_face_info *info, qm_vmesh *v, const int *keep,
                    sq_error *err);
/* Whether v has an interior vertex of valence other than 4 that keep does
 * not hold: one that qm_relax frees with move_singular, else both its
 * modes hold the same vertices. */
int qm_has_free_singular(const qm_vmesh *v, const int *keep);
/* Winslow relaxation (quad_relax.h) with the singular points free or held;
 * keeping the quads' aspect ratios where opt has the user's sizes;
 * untangle: the untangling of folded corners instead (sq_quad_untangle). */
sq_status qm_relax(const cad_face *face, const sq_face_info *info, qm_vmesh *v, const int *keep,
                   int move_singular, int untangle, const sq_mesher_options *opt,
                   sq_relax_work **work, int *folded, sq_error *err);

/* ---- quad_raise.c: design 4 ---- */

sq_status qm_raise_order(const cad_face *face, const qm_vmesh *v, int Q, sq_node_kind kind,
                         const sq_mesher_options *opt, sq_quad_mesh **out, sq_error *err);
/* Arc lengths *s0, *s1 on CAD edge `tag` of the ends A, B of a side
 * walked from A to B (`along`: in the curve's direction of travel), one
 * continued past a closed curve's closing point so that s0 + t (s1 - s0),
 * t in [0, 1], runs along the side (quad_refine.c uses them too). */
sq_status qm_side_arcs(const cad_face *face, int tag, const double A[2], const double B[2],
                       int along, double *s0, double *s1, sq_error *err);
/* The point of CAD edge `tag` at arc length s, s past the length wrapped
 * round a closed curve. */
sq_status qm_curve_point(const cad_face *face, int tag, double s, double xy[2], sq_error *err);

#endif
