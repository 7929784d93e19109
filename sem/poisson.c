/* semquad sem/ — the public Poisson handle: validates arguments and
 * dispatches to the CG (poisson_cg.c) or DG (poisson_dg.c) discretization
 * through the ops table of poisson_impl.h. */
#include "poisson.h"

#include "gauss.h"
#include "poisson_impl.h"

#include <stdlib.h>

struct sem_poisson {
    const sem_tri_mesh *mesh;
    int P;
    sem_method method;
    const sem_poisson_ops *ops;
    void *state;
};

sq_status sem_poisson_create(const sem_tri_mesh *mesh, int P, sem_method method,
                             sem_bc_kind_fn kind, void *kind_ctx, sem_poisson **out,
                             sq_error *err)
{
    if (!out) return SQ_FAIL(err, SQ_ERR_USAGE, "poisson_create: NULL output");
    *out = NULL;
    if (!mesh || mesh->ntris <= 0) return SQ_FAIL(err, SQ_ERR_USAGE, "poisson_create: empty mesh");
    if (P < 1 || P > SEM_MAX_ORDER)
        return SQ_FAIL(err, SQ_ERR_USAGE, "poisson_create: order %d outside 1..%d", P, SEM_MAX_ORDER);
    if (method != SEM_CG && method != SEM_DG)
        return SQ_FAIL(err, SQ_ERR_USAGE, "poisson_create: unknown method %d", (int)method);
    sem_poisson *p = calloc(1, sizeof *p);
    if (!p) return SQ_FAIL(err, SQ_ERR_INTERNAL, "poisson_create: out of memory");
    p->mesh = mesh;
    p->P = P;
    p->method = method;
    sq_status st = method == SEM_CG
                       ? sem_poisson_cg_create(mesh, P, kind, kind_ctx, &p->ops, &p->state, err)
                       : sem_poisson_dg_create(mesh, P, kind, kind_ctx, &p->ops, &p->state, err);
    if (st != SQ_OK) {
        free(p);
        return st;
    }
    *out = p;
    return SQ_OK;
}

void sem_poisson_free(sem_poisson **s)
{
    if (!s || !*s) return;
    if ((*s)->ops && (*s)->state) (*s)->ops->free((*s)->state);
    free(*s);
    *s = NULL;
}

long sem_poisson_ndofs(const sem_poisson *s) { return s ? s->ops->ndofs(s->state) : 0; }
sem_poisson_work sem_poisson_work_done(const sem_poisson *s)
{
    return s ? s->ops->work(s->state) : (sem_poisson_work){0, 0};
}
int sem_poisson_order(const sem_poisson *s) { return s ? s->P : 0; }
sem_method sem_poisson_method(const sem_poisson *s) { return s ? s->method : SEM_CG; }

sq_status sem_poisson_solve(sem_poisson *s, const sem_poisson_data *data, sem_field *u,
                            sq_error *err)
{
    if (!s || !data || !u) return SQ_FAIL(err, SQ_ERR_USAGE, "poisson_solve: NULL argument");
    if (u->mesh != s->mesh || u->P != s->P || u->ncomp != 1)
        return SQ_FAIL(err, SQ_ERR_USAGE,
                       "poisson_solve: field must be on the solver's mesh with order %d and one "
                       "component (got order %d, %d components)",
                       s->P, u->P, u->ncomp);
    if (data->npoints < 0 || (data->npoints > 0 && !data->points))
        return SQ_FAIL(err, SQ_ERR_USAGE, "poisson_solve: %d point sources but no array",
                       data->npoints);
    for (int j = 0; j < data->npoints; ++j) {
        const sem_point_source *q = &data->points[j];
        if (q->elem < 0 || q->elem >= s->mesh->ntris || !(q->r >= -1e-12) || !(q->s >= -1e-12) ||
            !(q->r + q->s <= 1.0 + 1e-12))
            return SQ_FAIL(err, SQ_ERR_USAGE,
                           "poisson_solve: point source %d at element %d (r,s) = (%g,%g) is not "
                           "in the mesh",
                           j, q->elem, q->r, q->s);
    }
    return s->ops->solve(s->state, data, u, err);
}
