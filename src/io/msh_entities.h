/* semquad — the model entities of a quad mesh as Gmsh classifies a mesh
 * on its CAD model (docs/formats.md, "Entities"): every node on the entity
 * of lowest dimension that holds it.
 *
 *  - curves: the boundary curves (boundary tags 0..ntags-1, entity t+1),
 *    then the interfaces of a mesh of several faces (the element sides
 *    between quads of two faces), one curve per chain of sides between the
 *    same two faces that meets no other curve on its way, numbered from
 *    ntags+1 in the order of their first side.  A curve runs the way its
 *    sides walk their quads (the boundary: with the face on its left; an
 *    interface: with the lower-numbered face on its left);
 *  - points: the nodes where a curve begins or ends, or that lie on two
 *    curves (the CAD vertices at the corners of the boundary and at the
 *    ends of the interfaces).  A closed curve (a full circle, one CAD edge)
 *    has no point: a mesh node need not sit at its CAD vertex;
 *  - surfaces: one per face (region), bounded by its curves.
 *
 * Only the mesh is read: an interface of two CAD edges in a row between
 * the same two faces is one curve (their common vertex is no point). */
#ifndef SQ_MSH_ENTITIES_H
#define SQ_MSH_ENTITIES_H

#include "quad_mesh.h"

typedef struct {
    int npoints, ncurves, nsurfaces; /* entities point p+1, curve c+1, surface r+1 */
    int *point_node;  /* npoints: its node, ascending */
    int *curve_ends;  /* 2 ncurves: the points it begins and ends at (-1: none, closed) */
    int *curve_faces; /* 2 ncurves: the surfaces it bounds with + and with - (-1: none) */
    int *curve_sides; /* ncurves: its element sides (a boundary curve's lines) */
    double *curve_bb, *surface_bb; /* 4 each: x min, y min, x max, y max (all 0: empty) */
    /* nodes by entity: points, curves, surfaces in that order, ascending
     * within one: entity k's (k = p, npoints + c, npoints + ncurves + r)
     * are node[first[k] .. first[k+1]) */
    int *node, *first;
} sq_msh_entities;

sq_status sq_msh_entities_build(const sq_quad_mesh *m, sq_msh_entities *e, sq_error *err);
void sq_msh_entities_free(sq_msh_entities *e); /* NULL-safe, zeroes *e */

#endif
