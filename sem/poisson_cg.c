/* semquad sem/ — continuous Galerkin Poisson solver of order P
 * (Marcon 2019 §2.2.1; Karniadakis & Sherwin 2005 §4.1–4.2):
 *   C0 modal boundary/interior basis (cg_basis.h), global numbering of
 *   vertex and edge modes (cg_space.h), element stiffness by quadrature with
 *   the curved geometric factors, static condensation of the interior modes
 *   (Schur complement per element, LAPACK), Dirichlet data by lifting,
 *   Neumann data by boundary quadrature, point sources, pure Neumann
 *   problems by fixing one vertex dof, then shifting to zero mean.
 *
 * Element stiffness: with J = [[x_r, x_s], [y_r, y_s]] and adj(J^T J) =
 *   [[x_s^2 + y_s^2, -(x_r x_s + y_r y_s)], [., x_r^2 + y_r^2]],
 *   K_ij = sum_q w_q / |J| (grad_rs psi_i)^T adj(J^T J) grad_rs psi_j,
 * one dgemm per curved element; straight elements combine three
 * precomputed reference matrices. */
#include "lib_lock.h"
#include "cg_basis.h"
#include "cg_space.h"
#include "gauss.h"
#include "poisson_impl.h"
#include "sparse.h"
#include "tri_lagrange.h"
#include "tri_nodes.h"
#include "tri_quad.h"

#include <cblas.h>
#include <lapacke.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#define CG_NMAX ((SEM_MAX_ORDER + 1) * (SEM_MAX_ORDER + 2) / 2)
/* Pure Neumann data must balance to this fraction of its size.  It is
 * integrated by quadrature on the curved geometry, whose edges' arc length
 * is off by up to about 1e-5 relative near sharp features (naca0012's
 * trailing edge: the H field's curvature data, 5e-6); data that is really
 * incompatible is off by far more (a wrong singularity pattern: a multiple
 * of pi/2 against 2 pi). */
#define CG_COMPAT_RTOL 1e-4

typedef struct {
    const sem_tri_mesh *mesh;
    int P, nloc, nb, ni;
    sem_cg_basis *basis;
    sem_cg_space *space;
    sem_tri_lagrange *geo; /* geometry basis, order mesh->order */
    int ng;                /* geometry nodes per element */
    /* volume rule and tables (row-major, point by point) */
    sem_tri_quad *quad;
    double *B;        /* nq x nloc */
    double *BrBs;     /* 2nq x nloc: d/dr rows, then d/ds rows */
    double *G, *Gr, *Gs; /* nq x ng geometry Lagrange values, derivatives */
    /* edge rule (Gauss–Legendre on [-1,1]) */
    int nqe;
    double *te, *we;
    /* the edge rule's points on each local edge k, then t = -1 and t = +1
     * (Dirichlet vertex values): point q of edge k is row k nte + q of the
     * geometry Lagrange values El, Elr, Els (ng each) and of the modes Epsi
     * (nloc), the same for every element (tabulated once: the solves'
     * boundary data needed a Lagrange and a modal evaluation per point) */
    int nte;
    double *Ers, *El, *Elr, *Els, *Epsi;
    double *Mf;       /* (P-1)^2 Cholesky factor of the edge-mode mass matrix */
    /* per element */
    char *bc_kind;    /* 3*ntris: -1 interior, else sem_bc_kind */
    double *S;        /* ntris x nb x nb condensed stiffness */
    double *W;        /* ntris x ni x nb: Kii^-1 Kib */
    double *Lii;      /* ntris x ni x ni Cholesky factors of Kii */
    double *mloc;     /* ntris x nloc: ∫ psi_i */
    double area;
    /* global */
    long *gfree;      /* nbdofs: system index, or -1 - (Dirichlet index) */
    long nfree, ndir;
    int pure_neumann;
    sem_sparse *A;
    sem_poisson_work work;
} cg_state;

static void cg_free(void *state)
{
    cg_state *c = state;
    if (!c) return;
    sem_cg_basis_free(&c->basis);
    sem_cg_space_free(&c->space);
    sem_tri_lagrange_free(&c->geo);
    sem_tri_quad_free(&c->quad);
    free(c->B);
    free(c->BrBs);
    free(c->G);
    free(c->Gr);
    free(c->Gs);
    free(c->te);
    free(c->we);
    free(c->Ers);
    free(c->El);
    free(c->Elr);
    free(c->Els);
    free(c->Epsi);
    free(c->Mf);
    free(c->bc_kind);
    free(c->S);
    free(c->W);
    free(c->Lii);
    free(c->mloc);
    free(c->gfree);
    sem_sparse_free(&c->A);
    free(c);
}

static long cg_ndofs(const void *state) { return ((const cg_state *)state)->space->ndofs; }
static sem_poisson_work cg_work(const void *state) { return ((const cg_state *)state)->work; }

