/* The MSH 4.1 files read back by Gmsh's own reader (Debian python3-gmsh
 * through /usr/bin/python3, tests/t604-gmsh-check.py): same node and
 * element counts and types, physical groups, positive Jacobians and the
 * mesh area by Gmsh's quadrature equal to ours, for Q = 1..10, GLL and
 * equispaced meshes.  Exit 77 (skip) when /usr/bin/python3 cannot import
 * gmsh.  argv[1]: the helper script. */
#include "quad_order.h"
#include "t6xx-quad-meshes.h"
#include "write_msh.h"

#include <sys/wait.h>
#include <unistd.h>

int main(int argc, char **argv)
{
    const char *py = "/usr/bin/python3";
    if (argc < 2 || access(py, X_OK) != 0) return 77;
    char cmd[1024];
    snprintf(cmd, sizeof cmd, "%s -c 'import gmsh' 2>/dev/null", py);
    if (system(cmd) != 0) return 77;
    char dir[] = "/tmp/sq_t604_XXXXXX";
    if (!mkdtemp(dir)) return printf("cannot make a temporary directory\n"), 1;
    int f = 0;
    for (int Q = 1; Q <= 10; Q++)
        for (int k = 0; k < 2; k++)
            for (int which = 0; which < 2; which++) {
                sq_node_kind kind = k ? SQ_NODES_EQUISPACED : SQ_NODES_GLL;
                sq_quad_mesh *m = which ? t6_quarter_disc(2, Q, kind) : t6_annulus(3, Q, kind);
                sq_quad_quality q;
                sq_error err;
                SQ_TEST_OK(sq_quad_mesh_quality(m, NULL, NULL, 1, &q, &err), err);
                char path[256];
                snprintf(path, sizeof path, "%s/m%d%d%d.msh", dir, Q, k, which);
                SQ_TEST_OK(sq_write_msh(path, m, NULL, &err), err);
                snprintf(cmd, sizeof cmd, "%s '%s' '%s' %d %d %d %d %d %d %.17g", py, argv[1], path,
                         m->nnodes, m->nquads, m->nbnd, sq_gmsh_quad_type(Q), sq_gmsh_line_type(Q),
                         m->ntags + 1, q.area);
                int rc = system(cmd);
                if (rc == -1 || !WIFEXITED(rc) || WEXITSTATUS(rc) != 0) {
                    printf("Q=%d %s %s: gmsh check failed (%d)\n", Q, k ? "equi" : "gll",
                           which ? "disc" : "annulus", rc);
                    f++;
                }
                remove(path);
                sq_quad_mesh_free(&m);
            }
    rmdir(dir);
    return f ? 1 : 0;
}
