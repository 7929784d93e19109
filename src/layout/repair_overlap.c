/* semquad — overlaps of the separatrix set, merged for the all-quad last
 * resort.  Where two separatrices, or two passages of one, run along each
 * other (within OVERLAP_DIST_REL, near parallel) they do not cross: the
 * intersection search skips parallel segments, so the untangling leaves
 * both, and the graph holds two pieces along one line, a patch whose ring
 * runs along both and crosses itself (stress corpus 0055_tiny_edge: lines
 * 1e-9 apart along the side of a tiny edge, one doubling back on itself;
 * 0140_many_sided: a bent chord out and back along itself).  The later
 * one's overlapping part is removed and its remaining pieces end on the
 * kept one at inserted nodes: the two share one piece. */
#include "repair_private.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Two lines closer than this (relative to the face size) are one: ten
 * times the graph's coincidence distance, far below the trace step
 * (4e-3).  At 1e-6 the all-quad splits' own features (a sliver's parts
 * 1e-6 across, stress corpus 0140) were taken for overlaps and spikes
 * left where no line doubled back. */
#define OVERLAP_DIST_REL 1e-8
/* The graph's coincidence distance: an overlap shorter than it is none, a
 * cut within it of a line's end is at that end. */
#define OVERLAP_END_REL 1e-9
/* Segments within about 1.1 degrees of parallel may overlap (a crossing at
 * a steeper angle is one the untangling makes a node). */
#define OVERLAP_SIN_MAX 0.02
/* Passes at most (each merges the overlaps of lines apart). */
#define OVERLAP_PASSES_MAX 64

/* The part [b0, b1] of separatrix b runs along [a0, a1] of a (positions:
 * segment + t); a < b, or a == b and [a0, a1] an earlier passage. */
typedef struct {
    int b, a;
    double b0, b1, a0, a1;
} lay_overlap;

static int cmp_overlap(const void *x, const void *y)
{
    const lay_overlap *p = x, *q = y;
    if (p->b != q->b) return p->b - q->b;
    if (p->a != q->a) return p->a - q->a;
    if (p->b0 != q->b0) return p->b0 < q->b0 ? -1 : 1;
    return (p->a0 > q->a0) - (p->a0 < q->a0);
}

/* The point at position pos of s. */
static void pos_point(const sq_separatrix *s, double pos, double xy[2])
{
    int j = (int)floor(pos);
    if (j >= s->npts - 1) j = s->npts - 2;
    if (j < 0) j = 0;
    double t = pos - j;
    xy[0] = s->xy[2 * j] + t * (s->xy[2 * j + 2] - s->xy[2 * j]);
    xy[1] = s->xy[2 * j + 1] + t * (s->xy[2 * j + 3] - s->xy[2 * j + 1]);
}

/* Arc length of s between positions p0 <= p1. */
static double arc(const sq_separatrix *s, double p0, double p1)
{
    if (p1 < p0) {
        double t = p0;
        p0 = p1;
        p1 = t;
    }
    double a[2], b[2], len = 0.0;
    pos_point(s, p0, a);
    for (int j = (int)floor(p0) + 1; j < p1; j++) {
        len += hypot(s->xy[2 * j] - a[0], s->xy[2 * j + 1] - a[1]);
        a[0] = s->xy[2 * j], a[1] = s->xy[2 * j + 1];
    }
    pos_point(s, p1, b);
    return len + hypot(b[0] - a[0], b[1] - a[1]);
}

/* Segment jb of sb along segment ja of sa: the interval of jb within d of
 * ja's line and between its ends' projections, when the two are near
 * parallel; 0 when none. */
static int seg_overlap(const sq_separatrix *sb, int jb, const sq_separatrix *sa, int ja, double d,
                       double pb[2], double pa[2])
{
    const double *p = &sb->xy[2 * jb], *q = &sa->xy[2 * ja];
    double r[2] = {p[2] - p[0], p[3] - p[1]}, s[2] = {q[2] - q[0], q[3] - q[1]};
    double lr2 = r[0] * r[0] + r[1] * r[1], ls2 = s[0] * s[0] + s[1] * s[1];
    if (lr2 == 0.0 || ls2 == 0.0) return 0;
    if (fabs(r[0] * s[1] - r[1] * s[0]) > OVERLAP_SIN_MAX * sqrt(lr2 * ls2)) return 0;
    double u0 = ((q[0] - p[0]) * r[0] + (q[1] - p[1]) * r[1]) / lr2;
    double u1 = ((q[2] - p[0]) * r[0] + (q[3] - p[1]) * r[1]) / lr2;
    double lo = fmax(0.0, fmin(u0, u1)), hi = fmin(1.0, fmax(u0, u1));
    if (!(hi > lo)) return 0;
    const double u[2] = {lo, hi};
    for (int k = 0; k < 2; k++) {
        double x[2] = {p[0] + u[k] * r[0] - q[0], p[1] + u[k] * r[1] - q[1]};
        if (fabs(x[0] * s[1] - x[1] * s[0]) > d * sqrt(ls2)) return 0; /* off ja's line */
        pb[k] = jb + u[k];
        pa[k] = ja + fmin(fmax((x[0] * s[0] + x[1] * s[1]) / ls2, 0.0), 1.0);
    }
    return 1;
}