/* Position, Jacobian (x_r, x_s, y_r, y_s) and det at volume point k. */
static double cg_geom_at(const cg_state *c, const double *gxy, int k, double x[2], double J[4])
{
    const double *g = c->G + (size_t)k * c->ng, *gr = c->Gr + (size_t)k * c->ng,
                 *gs = c->Gs + (size_t)k * c->ng;
    double X = 0, Y = 0, xr = 0, xs = 0, yr = 0, ys = 0;
    for (int n = 0; n < c->ng; ++n) {
        const double px = gxy[2 * n], py = gxy[2 * n + 1];
        X += g[n] * px, Y += g[n] * py;
        xr += gr[n] * px, yr += gr[n] * py;
        xs += gs[n] * px, ys += gs[n] * py;
    }
    if (x) x[0] = X, x[1] = Y;
    J[0] = xr, J[1] = xs, J[2] = yr, J[3] = ys;
    return xr * ys - xs * yr;
}

/* Reference coordinates of the point at parameter t in [-1,1] on local
 * edge k (t = -1 at vertex k, +1 at vertex k+1) and d(r,s)/dt. */
static void cg_edge_point(int k, double t, double rs[2], double drs[2])
{
    static const double V[3][2] = {{0, 0}, {1, 0}, {0, 1}};
    const double *a = V[k], *b = V[(k + 1) % 3];
    rs[0] = 0.5 * (1 - t) * a[0] + 0.5 * (1 + t) * b[0];
    rs[1] = 0.5 * (1 - t) * a[1] + 0.5 * (1 + t) * b[1];
    drs[0] = 0.5 * (b[0] - a[0]);
    drs[1] = 0.5 * (b[1] - a[1]);
}

/* Reference point, position, outward unit normal and ds/dt at tabulated
 * point q of edge k (see cg_state.nte). */
static void cg_edge_geom(const cg_state *c, const double *gxy, int k, int q, double rs[2],
                         double x[2], double n[2], double *dsdt)
{
    double drs[2];
    const size_t row = (size_t)k * c->nte + q;
    cg_edge_point(k, 0.0, rs, drs); /* d(r,s)/dt, the same all along the edge */
    rs[0] = c->Ers[2 * row], rs[1] = c->Ers[2 * row + 1];
    /* map through the geometry Lagrange basis */
    const double *l = c->El + row * c->ng, *lr = c->Elr + row * c->ng, *ls = c->Els + row * c->ng;
    double X = 0, Y = 0, xr = 0, xs = 0, yr = 0, ys = 0;
    for (int m = 0; m < c->ng; ++m) {
        const double px = gxy[2 * m], py = gxy[2 * m + 1];
        X += l[m] * px, Y += l[m] * py;
        xr += lr[m] * px, yr += lr[m] * py;
        xs += ls[m] * px, ys += ls[m] * py;
    }
    const double tx = xr * drs[0] + xs * drs[1], ty = yr * drs[0] + ys * drs[1];
    const double len = hypot(tx, ty);
    x[0] = X, x[1] = Y;
    /* counter-clockwise element: the outward normal is the tangent turned
     * clockwise */
    n[0] = ty / len, n[1] = -tx / len;
    *dsdt = len;
}

/* Element stiffness (nloc x nloc, row-major) and mass vector of element t.
 * work: 4 nq nloc doubles. */
static sq_status cg_element(const cg_state *c, int t, const double *Sref, double *K, double *mv,
                            double *work, sq_error *err)
{
    const sem_tri_mesh *m = c->mesh;
    const double *gxy = m->gxy + 2 * (size_t)m->nodes_per_tri * t;
    const int n = c->nloc, nq = c->quad->npts;
    /* straight element: geometry nodes are the affine image of the corners */
    const double *p0 = gxy, *p1 = gxy + 2 * sem_tri_node_index(m->order, m->order, 0),
                 *p2 = gxy + 2 * sem_tri_node_index(m->order, 0, m->order);
    const double J0[4] = {p1[0] - p0[0], p2[0] - p0[0], p1[1] - p0[1], p2[1] - p0[1]};
    const double det0 = J0[0] * J0[3] - J0[1] * J0[2];
    int straight = 1;
    if (m->order > 1) {
        const double *rs = sem_tri_lagrange_nodes(c->geo);
        const double h = fabs(J0[0]) + fabs(J0[1]) + fabs(J0[2]) + fabs(J0[3]);
        for (int k = 0; k < c->ng && straight; ++k) {
            const double x = p0[0] + J0[0] * rs[2 * k] + J0[1] * rs[2 * k + 1];
            const double y = p0[1] + J0[2] * rs[2 * k] + J0[3] * rs[2 * k + 1];
            if (fabs(x - gxy[2 * k]) + fabs(y - gxy[2 * k + 1]) > 1e-14 * h) straight = 0;
        }
    }
    if (straight) {
        if (!(det0 > 0))
            return SQ_FAIL(err, SQ_ERR_USAGE, "poisson_cg: element %d is degenerate or clockwise",
                           t);
        const double a00 = (J0[1] * J0[1] + J0[3] * J0[3]) / det0;
        const double a01 = -(J0[0] * J0[1] + J0[2] * J0[3]) / det0;
        const double a11 = (J0[0] * J0[0] + J0[2] * J0[2]) / det0;
        const double *Srr = Sref, *Srs = Sref + (size_t)n * n, *Sss = Sref + 2 * (size_t)n * n;
        for (int i = 0; i < n; ++i)
            for (int j = 0; j < n; ++j)
                K[i * n + j] = a00 * Srr[i * n + j] + a01 * (Srs[i * n + j] + Srs[j * n + i]) +
                               a11 * Sss[i * n + j];
        const double *mref = Sref + 3 * (size_t)n * n;
        for (int i = 0; i < n; ++i) mv[i] = det0 * mref[i];
        return SQ_OK;
    }
    double *D = work;               /* 2nq x nloc */
    double *wj = work + 2 * (size_t)nq * n; /* nq */
    for (int k = 0; k < nq; ++k) {
        double J[4];
        const double det = cg_geom_at(c, gxy, k, NULL, J);
        if (!(det > 0))
            return SQ_FAIL(err, SQ_ERR_USAGE,
                           "poisson_cg: element %d has a non-positive Jacobian (%g) inside", t, det);
        const double w = c->quad->w[k] / det;
        const double a00 = w * (J[1] * J[1] + J[3] * J[3]);
        const double a01 = -w * (J[0] * J[1] + J[2] * J[3]);
        const double a11 = w * (J[0] * J[0] + J[2] * J[2]);
        const double *br = c->BrBs + (size_t)k * n, *bs = c->BrBs + (size_t)(nq + k) * n;
        double *dr = D + (size_t)k * n, *ds = D + (size_t)(nq + k) * n;
        for (int i = 0; i < n; ++i) {
            dr[i] = a00 * br[i] + a01 * bs[i];
            ds[i] = a01 * br[i] + a11 * bs[i];
        }
        wj[k] = c->quad->w[k] * det;
    }
    /* K = [Br; Bs]^T [Dr; Ds] */
    sem_lib_lock();
    cblas_dgemm(CblasRowMajor, CblasTrans, CblasNoTrans, n, n, 2 * nq, 1.0, c->BrBs, n, D, n, 0.0,
                K, n);
    cblas_dgemv(CblasRowMajor, CblasTrans, nq, n, 1.0, c->B, n, wj, 1, 0.0, mv, 1);
    sem_lib_unlock();
    return SQ_OK;
}

