/* semquad sem/ — symmetric interior penalty DG for -Δu = f on curved
 * triangles, in the orthonormal Dubiner basis of order P.
 *
 * Bilinear form (Arnold, Brezzi, Cockburn & Marini 2002, SIPG; Hesthaven &
 * Warburton 2008, §7.2), with [v] = v⁺ - v⁻ and {∂ₙu} = (∂ₙu⁺ + ∂ₙu⁻)/2
 * taken along the normal n pointing out of the + side:
 *   a(u,v) = Σ_K ∫_K ∇u·∇v
 *          - Σ_F ∫_F ({∂ₙu}[v] + {∂ₙv}[u]) + Σ_F σ_F ∫_F [u][v]
 *          - Σ_D ∫_D (∂ₙu v + ∂ₙv u) + Σ_D σ_D ∫_D u v        (Nitsche)
 *   l(v)   = ∫ f v + Σ_D ∫_D g (σ_D v - ∂ₙv) + Σ_N ∫_N g v + Σ_j c_j v(x_j).
 * Dirichlet data enters only through l, so data that jumps at a corner is
 * imposed consistently edge by edge (Marcon 2019 §2.2.1).
 *
 * Penalty σ = C (P+1)(P+2) / h with h = |K| / |F| (element area over edge
 * length, the smaller of the two sides; Shahbazi 2005 gives the trace
 * constant (P+1)(P+2)/2 · |F|/|K| for triangles); boundary faces carry no
 * average, hence twice the interior value.
 *
 * Faces are integrated with Gauss–Legendre on the curved edge map of each
 * side: the point at parameter t on one side is 1 - t on the neighbour
 * (the shared edge runs the other way), and the symmetric Gauss points
 * make that the reversed index.  The geometry order is independent of P,
 * so the rules have P + order + 1 points per direction: exact for the
 * polynomial part of every integrand, and the rational curved factors are
 * resolved to spectral accuracy.
 *
 * Pure Neumann: the kernel is the constants.  The right-hand side is made
 * exactly compatible (the discrete imbalance, once checked to be round-off
 * of the data, is removed as a uniform source), the first unknown (mode 0
 * of element 0, never zero in the kernel vector) is pinned, which keeps the
 * matrix sparse and SPD, and the mean is removed after the solve. */
#include "lib_lock.h"
#include "dg_modal.h"
#include "gauss.h"
#include "poisson_impl.h"
#include "sparse.h"
#include "tri_basis.h"
#include "tri_lagrange.h"
#include "tri_nodes.h"
#include "tri_quad.h"

#include <cblas.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* C in σ = C (P+1)(P+2)/h.  Coercivity needs C (P+1)(P+2)|F|/|K| above the
 * inverse-trace constant; curved elements (non-constant det J) need some
 * margin beyond the straight-sided value 1/2. */
#define DG_PENALTY 1.0
/* Relative tolerance of the pure-Neumann compatibility check: the data are
 * integrated by quadrature on the curved geometry, so a compatible problem
 * shows an imbalance of quadrature/geometry error only (see poisson_cg.c:
 * up to about 1e-5 near sharp features). */
#define DG_COMPAT_TOL 1e-4

typedef struct {
    const sem_tri_mesh *mesh;
    int P, nm, go, ngn;
    long ndofs;
    int pure_neumann;
    sem_sparse *A;
    int nq;       /* volume points */
    double *phiq; /* nq*nm: Dubiner values at the volume points (weights not included) */
    double *vx;   /* 3*nq*ntris: x, y, w det J per element and volume point */
    double *mom;  /* ndofs: int_K phi_m (pure Neumann only) */
    double area;  /* |Omega| */
    int ne;       /* edge points */
    int nb;       /* boundary faces */
    int *bface;   /* 2*nb: element, local edge */
    int *bdir;    /* nb: 1 Dirichlet, 0 Neumann */
    double *bx;   /* 5*ne*nb: x, y, nx, ny, W (weight times |dx/dt|) */
    double *bphi; /* ne*nm*nb: phi at the face points */
    double *bdn;  /* ne*nm*nb: d phi/dn */
    double *bsig; /* nb: penalty */
    double *rhs;  /* ndofs work */
    sem_poisson_work work;
} dg_state;

static void dg_free(void *state)
{
    dg_state *S = state;
    if (!S) return;
    sem_sparse_free(&S->A);
    free(S->phiq);
    free(S->vx);
    free(S->mom);
    free(S->bface);
    free(S->bdir);
    free(S->bx);
    free(S->bphi);
    free(S->bdn);
    free(S->bsig);
    free(S->rhs);
    free(S);
}

