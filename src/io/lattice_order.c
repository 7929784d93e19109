#include "lattice_order.h"

/* Fill the nodes of the sub-triangle of order p whose vertex 0 sits at
 * lattice point (i0, j0) (offset by `off` rows in barycentric terms). */
static int fill(int p, int i0, int j0, int *ij, int k)
{
    if (p < 0) return k;
    if (p == 0) {
        ij[2 * k] = i0;
        ij[2 * k + 1] = j0;
        return k + 1;
    }
    /* vertices */
    int vi[3] = {i0, i0 + p, i0}, vj[3] = {j0, j0, j0 + p};
    for (int v = 0; v < 3; v++, k++) {
        ij[2 * k] = vi[v];
        ij[2 * k + 1] = vj[v];
    }
    /* edge interiors: 0->1 along i, 1->2 diagonal, 2->0 down j */
    for (int t = 1; t < p; t++, k++) {
        ij[2 * k] = i0 + t;
        ij[2 * k + 1] = j0;
    }
    for (int t = 1; t < p; t++, k++) {
        ij[2 * k] = i0 + p - t;
        ij[2 * k + 1] = j0 + t;
    }
    for (int t = 1; t < p; t++, k++) {
        ij[2 * k] = i0;
        ij[2 * k + 1] = j0 + p - t;
    }
    return fill(p - 3, i0 + 1, j0 + 1, ij, k);
}

void sq_tri_lattice_order(int P, int *ij) { fill(P, 0, 0, ij, 0); }