/* Every pair of near-parallel segments within d of each other, as
 * overlaps of the later one (by separatrix, then segment) along the
 * earlier; *ov malloc'ed. */
static sq_status segment_overlaps(const sq_separatrix_set *S, double d, lay_overlap **ov, int *nov,
                                  sq_error *err)
{
    *ov = NULL;
    *nov = 0;
    int nch = 0, cap = 0;
    lay_chunk *ch = NULL;
    SQ_TRY(lay_chunks(S, d, &ch, &nch, err));
    sq_status st = SQ_OK;
    for (int ci = 0; ci < nch && st == SQ_OK; ci++)
        for (int cj = ci; cj < nch && st == SQ_OK; cj++) {
            const lay_chunk *A = &ch[ci], *B = &ch[cj];
            if (A->bb[0] > B->bb[2] || B->bb[0] > A->bb[2] || A->bb[1] > B->bb[3] ||
                B->bb[1] > A->bb[3])
                continue;
            const sq_separatrix *sa = &S->s[A->sep], *sb = &S->s[B->sep];
            for (int ja = A->j0; ja < A->j1 && st == SQ_OK; ja++)
                for (int jb = (ci == cj ? ja + 2 : B->j0); jb < B->j1 && st == SQ_OK; jb++) {
                    if (A->sep == B->sep && abs(ja - jb) <= 1) continue;
                    /* the later segment is the one removed (B's chunk is
                     * never before A's: the set's order) */
                    double pb[2], pa[2];
                    if (!seg_overlap(sb, jb, sa, ja, d, pb, pa)) continue;
                    lay_overlap *q = lay_grow(*ov, &cap, *nov + 1, sizeof **ov);
                    if (!q) {
                        st = SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
                        break;
                    }
                    *ov = q;
                    int later_a = A->sep == B->sep && ja > jb;
                    q[(*nov)++] = later_a ? (lay_overlap){A->sep, B->sep, pa[0], pa[1], pb[0], pb[1]}
                                          : (lay_overlap){B->sep, A->sep, pb[0], pb[1], pa[0], pa[1]};
                }
        }
    free(ch);
    if (st != SQ_OK) {
        free(*ov);
        *ov = NULL;
        *nov = 0;
    }
    return st;
}

/* The overlaps at least minlen long on both lines, by
 * b, a and position on b: the segment overlaps of one pair joined where
 * they touch.  Written over ov[0..*nov). */
static void join_overlaps(const sq_separatrix_set *S, lay_overlap *ov, int *nov, double minlen)
{
    qsort(ov, (size_t)*nov, sizeof *ov, cmp_overlap);
    const double touch = 1e-9;
    int out = 0;
    for (int k = 0; k < *nov;) {
        lay_overlap run = ov[k];
        int m = k + 1;
        while (m < *nov && ov[m].b == run.b && ov[m].a == run.a && ov[m].b0 <= run.b1 + touch) {
            if (ov[m].b1 > run.b1) run.b1 = ov[m].b1, run.a1 = ov[m].a1;
            m++;
        }
        const sq_separatrix *sb = &S->s[run.b], *sa = &S->s[run.a];
        int apart = run.a != run.b || fmax(run.a0, run.a1) < run.b0;
        if (apart && arc(sb, run.b0, run.b1) >= minlen && arc(sa, run.a0, run.a1) >= minlen)
            ov[out++] = run;
        k = m;
    }
    *nov = out;
}

/* The node at position pos of separatrix k: its end when pos is within d
 * of one, else a new inserted node where k is split (a T-junction: the
 * other line's piece ends there).  Positions past pos move to the appended
 * piece. */
static sq_status node_at(sq_layout *L, int k, double pos, double d, sq_sep_end *node,
                         sq_error *err)
{
    const sq_separatrix *s = &L->seps.s[k];
    if (arc(s, 0.0, pos) <= d) {
        *node = s->start;
        return SQ_OK;
    }
    if (arc(s, pos, s->npts - 1) <= d) {
        *node = s->end;
        return SQ_OK;
    }
    double p[2];
    pos_point(s, pos, p);
    SQ_TRY(lay_sing_push(L, p[0], p[1], 3, SQ_LROLE_TJUNCTION, err));
    *node = (sq_sep_end){SQ_END_SINGULAR, L->nsing - 1, 0.0};
    return lay_split_sep(L, k, pos, p, L->nsing - 1, err);
}

/* Separatrix b without its part (b0, b1): the piece before ends at node e0
 * (point p0), the piece after starts at e1 (p1).  A piece is left out when
 * b's end is that node already, or, before, when `turn`; otherwise kept,
 * however short, so that b's end stays joined to the kept line.  The piece
 * before keeps index b (when there is none, b is left with no points,
 * removed by the caller), the piece after is appended. */