static sq_status cg_solve(void *state, const sem_poisson_data *data, sem_field *u, sq_error *err);

static const sem_poisson_ops cg_ops = {cg_solve, cg_free, cg_ndofs, cg_work};

/* The reference tables. */
static sq_status cg_tables(cg_state *c, sq_error *err)
{
    const sem_tri_mesh *m = c->mesh;
    const int n = c->nloc, P = c->P;
    /* Degree 2P - 2 is exact on straight elements (∇ψ_i·∇ψ_j, constant
     * metric).  On a curved element the metric adj(J^T J)/|J| is rational;
     * 2P + 2 integrates its part up to degree 4 exactly, and what is left
     * decays like (κh)^5 with the element's curvature κh, which the
     * triangulation keeps small.  Measured against degree 2P + 2(Pg - 1)
     * (P = Pg = 8, the H/θ field; 100 points instead of 256): H moves by
     * 4e-15 on the disc, ∇H by at most 2e-6 of max|∇H| on the stress
     * corpus's H/θ faces (0003_bspline; θ by 5e-6°), far below the field's
     * own discretization error (θ's misalignment with the boundary: 5e-4°,
     * docs/benchmarks.md). */
    SQ_TRY(sem_tri_quad_create(2 * P + 2, &c->quad, err));
    SQ_TRY(sem_tri_lagrange_create(m->order, &c->geo, err));
    c->ng = sem_tri_lagrange_num_nodes(c->geo);
    const int nq = c->quad->npts, ng = c->ng;
    c->nqe = P + m->order + 2;
    c->nte = c->nqe + 2;
    const size_t ne3 = 3 * (size_t)c->nte, nmf = (size_t)(P - 1) * (P - 1);
    c->B = malloc(sizeof(double) * (size_t)nq * n);
    c->BrBs = malloc(sizeof(double) * 2 * (size_t)nq * n);
    c->G = malloc(sizeof(double) * (size_t)nq * ng);
    c->Gr = malloc(sizeof(double) * (size_t)nq * ng);
    c->Gs = malloc(sizeof(double) * (size_t)nq * ng);
    c->te = malloc(sizeof(double) * c->nqe);
    c->we = malloc(sizeof(double) * c->nqe);
    c->Mf = malloc(sizeof(double) * (nmf + 1));
    c->Ers = malloc(sizeof(double) * 2 * ne3);
    c->El = malloc(sizeof(double) * ne3 * ng);
    c->Elr = malloc(sizeof(double) * ne3 * ng);
    c->Els = malloc(sizeof(double) * ne3 * ng);
    c->Epsi = malloc(sizeof(double) * ne3 * n);
    if (!c->B || !c->BrBs || !c->G || !c->Gr || !c->Gs || !c->te || !c->we || !c->Mf ||
        !c->Ers || !c->El || !c->Elr || !c->Els || !c->Epsi)
        return SQ_FAIL(err, SQ_ERR_INTERNAL, "poisson_cg: out of memory");
    for (int k = 0; k < nq; ++k) {
        const double r = c->quad->rs[2 * k], s = c->quad->rs[2 * k + 1];
        sem_cg_basis_eval(c->basis, r, s, c->B + (size_t)k * n, c->BrBs + (size_t)k * n,
                          c->BrBs + (size_t)(nq + k) * n);
        sem_tri_lagrange_eval(c->geo, r, s, c->G + (size_t)k * ng, c->Gr + (size_t)k * ng,
                              c->Gs + (size_t)k * ng);
    }
    SQ_TRY(sem_gauss_jacobi(c->nqe, 0.0, 0.0, c->te, c->we, err));
    for (size_t row = 0; row < ne3; ++row) {
        const int k = (int)(row / c->nte), q = (int)(row % c->nte);
        const double t = q < c->nqe ? c->te[q] : q == c->nqe ? -1.0 : 1.0;
        double drs[2], *rs = c->Ers + 2 * row;
        cg_edge_point(k, t, rs, drs);
        sem_tri_lagrange_eval(c->geo, rs[0], rs[1], c->El + row * ng, c->Elr + row * ng,
                              c->Els + row * ng);
        sem_cg_basis_eval(c->basis, rs[0], rs[1], c->Epsi + row * n, NULL, NULL);
    }
    /* 1D mass matrix of the edge modes f_p(t) = (1-t^2)/4 P_{p-1}^{(1,1)}(t) */
    if (P >= 2) {
        const int ne = P - 1;
        memset(c->Mf, 0, sizeof(double) * ne * ne);
        for (int k = 0; k < c->nqe; ++k) {
            double f[SEM_MAX_ORDER];
            const double t = c->te[k];
            for (int p = 1; p <= ne; ++p)
                f[p - 1] = 0.25 * (1 - t) * (1 + t) * sem_jacobi(p - 1, 1.0, 1.0, t, NULL);
            for (int i = 0; i < ne; ++i)
                for (int j = 0; j < ne; ++j) c->Mf[i * ne + j] += c->we[k] * f[i] * f[j];
        }
        sem_lib_lock();
        const lapack_int info = LAPACKE_dpotrf(LAPACK_ROW_MAJOR, 'L', ne, c->Mf, ne);
        sem_lib_unlock();
        if (info != 0)
            return SQ_FAIL(err, SQ_ERR_INTERNAL, "poisson_cg: edge mass matrix not SPD (P = %d)", P);
    }
    return SQ_OK;
}

