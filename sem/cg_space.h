/* semquad sem/ — global numbering of the C0 modal space of order P on a
 * triangle mesh (cg_basis.h): one dof per mesh vertex used by a triangle,
 * P-1 per edge (shared through the neighbour information, oriented from
 * its lower to its higher global vertex), and the interior modes, which
 * stay local to their element (statically condensed). */
#ifndef SEM_CG_SPACE_H
#define SEM_CG_SPACE_H

#include "sq_status.h"
#include "tri_mesh.h"

typedef struct {
    int P, nb, ni;
    long nvdofs;  /* vertex dofs: 0..nvdofs-1 */
    long nedges;  /* edge e has dofs nvdofs + e(P-1) + p-1, p = 1..P-1 */
    long nbdofs;  /* nvdofs + nedges (P-1): the global (boundary) dofs */
    long ndofs;   /* nbdofs + ntris ni: every mode of the space */
    long *bmap;   /* ntris*nb: global dof of each local boundary mode */
    signed char *bsign; /* ntris*nb: +1 or -1 (local = sign * global) */
    long *edge;   /* 3*ntris: global edge of local edge k */
} sem_cg_space;

sq_status sem_cg_space_create(const sem_tri_mesh *mesh, int P, sem_cg_space **out, sq_error *err);
void sem_cg_space_free(sem_cg_space **s); /* NULL-safe, NULLs *s */

#endif
