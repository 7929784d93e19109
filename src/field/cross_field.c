#include "cross_field.h"

#include <math.h>
#include <stddef.h>

static int guiding_direction(void *ctx, const double x[2], int *elem, double *theta)
{
    double uv[2];
    if (sq_guiding_field_eval(ctx, x, elem, uv, NULL)) return 1;
    *theta = 0.25 * atan2(uv[1], uv[0]); /* Marcon 2019, eq. (2) */
    return 0;
}

static double guiding_element_size(void *ctx, int e)
{
    const sem_tri_mesh *m = ((const sq_guiding_field *)ctx)->mesh;
    const double *a = &m->vxy[2 * m->tri[3 * e]], *b = &m->vxy[2 * m->tri[3 * e + 1]],
                 *c = &m->vxy[2 * m->tri[3 * e + 2]];
    return sqrt(0.5 * fabs((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])));
}

sq_cross_field sq_guiding_cross_field(const sq_guiding_field *g)
{
    sq_cross_field f = {(void *)g, guiding_direction, guiding_element_size, NULL};
    return f;
}
