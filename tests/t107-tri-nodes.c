/* t107: the Blyth–Pozrikidis node set: lattice numbering, vertices, edge
 * nodes equal to the GLL points of each edge in the documented direction,
 * interior nodes strictly inside, and the set invariant under the
 * rotations of T. */
#include "gauss.h"
#include "tri_nodes.h"

#include <math.h>
#include <stdio.h>

static int failures;

static void check(const char *what, int P, int k, double value, double expected, double tol)
{
    if (!(fabs(value - expected) <= tol)) {
        printf("t107 %s (P=%d, #%d): value %.17g expected %.17g tolerance %g\n", what, P, k, value,
               expected, tol);
        ++failures;
    }
}

int main(void)
{
    static double rs[2 * (SEM_MAX_ORDER + 1) * (SEM_MAX_ORDER + 2) / 2];
    for (int P = 1; P <= SEM_MAX_ORDER; ++P) {
        if (sem_tri_nodes(P, rs, NULL) != SQ_OK) {
            printf("t107 tri_nodes(%d) failed\n", P);
            return 1;
        }
        double x[SEM_MAX_ORDER + 1], w[SEM_MAX_ORDER + 1];
        sem_gauss_lobatto(P + 1, x, w, NULL);
        /* numbering */
        int expect = 0;
        for (int j = 0; j <= P; ++j)
            for (int i = 0; i + j <= P; ++i) check("lattice index", P, i, sem_tri_node_index(P, i, j), expect++, 0);
        check("num nodes", P, 0, sem_tri_num_nodes(P), expect, 0);
        /* vertices */
        const int v0 = sem_tri_node_index(P, 0, 0), v1 = sem_tri_node_index(P, P, 0), v2 = sem_tri_node_index(P, 0, P);
        check("v0 r", P, 0, rs[2 * v0], 0, 0), check("v0 s", P, 0, rs[2 * v0 + 1], 0, 0);
        check("v1 r", P, 1, rs[2 * v1], 1, 0), check("v1 s", P, 1, rs[2 * v1 + 1], 0, 0);
        check("v2 r", P, 2, rs[2 * v2], 0, 0), check("v2 s", P, 2, rs[2 * v2 + 1], 1, 0);
        /* edges: endpoints, GLL spacing along the edge direction */
        const double A[3][2] = {{0, 0}, {1, 0}, {0, 1}};
        for (int k = 0; k < 3; ++k) {
            int idx[SEM_MAX_ORDER + 1];
            sem_tri_edge_nodes(P, k, idx);
            const double *a = A[k], *b = A[(k + 1) % 3];
            /* two or three roundings of numbers <= 1 on either side (no
             * BLAS): 1e-15 = 9 U */
            for (int t = 0; t <= P; ++t) {
                const double g = 0.5 * (x[t] + 1.0);
                check("edge node r", P, k * 100 + t, rs[2 * idx[t]], a[0] + g * (b[0] - a[0]), 1e-15);
                check("edge node s", P, k * 100 + t, rs[2 * idx[t] + 1], a[1] + g * (b[1] - a[1]), 1e-15);
            }
        }
        /* interior strictly inside; rotation (r,s) -> (s, 1-r-s) maps node
         * (i,j) to node (j,k) */
        for (int j = 0; j <= P; ++j)
            for (int i = 0; i + j <= P; ++i) {
                const int k = P - i - j, n = sem_tri_node_index(P, i, j), m = sem_tri_node_index(P, j, k);
                const double r = rs[2 * n], s = rs[2 * n + 1];
                if (i > 0 && j > 0 && k > 0 && !(r > 0 && s > 0 && r + s < 1))
                    check("interior node inside", P, n, r + s, 0.5, 0.5);
                /* (1 + 2 v_j - v_i - v_k) / 3 summed in another order: 4
                 * roundings of terms <= 3, over 3: 4 U * 3 / 3 + U < 1e-15 */
                check("rotation symmetry r", P, n, rs[2 * m], s, 1e-15);
                check("rotation symmetry s", P, n, rs[2 * m + 1], 1.0 - r - s, 1e-15);
            }
    }
    if (sem_tri_nodes(SEM_MAX_ORDER + 1, rs, NULL) != SQ_ERR_USAGE) {
        printf("t107 order above SEM_MAX_ORDER accepted\n");
        ++failures;
    }
    return failures ? 1 : 0;
}
