/* Node order of VTK Lagrange triangles / Gmsh high-order triangles:
 * vertices, edge interiors in edge direction, interior recursively. */
#include "lattice_order.h"
#include "test_util.h"

static int check(int P, const int *want, int n)
{
    int ij[2 * 66], fails = 0;
    sq_tri_lattice_order(P, ij);
    for (int k = 0; k < n; k++) {
        char what[48];
        snprintf(what, sizeof what, "P=%d node %d i", P, k);
        fails += sq_check_int("lattice order", what, ij[2 * k], want[2 * k]);
        snprintf(what, sizeof what, "P=%d node %d j", P, k);
        fails += sq_check_int("lattice order", what, ij[2 * k + 1], want[2 * k + 1]);
    }
    /* every lattice point exactly once */
    int seen[11][11] = {{0}};
    for (int k = 0; k < (P + 1) * (P + 2) / 2; k++) seen[ij[2 * k]][ij[2 * k + 1]]++;
    for (int j = 0; j <= P; j++)
        for (int i = 0; i + j <= P; i++) fails += sq_check_int("lattice order", "multiplicity", seen[i][j], 1);
    return fails;
}

int main(void)
{
    const int p1[] = {0, 0, 1, 0, 0, 1};
    const int p3[] = {0, 0, 3, 0, 0, 3, 1, 0, 2, 0, 2, 1, 1, 2, 0, 2, 0, 1, 1, 1};
    const int p4[] = {0, 0, 4, 0, 0, 4, 1, 0, 2, 0, 3, 0, 3, 1, 2, 2, 1, 3,
                      0, 3, 0, 2, 0, 1, 1, 1, 2, 1, 1, 2};
    int fails = check(1, p1, 3) + check(3, p3, 10) + check(4, p4, 15);
    for (int P = 5; P <= 10; P++) fails += check(P, p1, 0);
    return fails ? 1 : 0;
}
