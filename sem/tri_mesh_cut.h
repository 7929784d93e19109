/* semquad sem/ — a mesh cut open along some of its interior edges, or
 * glued along pairs of its boundary edges.
 *
 * Cut: the
 * marked edges become boundary edges on both sides and their vertices are
 * duplicated, one copy per fan of elements still joined across unmarked
 * edges (a branch cut for multi-valued fields such as θ of Jezdimirović
 * 2021 §5.2, solved with an ordinary CG space on the cut mesh).
 * Elements keep their numbering and geometry nodes, so a field on the cut
 * mesh is evaluated with the original mesh's locator. */
#ifndef SEM_TRI_MESH_CUT_H
#define SEM_TRI_MESH_CUT_H

#include "tri_mesh.h"

/* cut[3*ntris]: nonzero on edge k of element t to cut it (an interior edge;
 * marking either side is enough; boundary edges are ignored).  The cut
 * edges get btag = cut_tag on both sides.  vert_orig (may be NULL) receives
 * an array of out->nverts original vertex indices (caller frees).
 * *out stays NULL on failure. */
sq_status sem_tri_mesh_cut(const sem_tri_mesh *mesh, const unsigned char *cut, int cut_tag,
                           sem_tri_mesh **out, int **vert_orig, sq_error *err);

/* Glue, the inverse of the cut: each pair of boundary edges becomes one
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
