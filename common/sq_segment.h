/* semquad common — a point against a straight segment in the plane: the
 * nearest point's parameter, the distance, and the even-odd crossing
 * test of point-in-polygon. */
#ifndef SQ_SEGMENT_H
#define SQ_SEGMENT_H

#include <math.h>

/* The parameter in [0, 1] of the point of segment [a, b] nearest p (0 on
 * a segment of zero length). */
static inline double sq_segment_foot(const double p[2], const double a[2], const double b[2])
{
    const double dx = b[0] - a[0], dy = b[1] - a[1], l2 = dx * dx + dy * dy;
    const double t = l2 > 0.0 ? ((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / l2 : 0.0;
    return t < 0.0 ? 0.0 : (t > 1.0 ? 1.0 : t);
}

/* Distance from p to segment [a, b]; *u (may be NULL) the foot's parameter. */
static inline double sq_segment_distance(const double p[2], const double a[2], const double b[2],
                                         double *u)
{
    const double t = sq_segment_foot(p, a, b);
    if (u) *u = t;
    return hypot(a[0] + t * (b[0] - a[0]) - p[0], a[1] + t * (b[1] - a[1]) - p[1]);
}

/* Whether the ray from p towards +x crosses segment [a, b], each segment
 * counted half-open in y so that a polygon's vertices count once: an odd
 * number of crossings over a closed polygon puts p inside. */
static inline int sq_segment_crosses_ray(const double p[2], const double a[2], const double b[2])
{
    return (a[1] > p[1]) != (b[1] > p[1]) &&
           p[0] < a[0] + (p[1] - a[1]) * (b[0] - a[0]) / (b[1] - a[1]);
}

#endif