static long dg_ndofs(const void *state) { return ((const dg_state *)state)->ndofs; }
static sem_poisson_work dg_work(const void *state) { return ((const dg_state *)state)->work; }

/* Edge k of the reference triangle at parameter t in [0,1]: vertices
 * (0,0), (1,0), (0,1); direction (dr, ds) = v_{k+1} - v_k. */
static void edge_point(int k, double t, double rs[2], double d[2])
{
    static const double V[3][2] = {{0, 0}, {1, 0}, {0, 1}};
    const double *a = V[k], *b = V[(k + 1) % 3];
    d[0] = b[0] - a[0];
    d[1] = b[1] - a[1];
    rs[0] = a[0] + t * d[0];
    rs[1] = a[1] + t * d[1];
}

/* Per-face tabulation: everything needed on one side of a face. */
typedef struct {
    int ne, nm, ngn;
    const double *t, *w;      /* ne points on [0,1] and weights */
    double *ephi, *edr, *eds; /* 3*ne*nm: Dubiner on each local edge */
    double *el, *elr, *els;   /* 3*ne*ngn: geometry Lagrange on each local edge */
} edge_tab;

/* Physical data of element e's edge k at its ne points: x (2ne), outward
 * unit normal (2ne), W = w |dx/dt| (ne), phi (ne*nm) and d phi/dn (ne*nm)
 * along the supplied normals `nrm` if given (the + side's normal, point i
 * of this side matched to point i of the normals array), else along this
 * side's own outward normal.  Returns -1 if det J <= 0 somewhere. */
static int edge_side(const edge_tab *E, const double *g, int k, const double *nrm, int reverse,
                     double *x, double *nout, double *W, double *phi, double *dn)
{
    const int ne = E->ne, nm = E->nm, ngn = E->ngn;
    double rs[2], d[2];
    edge_point(k, 0.0, rs, d);
    for (int ii = 0; ii < ne; ++ii) {
        const int i = reverse ? ne - 1 - ii : ii; /* index into this side's tables */
        const double *l = E->el + ((size_t)k * ne + i) * ngn;
        const double *lr = E->elr + ((size_t)k * ne + i) * ngn;
        const double *ls = E->els + ((size_t)k * ne + i) * ngn;
        double px = 0, py = 0, xr = 0, xs = 0, yr = 0, ys = 0;
        for (int n = 0; n < ngn; ++n) {
            const double gx = g[2 * n], gy = g[2 * n + 1];
            px += gx * l[n];
            py += gy * l[n];
            xr += gx * lr[n];
            xs += gx * ls[n];
            yr += gy * lr[n];
            ys += gy * ls[n];
        }
        const double det = xr * ys - xs * yr;
        if (!(det > 0.0)) return -1;
        const double tx = xr * d[0] + xs * d[1], ty = yr * d[0] + ys * d[1];
        const double len = hypot(tx, ty);
        double nx = ty / len, ny = -tx / len; /* outward for a counter-clockwise element */
        if (x) {
            x[2 * ii] = px;
            x[2 * ii + 1] = py;
        }
        if (nout) {
            nout[2 * ii] = nx;
            nout[2 * ii + 1] = ny;
        }
        if (W) W[ii] = E->w[i] * len;
        if (nrm) {
            nx = nrm[2 * ii];
            ny = nrm[2 * ii + 1];
        }
        /* grad phi = J^{-T} (phi_r, phi_s) */
        const double rx = ys / det, ry = -xs / det, sx = -yr / det, sy = xr / det;
        const double an = rx * nx + ry * ny, bn = sx * nx + sy * ny;
        const double *p = E->ephi + ((size_t)k * ne + i) * nm;
        const double *pr = E->edr + ((size_t)k * ne + i) * nm;
        const double *ps = E->eds + ((size_t)k * ne + i) * nm;
        for (int m = 0; m < nm; ++m) {
            phi[(size_t)ii * nm + m] = p[m];
            dn[(size_t)ii * nm + m] = an * pr[m] + bn * ps[m];
        }
    }
    return 0;
}

/* Add block M (nm x nm, row-major, rows = test dofs of element e, cols =
 * trial dofs of element b); an off-diagonal block stands for its transpose
 * too.  Pure Neumann: the pinned unknown's row and column stay out (M is
 * work space and is changed). */
