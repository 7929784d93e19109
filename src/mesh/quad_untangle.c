/* semquad — the vertex mesh made valid before it is relaxed: Laplace
 * smoothing that keeps every quad convex at its corners, boundary vertices
 * sliding on their CAD curve; the vertices the relaxation holds. */
#include "quad_mesher_private.h"

#include <math.h>
#include <stdlib.h>

static double quad_area2(const double *a, const double *b, const double *c)
{
    return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
}

/* Every corner triangle of quad q has positive area. */
int qm_quad_valid(const qm_vmesh *v, int q)
{
    const int *c = &v->quad[4 * q];
    for (int k = 0; k < 4; k++)
        if (!(quad_area2(&v->xy[2 * c[k]], &v->xy[2 * c[(k + 1) % 4]], &v->xy[2 * c[(k + 3) % 4]]) >
              0.0))
            return 0;
    return 1;
}

/* Is xy a corner of the face (a non-smooth vertex, even one inside a
 * single closed edge, such as a trailing edge)? */
static int at_face_corner(const sq_face_info *info, const double xy[2])
{
    double scale = hypot(info->bbox[2] - info->bbox[0], info->bbox[3] - info->bbox[1]);
    for (int c = 0; c < info->nvertices; c++)
        if (!info->vertices[c].smooth &&
            hypot(info->vertices[c].x - xy[0], info->vertices[c].y - xy[1]) < 1e-9 * scale)
            return 1;
    return 0;
}

/* Slide boundary vertex i towards the middle of its two boundary
 * neighbours, staying on the CAD curve: keeps the spacing even where a
 * patch side is made of several layout edges (e.g. across the seam vertex
 * of a closed curve).  Returns the distance moved. */
static double slide(const cad_face *face, qm_vmesh *v, int i, const int nb[2], const int tg[2],
                    const int *adjq, int q0, int q1)
{
    double mid[2] = {0.5 * (v->xy[2 * nb[0]] + v->xy[2 * nb[1]]),
                     0.5 * (v->xy[2 * nb[0] + 1] + v->xy[2 * nb[1] + 1])};
    double best[2] = {mid[0], mid[1]}, bestd = HUGE_VAL;
    for (int k = 0; k < 2; k++) {
        double foot[2], d;
        if (cad_face_edge_project(face, tg[k], mid, NULL, foot, &d, NULL) != SQ_OK) return 0.0;
        if (d < bestd) {
            bestd = d;
            best[0] = foot[0];
            best[1] = foot[1];
        }
    }
    double old[2] = {v->xy[2 * i], v->xy[2 * i + 1]};
    v->xy[2 * i] = best[0];
    v->xy[2 * i + 1] = best[1];
    for (int t = q0; t < q1; t++)
        if (!qm_quad_valid(v, adjq[t])) {
            v->xy[2 * i] = old[0];
            v->xy[2 * i + 1] = old[1];
            return 0.0;
        }
    return hypot(best[0] - old[0], best[1] - old[1]);
}

/* Laplacian smoothing of the free vertices (inside the face, valence 4),
 * a move kept only if every quad around the vertex stays convex at its
 * corners: untangles what the patches' transfinite interpolation folded,
 * so that the relaxation (relax below) starts from a valid mesh. */
sq_status qm_smooth(const cad_face *face, const sq_face_info *info, qm_vmesh *v, const int *keep,
                    sq_error *err)
{
    int *deg = calloc((size_t)v->nv, sizeof(int)), *fixed = calloc((size_t)v->nv, sizeof(int));
    /* boundary neighbours and the CAD edges of the two boundary sides */
    int *bn = malloc(sizeof(int) * 2 * (size_t)v->nv), *bt = malloc(sizeof(int) * 2 * (size_t)v->nv);
    int *nbn = calloc((size_t)v->nv, sizeof(int));
    if (!bn || !bt || !nbn) {
        free(deg);
        free(fixed);
        free(bn);
        free(bt);
        free(nbn);
        return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    }
    int *start = calloc((size_t)v->nv + 1, sizeof(int)), *adjq = malloc(sizeof(int) * 4 * (size_t)v->nq);
    sq_status st = deg && fixed && start && adjq ? SQ_OK : SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    if (st == SQ_OK) {
        for (int q = 0; q < v->nq; q++)
            for (int k = 0; k < 4; k++) {
                deg[v->quad[4 * q + k]]++;
                if (v->side_tag[4 * q + k] >= 0) {
                    int a = v->quad[4 * q + k], b = v->quad[4 * q + (k + 1) % 4];
                    fixed[a] = fixed[b] = 1;
                    if (nbn[a] < 2) bn[2 * a + nbn[a]] = b, bt[2 * a + nbn[a]++] = v->side_tag[4 * q + k];
                    if (nbn[b] < 2) bn[2 * b + nbn[b]] = a, bt[2 * b + nbn[b]++] = v->side_tag[4 * q + k];
                }
            }
        /* boundary vertices that may slide: two quads, two boundary
         * neighbours on the same CAD edge, not a separatrix's foot, not in a
         * boundary layer, not at a corner of the face */
        for (int i = 0; i < v->nv; i++) {
            /* both sides on one CAD edge: an element side must never span
             * two curves (its high-order nodes follow one) */
            if (nbn[i] != 2 || deg[i] != 2 || v->foot[i] || (keep && keep[i]) ||
                bt[2 * i] != bt[2 * i + 1]) {
                nbn[i] = 0;
                continue;
            }
            if (at_face_corner(info, &v->xy[2 * i])) nbn[i] = 0;
        }
        for (int i = 0; i < v->nv; i++) {
            if (deg[i] != 4) fixed[i] = 1; /* singular points stay where the field put them */
            if (keep && keep[i]) fixed[i] = 1;
            start[i + 1] = start[i] + deg[i];
        }
        int *fill = calloc((size_t)v->nv, sizeof(int));
        if (!fill) st = SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
        for (int q = 0; q < v->nq && fill; q++)
            for (int k = 0; k < 4; k++) {
                int a = v->quad[4 * q + k];
                adjq[start[a] + fill[a]++] = q;
            }
        free(fill);
    }
    for (int it = 0; it < 200 && st == SQ_OK; it++) {
        double moved = 0.0;
        for (int i = 0; i < v->nv; i++) {
            if (fixed[i]) continue;
            /* average of the edge neighbours: in each quad, the two corners
             * adjacent to i (each counted twice over its two quads) */
            double sx = 0.0, sy = 0.0;
            for (int t = start[i]; t < start[i + 1]; t++) {
                const int *c = &v->quad[4 * adjq[t]];
                int k = 0;
                while (c[k] != i) k++;
                sx += v->xy[2 * c[(k + 1) % 4]] + v->xy[2 * c[(k + 3) % 4]];
                sy += v->xy[2 * c[(k + 1) % 4] + 1] + v->xy[2 * c[(k + 3) % 4] + 1];
            }
            double n = 2.0 * (start[i + 1] - start[i]), old[2] = {v->xy[2 * i], v->xy[2 * i + 1]};
            v->xy[2 * i] = sx / n;
            v->xy[2 * i + 1] = sy / n;
            int ok = 1;
            for (int t = start[i]; t < start[i + 1] && ok; t++) ok = qm_quad_valid(v, adjq[t]);
            if (!ok) {
                v->xy[2 * i] = old[0];
                v->xy[2 * i + 1] = old[1];
            } else {
                moved = fmax(moved, hypot(v->xy[2 * i] - old[0], v->xy[2 * i + 1] - old[1]));
            }
        }
        for (int i = 0; i < v->nv; i++)
            if (nbn[i] == 2) moved = fmax(moved, slide(face, v, i, &bn[2 * i], &bt[2 * i], adjq, start[i], start[i + 1]));
        if (moved < 1e-12) break;
    }
    free(bn);
    free(bt);
    free(nbn);
    free(deg);
    free(fixed);
    free(start);
    free(adjq);
    return st;
}