/* A new state on mesh: basis, global numbering, tables. */
static sq_status cg_start(const sem_tri_mesh *mesh, int P, cg_state **out, sq_error *err)
{
    cg_state *c = calloc(1, sizeof *c);
    if (!c) return SQ_FAIL(err, SQ_ERR_INTERNAL, "poisson_cg_create: out of memory");
    *out = c;
    c->mesh = mesh;
    c->P = P;
    SQ_TRY(sem_cg_basis_create(P, &c->basis, err));
    c->nloc = c->basis->nloc;
    c->nb = c->basis->nb;
    c->ni = c->basis->ni;
    SQ_TRY(sem_cg_space_create(mesh, P, &c->space, err));
    return cg_tables(c, err);
}

/* Boundary condition kind of every element edge; the free and Dirichlet
 * dofs. */
static sq_status cg_dofs(cg_state *c, sem_bc_kind_fn kind, void *kind_ctx, sq_error *err)
{
    const sem_tri_mesh *mesh = c->mesh;
    const sem_cg_space *sp = c->space;
    const int nt = mesh->ntris, nb = c->nb, P = c->P;
    c->bc_kind = malloc(3 * (size_t)nt);
    c->gfree = malloc(sizeof(long) * ((size_t)sp->nbdofs + 1));
    if (!c->bc_kind || !c->gfree) return SQ_FAIL(err, SQ_ERR_INTERNAL, "poisson_cg: out of memory");
    int any_dir = 0;
    for (size_t h = 0; h < 3 * (size_t)nt; ++h) {
        c->bc_kind[h] = -1;
        if (mesh->neigh[h] >= 0) continue;
        const int tag = mesh->btag[h];
        const sem_bc_kind kd = kind ? kind(tag, kind_ctx) : SEM_BC_DIRICHLET;
        if (kd != SEM_BC_DIRICHLET && kd != SEM_BC_NEUMANN)
            return SQ_FAIL(err, SQ_ERR_USAGE, "poisson_cg_create: unknown condition %d on tag %d",
                           (int)kd, tag);
        c->bc_kind[h] = (char)kd;
        any_dir |= kd == SEM_BC_DIRICHLET;
    }

    /* Dirichlet dofs: vertices and edge modes of Dirichlet edges; a pure
     * Neumann problem pins vertex dof 0 (then shifts to zero mean). */
    for (long g = 0; g < sp->nbdofs; ++g) c->gfree[g] = 0;
    for (int t = 0; t < nt; ++t)
        for (int k = 0; k < 3; ++k) {
            if (c->bc_kind[3 * t + k] != SEM_BC_DIRICHLET) continue;
            const long *map = sp->bmap + (size_t)t * nb;
            c->gfree[map[k]] = c->gfree[map[(k + 1) % 3]] = 1;
            for (int p = 1; p <= P - 1; ++p) c->gfree[map[sem_cg_edge_mode(P, k, p)]] = 1;
        }
    c->pure_neumann = !any_dir;
    if (c->pure_neumann) c->gfree[0] = 1;
    c->nfree = c->ndir = 0;
    for (long g = 0; g < sp->nbdofs; ++g)
        c->gfree[g] = c->gfree[g] ? -1 - c->ndir++ : c->nfree++;
    return SQ_OK;
}

