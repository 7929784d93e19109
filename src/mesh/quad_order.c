#include "quad_order.h"

/* Gmsh: corners, edges counter-clockwise, interior recursively (Gmsh
 * reference manual, "MSH file format", node ordering of quadrangles). */
static int gmsh_rec(int Q, int off, int *ij, int k)
{
    if (Q < 0) return k;
    if (Q == 0) {
        ij[2 * k] = off;
        ij[2 * k + 1] = off;
        return k + 1;
    }
    const int c[4][2] = {{0, 0}, {Q, 0}, {Q, Q}, {0, Q}};
    for (int v = 0; v < 4; v++) {
        ij[2 * k] = off + c[v][0];
        ij[2 * k + 1] = off + c[v][1];
        k++;
    }
    for (int e = 0; e < 4; e++) {
        const int *a = c[e], *b = c[(e + 1) % 4];
        int di = (b[0] - a[0]) / Q, dj = (b[1] - a[1]) / Q;
        for (int s = 1; s < Q; s++) {
            ij[2 * k] = off + a[0] + s * di;
            ij[2 * k + 1] = off + a[1] + s * dj;
            k++;
        }
    }
    return gmsh_rec(Q - 2, off + 1, ij, k);
}

void sq_quad_gmsh_order(int Q, int *ij) { gmsh_rec(Q, 0, ij, 0); }

/* VTK Lagrange quadrilateral (vtkHigherOrderQuadrilateral::PointIndexFromIJK). */
void sq_quad_vtk_order(int Q, int *ij)
{
    int k = 0;
    const int c[4][2] = {{0, 0}, {Q, 0}, {Q, Q}, {0, Q}};
    for (int v = 0; v < 4; v++, k++) {
        ij[2 * k] = c[v][0];
        ij[2 * k + 1] = c[v][1];
    }
    for (int s = 1; s < Q; s++, k++) ij[2 * k] = s, ij[2 * k + 1] = 0;
    for (int s = 1; s < Q; s++, k++) ij[2 * k] = Q, ij[2 * k + 1] = s;
    for (int s = 1; s < Q; s++, k++) ij[2 * k] = s, ij[2 * k + 1] = Q;
    for (int s = 1; s < Q; s++, k++) ij[2 * k] = 0, ij[2 * k + 1] = s;
    for (int j = 1; j < Q; j++)
        for (int i = 1; i < Q; i++, k++) ij[2 * k] = i, ij[2 * k + 1] = j;
}

int sq_gmsh_quad_type(int Q)
{
    static const int t[11] = {0, 3, 10, 36, 37, 38, 47, 48, 49, 50, 51};
    return Q >= 1 && Q <= 10 ? t[Q] : 0;
}

int sq_gmsh_line_type(int Q)
{
    static const int t[11] = {0, 1, 8, 26, 27, 28, 62, 63, 64, 65, 66};
    return Q >= 1 && Q <= 10 ? t[Q] : 0;
}

void sq_line_order(int Q, int *idx)
{
    idx[0] = 0;
    idx[1] = Q;
    for (int s = 1; s < Q; s++) idx[s + 1] = s;
}
