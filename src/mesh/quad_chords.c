/* semquad — chord quantization (quad_mesher.h design 1): segments per layout
 * edge from its length, or its measure in units of the field's size e^H, and
 * the boundary layers' segments; opposite sides of every patch matched. */
#include "quad_mesher_private.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define MAX_SEGMENTS 1000000 /* per edge: quantization that runs away is a bug */

/* Segments on side k of patch p. */
long qm_side_count(const sq_layout_patch *p, int k, const int *n)
{
    long c = 0;
    for (int h = p->side_start[k]; h < p->side_start[k + 1]; h++) c += n[p->half[h].edge];
    return c;
}

/* Quads of a quantization: the product of each patch's two side counts. */
double qm_quantized_quads(const sq_layout *L, const int *n)
{
    double quads = 0.0;
    for (int q = 0; q < L->npatches; q++)
        quads += (double)qm_side_count(&L->patches[q], 0, n) *
                 (double)qm_side_count(&L->patches[q], 1, n);
    return quads;
}

/* Segments an edge of measure len needs at size `size`. */
static int edge_segments(double len, double size)
{
    long v = lround(len / size);
    return (int)fmin((double)(v < 1 ? 1 : v), MAX_SEGMENTS);
}

/* Sub-intervals per sample where the user's size field is read: the
 * trapezoid rule's error on 1/h, (len/256)^2/12 |(1/h)''| per unit length,
 * stays far below a cell wherever h varies by the gradation's bound. */
#define USER_SIZE_SUB 8

/* The integrands at arc fraction t of edge e: *place = size / h(x,
 * tangent) where the user set sizes or boundary layers (1 elsewhere), so
 * that the integral of *place along the edge is its measure in units of
 * size; *count = *place / the field's size where it carries one (e^H,
 * bounded and scaled: cross_field.h). */
static sq_status measure_weight(const sq_layout *L, const cad_face *face,
                                const sq_mesher_options *o, double size, int e, double t,
                                int *elem, double *place, double *count, sq_error *err)
{
    double x[2], sz;
    *place = *count = 1.0;
    if (!(o->field && o->field->size) && !o->sizes) return SQ_OK;
    SQ_TRY(sq_layout_edge_point(L, face, e, t, x, err));
    if (o->sizes) {
        /* the tangent by a central difference, one-sided at the ends: read
         * only by boundary layers' walls */
        double a[2], b[2], dt = 1.0 / 4096.0, t0 = fmax(t - dt, 0.0), t1 = fmin(t + dt, 1.0);
        double tg[2] = {0.0, 0.0};
        if (o->nbl > 0) {
            SQ_TRY(sq_layout_edge_point(L, face, e, t0, a, err));
            SQ_TRY(sq_layout_edge_point(L, face, e, t1, b, err));
            tg[0] = b[0] - a[0], tg[1] = b[1] - a[1];
        }
        *place = *count = size / sq_size_field_eval_dir(o->sizes, x, tg, size);
    }
    if (o->field && o->field->size && (sz = o->field->size(o->field->ctx, x, elem)) > 0.0)
        *count /= sz;
    return SQ_OK;
}

int qm_size_samples(const sq_mesher_options *o)
{
    return o->nbl > 0 ? SIZE_SAMPLES_BL : SIZE_SAMPLES;
}

/* Edge measure in units of the target size: m[e] = the integral of
 * size ds / (s(x) h(x, t)) along edge e, s the field's size (e^H) and h
 * the user's (its length with neither), which counts its segments, and the
 * cumulative values of the integral of size ds / h(x, t) at
 * qm_size_samples + 1 equal arc-length fractions, which place its
 * vertices.  Only the count follows s: the relaxation's energy knows
 * the user's sizes but not e^H, and vertices spaced by e^H were moved
 * back by up to a cell and a half (the disc at --size 0.025: 10 Newton
 * steps and 5 factorizations from there, 7 and 2 from even spacing, to
 * the same optimum). */
