/* semquad — convergence study of the sem/ Poisson solvers on a CAD face.
 *
 * -Δu = 0 with Dirichlet data u = u_exact on the whole boundary, u_exact a
 * harmonic function of position (so f = 0 and the solution is u_exact
 * itself); the discrete solution of order P on the curved triangulation of
 * longest edge h is compared with u_exact in L2 and in the H1 seminorm
 * (sem_field_error).  Every (method, P, h) of the requested grid is one run:
 * the runs at the first size form the p-refinement study, those at one P
 * and method the h-refinement study.  The geometry order of the
 * triangulation defaults to max(P, 8) capped at 12, so for P <= 12 the
 * boundary is represented at least as accurately as the solution
 * (isoparametric or superparametric; Karniadakis & Sherwin 2005 §4.1.3). */
#ifndef SQ_CONVERGE_H
#define SQ_CONVERGE_H

#include "field_error.h"
#include "poisson.h"
#include "triangulate.h"

#define SQ_CONV_CG 1 /* bits of sq_converge_options.methods */
#define SQ_CONV_DG 2

typedef struct {
    const char *solution;  /* name, see sq_converge_solution (default exp-sin) */
    int methods;           /* SQ_CONV_CG | SQ_CONV_DG */
    int pmin, pmax;        /* orders, 1 <= pmin <= pmax <= 16 */
    int nsizes;            /* 0: one run per P at the automatic size */
    const double *sizes;   /* longest edge of each triangulation (> 0) */
    int geom_order;        /* 0: max(P, 8) capped at 12 */
    sq_tri_options tri;    /* min angle, max turn; order and size set per run */
} sq_converge_options;

void sq_converge_options_default(sq_converge_options *opt);

/* The exact harmonic solutions: "exp-sin" u = e^x sin y, "re-z5"
 * u = Re (x+iy)^5, "poly" u = x^3 - 3xy^2 + xy (= Re z^3 + Im z^2 / 2),
 * "sin-sinh" u = sin x sinh y.  SQ_ERR_USAGE listing the names otherwise. */
sq_status sq_converge_solution(const char *name, sem_exact_fn *fn, sq_error *err);
const char *sq_converge_solution_names(void); /* "exp-sin, re-z5, ..." */

typedef struct {
    sem_method method;
    int P;
    double h;        /* size bound of the triangulation */
    int size_index;  /* into the sizes (0 for the automatic size) */
    int ntris, geom_order;
    long dofs;       /* sem_poisson_ndofs */
    double l2, h1;   /* ||u_h - u||_L2, |u_h - u|_H1 */
    double seconds;  /* assembly, factorization and solve */
} sq_converge_run;

typedef struct {
    int nruns;
    sq_converge_run *runs; /* sorted by method, P, size index */
    int nsizes;            /* distinct sizes (>= 1) */
} sq_converge_result;

sq_status sq_converge_study(const cad_face *face, const sq_converge_options *opt,
                            sq_converge_result *out, sq_error *err);
void sq_converge_result_free(sq_converge_result *r); /* frees, zeroes */

/* Observed h-convergence rate of the runs of (method, P): the least-squares
 * slope of log(error) against log(h_eff), h_eff = dofs^(-1/2) (dofs ~ h^-2
 * at fixed P in 2D; unlike the size bound it follows what the mesher did).
 * norm 0: L2, 1: H1.  Returns 0, or -1 with fewer than two runs. */
int sq_converge_rate(const sq_converge_result *r, sem_method method, int P, int norm,
                     double *rate);

/* The CSV (header method,P,h,dofs,L2,H1; one row per run) and the log-log
 * plot of the errors against dofs, each written atomically.  The plot shows
 * the p-refinement (one series per method and norm) when there is one size,
 * else the h-refinement (one series per method, P and norm). */
sq_status sq_converge_write_csv(const char *path, const sq_converge_result *r, sq_error *err);
sq_status sq_converge_write_svg(const char *path, const sq_converge_result *r, const char *title,
                                sq_error *err);

#endif
