/* semquad sem/ — private: how poisson.c dispatches to the CG and DG
 * discretizations.  Each implementation provides create/solve/free on its
 * own state; poisson.c owns the public handle. */
#ifndef SEM_POISSON_IMPL_H
#define SEM_POISSON_IMPL_H

#include "poisson.h"

typedef struct {
    sq_status (*solve)(void *state, const sem_poisson_data *data, sem_field *u, sq_error *err);
    void (*free)(void *state);
    long (*ndofs)(const void *state);
    sem_poisson_work (*work)(const void *state);
} sem_poisson_ops;

/* Each returns its ops table and a new state (NULL on failure). */
sq_status sem_poisson_cg_create(const sem_tri_mesh *mesh, int P, sem_bc_kind_fn kind,
                                void *kind_ctx, const sem_poisson_ops **ops, void **state,
                                sq_error *err);
sq_status sem_poisson_dg_create(const sem_tri_mesh *mesh, int P, sem_bc_kind_fn kind,
                                void *kind_ctx, const sem_poisson_ops **ops, void **state,
                                sq_error *err);

#endif