sq_status qm_size_measure(const sq_layout *L, const cad_face *face,
                          const sq_mesher_options *o, double *m, double *cum, sq_error *err)
{
    double size = sq_mesher_size(o, L->face_area);
    int S = qm_size_samples(o), sub = o->sizes ? USER_SIZE_SUB : 1, ns = S * sub;
    for (int e = 0; e < L->nedges; e++) {
        double *c = &cum[(size_t)e * (S + 1)], prev = 1.0, r = 1.0, cprev = 1.0, cr = 1.0;
        double count = 0.0;
        int elem = -1;
        c[0] = 0.0;
        SQ_TRY(measure_weight(L, face, o, size, e, 0.0, &elem, &prev, &cprev, err));
        for (int k = 1; k <= S; k++) {
            double acc = c[k - 1];
            for (int j = (k - 1) * sub + 1; j <= k * sub; j++) {
                SQ_TRY(measure_weight(L, face, o, size, e, (double)j / ns, &elem, &r, &cr, err));
                acc += 0.5 * (prev + r) * L->edges[e].length / ns;
                count += 0.5 * (cprev + cr) * L->edges[e].length / ns;
                prev = r;
                cprev = cr;
            }
            c[k] = acc;
        }
        m[e] = count;
    }
    return SQ_OK;
}

/* Arc-length fraction where the cumulative measure cum[S + 1] reaches
 * fraction u. */
double qm_measure_fraction(const double *cum, int S, double u)
{
    double target = u * cum[S];
    int k = 0;
    while (k < S - 1 && cum[k + 1] < target) k++;
    double d = cum[k + 1] - cum[k];
    return (k + (d > 0.0 ? (target - cum[k]) / d : 0.0)) / S;
}

void qm_periodic_partners(const sq_layout *L, const cad_face *face, const sq_mesher_options *o,
                          double size, int *partner)
{
    for (int e = 0; e < L->nedges; e++) partner[e] = -1;
    for (int k = 0; k < o->periodic.npairs; k++) {
        const sq_identified_pair *p = &o->periodic.pairs[k];
        const double La = cad_face_edge_length(face, p->a), Lb = cad_face_edge_length(face, p->b);
        for (int e = 0; e < L->nedges; e++) {
            const sq_layout_edge *E = &L->edges[e];
            if (E->cad_edge != p->a) continue;
            /* b at L_b − s is T(a at s): the piece [s0, s1] maps to [L_b − s1, L_b − s0] */
            const double t0 = Lb * (1.0 - E->s1 / La), t1 = Lb * (1.0 - E->s0 / La);
            for (int f = 0; f < L->nedges; f++) {
                const sq_layout_edge *F = &L->edges[f];
                if (F->cad_edge != p->b || partner[f] >= 0 ||
                    fabs(F->s0 - t0) > SQ_IDENTIFIED_CROSSING_REL_TOL * size || fabs(F->s1 - t1) > SQ_IDENTIFIED_CROSSING_REL_TOL * size)
                    continue;
                partner[e] = f, partner[f] = e;
                break;
            }
        }
    }
}

/* Opposite sides of every patch matched (and a piece and its partner one
 * count): each short side's coarsest edge raised until nothing changes,
 * an edge marked in avoid (may be NULL) only where the whole side is. */
static sq_status settle(const sq_layout *L, const double *len, double size, const double *need,
                        const int *partner, const char *avoid, int *n, sq_error *err)
{
    for (int changed = 1; changed;) {
        changed = 0;
        /* a piece of an identified edge and its image: one count, the larger */
        for (int e = 0; partner && e < L->nedges; e++)
            if (partner[e] > e && n[e] != n[partner[e]]) {
                n[e] = n[partner[e]] = n[e] > n[partner[e]] ? n[e] : n[partner[e]];
                changed = 1;
            }
        for (int q = 0; q < L->npatches; q++) {
            const sq_layout_patch *p = &L->patches[q];
            for (int k = 0; k < 2; k++) {
                long a = qm_side_count(p, k, n), c = qm_side_count(p, k + 2, n);
                /* a refinement inside the patch: side k raised to what its
                 * interior needs, side k + 2 matched below */
                long want = need ? lround(need[2 * q + k] / size) : 0;
                if (want > a && want > c) c = want;
                if (a == c) continue;
                int s = a < c ? k : k + 2, best = -1, best_avoided = 1;
                double ratio = -1.0;
                for (int h = p->side_start[s]; h < p->side_start[s + 1]; h++) {
                    int e = p->half[h].edge, avoided = avoid && avoid[e];
                    double r = len[e] / n[e];
                    if (avoided < best_avoided || (avoided == best_avoided && r > ratio)) {
                        ratio = r;
                        best = e;
                        best_avoided = avoided;
                    }
                }
                n[best] += (int)labs(a - c);
                if (n[best] > MAX_SEGMENTS)
                    return SQ_FAIL(err, SQ_ERR_LAYOUT,
                                   "chord quantization does not settle (patch %d): the layout's "
                                   "chords are inconsistent", q);
                changed = 1;
            }
        }
    }
    return SQ_OK;
}