static sq_status scatter(dg_state *S, double *M, long e, long b, sq_error *err)
{
    const int nm = S->nm;
    if (S->pure_neumann && e == 0)
        for (int j = 0; j < nm; ++j)
            M[j] = 0.0;
    if (S->pure_neumann && b == 0)
        for (int i = 0; i < nm; ++i)
            M[(size_t)i * nm] = 0.0;
    return sem_sparse_add_block(S->A, e, b, M, err);
}

/* The block pattern of the matrix: block column e holds e itself and the
 * neighbours after it. */
static sq_status create_matrix(dg_state *S, sq_error *err)
{
    const sem_tri_mesh *mesh = S->mesh;
    const int nt = mesh->ntris;
    long *bptr = malloc(sizeof(long) * ((size_t)nt + 1)),
         *brow = malloc(sizeof(long) * 4 * (size_t)nt);
    if (!bptr || !brow) {
        free(bptr);
        free(brow);
        return SQ_FAIL(err, SQ_ERR_INTERNAL, "poisson_dg_create: out of memory");
    }
    long k = 0;
    for (int e = 0; e < nt; ++e) {
        bptr[e] = k;
        brow[k++] = e;
        int nb[3], n = 0;
        for (int j = 0; j < 3; ++j)
            if (mesh->neigh[3 * e + j] > e) nb[n++] = mesh->neigh[3 * e + j];
        for (int a = 1; a < n; ++a) /* ascending */
            for (int c = a; c > 0 && nb[c] < nb[c - 1]; --c) {
                const int t = nb[c];
                nb[c] = nb[c - 1];
                nb[c - 1] = t;
            }
        for (int j = 0; j < n; ++j)
            if (j == 0 || nb[j] != nb[j - 1]) brow[k++] = nb[j];
    }
    bptr[nt] = k;
    const sq_status st = sem_sparse_create_blocks(nt, S->nm, bptr, brow, &S->A, err);
    free(bptr);
    free(brow);
    return st;
}

/* C = alpha A^T B + beta C for A, B of ne x nm (row-major), C nm x nm. */
static void gemm_tn(int nm, int ne, double alpha, const double *A, const double *B, double beta,
                    double *C)
{
    sem_lib_lock();
    cblas_dgemm(CblasRowMajor, CblasTrans, CblasNoTrans, nm, nm, ne, alpha, A, nm, B, nm, beta, C,
                nm);
    sem_lib_unlock();
}

/* out = diag(W) in (rows of ne x nm). */
static void weigh(int ne, int nm, const double *W, const double *in, double *out)
{
    for (int p = 0; p < ne; ++p)
        for (int m = 0; m < nm; ++m)
            out[(size_t)p * nm + m] = W[p] * in[(size_t)p * nm + m];
}

static sq_status dg_solve(void *state, const sem_poisson_data *data, sem_field *u, sq_error *err);

static const sem_poisson_ops dg_ops = {dg_solve, dg_free, dg_ndofs, dg_work};

static sq_status find_back_edge(const sem_tri_mesh *M, int e, int k, int b, int *kb, sq_error *err)
{
    const int va = M->tri[3 * e + k], vb = M->tri[3 * e + (k + 1) % 3];
    for (int j = 0; j < 3; ++j)
        if (M->neigh[3 * b + j] == e && M->tri[3 * b + j] == vb &&
            M->tri[3 * b + (j + 1) % 3] == va) {
            *kb = j;
            return SQ_OK;
        }
    return SQ_FAIL(err, SQ_ERR_USAGE,
                   "poisson_dg: element %d edge %d names neighbour %d, which does not share that "
                   "edge (run sem_tri_mesh_build_neighbours)",
                   e, k, b);
}

