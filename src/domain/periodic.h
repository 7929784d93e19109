/* semquad — periodic boundaries of a face (`--periodic`, docs/domains.md).
 *
 * design:
 *  1. pairs: edge a of the face and edge b are periodic under a proper
 *     rigid motion T (a translation, or a rotation about a point) when
 *     their lengths agree and T(a at arc s) = b at arc L - s for nine
 *     points s = 0, L/8, ..., L, within the tolerance (a sense of travel
 *     reversed: the face lies on opposite sides of the two curves, so that
 *     T(face) is the next passage, not the face again).  T comes from the
 *     end points, the angle between the chords; under SQ_PERIODIC_REL_TOL
 *     of turning it is a translation.  `auto` groups the matching pairs by
 *     transform (a chain of edges is a group: the cascade's periodic lines
 *     of four segments each) and takes the group of the most matched
 *     length (ties: every disjoint group as long, the doubly periodic box);
 *     the others are candidates, reported, for `A:B` to take.  `A:B` pairs
 *     are checked the same way: a pair that does not match is refused
 *     (SQ_ERR_PERIODIC);
 *  2. meshing: the layout road, traced on the identified domain where the
 *     pairs are translations (sq_periodic.identified: the field glued across
 *     them, separatrices re-entering, a piece and its image one chord
 *     count; src/field/identified_edges.h), kept where its nodes on the
 *     pairs correspond; else the face's own layout with one chord total
 *     per curve of a pair and the image's vertices slid onto the master's
 *     images (route 1b, sq_mesher_options.slid); else the face as a
 *     domain of one face whose interfaces are the pairs (sq_periodic_domain: the split road's
 *     exchange of vertices, domain.h design 2, maps b's arc lengths to
 *     a's); either way the nodes of b are then set to the images of a's
 *     (sq_periodic_link), so they coincide to one rounding of T;
 *  3. the identified domain (sq_periodic_identified): Euler characteristic
 *     and the net index its interior vertices must carry (Gauss–Bonnet). */
#ifndef SQ_PERIODIC_H
#define SQ_PERIODIC_H

#include "domain.h"
#include "face_info.h"
#include "guiding_field.h"
#include "identified_edges.h"
#include "quad_mesh.h"

/* nodes within this part of the size are partners (a layout that agrees,
 * or the split road's exchanged arc lengths, put them within rounding of
 * the arc-length evaluation; a mesh of that size has no two nodes of one
 * curve that close) */
#define SQ_PERIODIC_NODE_REL_TOL 1e-6

/* tolerance of design 1, relative to the face's bounding-box diagonal */
#define SQ_PERIODIC_REL_TOL 1e-6

/* Two kinks of a class are one regular point when their angles sum to 360
 * deg within this (degrees): pairs matching within SQ_PERIODIC_REL_TOL
 * have tangents that agree to about that over an edge's length, far
 * below it */
#define SQ_PERIODIC_BEND_TOL_DEG 1e-3

typedef struct {
    int a, b;          /* edges: b's points are T(a's), senses opposite */
    int group;         /* pairs of one transform (a chain) share it */
    int rotation;      /* 0: a translation */
    double affine[6];  /* T(x, y) = (a0 x + a1 y + a2, a3 x + a4 y + a5) */
    double shift[2];   /* translation: T(p) - p */
    double centre[2];  /* rotation: its centre and angle (degrees, counter-clockwise) */
    double angle_deg;
    double gap;        /* largest |T(a) - b| over the checked points */
} sq_periodic_pair;

typedef struct {
    int npairs, ncandidates;
    sq_periodic_pair *pairs;      /* taken */
    sq_periodic_pair *candidates; /* `auto`: matched pairs of other transforms, not taken */
    double tol;                   /* of design 1, file unit */
    /* the pairs the guiding field is solved across (identified_edges.h):
     * the translations, when some edge of the face is left with boundary
     * data (a torus has none: its field would be zero) */
    int nidentified;
    sq_identified_pair *identified;
} sq_periodic;

/* A curve pairs are sought among (design 1): edge `edge` of `face`, its
 * points mapped into the frame the transforms are in by `frame` (an affine
 * map as sq_periodic_pair.affine: a face of a domain into the domain's
 * first face's frame) and travelled backwards where that face's normal is
 * the first's reversed (flip), so that every curve has the domain on its
 * left; ends: its start and end there (none when closed). */
typedef struct {
    const cad_face *face;
    int edge;
    double frame[6];
    int flip, closed;
    double ends[4];
} sq_periodic_curve;

/* Curve c of edge e of face (info its data). */
void sq_periodic_curve_of(const cad_face *face, const sq_face_info *info, int e, const double frame[6],
                          int flip, sq_periodic_curve *c);

/* Design 1 over nc curves (pairs' a and b: indices into c), bbox the
 * domain's box in the common frame (the tolerance is relative to it): spec
 * "auto" or "A:B[,C:D...]". SQ_ERR_USAGE for a bad spec, SQ_ERR_PERIODIC
 * for named curves that do not match or `auto` finding none.  Leaves
 * sq_periodic.identified empty. */
