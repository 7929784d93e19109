/* semquad — internals shared by the layout's repairs, repair_*.c and the
 * correction loop layout_repair.c (not a public contract). */
#ifndef SQ_REPAIR_PRIVATE_H
#define SQ_REPAIR_PRIVATE_H

#include "layout_internal.h"

/* The state of one correction (sq_layout_build). */
typedef struct {
    sq_layout *L;
    const cad_face *face;
    const sq_face_info *info;
    const sq_cross_field *field;
    double step, maxlen, tol;
    int nb;        /* boundary sample segments */
    double *bxy;   /* 4*nb: segment ends */
    int *bedge;    /* per segment: CAD edge */
    double *bs;    /* 2*nb: arc lengths of the ends */
    lay_hit *hit;  /* the set's crossings (crossings()), nhit of them, */
    int nhit, hit_ok; /* valid while hit_ok: the set has not changed */
    int trials;    /* patch repairs tried (try_candidate), up to MAX_TRIALS */
    double work;   /* separatrix points the set-level passes visited (WORK_MAX) */
    double lwork;  /* segments the repair lines' steps tested (LINE_WORK_MAX) */
    int all_quad;  /* the all-quad last resort (layout_allquad.c): the n-quad
                      split's triangulation never splits the patch's ring (it
                      needs a path, not Delaunay edges, and tiny sides made
                      CGAL split on); spokes share an inserted node at their
                      end (lay_edge_end) */
} lay_repair;

/* The repairs' work bound, in separatrix points visited by the set-level
 * passes (each finds every crossing of the set again): about 10 s of one
 * core for the densest sets (1.5e-5 s a point at 10^4 crossings); the
 * examples' layouts take less than 2.4e5 (T106), 0.02 to 1 s.  (A repair
 * line's steps have their own bound.)  A bound on the work, not on the
 * clock, keeps the answer the same on every machine. */
#define WORK_MAX 1e6
/* The repair lines' work bound, in segments (separatrix and boundary) their
 * steps tested: each step tests every one, and a line in a thin patch (a
 * tiny edge's) steps at MIN_STEP_FRACTION of the default step, so lines
 * within their step budget could still take minutes (stress corpus 0311, a
 * 1.7e-6 edge: over 49 s of CPU, 1e10 tests).  About 10 s of one core, as
 * WORK_MAX (5 ns a test): of the stress corpus's 131 layouts that succeed
 * (2026-11-26), the most took 1.3e8 (0100), the examples' 1.3e5 (annulus),
 * T106's none.  A bound on the work, not on the clock, as WORK_MAX. */
#define LINE_WORK_MAX 2e9
/* A step's field evaluation (locating the point, the element's Dubiner
 * modes) in the same unit: about 2 us against 5 ns a segment test.  Without
 * it a line among few segments ran uncounted (stress corpus 0311: 60 s of
 * field evaluations within the bound). */
#define LINE_STEP_WORK 400.0

/* The correction's state for layout L (layout_repair.c): field may be NULL
 * (repair lines then continue straight), opt NULL (defaults); the boundary
 * sampled.  lay_repair_end frees its arrays (not L), keeping its counters. */
sq_status lay_repair_begin(lay_repair *r, sq_layout *L, const cad_face *face,
                           const sq_face_info *info, const sq_cross_field *field,
                           const sq_trace_options *opt, sq_error *err);
void lay_repair_end(lay_repair *r);

/* Points of the separatrix set (repair_set.c). */
long lay_set_points(const sq_separatrix_set *S);

/* A repair line (repair_line.c): its points and where it ended. */
typedef struct {
    int npts, cap;
    double *xy;
    sq_sep_end end;
    int hit_sep;     /* SQ_END_SEPARATRIX-like end: separatrix and position */
    double hit_pos;
} lay_line;

/* ---- repair_line.c ---- */

/* The boundary sampled into segments (r->bxy, r->bs, r->bedge). */
sq_status lay_sample_boundary(lay_repair *r, sq_error *err);

/* Segment p-q against segment a-b: parameters t on p-q and u on a-b. */
int lay_seg_seg(const double p[2], const double q[2], const double a[2], const double b[2],
                double *t, double *u);

/* A cross branch at x nearest to direction d (unit); 1 if x is outside. */
int lay_branch(const lay_repair *r, const double x[2], int *elem, const double d[2],
               double out[2]);

/* A field line from p0 in direction d0 to the boundary or a separatrix
 * (hits within `skip` of p0 ignored); out->xy malloc'ed. */
sq_status lay_trace_line(lay_repair *r, const double p0[2], const double d0[2], double skip,
                         lay_line *out, sq_error *err);