/* Element matrices, condensed (S, W, Lii), mass vectors and the area. */
static sq_status cg_elements(cg_state *c, sq_error *err)
{
    const int n = c->nloc, nb = c->nb, ni = c->ni, nt = c->mesh->ntris, nq = c->quad->npts;
    sq_status st = SQ_OK;
    c->S = malloc(sizeof(double) * ((size_t)nt * nb * nb + 1));
    c->W = malloc(sizeof(double) * ((size_t)nt * ni * nb + 1));
    c->Lii = malloc(sizeof(double) * ((size_t)nt * ni * ni + 1));
    c->mloc = malloc(sizeof(double) * (size_t)nt * n);
    double *Sref = calloc(3 * (size_t)n * n + n, sizeof(double));
    double *K = malloc(sizeof(double) * (size_t)n * n);
    double *work = malloc(sizeof(double) * (4 * (size_t)nq * n + nq));
    if (!c->S || !c->W || !c->Lii || !c->mloc || !Sref || !K || !work) {
        st = SQ_FAIL(err, SQ_ERR_INTERNAL, "poisson_cg_create: out of memory (%d elements, P = %d)",
                     nt, c->P);
        goto done;
    }
    /* reference matrices for straight elements: Srr, Srs, Sss, mass vector */
    {
        double *Srr = Sref, *Srs = Sref + (size_t)n * n, *Sss = Sref + 2 * (size_t)n * n,
               *mref = Sref + 3 * (size_t)n * n;
        for (int k = 0; k < nq; ++k) {
            const double w = c->quad->w[k];
            const double *br = c->BrBs + (size_t)k * n, *bs = c->BrBs + (size_t)(nq + k) * n,
                         *b = c->B + (size_t)k * n;
            for (int i = 0; i < n; ++i) {
                mref[i] += w * b[i];
                const double wr = w * br[i], ws = w * bs[i];
                for (int j = 0; j < n; ++j) {
                    Srr[i * n + j] += wr * br[j];
                    Srs[i * n + j] += wr * bs[j];
                    Sss[i * n + j] += ws * bs[j];
                }
            }
        }
    }
    c->area = 0.0;
    for (int t = 0; t < nt && st == SQ_OK; ++t) {
        double *mv = c->mloc + (size_t)t * n;
        if ((st = cg_element(c, t, Sref, K, mv, work, err)) != SQ_OK) break;
        c->work.element_matrices++;
        for (int i = 0; i < 3; ++i) c->area += mv[i];
        /* Static condensation (K&S §4.1.6): S = Kbb - Kbi Kii^-1 Kib. */
        double *S = c->S + (size_t)t * nb * nb;
        for (int i = 0; i < nb; ++i) memcpy(S + i * nb, K + i * n, sizeof(double) * nb);
        if (ni == 0) continue;
        double *L = c->Lii + (size_t)t * ni * ni, *W = c->W + (size_t)t * ni * nb;
        for (int i = 0; i < ni; ++i) {
            memcpy(L + i * ni, K + (size_t)(nb + i) * n + nb, sizeof(double) * ni);
            memcpy(W + i * nb, K + (size_t)(nb + i) * n, sizeof(double) * nb);
        }
        sem_lib_lock();
        const lapack_int info = LAPACKE_dpotrf(LAPACK_ROW_MAJOR, 'L', ni, L, ni);
        if (info == 0) {
            LAPACKE_dpotrs(LAPACK_ROW_MAJOR, 'L', ni, nb, L, ni, W, nb);
            cblas_dgemm(CblasRowMajor, CblasNoTrans, CblasNoTrans, nb, nb, ni, -1.0, K + nb, n, W,
                        nb, 1.0, S, nb);
        }
        sem_lib_unlock();
        if (info != 0) {
            st = SQ_FAIL(err, SQ_ERR_INTERNAL,
                         "poisson_cg_create: interior block of element %d not SPD", t);
            break;
        }
    }
done:
    free(Sref);
    free(K);
    free(work);
    return st;
}

/* The matrix's pattern and its assembly, column by column, from the
 * elements of each free dof: elem[eptr[f] .. eptr[f+1]-1] are t nb + i for
 * the local modes i of elements t (ascending) that are free dof f. */
typedef struct {
    long *eptr, *elem, *mark, *ptr, *row;
} cg_graph;

static void cg_graph_free(cg_graph *g)
{
    free(g->eptr);
    free(g->elem);
    free(g->mark);
    free(g->ptr);
    free(g->row);
}

/* The lower-triangular pattern of the condensed matrix: column j holds the
 * free dofs i >= j that share an element with j, found row by row (i
 * ascending, so each column's rows come out sorted, j first), counted on
 * a first pass and stored on a second. */