/* Segments on CAD edge t: the sum over its layout edges. */
static long cad_edge_count(const sq_layout *L, int t, const int *n)
{
    long c = 0;
    for (int e = 0; e < L->nedges; e++)
        if (L->edges[e].cad_edge == t) c += n[e];
    return c;
}

/* The pairs' imbalance: the sum over pairs of |total on a - total on b|. */
static long slid_imbalance(const sq_layout *L, const sq_identification *id, const int *n)
{
    long d = 0;
    for (int k = 0; k < id->npairs; k++)
        d += labs(cad_edge_count(L, id->pairs[k].a, n) - cad_edge_count(L, id->pairs[k].b, n));
    return d;
}

/* avoid[e]: layout edge e lies on the longer curve of a pair of id whose
 * totals differ in n. */
static void longer_curves(const sq_layout *L, const sq_identification *id, const int *n,
                          char *avoid)
{
    memset(avoid, 0, (size_t)L->nedges + 1);
    for (int k = 0; k < id->npairs; k++) {
        const long na = cad_edge_count(L, id->pairs[k].a, n), nb = cad_edge_count(L, id->pairs[k].b, n);
        const int longer = na > nb ? id->pairs[k].a : id->pairs[k].b;
        for (int e = 0; na != nb && e < L->nedges; e++) avoid[e] |= L->edges[e].cad_edge == longer;
    }
}

/* Is layout edge e on the shorter curve of a pair of id whose totals
 * differ in n? */
static int on_shorter_curve(const sq_layout *L, const sq_identification *id, const int *n, int e)
{
    for (int k = 0; k < id->npairs; k++) {
        const long na = cad_edge_count(L, id->pairs[k].a, n), nb = cad_edge_count(L, id->pairs[k].b, n);
        if (na != nb && L->edges[e].cad_edge == (na < nb ? id->pairs[k].a : id->pairs[k].b))
            return 1;
    }
    return 0;
}

typedef struct {
    const sq_layout *L;
    const double *len, *need;
    double size;
    const sq_identification *id;
    char *avoid; /* L->nedges + 1 */
} totals_ctx;

/* out = from with layout edge e raised by one and settled, the raise kept
 * off the longer curves of from's unbalanced pairs where a patch side
 * allows (there it would undo itself: the sheet from the short curve
 * ending on its partner). */
static sq_status raise_one(const totals_ctx *c, const int *from, int e, int *out, sq_error *err)
{
    longer_curves(c->L, c->id, from, c->avoid);
    memcpy(out, from, sizeof(int) * (size_t)c->L->nedges);
    out[e]++;
    return settle(c->L, c->len, c->size, c->need, NULL, c->avoid, out, err);
}

/* The best admissible move from n of one raise (depth 1) or two (depth 2,
 * each on a shorter curve when it is made): the pairs' imbalance falls
 * below d, fewest quads added, the lowest edges at a tie; *best = -1 when
 * none.  Two raises are needed where the sheets of a patch side reach two
 * pairs' curves: raising the short curve of one moves the imbalance to the
 * other, whose short curve the second raise evens. */
static sq_status best_move(const totals_ctx *c, const int *n, long d, int depth, int *t1, int *t2,
                           int best[2], sq_error *err)
{
    const sq_layout *L = c->L;
    double best_quads = HUGE_VAL, quads = qm_quantized_quads(L, n);
    best[0] = best[1] = -1;
    for (int e = 0; e < L->nedges; e++) {
        if (!on_shorter_curve(L, c->id, n, e)) continue;
        SQ_TRY(raise_one(c, n, e, t1, err));
        for (int f = depth == 1 ? -1 : 0; f < (depth == 1 ? 0 : L->nedges); f++) {
            if (f >= 0 && !on_shorter_curve(L, c->id, t1, f)) continue;
            if (f >= 0) SQ_TRY(raise_one(c, t1, f, t2, err));
            const int *t = f >= 0 ? t2 : t1;
            const double added = qm_quantized_quads(L, t) - quads;
            if (slid_imbalance(L, c->id, t) < d && added < best_quads)
                best_quads = added, best[0] = e, best[1] = f;
        }
    }
    return SQ_OK;
}

