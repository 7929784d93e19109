/* semquad sem/ — the Poisson problem -Δu = f on a curved triangle mesh,
 * discretized with continuous (CG, C0 modal boundary/interior basis, static
 * condensation) or discontinuous (DG, symmetric interior penalty) spectral/hp
 * elements of order P (Marcon 2019 §2.2.1; Karniadakis & Sherwin 2005).
 *
 * The boundary condition kind is fixed per boundary tag when the solver is
 * created (it fixes the matrix, which is assembled and factored once); the
 * data (f, boundary values, point sources) comes with each solve, so several
 * right-hand sides reuse one factorization.
 *
 * Weak form: ∫ ∇u·∇v = ∫ f v + ∮_Neumann g v + Σ_j c_j v(x_j).
 * A point source (element, r, s, c) adds c v(x_j): inside the domain it is
 * -Δu = c δ(x - x_j); on a Neumann boundary it is a point flux ∂u/∂n = c δ.
 * When every tag is Neumann the problem is pure Neumann: the solution has
 * zero mean, and the data must satisfy ∫ f + ∮ g + Σ c_j = 0 (checked;
 * SQ_ERR_USAGE naming the imbalance otherwise). */
#ifndef SEM_POISSON_H
#define SEM_POISSON_H

#include "field.h"
#include "sq_status.h"
#include "tri_mesh.h"

typedef enum { SEM_CG = 0, SEM_DG = 1 } sem_method;
typedef enum { SEM_BC_DIRICHLET = 0, SEM_BC_NEUMANN = 1 } sem_bc_kind;

/* Kind of boundary condition on boundary tag `tag` (mesh btag values). */
typedef sem_bc_kind (*sem_bc_kind_fn)(int tag, void *ctx);
/* Source f(x). */
typedef double (*sem_source_fn)(const double x[2], void *ctx);
/* Boundary data at x on tag `tag` with outward unit normal n: the value u
 * on Dirichlet tags, the outward flux ∂u/∂n on Neumann tags. */
typedef double (*sem_boundary_fn)(const double x[2], const double n[2], int tag, void *ctx);

typedef struct {
    int elem;
    double r, s;     /* reference coordinates of the point in elem */
    double strength; /* c_j */
} sem_point_source;

typedef struct {
    sem_source_fn f;   /* NULL: f = 0 */
    void *f_ctx;
    sem_boundary_fn g; /* NULL: g = 0 */
    void *g_ctx;
    int npoints;
    const sem_point_source *points;
    /* nonzero: g's tag is the boundary half-edge 3 t + k (edge k of element
     * t) instead of the mesh's btag, for data defined element by element
     * (the θ field's: H_r's derivative in the edge's own element) */
    int g_by_edge;
} sem_poisson_data;

typedef struct sem_poisson sem_poisson; /* opaque: assembled, factored */

/* The work a solver's creation did, counted where it was done: element
 * stiffness matrices computed and sparse factorizations (none for a system without free unknowns). */
typedef struct {
    long element_matrices;
    int factorizations;
} sem_poisson_work;

/* Assemble and factor (CHOLMOD).  kind may be NULL: all Dirichlet.
 * The mesh is borrowed and must outlive the solver. */
sq_status sem_poisson_create(const sem_tri_mesh *mesh, int P, sem_method method,
                             sem_bc_kind_fn kind, void *kind_ctx, sem_poisson **out,
                             sq_error *err);
void sem_poisson_free(sem_poisson **s); /* NULL-safe, NULLs *s */

/* Number of global unknowns (after static condensation for CG, the global
 * count before condensation is what is reported: all modes of the space). */
long sem_poisson_ndofs(const sem_poisson *s);
sem_poisson_work sem_poisson_work_done(const sem_poisson *s); /* zeros for NULL */
int sem_poisson_order(const sem_poisson *s);
sem_method sem_poisson_method(const sem_poisson *s);

/* Solve for one right-hand side; u must have order P and one component
 * (create it with sem_field_create(mesh, P, 1, ...)). */
sq_status sem_poisson_solve(sem_poisson *s, const sem_poisson_data *data, sem_field *u,
                            sq_error *err);

#endif