sq_status sq_periodic_find_curves(const sq_periodic_curve *c, int nc, const double bbox[4],
                                  const char *spec, sq_periodic *p, sq_error *err);

/* Design 1 on one face, its edges the curves, and the pairs the field is
 * solved across (sq_periodic.identified). */
sq_status sq_periodic_find(const cad_face *face, const sq_face_info *info, const char *spec,
                           sq_periodic *p, sq_error *err);
void sq_periodic_free(sq_periodic *p); /* frees, zeroes */

/* held[e] = 1 for the edges of a pair (ne entries). */
void sq_periodic_held(const sq_periodic *p, int *held, int ne);

/* Design 2: the face as a one-face domain (domain.h) whose interfaces are
 * the pairs, for sq_domain_mesh_split; free with sq_domain_free. */
sq_status sq_periodic_domain(const cad_face *const *face, const sq_face_info *info,
                             const sq_periodic *p, sq_domain *d, sq_error *err);

/* Design 2: m's nodes on each pair's b set to T(their partner on a), the
 * links kept in m->periodic; SQ_ERR_LAYOUT if the two sides' nodes do not
 * correspond one to one within rel_tol of size: SQ_PERIODIC_NODE_REL_TOL
 * (the split road's exchanged arc lengths, a layout that agrees) or, on a
 * layout traced on the identified domain, SQ_IDENTIFIED_CROSSING_REL_TOL. */
sq_status sq_periodic_link(const sq_periodic *p, sq_quad_mesh *m, double size, double rel_tol,
                           sq_error *err);

/* The links of `from` found again on dst, a mesh made from it with the
 * same boundary curves (a family's refined or re-ordered mesh,
 * docs/convergence-families.md): each link's curves paired as
 * sq_periodic_link pairs them, within rel_tol of size, dst's image nodes
 * set, and from's counts of the identified domain kept (splitting quads
 * adds regular vertices only). */
sq_status sq_periodic_relink(const sq_quad_mesh *from, sq_quad_mesh *dst, double size,
                             double rel_tol, sq_error *err);

/* Kinks whose angles sum to SQ_PERIODIC_BEND_TOL_DEG of 360 deg: the two
 * vertices of a class of the identified domain (a pair joins a's ends with
 * b's) whose edges are all periodic, one regular point of that domain,
 * taking 4 quads.  The face's field splits them 3 + 1 where an angle is
 * over 45 deg from straight (it rounds angle / 90 deg; the cascades'
 * outlet kinks, 245 and 115 deg), which puts a separatrix where the
 * identified domain has none; split 2 + 2 each is a bend of a patch side.
 * *bends (allocated here, *nbends of them) are those vertices, for the
 * guiding field to turn through (guiding_field.h), over a stretch of each
 * edge as long as the kink's local feature size (its distance to the rest
 * of the boundary; why, periodic_mesh.c bend_of) and at most half the edge
 * (its other end may bend). */
sq_status sq_periodic_bends(const cad_face *face, const sq_face_info *info, const sq_periodic *p,
                            sq_bend **bends, int *nbends, sq_error *err);

/* Design 3: chi of the identified domain; *index: the net sum of
 * (4 - valence) over its interior vertices that Gauss–Bonnet requires when
 * every boundary vertex has its ideal valence (then at least |index|
 * vertices of valence 3 or 5); *irregular and *mesh_index: m's interior
 * vertices of the identified domain (a pair's partners one vertex, its
 * valence the quads around both) with valence != 4, and their net index. */
sq_status sq_periodic_identified(const sq_face_info *info, const sq_periodic *p,
                                 const sq_quad_mesh *m, int *chi, int *index, int *irregular,
                                 int *mesh_index, sq_error *err);

/* Design 3 on any mesh: cls[v] (allocated here) the representative of node
 * v's class, the nodes m's periodic links join; *irregular and
 * *mesh_index as sq_periodic_identified's. */
sq_status sq_periodic_node_classes(const sq_quad_mesh *m, int **cls, sq_error *err);
sq_status sq_periodic_irregular(const sq_periodic *p, const sq_quad_mesh *m, int *irregular,
                                int *mesh_index, sq_error *err);

/* Several faces (domain_periodic.c, docs/domains.md): design 1 over the
 * domain's boundary curves, numbered by their tags (pairs' a and b are
 * tags), in the first face's frame. */
sq_status sq_domain_periodic_find(const sq_domain *d, const char *spec, sq_periodic *p,
                                  sq_error *err);

/* s: d with every pair an interface too (b's curve a's second side), for
 * sq_domain_mesh_split and the faces' held edges; its arrays its own
 * (sq_domain_free), its faces and info d's. */
sq_status sq_domain_periodic_split(const sq_domain *d, const sq_periodic *p, sq_domain *s,
                                   sq_error *err);

/* Design 3 on the merged mesh m of a domain (its links made): chi = V - E
 * + F of the identified mesh, the index from the angles of its classes of
 * vertices (the quads' corner angles summed), the irregular vertices as
 * sq_periodic_irregular. */
sq_status sq_domain_periodic_identified(const sq_periodic *p, const sq_quad_mesh *m, int *chi,
                                        int *index, int *irregular, int *mesh_index, sq_error *err);

#endif
