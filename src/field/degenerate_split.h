/* semquad — the guiding field's singular points as elementary ones: a zero
 * of |index| > 1 (four valence-3 points coinciding at the disc's centre,
 * where (u, v) ≈ z^4) carries no valid layout by itself, so it is split
 * into |index| points of valence 3 (index > 0) or 5 (index < 0), which the
 * H/θ field (Jezdimirović 2021 §4-5) then takes as an imposed pattern.
 *
 * design: the split points are the |m| roots of the expansion
 * c (z − z0)^m perturbed by its own size, c (z − z0)^m = c r^m e^{imφ}
 * (conjugated for m < 0): z0 + r e^{i(φ + 2πk/|m|)}, with
 *  - r = SQ_SPLIT_FRACTION x the distance from z0 to the boundary or to the
 *    nearest other singular point, whichever is smaller (the points stay
 *    well inside, apart from the others, and at the scale of the face:
 *    the disc's four valence-3 points at half its radius);
 *  - φ = arg(c)/(4 − m): the ray to the first split point is a direction of
 *    the cross there (arg(w)/4 = φ mod π/2, eq. 2), and so is the ray to
 *    every one when (4 − m)/|m| is an integer (m = 2, −2, −4), so the points
 *    are joined to z0's neighbourhood along field lines; the placement turns
 *    with the face (rotating face and field by α multiplies c by
 *    e^{i(4−m)α});
 *    m = 4 makes every ray a field line (z^4 is rotation invariant): φ
 *    points at the nearest boundary point (the x axis when the boundary is
 *    a circle about z0, as for the disc). */
#ifndef SQ_DEGENERATE_SPLIT_H
#define SQ_DEGENERATE_SPLIT_H

#include "field_analysis.h"
#include "singularity.h"

#define SQ_SPLIT_FRACTION 0.5

/* The analysis' interior singular points (valence != 4, not on the
 * boundary) with each zero of |index| > 1 split as above (origin
 * SQ_ORIGIN_SPLIT).  *pts is allocated (free it); *ndegenerate counts the
 * zeros split (may be NULL). */
sq_status sq_elementary_points(const cad_face *face, const sq_field_analysis *a,
                               sq_singularity **pts, int *npts, int *ndegenerate, sq_error *err);

/* Cancels valence-3/valence-5 pairs closer than `near`, nearest first
 * (their indices +1 and -1 sum to 0: Gauss–Bonnet still holds); the
 * others keep their order.  Returns the pairs removed. */
int sq_cancel_pairs(sq_singularity *s, int *n, double near);

/* The first (at most max) valence-3/valence-5 pairs of s that
 * sq_cancel_pairs(s, n, HUGE_VAL) would remove, nearest first: pairs[k][0]
 * the valence-3 point, [1] the valence-5 one (indices into s), *npairs of
 * them. */
sq_status sq_list_pairs(const sq_singularity *s, int n, int max, int (*pairs)[2], int *npairs,
                        sq_error *err);

#endif
