/* Point location in small curved elements away from the origin: there the
 * coordinates' rounding alone exceeds 1e-13 in reference units, and Newton's
 * inverse map must still report convergence (regression: points inside such
 * elements near a graded corner were reported outside). */
#include "locate.h"
#include "test_util.h"
#include "tri_nodes.h"

int main(void)
{
    const int P = 4;
    sem_tri_mesh *m = NULL;
    sq_error err;
    SQ_TEST_OK(sem_tri_mesh_create(P, 3, 1, &m, &err), err);
    const double h = 1e-3, ox = 0.98, oy = 1.0;
    const double v[6] = {ox, oy, ox + h, oy, ox, oy + h};
    for (int k = 0; k < 6; k++) m->vxy[k] = v[k];
    m->tri[0] = 0;
    m->tri[1] = 1;
    m->tri[2] = 2;
    double rs[2 * 15];
    SQ_TEST_OK(sem_tri_nodes(P, rs, &err), err);
    /* bend the hypotenuse outwards a little: a genuinely curved element */
    for (int n = 0; n < m->nodes_per_tri; n++) {
        double r = rs[2 * n], s = rs[2 * n + 1];
        m->gxy[2 * n] = ox + h * r + 0.05 * h * r * s;
        m->gxy[2 * n + 1] = oy + h * s + 0.05 * h * r * s;
    }
    SQ_TEST_OK(sem_tri_mesh_build_neighbours(m, &err), err);
    sem_locator *loc = NULL;
    SQ_TEST_OK(sem_locator_create(m, &loc, &err), err);
    int fails = 0, misses = 0;
    for (int i = 1; i < 200; i++)
        for (int j = 1; i + j < 200; j++) {
            double r = i / 200.0, s = j / 200.0, x[2], rr, ss;
            int e;
            sem_locator_map(loc, 0, r, s, x, NULL);
            if (sem_locator_find(loc, x, -1, &e, &rr, &ss)) misses++;
            else if (fabs(rr - r) + fabs(ss - s) > 1e-8) fails++;
        }
    fails += sq_check_int("small curved element", "points reported outside", misses, 0);
    sem_locator_free(&loc);
    sem_tri_mesh_free(&m);
    return fails ? 1 : 0;
}