/* The straight ray from p0 in direction d0 to the first boundary point or
 * separatrix it meets (hits within `skip` of p0 ignored), as lay_trace_line's
 * line: the shortest admissible connection where the field line cannot be
 * followed to an end; out->xy malloc'ed. */
sq_status lay_ray_line(lay_repair *r, const double p0[2], const double d0[2], double skip,
                       lay_line *out, sq_error *err);

/* The line appended to the set from `start`, ending on the boundary, at a
 * nearby inserted node or at a new T-junction. */
sq_status lay_add_line(lay_repair *r, lay_line *ln, sq_sep_end start, sq_error *err);

/* ---- repair_sep.c ---- */

double lay_nearest_pos(const sq_separatrix *s, const double p[2], double *dist);
sq_status lay_split_sep(sq_layout *L, int k, double pos, const double p[2], int node,
                        sq_error *err);
void lay_leave_dir(const sq_separatrix *s, int at_end, double d[2], double scale);
/* The end of a separatrix leaving node v (a face vertex, a foot, a
 * singular or inserted node); 0 for a crossing or an open end. */
int lay_node_end(const sq_layout *L, int v, sq_sep_end *end);

/* ---- repair_spoke.c ---- */

int lay_patch_centroid(const sq_layout *L, const sq_layout_patch *P, double cen[2]);
sq_status lay_side_point(lay_repair *r, const sq_layout_patch *P, int k, double t, int *edge,
                         double *frac, double xy[2], sq_error *err);
sq_status lay_straight_sep(sq_layout *L, sq_sep_end start, const double a[2], const double b[2],
                           sq_sep_end end, sq_error *err);
sq_status lay_edge_end(lay_repair *r, int edge, double frac, const double p[2], sq_sep_end *end,
                       sq_error *err);
sq_status lay_add_spoke(lay_repair *r, sq_sep_end start, const double cen[2], const double *path,
                        int np, int edge, double frac, const double p[2], sq_error *err);

/* ---- repair_nsplit.c ---- */

/* The patch's outer ring with the n side points sp[n] inserted (each on the
 * ring segment nearest it, in walking order; malloc'ed, *nring points). */
sq_status lay_ring_with_points(const sq_layout *L, const sq_layout_patch *P, const double *sp,
                               int n, double **ring, int *nring, sq_error *err);

/* A patch ring's constrained Delaunay triangulation, along which spokes and
 * chords bend where straight ones would leave the patch. */
typedef struct {
    cad_cdt_output o;
    int *nb; /* nb[3t + j]: the triangle across edge j of triangle t, -1 on the rim */
} lay_ring_cdt;
sq_status lay_ring_cdt_build(const lay_repair *r, const double *ring, int nring, lay_ring_cdt *t,
                             sq_error *err);
/* A path inside the ring from `from` to the ring point `to` through the
 * triangles, shortened where straight pieces stay inside; *path malloc'ed
 * (*np points, from first, to last). */
sq_status lay_ring_cdt_path(const lay_ring_cdt *t, const double *ring, int nring,
                            const double from[2], const double to[2], double tol, double **path,
                            int *np, sq_error *err);
void lay_ring_cdt_free(lay_ring_cdt *t);

/* The n-quad split of patch p; spokes may bend only if `bent`. */
sq_status lay_split_centre(lay_repair *r, int p, int bent, sq_error *err);

/* ---- repair_remove.c ---- */

/* The separatrices ending at singular node t: their count; the first `max`
 * of them in ids[] with the end (0 start, 1 end) in ends[]. */
int lay_ends_at(const sq_layout *L, int t, int *ids, int *ends, int max);

/* Remove separatrix k of the set: SQ_ERR_LAYOUT (nothing changed) if a
 * singular point it ends at would be left short of its valence or an
 * inserted node it ends at would not keep two ends, joined through it. */
sq_status lay_remove_sep(lay_repair *r, int k, sq_error *err);

/* ---- the repairs: each applies at most one change (*done) ---- */

sq_status lay_set_repair(lay_repair *r, int *done, sq_error *err);        /* repair_set.c */
/* the all-quad last resort's (repair_set.c): every crossing of the set
 * made a node, found once; the pieces that end open removed */
sq_status lay_set_untangle(lay_repair *r, sq_error *err);
sq_status lay_cut_annulus(lay_repair *r, int *done, sq_error *err);       /* repair_annulus.c */
sq_status lay_split_valence2(lay_repair *r, int *done, sq_error *err);    /* repair_triangle.c */
sq_status lay_split_triangle(lay_repair *r, int *done, sq_error *err);    /* repair_triangle.c */
/* kept only if fewer than `before` defects are left (repair_polygon.c) */
sq_status lay_repair_polygon(lay_repair *r, int before, int *done, sq_error *err);

#endif