static sq_status cg_graph_build(const cg_state *c, cg_graph *g, sq_error *err)
{
    const int nb = c->nb;
    const long n = c->nfree, nq = (long)c->mesh->ntris * nb;
    const long *bmap = c->space->bmap, *gf = c->gfree;
    g->eptr = calloc((size_t)n + 2, sizeof(long));
    g->elem = malloc(sizeof(long) * ((size_t)nq + 1));
    g->mark = malloc(sizeof(long) * (size_t)n);
    g->ptr = calloc((size_t)n + 2, sizeof(long));
    if (!g->eptr || !g->elem || !g->mark || !g->ptr)
        return SQ_FAIL(err, SQ_ERR_INTERNAL, "poisson_cg: out of memory (pattern)");
    for (long q = 0; q < nq; ++q)
        if (gf[bmap[q]] >= 0) g->eptr[gf[bmap[q]] + 2]++;
    for (long f = 0; f < n; ++f)
        g->eptr[f + 2] += g->eptr[f + 1];
    for (long q = 0; q < nq; ++q)
        if (gf[bmap[q]] >= 0) g->elem[g->eptr[gf[bmap[q]] + 1]++] = q;
    for (int pass = 0; pass < 2; ++pass) {
        for (long f = 0; f < n; ++f)
            g->mark[f] = -1;
        for (long i = 0; i < n; ++i)
            for (long p = g->eptr[i]; p < g->eptr[i + 1]; ++p) {
                const long *map = bmap + g->elem[p] / nb * nb;
                for (int k = 0; k < nb; ++k) {
                    const long j = gf[map[k]];
                    if (j < 0 || j > i || g->mark[j] == i) continue;
                    g->mark[j] = i;
                    if (pass == 0)
                        g->ptr[j + 2]++;
                    else
                        g->row[g->ptr[j + 1]++] = i;
                }
            }
        if (pass == 1) break;
        for (long f = 0; f < n; ++f)
            g->ptr[f + 2] += g->ptr[f + 1];
        g->row = malloc(sizeof(long) * ((size_t)g->ptr[n + 1] + 1));
        if (!g->row) return SQ_FAIL(err, SQ_ERR_INTERNAL, "poisson_cg: out of memory (pattern)");
    }
    return SQ_OK;
}

/* The condensed global matrix of the free dofs, assembled in place in its
 * pattern and factored.  Column j's entries are summed over j's elements
 * in ascending order, the order an element-by-element assembly of
 * triplets sums them in: the same matrix, bit for bit. */
static sq_status cg_assemble(cg_state *c, sq_error *err)
{
    const int nb = c->nb;
    const long n = c->nfree;
    const sem_cg_space *sp = c->space;
    if (n == 0) return SQ_OK;
    cg_graph g = {0};
    sq_status st = cg_graph_build(c, &g, err);
    if (st == SQ_OK) st = sem_sparse_create_pattern(n, g.ptr, g.row, &c->A, err);
    double *x = st == SQ_OK ? sem_sparse_values(c->A) : NULL;
    long *at = g.mark; /* at[i]: where row i of the current column is */
    for (long j = 0; j < n && st == SQ_OK; ++j) {
        for (long p = g.ptr[j]; p < g.ptr[j + 1]; ++p)
            at[g.row[p]] = p;
        for (long p = g.eptr[j]; p < g.eptr[j + 1]; ++p) {
            const long t = g.elem[p] / nb;
            const int jl = (int)(g.elem[p] % nb);
            const double *S = c->S + (size_t)t * nb * nb;
            const long *map = sp->bmap + (size_t)t * nb;
            const signed char *sg = sp->bsign + (size_t)t * nb;
            for (int i = 0; i < nb; ++i) {
                const long fi = c->gfree[map[i]];
                if (fi >= j) x[at[fi]] += sg[i] * sg[jl] * S[i * nb + jl];
            }
        }
    }
    cg_graph_free(&g);
    SQ_TRY(st);
    SQ_TRY(sem_sparse_factor(c->A, err));
    c->work.factorizations++;
    return SQ_OK;
}

sq_status sem_poisson_cg_create(const sem_tri_mesh *mesh, int P, sem_bc_kind_fn kind,
                                void *kind_ctx, const sem_poisson_ops **ops, void **state,
                                sq_error *err)
{
    if (!ops || !state) return SQ_FAIL(err, SQ_ERR_USAGE, "poisson_cg_create: NULL output");
    *ops = NULL;
    *state = NULL;
    if (!mesh || mesh->ntris <= 0 || P < 1 || P > SEM_MAX_ORDER)
        return SQ_FAIL(err, SQ_ERR_USAGE, "poisson_cg_create: bad mesh or order %d", P);
    cg_state *c = NULL;
    sq_status st = cg_start(mesh, P, &c, err);
    if (st == SQ_OK) st = cg_dofs(c, kind, kind_ctx, err);
    if (st == SQ_OK) st = cg_elements(c, err);
    if (st == SQ_OK) st = cg_assemble(c, err);
    if (st != SQ_OK) {
        cg_free(c);
        return st;
    }
    *ops = &cg_ops;
    *state = c;
    return SQ_OK;
}

/* Values of the Dirichlet dofs for data g (vertex values by interpolation,
 * edge modes by the 1D L2 projection of g minus the vertex interpolant on
 * the edge's reference parameter). */
