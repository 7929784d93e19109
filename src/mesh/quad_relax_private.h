/* semquad — what the relaxation's files share (quad_relax.c: the Newton
 * steps on Winslow's energy; quad_compass.c: the compass search after
 * them). */
#ifndef SQ_QUAD_RELAX_PRIVATE_H
#define SQ_QUAD_RELAX_PRIVATE_H

#include "quad_relax.h"
#include "sparse.h"

#include <stdint.h>

/* How each vertex moves; kept from one relaxation of a mesh to the next
 * (sq_relax_work). */
struct sq_relax_work {
    int nv, nq;
    char *fixed0; /* nv: the caller's fixed vertices when this was made */
    int *dof;     /* nv: its two unknowns 2b, 2b + 1 (b its block), -1 when fixed */
    int *var;     /* nv: dof, or -1 where this relaxation holds the vertex */
    int *edge;    /* nv: CAD edge a sliding vertex moves on, else -1 */
    double *s;    /* nv: arc length of a sliding vertex */
    double *len;  /* nv: length of that edge, negative when the edge is open */
    double *tan;  /* 2*nv: unit tangent of a sliding vertex */
    double *kappa; /* nv: signed curvature of its edge there (> 0 turning left) */
    int ndof;
    /* the motions under which the energy does not change, or hardly
     * (prepare): with every boundary vertex sliding on a circle about
     * `centre` and none held, the rotation about it; on a disc (one
     * circle, of `radius`) also its two other conformal automorphisms.
     * `modes` of them, 0 where this relaxation holds a vertex (begin) */
    int symmetries, modes;
    double centre[2], radius;
    int *start; /* nv+1: CSR of the quads around each vertex */
    int *around;
    long *bptr, *brow; /* the Hessian's block pattern (sparse.h): moving
                        * vertices that share a quad; freed once A is made */
    int32_t *pos;      /* 24 per quad corner: where the blocks of its vertex
                        * pairs (0,0) (0,1) (0,2) (1,1) (1,2) (2,2) are summed
                        * in the Hessian's values (sem_sparse_block_positions);
                        * 32 bits: the largest share of the relaxation's
                        * memory, and 2^31 values are far beyond --max-quads */
    sem_sparse *A;     /* the Hessian, its analysis and last factorization */
    int factored;      /* A has been factored */
    int steps;         /* the last relaxation's Newton steps */
    long polls;        /* and its compass search's evaluations of the quads
                        * around a vertex (sq_relax_work_stats) */
};
typedef struct sq_relax_work relax_work;

/* The point of sliding vertex i's edge at arc length *s (wrapped on a
 * closed edge, clamped on an open one), the tangent and the signed
 * curvature there (t, kappa may be NULL). */
sq_status qr_on_edge(const cad_face *face, const relax_work *w, int i, double *s, double x[2],
                     double t[2], double *kappa, sq_error *err);

/* Compass search on the free vertices after the energy's optimum: phase 0
 * raises the worst eta around each vertex, phase 1 the quads just below
 * TAU_ETA (quad_compass.c). */
sq_status qr_compass(const cad_face *face, const sq_relax_mesh *m, relax_work *w, int phase,
                     sq_error *err);

#endif
