/* semquad sem/ — point location on a curved triangle mesh (see locate.h).
 *
 * design:
 *  1. modal geometry of every element (dg_modal.h): x(r,s) and J cost one
 *     Dubiner recurrence of the geometry order;
 *  2. affine elements (all modes above degree 1 zero) are inverted in
 *     closed form; on the others Newton starts from the inverse of the
 *     straight-sided triangle through the vertices;
 *  3. bounding box of each element: its vertices' if affine, else from its
 *     map on a lattice of order 2*order + 2; enlarged by 2% of its diagonal
 *     (the map between samples bulges by far less for any valid element);
 *  4. a uniform grid of about one cell per element over the mesh box; each
 *     cell lists the elements whose box meets it (compressed rows);
 *  5. find: walk from the hint (Newton in the current element; step across
 *     the edge whose barycentric coordinate is most negative), fall back to
 *     the grid cell of the point if the walk leaves the mesh, stalls or
 *     runs too long. */
#include "locate.h"

#include "dg_modal.h"
#include "tri_nodes.h"

#include <math.h>
#include <stdlib.h>

#define LOC_NEWTON_MAX 40
#define LOC_FAR 4.0 /* |r|,|s| beyond which Newton is abandoned */

struct sem_locator {
    const sem_tri_mesh *mesh;
    int go, ngm;
    sem_dubiner_tab tab; /* geometry order */
    double *gm;          /* 2*ngm*ntris modal geometry */
    double *aff;         /* 6*ntris: x0, y0 and J^{-1} (row-major) of the map if affine, else of the
                            straight-sided triangle through the vertices (Newton's start) */
    unsigned char *is_aff;
    double *ebox; /* 4*ntris: xmin, xmax, ymin, ymax */
    double x0, y0, cw, ch;
    int nx, ny;
    int *cstart; /* nx*ny + 1 */
    int *celem;
    int maxwalk;
};

const sem_tri_mesh *sem_locator_mesh(const sem_locator *loc) { return loc->mesh; }
const double *sem_locator_modal_geometry(const sem_locator *loc) { return loc->gm; }

double sem_locator_map(const sem_locator *loc, int e, double r, double s, double x[2],
                       double jac[4])
{
    double phi[SEM_MAX_MODES], dr[SEM_MAX_MODES], ds[SEM_MAX_MODES];
    sem_dubiner_tab_eval(&loc->tab, r, s, phi, dr, ds);
    return sem_modal_map(loc->ngm, loc->gm + 2 * (size_t)loc->ngm * e, phi, dr, ds, x, jac);
}

int sem_locator_invert(const sem_locator *loc, int e, const double xy[2], double rs[2])
{
    if (loc->is_aff[e]) {
        const double *a = loc->aff + 6 * (size_t)e;
        const double dx = xy[0] - a[0], dy = xy[1] - a[1];
        rs[0] = a[2] * dx + a[3] * dy;
        rs[1] = a[4] * dx + a[5] * dy;
        return 0;
    }
    /* start from the inverse of the straight-sided triangle through the
     * vertices: on a curved element near the point it is a few rounds of
     * Newton closer than the centroid */
    const double *a = loc->aff + 6 * (size_t)e;
    const double dx = xy[0] - a[0], dy = xy[1] - a[1];
    double r = a[2] * dx + a[3] * dy, s = a[4] * dx + a[5] * dy, prev = HUGE_VAL;
    if (!(fabs(r) < LOC_FAR && fabs(s) < LOC_FAR && isfinite(r) && isfinite(s))) r = s = 1.0 / 3.0;
    for (int it = 0; it < LOC_NEWTON_MAX; ++it) {
        double x[2], J[4];
        const double det = sem_locator_map(loc, e, r, s, x, J);
        if (!(det != 0.0)) break;
        const double fx = xy[0] - x[0], fy = xy[1] - x[1];
        const double d0 = (J[3] * fx - J[1] * fy) / det, d1 = (-J[2] * fx + J[0] * fy) / det;
        r += d0;
        s += d1;
        /* Converged, or stalled at round-off: on a small element far from
         * the origin the coordinates' rounding alone is above 1e-13 in
         * reference units, so a step that no longer halves is the end. */
        const double step = fabs(d0) + fabs(d1);
        if (step < 1e-13 || (step < 1e-9 && step > 0.5 * prev)) {
            rs[0] = r;
            rs[1] = s;
            return 0;
        }
        prev = step;
        if (!(fabs(r) < LOC_FAR && fabs(s) < LOC_FAR)) break;
    }
    rs[0] = r;
    rs[1] = s;
    return 1;
}