static sq_status cg_dirichlet(const cg_state *c, const sem_poisson_data *data, double *ud,
                              char *done, sq_error *err)
{
    const sem_tri_mesh *m = c->mesh;
    const sem_cg_space *sp = c->space;
    const int P = c->P, nb = c->nb, ne = P - 1;
    memset(ud, 0, sizeof(double) * (size_t)(c->ndir + 1));
    if (!data->g) return SQ_OK;
    memset(done, 0, (size_t)c->ndir + 1);
    for (int pass = 0; pass < 2; ++pass) /* vertices first, then edges */
        for (int t = 0; t < m->ntris; ++t)
            for (int k = 0; k < 3; ++k) {
                if (c->bc_kind[3 * t + k] != SEM_BC_DIRICHLET) continue;
                const double *gxy = m->gxy + 2 * (size_t)m->nodes_per_tri * t;
                const long *map = sp->bmap + (size_t)t * nb;
                const signed char *sg = sp->bsign + (size_t)t * nb;
                const int tag = data->g_by_edge ? 3 * t + k : m->btag[3 * t + k];
                double rs[2], x[2], nrm[2], dsdt;
                if (pass == 0) {
                    for (int e = 0; e < 2; ++e) {
                        const long d = -1 - c->gfree[map[(k + e) % 3]];
                        if (done[d]) continue;
                        cg_edge_geom(c, gxy, k, c->nqe + e, rs, x, nrm, &dsdt);
                        ud[d] = data->g(x, nrm, tag, data->g_ctx);
                        done[d] = 1;
                    }
                    continue;
                }
                if (ne < 1) continue;
                const double ga = ud[-1 - c->gfree[map[k]]];
                const double gb = ud[-1 - c->gfree[map[(k + 1) % 3]]];
                double rhs[SEM_MAX_ORDER] = {0};
                for (int q = 0; q < c->nqe; ++q) {
                    const double tq = c->te[q];
                    cg_edge_geom(c, gxy, k, q, rs, x, nrm, &dsdt);
                    const double r = data->g(x, nrm, tag, data->g_ctx) - 0.5 * (1 - tq) * ga -
                                     0.5 * (1 + tq) * gb;
                    for (int p = 1; p <= ne; ++p)
                        rhs[p - 1] += c->we[q] * r * 0.25 * (1 - tq) * (1 + tq) *
                                      sem_jacobi(p - 1, 1.0, 1.0, tq, NULL);
                }
                sem_lib_lock();
                const lapack_int info =
                    LAPACKE_dpotrs(LAPACK_ROW_MAJOR, 'L', ne, 1, c->Mf, ne, rhs, 1);
                sem_lib_unlock();
                if (info != 0)
                    return SQ_FAIL(err, SQ_ERR_INTERNAL, "poisson_cg: edge projection failed");
                for (int p = 1; p <= ne; ++p) {
                    const int i = sem_cg_edge_mode(P, k, p);
                    ud[-1 - c->gfree[map[i]]] = sg[i] * rhs[p - 1];
                }
            }
    return SQ_OK;
}

