/* semquad — a 2D domain of several planar faces meshed as one conforming
 * mesh (docs/domains.md).
 *
 * design:
 *  1. the curves: every edge of every face is one curve of the domain, or
 *     the same curve as an edge of another face (cad_edges_shared: the same
 *     OCCT edge, or coincident within the tolerance); a curve of one face
 *     is a boundary curve (a boundary tag), a curve of two an interface;
 *  2. the faces with an interface take the split road (where their layouts
 *     do not agree on the interfaces: docs/domains.md), whose boundary
 *     vertices are the triangulation's: each face is triangulated, the
 *     vertices every face put on each interface are joined into one list,
 *     and the faces are triangulated again from that list until all agree
 *     (a refinement that splits an interface segment in one face adds the
 *     split to the other in the next round);
 *  3. each face's quads are made with the interface vertices held (neither
 *     smoothing nor relaxation moves them), so the nodes of an interface —
 *     the midpoints, high-order nodes at the same arc-length fractions —
 *     are the same points in both faces;
 *  4. the faces' meshes are merged in the first face's frame: nodes of
 *     interfaces closer than a small part of the size are one node, every
 *     interface side must meet a side of the other face (else the faces do
 *     not conform: an error), quads keep their face as their region. */
#ifndef SQ_DOMAIN_H
#define SQ_DOMAIN_H

#include "face_info.h"
#include "quad_mesher.h"

typedef struct {
    int face[2], edge[2]; /* the faces (positions in the domain) and their edges; face[1] = -1:
                             a boundary curve */
    int reversed;         /* face[1] travels it against face[0] */
    int kind;             /* cad_shared_kind of an interface */
    int tag;              /* boundary tag (0..ntags-1), -1 for an interface */
} sq_domain_curve;

typedef struct {
    int nfaces;
    const cad_face *const *faces;    /* borrowed */
    const sq_face_info *info;        /* borrowed, one per face */
    int ncurves, ntags, ninterfaces;
    sq_domain_curve *curves;
    int **curve_of;                  /* per face, per edge: its curve */
} sq_domain;

/* Design 1; tol: the largest gap between coincident edges (file unit). */
sq_status sq_domain_build(int nfaces, const cad_face *const *faces, const sq_face_info *info,
                          double tol, sq_domain *d, sq_error *err);
void sq_domain_free(sq_domain *d); /* frees, zeroes */

/* 1 if face f has an interface. */
int sq_domain_face_shares(const sq_domain *d, int f);

/* Designs 2 and 3: the split road's meshes of the faces with an
 * interface into out[f] (the others' left as they are), at mo's size. */
sq_status sq_domain_mesh_split(const sq_domain *d, const sq_mesher_options *mo, sq_quad_mesh **out,
                               int *rounds, sq_error *err);

/* The layout road over the faces (docs/domains.md): face f's points
 * ep[e] (per edge of f, as sq_mesher_options.edge_points takes them: 0,
 * then the interior points in f's sense; on a closed curve all its vertices) on each shared curve whose other
 * face g comes before f, and on the image side of a periodic pair whose
 * master is in f too, from its mesh q[g] (in g's frame, tags g's edges):
 * the arc lengths of g's vertices there, so f's vertices slide onto them
 * and the two meshes meet; n 0 on the other edges.  *any 1 if
 * some edge has points.  Free with sq_domain_layout_points_free. */
sq_status sq_domain_layout_points(const sq_domain *d, int f, sq_quad_mesh *const *q,
                                  sq_edge_points *ep, int *any, sq_error *err);
void sq_domain_layout_points_free(sq_edge_points *ep, int ne);

/* Face f's frame into face 0's: x0 = A0 x + A1 y + A2, y0 = A3 x + A4 y +
 * A5; *flip when its normal is face 0's reversed (its boundary then runs
 * clockwise in face 0's frame). */
void sq_domain_frame(const sq_domain *d, int f, double A[6], int *flip);

/* Design 4: the faces' meshes m[f] (each in its face's frame, boundary
 * tags its edges) merged into one, in face 0's frame, regions the faces
 * (region_face[f] = cad_index[f]), boundary tags the domain's; size: the
 * target size (the merge tolerance is 1e-6 of it). */
sq_status sq_domain_merge(const sq_domain *d, sq_quad_mesh *const *m, const int *cad_index,
                          double size, sq_quad_mesh **out, sq_error *err);

#endif
