/* semquad — singularity patterns imposed on a face (Jezdimirović 2021 §4):
 * interior points with their valences, plus the number of quads at each
 * boundary vertex, read from a pattern file or taken from the guiding
 * field (`natural`), and checked against Gauss–Bonnet with Poincaré–Hopf
 * before anything is solved (docs/conventions.md, "H field").
 *
 * Pattern file (docs/singularity-patterns.md): one item per line,
 *   x y valence           an interior singular point (valence 1..32)
 *   corner x y quads      quads at the boundary vertex at (x, y) (>= 0)
 * `#` starts a comment, blank lines are skipped.  Errors name the line. */
#ifndef SQ_PATTERN_H
#define SQ_PATTERN_H

#include "face_info.h"
#include "field_analysis.h"
#include "singularity.h"

typedef struct {
    double x, y;
    int quads;
    int line; /* line of the pattern file (0: not from a file) */
} sq_corner_override;

typedef struct {
    int npoints;
    sq_singularity *points;
    int *lines; /* npoints: line of each point in the file (0: not from a file) */
    int ncorners;
    sq_corner_override *corners;
    /* quads per face vertex (sq_face_info order) when the pattern comes
     * with them (natural: the guiding field's corner valences), else NULL */
    int nvertex_quads;
    int *vertex_quads;
    int ndegenerate; /* natural: degenerate critical points split (degenerate_split.h) */
} sq_pattern;

/* Parse pattern text; `name` is used in messages.  SQ_ERR_PATTERN naming
 * the line for a malformed line or a valence out of range. */
sq_status sq_pattern_parse(const char *text, const char *name, sq_pattern *out, sq_error *err);

/* Read and parse a pattern file (SQ_ERR_INPUT if it cannot be read). */
sq_status sq_pattern_read(const char *path, sq_pattern *out, sq_error *err);

/* The `natural` pattern: the guiding field's interior critical points
 * (origin "critical-point"; points flagged on the boundary are left out;
 * a zero of |index| > 1 split into elementary points, origin "split", see
 * degenerate_split.h) and its corner valences (Marcon 2019, eq. 15). */
sq_status sq_pattern_from_analysis(const cad_face *face, const sq_field_analysis *a,
                                   sq_pattern *out, sq_error *err);

void sq_pattern_free(sq_pattern *p); /* frees, zeroes the struct */

/* Gauss–Bonnet with Poincaré–Hopf in units of π/2:
 *   lhs = Σ_j (4 − V_j) + Σ_i (2 − n_i),  rhs = 4χ
 * (i.e. Σ (π/2)(4 − V_j) + Σ (π − n_i π/2) = 2πχ). */
typedef struct {
    int lhs, rhs;
    int *quads; /* per face vertex: n_i (smooth junctions: 2) */
} sq_pattern_balance;

/* Default quads at a vertex of interior angle `angle_deg`:
 * max(1, round(angle/90°)) (DESIGN.md "Index and valence"). */
int sq_default_quads(double angle_deg);

/* Check a pattern on a face: every point strictly inside (not within
 * 1e-6 x the face's diagonal of the boundary: SQ_ERR_PATTERN naming the
 * line), every corner override at a vertex of the face, then the balance.
 * On a violated balance SQ_ERR_PATTERN with both sides and the smallest
 * change that fixes it.  bal->quads is allocated (free it). */
sq_status sq_pattern_check(const cad_face *face, const sq_face_info *info, const sq_pattern *p,
                           sq_pattern_balance *bal, sq_error *err);
void sq_pattern_balance_free(sq_pattern_balance *bal);

#endif