sq_status sem_poisson_dg_create(const sem_tri_mesh *mesh, int P, sem_bc_kind_fn kind,
                                void *kind_ctx, const sem_poisson_ops **ops, void **state,
                                sq_error *err)
{
    if (!ops || !state) return SQ_FAIL(err, SQ_ERR_USAGE, "poisson_dg_create: NULL output");
    *ops = NULL;
    *state = NULL;
    if (!mesh || mesh->ntris < 1)
        return SQ_FAIL(err, SQ_ERR_USAGE, "poisson_dg_create: empty mesh");
    if (P < 1 || P > SEM_MAX_ORDER)
        return SQ_FAIL(err, SQ_ERR_USAGE, "poisson_dg_create: order %d outside 1..%d", P,
                       SEM_MAX_ORDER);
    const int nt = mesh->ntris, nm = sem_tri_num_nodes(P), go = mesh->order;
    const int ngn = mesh->nodes_per_tri;
    if ((long)nt * nm > 2000000000L)
        return SQ_FAIL(err, SQ_ERR_USAGE, "poisson_dg_create: too many unknowns (%d x %d)", nt, nm);

    sq_status st = SQ_OK;
    dg_state *S = calloc(1, sizeof *S);
    sem_tri_lagrange *lag = NULL;
    sem_tri_quad *q = NULL;
    double *lq = NULL, *lrq = NULL, *lsq = NULL, *drq = NULL, *dsq = NULL, *B = NULL, *K = NULL;
    double *KT = NULL; /* face work: one nm x nm product */
    double *area = NULL, *et = NULL, *ew = NULL;
    edge_tab E = {0};
    double *fa = NULL; /* face work */
    if (!S) return SQ_FAIL(err, SQ_ERR_INTERNAL, "poisson_dg_create: out of memory");
    S->mesh = mesh;
    S->P = P;
    S->nm = nm;
    S->go = go;
    S->ngn = ngn;
    S->ndofs = (long)nt * nm;
    if ((st = sem_tri_lagrange_create(go, &lag, err)) != SQ_OK) goto fail;

    /* ---- volume rule and tables ---- */
    if ((st = sem_tri_quad_create(2 * P + 2 * go, &q, err)) != SQ_OK) goto fail;
    const int nq = S->nq = q->npts;
    S->phiq = malloc(sizeof(double) * (size_t)nq * nm);
    drq = malloc(sizeof(double) * (size_t)nq * nm);
    dsq = malloc(sizeof(double) * (size_t)nq * nm);
    lq = malloc(sizeof(double) * (size_t)nq * ngn);
    lrq = malloc(sizeof(double) * (size_t)nq * ngn);
    lsq = malloc(sizeof(double) * (size_t)nq * ngn);
    S->vx = malloc(sizeof(double) * 3 * (size_t)nq * nt);
    B = malloc(sizeof(double) * 2 * (size_t)nq * nm);
    K = malloc(sizeof(double) * (size_t)nm * nm * 4);
    KT = malloc(sizeof(double) * (size_t)nm * nm);
    area = malloc(sizeof(double) * (size_t)nt);
    S->rhs = malloc(sizeof(double) * (size_t)S->ndofs);
    if (!S->phiq || !drq || !dsq || !lq || !lrq || !lsq || !S->vx || !B || !K || !KT || !area ||
        !S->rhs) {
        st = SQ_FAIL(err, SQ_ERR_INTERNAL, "poisson_dg_create: out of memory (%ld unknowns)",
                     S->ndofs);
        goto fail;
    }
    for (int k = 0; k < nq; ++k) {
        const double r = q->rs[2 * k], s = q->rs[2 * k + 1];
        sem_tri_dubiner(P, r, s, S->phiq + (size_t)k * nm, drq + (size_t)k * nm,
                        dsq + (size_t)k * nm);
        sem_tri_lagrange_eval(lag, r, s, lq + (size_t)k * ngn, lrq + (size_t)k * ngn,
                              lsq + (size_t)k * ngn);
    }

    /* ---- boundary faces and the kind of each ---- */
    int nb = 0, ndir = 0;
    for (long h = 0; h < 3L * nt; ++h)
        if (mesh->neigh[h] < 0) ++nb;
    S->nb = nb;
    S->bface = malloc(sizeof(int) * 2 * (size_t)(nb + 1));
    S->bdir = malloc(sizeof(int) * (size_t)(nb + 1));
    S->bsig = malloc(sizeof(double) * (size_t)(nb + 1));
    if (!S->bface || !S->bdir || !S->bsig) {
        st = SQ_FAIL(err, SQ_ERR_INTERNAL, "poisson_dg_create: out of memory");
        goto fail;
    }
    nb = 0;
    for (int e = 0; e < nt; ++e)
        for (int k = 0; k < 3; ++k) {
            if (mesh->neigh[3 * e + k] >= 0) continue;
            S->bface[2 * nb] = e;
            S->bface[2 * nb + 1] = k;
            const int tag = mesh->btag[3 * e + k];
            S->bdir[nb] = kind ? kind(tag, kind_ctx) == SEM_BC_DIRICHLET : 1;
            ndir += S->bdir[nb];
            ++nb;
        }
    S->pure_neumann = ndir == 0;

    /* ---- edge rule and tables ---- */
    const int ne = S->ne = P + go + 1;
    et = malloc(sizeof(double) * (size_t)ne);
    ew = malloc(sizeof(double) * (size_t)ne);
    E.ne = ne;
    E.nm = nm;
    E.ngn = ngn;
    E.ephi = malloc(sizeof(double) * 3 * (size_t)ne * nm);
    E.edr = malloc(sizeof(double) * 3 * (size_t)ne * nm);
    E.eds = malloc(sizeof(double) * 3 * (size_t)ne * nm);
    E.el = malloc(sizeof(double) * 3 * (size_t)ne * ngn);
    E.elr = malloc(sizeof(double) * 3 * (size_t)ne * ngn);
    E.els = malloc(sizeof(double) * 3 * (size_t)ne * ngn);
    /* face work: x, n (2ne each), W (ne), then phi/dn of both sides (4 ne nm) */
    fa = malloc(sizeof(double) * ((size_t)7 * ne + 6 * (size_t)ne * nm));
    S->bx = malloc(sizeof(double) * 5 * (size_t)ne * (nb + 1));
    S->bphi = malloc(sizeof(double) * (size_t)ne * nm * (nb + 1));
    S->bdn = malloc(sizeof(double) * (size_t)ne * nm * (nb + 1));
    if (!et || !ew || !E.ephi || !E.edr || !E.eds || !E.el || !E.elr || !E.els || !fa || !S->bx ||
        !S->bphi || !S->bdn) {
        st = SQ_FAIL(err, SQ_ERR_INTERNAL, "poisson_dg_create: out of memory");
        goto fail;
    }
    if ((st = sem_gauss_jacobi(ne, 0.0, 0.0, et, ew, err)) != SQ_OK) goto fail;
    for (int i = 0; i < ne; ++i) {
        et[i] = 0.5 * (1.0 + et[i]);
        ew[i] *= 0.5;
    }
    /* make the rule exactly symmetric so point i matches ne-1-i */
    for (int i = 0; i < ne / 2; ++i) {
        const double t = 0.5 * (et[i] + 1.0 - et[ne - 1 - i]), w = 0.5 * (ew[i] + ew[ne - 1 - i]);
        et[i] = t;
        et[ne - 1 - i] = 1.0 - t;
        ew[i] = ew[ne - 1 - i] = w;
    }
    if (ne % 2) et[ne / 2] = 0.5;
    E.t = et;
    E.w = ew;
    for (int k = 0; k < 3; ++k)
        for (int i = 0; i < ne; ++i) {
            double rs[2], d[2];
            edge_point(k, et[i], rs, d);
            const size_t o = (size_t)k * ne + i;
            sem_tri_dubiner(P, rs[0], rs[1], E.ephi + o * nm, E.edr + o * nm, E.eds + o * nm);
            sem_tri_lagrange_eval(lag, rs[0], rs[1], E.el + o * ngn, E.elr + o * ngn,
                                  E.els + o * ngn);
        }

    if ((st = create_matrix(S, err)) != SQ_OK) goto fail;

    /* ---- volume terms: K = B^T B with B rows sqrt(w det J) grad phi ---- */
    S->area = 0.0;
    for (int e = 0; e < nt; ++e) {
        const double *g = mesh->gxy + 2 * (size_t)ngn * e;
        double *vx = S->vx + 3 * (size_t)nq * e;
        double a = 0.0;
        for (int k = 0; k < nq; ++k) {
            const double *l = lq + (size_t)k * ngn, *lr = lrq + (size_t)k * ngn,
                         *ls = lsq + (size_t)k * ngn;
            double px = 0, py = 0, xr = 0, xs = 0, yr = 0, ys = 0;
            for (int n = 0; n < ngn; ++n) {
                const double gx = g[2 * n], gy = g[2 * n + 1];
                px += gx * l[n];
                py += gy * l[n];
                xr += gx * lr[n];
                xs += gx * ls[n];
                yr += gy * lr[n];
                ys += gy * ls[n];
            }
            const double det = xr * ys - xs * yr;
            if (!(det > 0.0)) {
                st = SQ_FAIL(err, SQ_ERR_USAGE,
                             "poisson_dg_create: element %d has det J = %g <= 0 at (%g, %g) "
                             "(clockwise or tangled)",
                             e, det, q->rs[2 * k], q->rs[2 * k + 1]);
                goto fail;
            }
            vx[3 * k] = px;
            vx[3 * k + 1] = py;
            vx[3 * k + 2] = q->w[k] * det;
            a += q->w[k] * det;
            const double sw = sqrt(q->w[k] * det);
            const double rx = ys / det, ry = -xs / det, sx = -yr / det, sy = xr / det;
            const double *pr = drq + (size_t)k * nm, *ps = dsq + (size_t)k * nm;
            double *bx = B + (size_t)k * nm, *by = B + (size_t)(nq + k) * nm;
            for (int m = 0; m < nm; ++m) {
                bx[m] = sw * (rx * pr[m] + sx * ps[m]);
                by[m] = sw * (ry * pr[m] + sy * ps[m]);
            }
        }
        area[e] = a;
        S->area += a;
        /* dgemm rather than dsyrk: OpenBLAS's syrk is far slower for these
         * tall-skinny shapes */
        sem_lib_lock();
        cblas_dgemm(CblasRowMajor, CblasTrans, CblasNoTrans, nm, nm, 2 * nq, 1.0, B, nm, B, nm, 0.0,
                    K, nm);
        sem_lib_unlock();
        S->work.element_matrices++;
        if ((st = scatter(S, K, e, e, err)) != SQ_OK) goto fail;
    }

    /* ---- face terms ---- */
    {
        const double pp = (double)(P + 1) * (P + 2);
        double *x = fa, *nrm = fa + 2 * ne, *W = fa + 4 * ne, *Wb = fa + 5 * ne;
        double *va = fa + 7 * ne, *ga = va + (size_t)ne * nm, *vb = ga + (size_t)ne * nm,
               *gb = vb + (size_t)ne * nm, *wva = gb + (size_t)ne * nm,
               *wvb = wva + (size_t)ne * nm;
        double *Kaa = K, *Kab = K + (size_t)nm * nm, *Kbb = K + 2 * (size_t)nm * nm;
        int ib = 0;
        for (int e = 0; e < nt; ++e)
            for (int k = 0; k < 3; ++k) {
                const int b = mesh->neigh[3 * e + k];
                if (b >= 0 && b < e) continue; /* each interior face once */
                const double *ge = mesh->gxy + 2 * (size_t)ngn * e;
                if (edge_side(&E, ge, k, NULL, 0, x, nrm, W, va, ga) != 0) {
                    st = SQ_FAIL(err, SQ_ERR_USAGE,
                                 "poisson_dg_create: element %d has det J <= 0 on edge %d", e, k);
                    goto fail;
                }
                double len = 0.0;
                for (int i = 0; i < ne; ++i)
                    len += W[i];
                if (b < 0) {
                    /* boundary face: keep its data for the right-hand sides */
                    const double sig = 2.0 * DG_PENALTY * pp * len / area[e];
                    S->bsig[ib] = sig;
                    double *bx = S->bx + 5 * (size_t)ne * ib;
                    for (int i = 0; i < ne; ++i) {
                        bx[5 * i] = x[2 * i];
                        bx[5 * i + 1] = x[2 * i + 1];
                        bx[5 * i + 2] = nrm[2 * i];
                        bx[5 * i + 3] = nrm[2 * i + 1];
                        bx[5 * i + 4] = W[i];
                    }
                    memcpy(S->bphi + (size_t)ne * nm * ib, va, sizeof(double) * (size_t)ne * nm);
                    memcpy(S->bdn + (size_t)ne * nm * ib, ga, sizeof(double) * (size_t)ne * nm);
                    if (S->bdir[ib]) {
                        /* Kaa = sig Va^T W Va - (T + T^T), T = Va^T W Ga */
                        weigh(ne, nm, W, va, wva);
                        gemm_tn(nm, ne, sig, wva, va, 0.0, Kaa);
                        gemm_tn(nm, ne, 1.0, wva, ga, 0.0, KT);
                        for (int i = 0; i < nm; ++i)
                            for (int j = 0; j < nm; ++j)
                                Kaa[(size_t)i * nm + j] -=
                                    KT[(size_t)i * nm + j] + KT[(size_t)j * nm + i];
                        if ((st = scatter(S, Kaa, e, e, err)) != SQ_OK) goto fail;
                    }
                    ++ib;
                    continue;
                }
                int kb = -1;
                if ((st = find_back_edge(mesh, e, k, b, &kb, err)) != SQ_OK) goto fail;
                const double *gbn = mesh->gxy + 2 * (size_t)ngn * b;
                /* the neighbour's side, its points reversed, derivatives along
                 * the + side's normal */
                if (edge_side(&E, gbn, kb, nrm, 1, NULL, NULL, Wb, vb, gb) != 0) {
                    st = SQ_FAIL(err, SQ_ERR_USAGE,
                                 "poisson_dg_create: element %d has det J <= 0 on edge %d", b, kb);
                    goto fail;
                }
                const double sig = DG_PENALTY * pp * fmax(len / area[e], len / area[b]);
                /* blocks as products of the tabulations (W the face weights):
                 *   Kaa = sig Va'WVa - (Va'WGa + Ga'WVa)/2
                 *   Kab = -sig Va'WVb - Va'WGb/2 + Ga'WVb/2
                 *   Kbb = sig Vb'WVb + (Vb'WGb + Gb'WVb)/2 */
                weigh(ne, nm, W, va, wva);
                weigh(ne, nm, W, vb, wvb);
                gemm_tn(nm, ne, sig, wva, va, 0.0, Kaa);
                gemm_tn(nm, ne, 1.0, wva, ga, 0.0, KT);
                for (int i = 0; i < nm; ++i)
                    for (int j = 0; j < nm; ++j)
                        Kaa[(size_t)i * nm + j] -=
                            0.5 * (KT[(size_t)i * nm + j] + KT[(size_t)j * nm + i]);
                gemm_tn(nm, ne, -sig, wva, vb, 0.0, Kab);
                gemm_tn(nm, ne, -0.5, wva, gb, 1.0, Kab);
                gemm_tn(nm, ne, 1.0, wvb, ga, 0.0, KT);
                for (int i = 0; i < nm; ++i)
                    for (int j = 0; j < nm; ++j)
                        Kab[(size_t)i * nm + j] += 0.5 * KT[(size_t)j * nm + i];
                gemm_tn(nm, ne, sig, wvb, vb, 0.0, Kbb);
                gemm_tn(nm, ne, 1.0, wvb, gb, 0.0, KT);
                for (int i = 0; i < nm; ++i)
                    for (int j = 0; j < nm; ++j)
                        Kbb[(size_t)i * nm + j] +=
                            0.5 * (KT[(size_t)i * nm + j] + KT[(size_t)j * nm + i]);
                if ((st = scatter(S, Kaa, e, e, err)) != SQ_OK) goto fail;
                if ((st = scatter(S, Kab, e, b, err)) != SQ_OK) goto fail;
                if ((st = scatter(S, Kbb, b, b, err)) != SQ_OK) goto fail;
            }
    }

    if (S->pure_neumann) {
        /* pin the first unknown; keep int_K phi_m for the compatibility
         * projection and the mean */
        if ((st = sem_sparse_add(S->A, 0, 0, 1.0, err)) != SQ_OK) goto fail;
        S->mom = calloc((size_t)S->ndofs, sizeof(double));
        if (!S->mom) {
            st = SQ_FAIL(err, SQ_ERR_INTERNAL, "poisson_dg_create: out of memory");
            goto fail;
        }
        for (int e = 0; e < nt; ++e)
            for (int k = 0; k < nq; ++k) {
                const double wd = S->vx[3 * ((size_t)nq * e + k) + 2];
                for (int m = 0; m < nm; ++m)
                    S->mom[(size_t)e * nm + m] += wd * S->phiq[(size_t)k * nm + m];
            }
    }
    st = sem_sparse_factor(S->A, err);
    if (st == SQ_OK) S->work.factorizations++;

fail: /* success falls through: the work arrays go either way */
    free(lq);
    free(lrq);
    free(lsq);
    free(drq);
    free(dsq);
    free(B);
    free(K);
    free(KT);
    free(area);
    free(fa);
    free(E.ephi);
    free(E.edr);
    free(E.eds);
    free(E.el);
    free(E.elr);
    free(E.els);
    free(et);
    free(ew);
    sem_tri_quad_free(&q);
    sem_tri_lagrange_free(&lag);
    if (st != SQ_OK) {
        dg_free(S);
        return st;
    }
    *ops = &dg_ops;
    *state = S;
    return SQ_OK;
}