static sq_status cg_solve(void *state, const sem_poisson_data *data, sem_field *u, sq_error *err)
{
    cg_state *c = state;
    const sem_tri_mesh *m = c->mesh;
    const sem_cg_space *sp = c->space;
    const int n = c->nloc, nb = c->nb, ni = c->ni, nt = m->ntris, nq = c->quad->npts, P = c->P;
    sq_status st = SQ_OK;
    double *bl = malloc(sizeof(double) * (size_t)nt * n);
    double *ud = malloc(sizeof(double) * ((size_t)c->ndir + 1));
    char *done = malloc((size_t)c->ndir + 1);
    double *F = calloc((size_t)c->nfree + 1, sizeof(double));
    double *fq = malloc(sizeof(double) * (size_t)nq);
    if (!bl || !ud || !done || !F || !fq) {
        st = SQ_FAIL(err, SQ_ERR_INTERNAL, "poisson_cg: out of memory");
        goto done;
    }
    if ((st = cg_dirichlet(c, data, ud, done, err)) != SQ_OK) goto done;

    /* local right-hand sides: ∫ f psi + ∮_N g psi + sum c psi(x_j) */
    double scale = 0.0; /* ∫|f| + ∮|g| + sum |c| (pure Neumann check) */
    memset(bl, 0, sizeof(double) * (size_t)nt * n);
    for (int t = 0; t < nt; ++t) {
        const double *gxy = m->gxy + 2 * (size_t)m->nodes_per_tri * t;
        double *b = bl + (size_t)t * n;
        if (data->f) {
            for (int k = 0; k < nq; ++k) {
                double x[2], J[4];
                const double det = cg_geom_at(c, gxy, k, x, J);
                const double fv = data->f(x, data->f_ctx);
                fq[k] = c->quad->w[k] * det * fv;
                scale += fabs(fq[k]);
            }
            sem_lib_lock();
            cblas_dgemv(CblasRowMajor, CblasTrans, nq, n, 1.0, c->B, n, fq, 1, 0.0, b, 1);
            sem_lib_unlock();
        }
        if (!data->g) continue;
        for (int k = 0; k < 3; ++k) {
            if (c->bc_kind[3 * t + k] != SEM_BC_NEUMANN) continue;
            const int tag = data->g_by_edge ? 3 * t + k : m->btag[3 * t + k];
            for (int q = 0; q < c->nqe; ++q) {
                double rs[2], x[2], nrm[2], dsdt;
                cg_edge_geom(c, gxy, k, q, rs, x, nrm, &dsdt);
                const double w = c->we[q] * dsdt * data->g(x, nrm, tag, data->g_ctx);
                scale += fabs(w);
                const double *psi = c->Epsi + ((size_t)k * c->nte + q) * n;
                for (int i = 0; i < n; ++i) b[i] += w * psi[i];
            }
        }
    }
    for (int j = 0; j < data->npoints; ++j) {
        const sem_point_source *ps = &data->points[j];
        double psi[CG_NMAX];
        sem_cg_basis_eval(c->basis, ps->r, ps->s, psi, NULL, NULL);
        double *b = bl + (size_t)ps->elem * n;
        for (int i = 0; i < n; ++i) b[i] += ps->strength * psi[i];
        scale += fabs(ps->strength);
    }
    if (c->pure_neumann) {
        /* The constant function is the sum of the vertex modes, so b . 1 =
         * ∫f + ∮g + sum c.  Check it, then remove the quadrature residue
         * (as a constant shift of f) so that the system is consistent. */
        double imb = 0.0;
        for (int t = 0; t < nt; ++t)
            for (int k = 0; k < 3; ++k) imb += bl[(size_t)t * n + k];
        if (fabs(imb) > CG_COMPAT_RTOL * scale) {
            st = SQ_FAIL(err, SQ_ERR_USAGE,
                         "poisson_cg: pure Neumann data not compatible: ∫f + ∮g + Σc = %.6g, "
                         "but must be 0 (data size ∫|f| + ∮|g| + Σ|c| = %.6g)",
                         imb, scale);
            goto done;
        }
        const double shift = imb / c->area;
        for (size_t i = 0; i < (size_t)nt * n; ++i) bl[i] -= shift * c->mloc[i];
    }

    /* condensed, lifted global right-hand side */
    for (int t = 0; t < nt; ++t) {
        double *b = bl + (size_t)t * n;
        const double *S = c->S + (size_t)t * nb * nb;
        const long *map = sp->bmap + (size_t)t * nb;
        const signed char *sg = sp->bsign + (size_t)t * nb;
        /* b_b - Kbi Kii^-1 b_i = b_b - W^T b_i */
        if (ni > 0) {
            sem_lib_lock();
            cblas_dgemv(CblasRowMajor, CblasTrans, ni, nb, -1.0, c->W + (size_t)t * ni * nb, nb,
                        b + nb, 1, 1.0, b, 1);
            sem_lib_unlock();
        }
        double uloc[3 * SEM_MAX_ORDER];
        int has_dir = 0;
        for (int j = 0; j < nb; ++j) {
            const long g = c->gfree[map[j]];
            uloc[j] = g < 0 ? sg[j] * ud[-1 - g] : 0.0;
            has_dir |= g < 0 && uloc[j] != 0.0;
        }
        for (int i = 0; i < nb; ++i) {
            const long fi = c->gfree[map[i]];
            if (fi < 0) continue;
            double v = b[i];
            if (has_dir)
                for (int j = 0; j < nb; ++j) v -= S[i * nb + j] * uloc[j];
            F[fi] += sg[i] * v;
        }
    }
    if (c->A && (st = sem_sparse_solve(c->A, F, F, err)) != SQ_OK) goto done;

    /* back substitution per element, then to Dubiner coefficients */
    double mean = 0.0;
    for (int t = 0; t < nt; ++t) {
        double *b = bl + (size_t)t * n; /* becomes the local solution */
        const long *map = sp->bmap + (size_t)t * nb;
        const signed char *sg = sp->bsign + (size_t)t * nb;
        for (int j = 0; j < nb; ++j) {
            const long g = c->gfree[map[j]];
            b[j] = sg[j] * (g < 0 ? ud[-1 - g] : F[g]);
        }
        sem_lib_lock();
        if (ni > 0) { /* u_i = Kii^-1 b_i - W u_b (b_i is still the raw interior load) */
            LAPACKE_dpotrs(LAPACK_ROW_MAJOR, 'L', ni, 1, c->Lii + (size_t)t * ni * ni, ni, b + nb, 1);
            cblas_dgemv(CblasRowMajor, CblasNoTrans, ni, nb, -1.0, c->W + (size_t)t * ni * nb, nb, b,
                        1, 1.0, b + nb, 1);
        }
        if (c->pure_neumann) mean += cblas_ddot(n, c->mloc + (size_t)t * n, 1, b, 1);
        sem_lib_unlock();
    }
    mean /= c->area;
    (void)P;
    for (int t = 0; t < nt; ++t) {
        double *b = bl + (size_t)t * n;
        if (c->pure_neumann) /* the constant is the sum of the vertex modes */
            for (int k = 0; k < 3; ++k) b[k] -= mean;
        /* d_m = sum_i C[i][m] u_i */
        sem_lib_lock();
        cblas_dgemv(CblasRowMajor, CblasTrans, n, n, 1.0, c->basis->C, n, b, 1, 0.0,
                    u->coef + (size_t)t * n, 1);
        sem_lib_unlock();
    }
done:
    free(bl);
    free(ud);
    free(done);
    free(F);
    free(fq);
    return st;
}
