/* semquad sem/ — nodal point set on the reference triangle (Blyth &
 * Pozrikidis 2006: a symmetric blend of the 1D GLL points). */
#include "tri_nodes.h"

#include "gauss.h"

sq_status sem_tri_nodes(int P, double *rs, sq_error *err)
{
    if (P < 0 || P > SEM_MAX_ORDER || !rs)
        return SQ_FAIL(err, SQ_ERR_USAGE, "tri_nodes: bad order P=%d", P);
    if (P == 0) { /* single node: the centroid */
        rs[0] = rs[1] = 1.0 / 3.0;
        return SQ_OK;
    }
    double x[SEM_MAX_ORDER + 1], w[SEM_MAX_ORDER + 1], v[SEM_MAX_ORDER + 1];
    SQ_TRY(sem_gauss_lobatto(P + 1, x, w, err));
    /* GLL points mapped to [0,1] (sem_gauss_lobatto returns them exactly
     * symmetric, so v_{P-i} = 1 - v_i up to one rounding). */
    for (int i = 0; i <= P; ++i) v[i] = 0.5 * (x[i] + 1.0);
    v[0] = 0.0;
    v[P] = 1.0;

    for (int j = 0; j <= P; ++j)
        for (int i = 0; i + j <= P; ++i) {
            const int k = P - i - j, n = sem_tri_node_index(P, i, j);
            double r = (1.0 + 2.0 * v[i] - v[j] - v[k]) / 3.0;
            double s = (1.0 + 2.0 * v[j] - v[i] - v[k]) / 3.0;
            /* On the edges the formula reduces to the GLL points up to
             * rounding: snap so edge nodes lie exactly on the edge. */
            if (j == 0) { r = v[i]; s = 0.0; }
            if (i == 0) { r = 0.0; s = v[j]; }
            if (k == 0) { r = v[i]; s = 1.0 - v[i]; }
            rs[2 * n] = r;
            rs[2 * n + 1] = s;
        }
    return SQ_OK;
}

void sem_tri_edge_nodes(int P, int k, int *idx)
{
    for (int t = 0; t <= P; ++t) {
        int i, j;
        switch (k) {
        case 0: i = t; j = 0; break;          /* v0 -> v1 along s = 0 */
        case 1: i = P - t; j = t; break;      /* v1 -> v2 along r + s = 1 */
        default: i = 0; j = P - t; break;     /* v2 -> v0 along r = 0 */
        }
        idx[t] = sem_tri_node_index(P, i, j);
    }
}