/* Route 1b (docs/domains.md, "one total per curve"): the two curves of
 * every pair of o->slid carry one total count.  The face's own layout has
 * no partner pieces, so only totals are matched: an integer problem,
 * solved greedily and deterministically.  While some pair differs, every
 * layout edge on the shorter curve of such a pair is tried raised by one
 * and the quantization settled again (the raise runs along its sheet to
 * wherever the sheet ends, kept off the longer curves where a patch side
 * allows); a try is admissible when the pairs' total imbalance falls, and
 * the one adding the fewest quads (the least change of size) is kept, the
 * lowest edge index at a tie.  Where no single raise is admissible, two in
 * a row are tried (best_move).  None admissible: SQ_ERR_LAYOUT (every
 * sheet from the short curve ends on its partner too). */
static sq_status equal_totals(const sq_layout *L, const double *len, double size,
                              const double *need, const sq_identification *id, int *n,
                              sq_error *err)
{
    const size_t ne = (size_t)L->nedges + 1;
    int *t1 = malloc(sizeof(int) * ne), *t2 = malloc(sizeof(int) * ne);
    char *avoid = malloc(ne);
    totals_ctx c = {L, len, need, size, id, avoid};
    sq_status st = t1 && t2 && avoid ? SQ_OK : SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    for (long d = slid_imbalance(L, id, n); d > 0 && st == SQ_OK; d = slid_imbalance(L, id, n)) {
        int best[2] = {-1, -1};
        for (int depth = 1; depth <= 2 && best[0] < 0 && st == SQ_OK; depth++)
            st = best_move(&c, n, d, depth, t1, t2, best, err);
        if (st == SQ_OK && best[0] < 0) {
            int k = 0;
            while (cad_edge_count(L, id->pairs[k].a, n) == cad_edge_count(L, id->pairs[k].b, n)) k++;
            const sq_identified_pair *p = &id->pairs[k];
            const long na = cad_edge_count(L, p->a, n), nb = cad_edge_count(L, p->b, n);
            st = SQ_FAIL(err, SQ_ERR_LAYOUT,
                         "periodic edges %d and %d: %ld and %ld segments, and every sheet of the "
                         "layout from edge %d ends on edge %d or another pair's longer curve too: "
                         "no raise evens them",
                         p->a, p->b, na, nb, na < nb ? p->a : p->b, na < nb ? p->b : p->a);
        }
        if (st == SQ_OK) st = raise_one(&c, n, best[0], t1, err);
        if (st == SQ_OK && best[1] >= 0) st = raise_one(&c, t1, best[1], n, err);
        else if (st == SQ_OK) memcpy(n, t1, sizeof(int) * (size_t)L->nedges);
    }
    free(t1), free(t2), free(avoid);
    return st;
}

/* Faces of a domain (docs/domains.md): a shared curve split by this
 * face's layout into pieces still carries the count the face across asks
 * (min_chords), so their meshes can meet on it.  While some such curve
 * falls short, its coarsest piece (the longest segments: the face across
 * spaces its vertices evenly, so each piece's share of them follows its
 * length) is raised by one and the quantization settled, the lowest edge
 * index at a tie.  Counts only grow, so this ends. */
static sq_status min_totals(const sq_layout *L, const double *len, double size,
                            const double *need, const int *partner, const int *minc, int *n,
                            sq_error *err)
{
    for (;;) {
        int best = -1;
        double coarsest = -1.0;
        for (int e = 0; e < L->nedges; e++) {
            int c = L->edges[e].cad_edge;
            if (c < 0 || cad_edge_count(L, c, n) >= minc[c]) continue;
            if (len[e] / n[e] > coarsest) coarsest = len[e] / n[e], best = e;
        }
        if (best < 0) return SQ_OK; /* every curve carries what it is asked */
        n[best]++;
        SQ_TRY(settle(L, len, size, need, partner, NULL, n, err));
    }
}

/* Design 1: chord quantization. */
sq_status qm_quantize(const sq_layout *L, const double *len, double size, const double *need,
                      const int *partner, const sq_mesher_options *o, int *n, sq_error *err)
{
    for (int e = 0; e < L->nedges; e++) n[e] = edge_segments(len[e], size);
    for (int e = 0; o->min_chords && e < L->nedges; e++) {
        int c = L->edges[e].cad_edge, whole = c >= 0;
        for (int f = 0; whole && f < L->nedges; f++) whole = f == e || L->edges[f].cad_edge != c;
        if (whole && n[e] < o->min_chords[c]) n[e] = o->min_chords[c];
    }
    SQ_TRY(settle(L, len, size, need, partner, NULL, n, err));
    if (o->min_chords) SQ_TRY(min_totals(L, len, size, need, partner, o->min_chords, n, err));
    return o->slid.npairs ? equal_totals(L, len, size, need, &o->slid, n, err) : SQ_OK;
}
