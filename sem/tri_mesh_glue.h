/* semquad sem/ — a mesh glued along pairs of its boundary edges. */
#ifndef SEM_TRI_MESH_GLUE_H
#define SEM_TRI_MESH_GLUE_H

#include "tri_mesh.h"

/* Glue: each pair of boundary edges becomes one
 * interior edge and its vertices one vertex.  A periodic domain, whose two
 * periodic curves carry the same vertices, is solved on the glued mesh
 * with an ordinary CG or DG space: the unknowns of the two curves are then
 * one, the field periodic.  Elements keep their numbering and geometry
 * nodes (each on its own side of the identification), so a field on the
 * glued mesh is evaluated with the original mesh's locator.
 * pairs[2p], pairs[2p+1]: boundary edges 3t + k and 3t' + k', which run
 * against each other as neighbours do (vertex k of t becomes vertex k'+1
 * of t', vertex k+1 of t vertex k' of t').  SQ_ERR_USAGE for an edge not
 * on the boundary or in two pairs, or a glue that would join two vertices
 * of one element.  The glued edges lose their boundary tag.  *out stays
 * NULL on failure. */
sq_status sem_tri_mesh_glue(const sem_tri_mesh *mesh, int npairs, const int *pairs,
                            sem_tri_mesh **out, sq_error *err);

#endif