void sem_locator_free(sem_locator **loc)
{
    if (!loc || !*loc) return;
    sem_locator *L = *loc;
    free(L->gm);
    free(L->aff);
    free(L->is_aff);
    free(L->ebox);
    free(L->cstart);
    free(L->celem);
    free(L);
    *loc = NULL;
}

static int clampi(long v, int lo, int hi) { return v < lo ? lo : v > hi ? hi : (int)v; }

/* The geometry's modes at the points (i, j)/ns, i + j <= ns, of the
 * lattice of order ns = 2 go + 2 that samples curved elements, mode by mode
 * (lat[m nlat + k]): tabulated once for all of them.  Only the values: the
 * boxes need the positions alone (a third of the table: it stays below
 * malloc's mmap threshold, no fresh pages to fault in per locator). */
static double *lattice_modes(const sem_locator *L, int nlat)
{
    const int ns = 2 * L->go + 2, ngm = L->ngm;
    double *lat = malloc(sizeof(double) * (size_t)ngm * nlat);
    if (!lat) return NULL;
    int k = 0;
    for (int j = 0; j <= ns; ++j)
        for (int i = 0; i + j <= ns; ++i, ++k) {
            double phi[SEM_MAX_MODES];
            sem_dubiner_tab_eval(&L->tab, (double)i / ns, (double)j / ns, phi, NULL, NULL);
            for (int m = 0; m < ngm; ++m) lat[(size_t)m * nlat + k] = phi[m];
        }
    return lat;
}

/* Grow box b by element e's map on the lattice; nonzero if a point is not
 * finite.  The positions are sem_locator_map's sums, in its mode order
 * (sem_map_points); xy: 2 nlat doubles of work space. */
static int curved_box(const sem_locator *L, int e, const double *lat, int nlat, double *xy,
                      double b[4])
{
    const double *X = xy, *Y = xy + nlat;
    sem_map_points(L->ngm, L->gm + 2 * (size_t)L->ngm * e, lat, nlat, xy, xy + nlat);
    for (int k = 0; k < nlat; ++k) {
        if (!(isfinite(X[k]) && isfinite(Y[k]))) return 1;
        b[0] = fmin(b[0], X[k]);
        b[1] = fmax(b[1], X[k]);
        b[2] = fmin(b[2], Y[k]);
        b[3] = fmax(b[3], Y[k]);
    }
    return 0;
}