/* Each vertex's quads (deg) and whether it is on the boundary (bnd), nv
 * flags each. */
static void vertex_roles(const qm_vmesh *v, int *deg, int *bnd)
{
    for (int q = 0; q < v->nq; q++)
        for (int k = 0; k < 4; k++) {
            deg[v->quad[4 * q + k]]++;
            if (v->side_tag[4 * q + k] >= 0)
                bnd[v->quad[4 * q + k]] = bnd[v->quad[4 * q + (k + 1) % 4]] = 1;
        }
}

/* The vertices the relaxation holds (nv + 1 flags, NULL when out of
 * memory): keep, the face's corners and, unless move_singular, the
 * interior vertices of valence other than 4. */
static int *held_vertices(const sq_face_info *info, const qm_vmesh *v, const int *keep,
                          int move_singular)
{
    int *deg = calloc((size_t)v->nv + 1, sizeof(int)), *bnd = calloc((size_t)v->nv + 1, sizeof(int));
    int *fixed = calloc((size_t)v->nv + 1, sizeof(int));
    if (deg && bnd && fixed) {
        vertex_roles(v, deg, bnd);
        for (int i = 0; i < v->nv; i++)
            fixed[i] = (keep && keep[i]) || (!bnd[i] && deg[i] != 4 && !move_singular) ||
                       (bnd[i] && at_face_corner(info, &v->xy[2 * i]));
    } else {
        free(fixed);
        fixed = NULL;
    }
    free(deg);
    free(bnd);
    return fixed;
}

int qm_has_free_singular(const qm_vmesh *v, const int *keep)
{
    int *deg = calloc((size_t)v->nv + 1, sizeof(int)), *bnd = calloc((size_t)v->nv + 1, sizeof(int));
    int found = !deg || !bnd; /* out of memory: as if there were one (both attempts run) */
    if (!found) vertex_roles(v, deg, bnd);
    for (int i = 0; i < v->nv && !found; i++)
        found = !bnd[i] && deg[i] != 4 && !(keep && keep[i]);
    free(deg);
    free(bnd);
    return found;
}

/* Design 3b: the whole vertex mesh relaxed towards an orthogonal map
 * (quad_relax.h); what stays: singular points (interior vertices of valence
 * other than 4), the face's corners and the boundary layers.  With the
 * singular points free the relaxation gives up once it folds a curved
 * boundary quad (*folded): the attempt with them held follows.  With the
 * user's sizes (opt->sizes) the quads keep the grid's grading.  untangle:
 * sq_quad_untangle instead, the singular points free (*folded: corners
 * still not convex). */
sq_status qm_relax(const cad_face *face, const sq_face_info *info, qm_vmesh *v, const int *keep,
                   int move_singular, int untangle, const sq_mesher_options *opt,
                   sq_relax_work **work, int *folded, sq_error *err)
{
    int *fixed = held_vertices(info, v, keep, move_singular || untangle);
    if (!fixed) return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    double far = sq_mesher_size(opt, info->area);
    sq_relax_mesh rm = {v->nv,         v->nq, v->xy,          v->quad,          v->side_tag, fixed,
                        move_singular, 0,     opt->progress, opt->sizes, far};
    sq_status st = untangle ? sq_quad_untangle(face, &rm, work, err) : sq_quad_relax(face, &rm, work, err);
    *folded = rm.folded;
    free(fixed);
    return st;
}