static sq_status dg_solve(void *state, const sem_poisson_data *data, sem_field *u, sq_error *err)
{
    dg_state *S = state;
    const sem_tri_mesh *mesh = S->mesh;
    const int nm = S->nm, nq = S->nq, ne = S->ne, nt = mesh->ntris;
    if (!u || u->P != S->P || u->ncomp != 1 || u->nmodes != nm || u->mesh != mesh)
        return SQ_FAIL(err, SQ_ERR_USAGE,
                       "poisson_dg_solve: the field must be of order %d with one component on the "
                       "solver's mesh",
                       S->P);
    double *b = S->rhs;
    memset(b, 0, sizeof(double) * (size_t)S->ndofs);
    double sum_f = 0.0, abs_f = 0.0, sum_g = 0.0, abs_g = 0.0, sum_c = 0.0, abs_c = 0.0;
    if (data && data->f) {
        for (int e = 0; e < nt; ++e) {
            double *be = b + (size_t)e * nm;
            for (int k = 0; k < nq; ++k) {
                const double *v = S->vx + 3 * ((size_t)nq * e + k);
                const double fw = data->f(v, data->f_ctx) * v[2];
                sum_f += fw;
                abs_f += fabs(fw);
                const double *phi = S->phiq + (size_t)k * nm;
                for (int m = 0; m < nm; ++m)
                    be[m] += fw * phi[m];
            }
        }
    }
    if (data && data->g) {
        for (int ib = 0; ib < S->nb; ++ib) {
            const int e = S->bface[2 * ib], k = S->bface[2 * ib + 1];
            const int tag = data->g_by_edge ? 3 * e + k : mesh->btag[3 * e + k];
            const double *bx = S->bx + 5 * (size_t)ne * ib;
            const double *phi = S->bphi + (size_t)ne * nm * ib, *dn = S->bdn + (size_t)ne * nm * ib;
            double *be = b + (size_t)e * nm;
            for (int i = 0; i < ne; ++i) {
                const double gv = data->g(bx + 5 * i, bx + 5 * i + 2, tag, data->g_ctx);
                const double W = bx[5 * i + 4];
                const double *p = phi + (size_t)i * nm, *d = dn + (size_t)i * nm;
                if (S->bdir[ib]) {
                    const double a = W * gv * S->bsig[ib], c = W * gv;
                    for (int m = 0; m < nm; ++m)
                        be[m] += a * p[m] - c * d[m];
                } else {
                    sum_g += W * gv;
                    abs_g += fabs(W * gv);
                    for (int m = 0; m < nm; ++m)
                        be[m] += W * gv * p[m];
                }
            }
        }
    }
    if (data && data->npoints > 0) {
        if (!data->points)
            return SQ_FAIL(err, SQ_ERR_USAGE, "poisson_dg_solve: %d point sources but no array",
                           data->npoints);
        double phi[SEM_MAX_MODES];
        for (int j = 0; j < data->npoints; ++j) {
            const sem_point_source *ps = data->points + j;
            if (ps->elem < 0 || ps->elem >= nt)
                return SQ_FAIL(err, SQ_ERR_USAGE,
                               "poisson_dg_solve: point source %d in element %d outside 0..%d", j,
                               ps->elem, nt - 1);
            sem_tri_dubiner(S->P, ps->r, ps->s, phi, NULL, NULL);
            double *be = b + (size_t)ps->elem * nm;
            for (int m = 0; m < nm; ++m)
                be[m] += ps->strength * phi[m];
            sum_c += ps->strength;
            abs_c += fabs(ps->strength);
        }
    }
    if (S->pure_neumann) {
        const double imb = sum_f + sum_g + sum_c, scale = abs_f + abs_g + abs_c;
        if (fabs(imb) > DG_COMPAT_TOL * scale + 1e-300 && fabs(imb) > 1e-14)
            return SQ_FAIL(err, SQ_ERR_USAGE,
                           "pure Neumann problem with incompatible data: int f + oint g + sum c = "
                           "%.6g (int f = %.6g, oint g = %.6g, sum c = %.6g); it must vanish",
                           imb, sum_f, sum_g, sum_c);
        /* remove the (round-off) imbalance as a uniform source */
        const double a = imb / S->area;
        for (long i = 0; i < S->ndofs; ++i)
            b[i] -= a * S->mom[i];
        b[0] = 0.0;
    }
    SQ_TRY(sem_sparse_solve(S->A, b, b, err));
    if (S->pure_neumann) {
        double mean = 0.0;
        for (long i = 0; i < S->ndofs; ++i)
            mean += b[i] * S->mom[i];
        mean /= S->area;
        /* phi_0 = sqrt(2): the constant 1 has mode-0 coefficient 1/sqrt(2) */
        for (int e = 0; e < nt; ++e)
            b[(size_t)e * nm] -= mean / sqrt(2.0);
    }
    for (long i = 0; i < S->ndofs; ++i)
        u->coef[i] = b[i];
    return SQ_OK;
}