sq_status sem_locator_create(const sem_tri_mesh *mesh, sem_locator **out, sq_error *err)
{
    if (!out) return SQ_FAIL(err, SQ_ERR_USAGE, "locator_create: NULL output");
    *out = NULL;
    if (!mesh || mesh->ntris < 1) return SQ_FAIL(err, SQ_ERR_USAGE, "locator_create: empty mesh");
    const int nt = mesh->ntris;
    sem_locator *L = calloc(1, sizeof *L);
    if (!L) return SQ_FAIL(err, SQ_ERR_INTERNAL, "locator_create: out of memory");
    sq_status st;
    double *lat = NULL, *xy = NULL;
    L->mesh = mesh;
    L->go = mesh->order;
    L->ngm = sem_tri_num_nodes(L->go);
    sem_dubiner_tab_init(&L->tab, L->go);
    if ((st = sem_modal_geometry(mesh, &L->gm, err)) != SQ_OK) goto fail;
    L->aff = malloc(sizeof(double) * 6 * (size_t)nt);
    L->is_aff = calloc((size_t)nt, 1);
    L->ebox = malloc(sizeof(double) * 4 * (size_t)nt);
    if (!L->aff || !L->is_aff || !L->ebox) {
        st = SQ_FAIL(err, SQ_ERR_INTERNAL, "locator_create: out of memory (%d elements)", nt);
        goto fail;
    }
    const int nlat = sem_tri_num_nodes(2 * L->go + 2); /* sample lattice of curved elements */
    if (!(lat = lattice_modes(L, nlat)) || !(xy = malloc(sizeof(double) * 2 * (size_t)nlat))) {
        st = SQ_FAIL(err, SQ_ERR_INTERNAL, "locator_create: out of memory");
        goto fail;
    }
    double bx0 = HUGE_VAL, bx1 = -HUGE_VAL, by0 = HUGE_VAL, by1 = -HUGE_VAL;
    for (int e = 0; e < nt; ++e) {
        double *b = L->ebox + 4 * (size_t)e;
        /* the vertices, their box, and the map's derivative at vertex 0 */
        double xv[3][2], J[4];
        const double det = sem_locator_map(L, e, 0.0, 0.0, xv[0], J);
        sem_locator_map(L, e, 1.0, 0.0, xv[1], NULL);
        sem_locator_map(L, e, 0.0, 1.0, xv[2], NULL);
        b[0] = fmin(xv[0][0], fmin(xv[1][0], xv[2][0]));
        b[1] = fmax(xv[0][0], fmax(xv[1][0], xv[2][0]));
        b[2] = fmin(xv[0][1], fmin(xv[1][1], xv[2][1]));
        b[3] = fmax(xv[0][1], fmax(xv[1][1], xv[2][1]));
        if (!(isfinite(b[0]) && isfinite(b[1]) && isfinite(b[2]) && isfinite(b[3]))) {
            st = SQ_FAIL(err, SQ_ERR_USAGE, "locator_create: element %d has non-finite nodes", e);
            goto fail;
        }
        /* affine: every mode of degree >= 2 negligible against the size */
        const double *g = L->gm + 2 * (size_t)L->ngm * e;
        double hi = 0.0;
        for (int q = 0; q <= L->go; ++q)
            for (int p = 0; p + q <= L->go; ++p)
                if (p + q >= 2) {
                    const int m = sem_tri_node_index(L->go, p, q);
                    hi = fmax(hi, fmax(fabs(g[2 * m]), fabs(g[2 * m + 1])));
                }
        double *a = L->aff + 6 * (size_t)e;
        a[0] = xv[0][0];
        a[1] = xv[0][1];
        if (hi <= 1e-14 * (b[1] - b[0] + b[3] - b[2]) && det != 0.0) {
            /* the box of a straight-sided triangle is its vertices' */
            a[2] = J[3] / det;
            a[3] = -J[1] / det;
            a[4] = -J[2] / det;
            a[5] = J[0] / det;
            L->is_aff[e] = 1;
        } else {
            if (curved_box(L, e, lat, nlat, xy, b)) {
                st = SQ_FAIL(err, SQ_ERR_USAGE, "locator_create: element %d has non-finite nodes",
                             e);
                goto fail;
            }
            /* Newton's start: the straight-sided triangle through the vertices */
            const double j0 = xv[1][0] - xv[0][0], j1 = xv[2][0] - xv[0][0],
                         j2 = xv[1][1] - xv[0][1], j3 = xv[2][1] - xv[0][1], d = j0 * j3 - j1 * j2;
            a[2] = j3 / d;
            a[3] = -j1 / d;
            a[4] = -j2 / d;
            a[5] = j0 / d;
        }
        const double pad = 0.02 * hypot(b[1] - b[0], b[3] - b[2]) + 1e-300;
        b[0] -= pad;
        b[1] += pad;
        b[2] -= pad;
        b[3] += pad;
        bx0 = fmin(bx0, b[0]);
        bx1 = fmax(bx1, b[1]);
        by0 = fmin(by0, b[2]);
        by1 = fmax(by1, b[3]);
    }
    free(lat);
    free(xy);
    lat = xy = NULL;
    /* grid of about one cell per element */
    const double W = bx1 - bx0, H = by1 - by0;
    L->nx = clampi(lround(ceil(sqrt((double)nt * W / H))), 1, 4096);
    L->ny = clampi(lround(ceil((double)nt / L->nx)), 1, 4096);
    L->x0 = bx0;
    L->y0 = by0;
    L->cw = W / L->nx;
    L->ch = H / L->ny;
    const size_t nc = (size_t)L->nx * L->ny;
    L->cstart = calloc(nc + 1, sizeof(int));
    if (!L->cstart) {
        st = SQ_FAIL(err, SQ_ERR_INTERNAL, "locator_create: out of memory");
        goto fail;
    }
    for (int pass = 0; pass < 2; ++pass) {
        for (int e = 0; e < nt; ++e) {
            const double *b = L->ebox + 4 * (size_t)e;
            const int i0 = clampi((long)floor((b[0] - L->x0) / L->cw), 0, L->nx - 1);
            const int i1 = clampi((long)floor((b[1] - L->x0) / L->cw), 0, L->nx - 1);
            const int j0 = clampi((long)floor((b[2] - L->y0) / L->ch), 0, L->ny - 1);
            const int j1 = clampi((long)floor((b[3] - L->y0) / L->ch), 0, L->ny - 1);
            for (int j = j0; j <= j1; ++j)
                for (int i = i0; i <= i1; ++i) {
                    const size_t c = (size_t)j * L->nx + i;
                    if (pass == 0)
                        ++L->cstart[c + 1];
                    else
                        L->celem[L->cstart[c]++] = e;
                }
        }
        if (pass == 0) {
            for (size_t c = 0; c < nc; ++c) L->cstart[c + 1] += L->cstart[c];
            L->celem = malloc(sizeof(int) * ((size_t)L->cstart[nc] + 1));
            if (!L->celem) {
                st = SQ_FAIL(err, SQ_ERR_INTERNAL, "locator_create: out of memory");
                goto fail;
            }
        } else {
            /* cstart[c] now holds the end of cell c: shift back */
            for (size_t c = nc; c > 0; --c) L->cstart[c] = L->cstart[c - 1];
            L->cstart[0] = 0;
        }
    }
    L->maxwalk = 16 + 4 * (int)sqrt((double)nt);
    *out = L;
    return SQ_OK;
fail:
    free(lat);
    free(xy);
    sem_locator_free(&L);
    return st;
}

