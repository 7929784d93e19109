/* semquad — the size field h(x): the one target size every stage of the
 * layout road reads (docs/sizes.md).  Built from the user's size sources
 * (sq_size_source), it is the minimum of the far size and each source's
 * contribution, each contribution growing linearly with the distance from
 * its source, so that |grad h| <= g - 1 everywhere (g the gradation):
 * neighbouring cells of size h, a distance h apart, differ by a factor g
 * at most. */
#ifndef SQ_SIZE_FIELD_H
#define SQ_SIZE_FIELD_H

#include "cad.h"
#include "semquad.h"

typedef struct sq_size_field sq_size_field;

/* The field of sources src[n] on face (CAD edges sampled into polylines,
 * so evaluation needs no CAD call); gradation g > 1.  per_radian N > 0
 * adds the curvature sizes: at a point of a CAD edge where the curvature
 * is kappa, h = 1 / (N |kappa|) (N elements per radian of turning),
 * growing by g - 1 per unit distance away from the edge; 0: none.
 * SQ_ERR_USAGE naming the first bad source (an edge the face lacks, a
 * non-positive size, radius or box, a ratio below 1) or a bad N. */
sq_status sq_size_field_create(const cad_face *face, const sq_size_source *src, int n,
                               double gradation, double per_radian, sq_size_field **out,
                               sq_error *err);
void sq_size_field_free(sq_size_field **f); /* NULL-safe, NULLs *f */

/* h(x): the minimum of `far` (the uniform size) and every source's size at
 * x. */
double sq_size_field_eval(const sq_size_field *f, const double x[2], double far);

/* A boundary layer's field (docs/sizes.md): the isotropic sizes of base
 * (NULL: the far size alone; base must outlive it), and near the CAD
 * edges edges[n] (the walls) a size normal to them of b + (ln ratio) d at
 * distance d, b = first ln ratio / (ratio - 1), whose equidistribution
 * gives cells first, first ratio, first ratio^2, ... over `layers` cells,
 * then growing by ln(gradation) per unit distance (cells growing by
 * gradation) until it reaches the isotropic size; along the walls the
 * isotropic size. */
sq_status sq_size_field_walls(const cad_face *face, const sq_size_field *base, const int *edges,
                              int n, double first, double ratio, int layers, double gradation,
                              sq_size_field **out, sq_error *err);

/* The size at x along the direction t (not necessarily unit): the
 * isotropic size, smaller across a wall's layers (sq_size_field_walls);
 * sq_size_field_eval exactly where f has no walls. */
double sq_size_field_eval_dir(const sq_size_field *f, const double x[2], const double t[2],
                              double far);

/* SQ_ERR_USAGE naming the first bad source of src[n] (the checks of
 * sq_size_field_create that need no face). */
sq_status sq_size_sources_check(const sq_size_source *src, int n, double gradation, sq_error *err);

/* SQ_ERR_USAGE unless per_radian (elements per radian) is finite and
 * >= 0. */
sq_status sq_size_curvature_check(double per_radian, sq_error *err);

#endif