static sq_status cut_out(sq_layout *L, int b, double b0, double b1, int turn, sq_sep_end e0,
                         const double p0[2], sq_sep_end e1, const double p1[2], double eps,
                         sq_error *err)
{
    sq_separatrix *s = &L->seps.s[b];
    int n = s->npts;
    const int before = !turn && !lay_same_end(&s->start, &e0, eps);
    if (!lay_same_end(&s->end, &e1, eps)) {
        int j1 = fmin((int)floor(b1) + 1, n - 1); /* first point after b1 */
        double *xy = malloc(2 * (size_t)(n - j1 + 1) * sizeof *xy);
        if (!xy) return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
        xy[0] = p1[0], xy[1] = p1[1];
        memcpy(xy + 2, &s->xy[2 * j1], 2 * (size_t)(n - j1) * sizeof *xy);
        sq_status st = lay_sep_push(&L->seps, xy, n - j1 + 1, e1, s->end, err);
        free(xy);
        SQ_TRY(st);
        s = &L->seps.s[b]; /* the set may have moved */
    }
    if (!before) {
        s->npts = 0;
        return SQ_OK;
    }
    int j0 = (int)fmax(ceil(b0) - 1, 0); /* last point before b0 */
    s->xy[2 * (j0 + 1)] = p0[0];
    s->xy[2 * (j0 + 1) + 1] = p0[1];
    s->npts = j0 + 2;
    s->end = e0;
    return SQ_OK;
}

/* The later line's part of overlap o removed, its pieces ending on the
 * kept line at o's ends.  A line doubling back along itself would keep its
 * turn as a piece from one node back to it, a zero-area loop: removed too. */
static sq_status merge_one(sq_layout *L, const lay_overlap *o, double eps, sq_error *err)
{
    double p0[2], p1[2];
    pos_point(&L->seps.s[o->a], o->a0, p0);
    pos_point(&L->seps.s[o->a], o->a1, p1);
    /* the kept line split at its later position first, so that the
     * earlier one stays valid on the piece keeping index a */
    const int a0_hi = o->a0 >= o->a1;
    const double hi = fmax(o->a0, o->a1), lo = fmin(o->a0, o->a1);
    int b = o->b, nb = L->seps.n;
    double b0 = o->b0, b1 = o->b1;
    sq_sep_end ehi, elo;
    SQ_TRY(node_at(L, o->a, hi, eps, &ehi, err));
    if (o->a == o->b && L->seps.n > nb) {
        /* b's later passage is in the appended piece now (hi is two
         * segments or more before b0: lay_split_sep's shift is floor(hi)) */
        int j = (int)floor(hi);
        b = L->seps.n - 1, b0 -= j, b1 -= j;
    }
    SQ_TRY(node_at(L, o->a, lo, eps, &elo, err));
    /* a line doubling back: its turn goes from ehi back to it */
    return cut_out(L, b, b0, b1, o->a == o->b && a0_hi, a0_hi ? ehi : elo, p0, a0_hi ? elo : ehi,
                   p1, eps, err);
}

sq_status lay_set_merge_overlaps(lay_repair *r, int *merges, sq_error *err)
{
    *merges = 0;
    sq_layout *L = r->L;
    const double d = OVERLAP_DIST_REL * L->scale, eps = OVERLAP_END_REL * L->scale;
    sq_status st = SQ_OK;
    double work = 0.0; /* its own bound: the splits that follow have theirs */
    for (int pass = 0; pass < OVERLAP_PASSES_MAX && work <= WORK_MAX && st == SQ_OK; pass++) {
        lay_overlap *ov = NULL;
        int nov = 0, n = L->seps.n, merged = 0;
        work += (double)lay_set_points(&L->seps);
        st = segment_overlaps(&L->seps, d, &ov, &nov, err);
        char *used = st == SQ_OK ? calloc((size_t)n + 1, 1) : NULL;
        if (st == SQ_OK && !used) st = SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
        if (st == SQ_OK) join_overlaps(&L->seps, ov, &nov, eps);
        /* in one pass, overlaps of lines no other one of the pass touched
         * (their positions stay valid; pieces are appended, emptied lines
         * removed at the end) */
        for (int k = 0; k < nov && st == SQ_OK; k++) {
            if (used[ov[k].a] || used[ov[k].b]) continue;
            used[ov[k].a] = used[ov[k].b] = 1;
            st = merge_one(L, &ov[k], eps, err);
            merged++;
        }
        for (int k = L->seps.n - 1; k >= 0; k--)
            if (L->seps.s[k].npts == 0) lay_sep_remove(&L->seps, k);
        L->stats.overlaps_merged += merged;
        *merges += merged;
        free(ov);
        free(used);
        if (merged == 0) break;
    }
    r->hit_ok = 0;
    return st;
}