/* Grid search. */
static int find_grid(const sem_locator *L, const double xy[2], int *elem, double *r, double *s)
{
    const double fx = (xy[0] - L->x0) / L->cw, fy = (xy[1] - L->y0) / L->ch;
    if (!(fx >= 0.0 && fy >= 0.0 && fx <= L->nx && fy <= L->ny)) return 1;
    const int i = fx >= L->nx ? L->nx - 1 : (int)fx, j = fy >= L->ny ? L->ny - 1 : (int)fy;
    const size_t c = (size_t)j * L->nx + i;
    for (int k = L->cstart[c]; k < L->cstart[c + 1]; ++k) {
        const int e = L->celem[k];
        const double *b = L->ebox + 4 * (size_t)e;
        if (xy[0] < b[0] || xy[0] > b[1] || xy[1] < b[2] || xy[1] > b[3]) continue;
        double rs[2];
        if (sem_locator_invert(L, e, xy, rs) == 0 && sem_locator_inside(rs[0], rs[1])) {
            *elem = e;
            *r = rs[0];
            *s = rs[1];
            return 0;
        }
    }
    return 1;
}

int sem_locator_find(const sem_locator *L, const double xy[2], int hint, int *elem, double *r,
                     double *s)
{
    if (!(isfinite(xy[0]) && isfinite(xy[1]))) return 1;
    const sem_tri_mesh *M = L->mesh;
    if (hint >= 0 && hint < M->ntris) {
        int e = hint, prev = -1;
        for (int step = 0; step < L->maxwalk; ++step) {
            double rs[2];
            const int conv = sem_locator_invert(L, e, xy, rs) == 0;
            const double l0 = 1.0 - rs[0] - rs[1], l1 = rs[0], l2 = rs[1];
            if (conv && sem_locator_inside(rs[0], rs[1])) {
                *elem = e;
                *r = rs[0];
                *s = rs[1];
                return 0;
            }
            if (!conv && l0 >= 0 && l1 >= 0 && l2 >= 0) break; /* no direction: use the grid */
            /* edge 0 is s = 0 (l2), edge 1 is r + s = 1 (l0), edge 2 is r = 0 (l1) */
            int k = 0;
            double lm = l2;
            if (l0 < lm) lm = l0, k = 1;
            if (l1 < lm) lm = l1, k = 2;
            const int nb = M->neigh[3 * e + k];
            if (nb < 0 || nb == prev) break;
            prev = e;
            e = nb;
        }
    }
    return find_grid(L, xy, elem, r, s);
}
