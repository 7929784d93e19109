/* semquad — command-line entry: dispatch subcommands, map statuses to exit
 * codes (docs/conventions.md, "Exit statuses"), print errors as one line. */
#include "cli.h"

#include <omp.h>
#include <stdio.h>
#include <string.h>

static const char *usage =
    " - block-structured high-order quad meshes of planar CAD faces\n"
    "\n"
    "usage: semquad COMMAND [options]\n"
    "\n"
    "commands:\n"
    "  info FILE [--face N] [--json] [-q]\n"
    "      every face with its status (ok, healed, not planar, broken: reason), boundary\n"
    "      loops, edges (type, length), corners (angle), chi, area, what was healed.\n"
    "  triangulate FILE [--face N] [--order P] [--size H] [--min-angle A] [--max-turn T]\n"
    "              [-o out.vtu] [--svg out.svg] [--report out.json] [--quiet]\n"
    "      coarse curved triangulation of order P (1..12, default 4): CGAL constrained\n"
    "      Delaunay refinement (min angle A, default 20 deg; longest edge H, default\n"
    "      sqrt(area)/3), boundary segments turning at most T degrees (default 30),\n"
    "      high-order nodes exactly on the CAD curves.\n"
    "  field FILE [--face N] [--order P] [--method auto|cg|dg] [--size H] [--geom-order G]\n"
    "        [--singularities FILE|natural] [--allow-misaligned] [--no-grading]\n"
    "        [--vtu out.vtu] [--svg out.svg] [--report out.json] [--quiet]\n"
    "      guiding field (u,v) = (cos 4t, sin 4t) of order P (1..16, default 8), its\n"
    "      critical points with valences, corner valences, Poincare-Hopf check. auto\n"
    "      uses CG when every corner is a multiple of 90 deg, DG otherwise.\n"
    "      --no-grading: no hp grading of the triangulation towards singular corners.\n"
    "      --singularities FILE|natural [--allow-misaligned]: instead, the cross field of\n"
    "      an imposed pattern (FILE: lines 'x y valence' and 'corner x y quads', see\n"
    "      docs/singularity-patterns.md; natural: the guiding field's points and corner\n"
    "      valences): Gauss-Bonnet check (exit 5), H, branch cut, theta, jumps of theta,\n"
    "      holonomy (misaligned holes are warned about); VTU point data H, theta.\n"
    "  converge FILE [--face N] [--solution NAME] [--method cg|dg|both] [--orders A-B]\n"
    "           [--sizes h1,h2,...] [--geom-order G] [--csv out.csv] [--svg out.svg] [--quiet]\n"
    "      convergence study of the CG/DG Poisson solvers: -lap u = 0 with u = the exact\n"
    "      harmonic solution NAME (exp-sin: e^x sin y (default), re-z5: Re (x+iy)^5,\n"
    "      poly, sin-sinh) on the whole boundary; every P in A-B (default 1-12) on every\n"
    "      size (default: automatic), geometry order max(P,8) capped at 12 unless G.\n"
    "      Table on stdout; CSV method,P,h,dofs,L2,H1; SVG log-log plot of the errors\n"
    "      against dofs (p-refinement, or h-refinement per P with several sizes).\n"
    "  mesh FILE [--face N] [--order Q] [--size h] [--field-order P] [--method auto|cg|dg]\n"
    "       [--merge-distance K] [--singularities FILE|natural] [--allow-misaligned]\n"
    "       [--nodes gll|equispaced] [--bl E1,E2,.. --bl-first d --bl-ratio r --bl-layers n]\n"
    "       [--max-quads N] [--road auto|layout|split] [--min-quality X]\n"
    "       [-o out.msh|out.xml|out.vtu] [--svg F] [--report F] [-q]\n"
    "      block-structured high-order quad mesh of order Q (1..10, default 4) with\n"
    "      elements of size about h (default sqrt(area)/8, halved up to 3 times while\n"
    "      curved quads fold; --field-order P sets the\n"
    "      guiding and the H/theta fields, default 4 and 8):\n"
    "      Gmsh MSH 4.1, Nektar++ XML or VTU by extension;\n"
    "      quality summary on stdout, progress on stderr. --bl grades the elements\n"
    "      geometrically away from the CAD edges E1,E2,.. (indices as semquad info\n"
    "      prints them): first height d, ratio r (default 1.2), n layers.\n"
    "      --max-quads N (default 2e7) refuses a size giving more quads, before\n"
    "      meshing, and names the size that fits. --road: the layout road (field,\n"
    "      layout, patches), the split road (a triangulation split into 3 quads per\n"
    "      triangle: valid on every face, many irregular vertices) or auto (default:\n"
    "      the layout road, the split road where it fails, with a note saying why).\n"
    "      --min-quality X (default 0.01; 0: none): a mesh whose worst quad has a scaled\n"
    "      Jacobian (min det J / max det J, proven by Bezier bounds) below X is written,\n"
    "      then the run exits 8 naming that quad.\n"
    "  layout FILE [--face N] [--order P] [--method auto|cg|dg] [--size H]\n"
    "         [--merge-distance K] [--singularities FILE|natural] [--allow-misaligned]\n"
    "         [-o patches.step] [--svg F] [--report F] [--quiet]\n"
    "      quad layout: separatrices traced from the singular points and corners\n"
    "      (Adams-Bashforth 4), merged (K steps, default 1; larger: aggressive),\n"
    "      corrected until every patch is a quad; the face split into the patches\n"
    "      (STEP). Exit 6 if no valid layout can be made. --singularities traces the\n"
    "      H/theta field of an imposed pattern (docs/singularity-patterns.md).\n"
    "  help                 this text\n"
    "  --version            the version\n"
    "\n"
    "FILE is STEP (.step/.stp), IGES (.iges/.igs) or BREP (.brep/.brp); lengths stay in\n"
    "the file's unit. The default face is the only planar face (else face 0).\n"
    "Every command heals the planar faces it reads (gaps, unshared vertices, small\n"
    "edges) within the file's own tolerance (docs/healing.md):\n"
    "  --heal-tolerance T   heal within T (file unit) instead\n"
    "  --no-heal            take the faces as read\n"
    "\n"
    "exit status: 0 ok, 1 internal error, 2 usage, 3 bad input file, 4 unsupported\n"
    "geometry, 5 invalid singularity pattern, 6 no valid layout, 7 output not written,\n"
    "8 mesh written but its quality below --min-quality.\n";

int main(int argc, char **argv)
{
    sq_error err;
    sq_error_clear(&err);
    /* CHOLMOD's supernodal loops ask OpenMP for 4 threads, a number fixed
     * when it was built (CHOLMOD_OMP_NUM_THREADS), whatever the machine: on
     * small supernodes (the DG guiding field) and 2 cores their barriers
     * cost more than the loops, naca0012's whole run 0.25-0.29 s against
     * 0.21-0.22 s with every parallel region run by the calling thread */
    omp_set_max_active_levels(0);
    if (argc < 2) {
        fputs("semquad: usage error: missing command (try: semquad help)\n", stderr);
        return SQ_ERR_USAGE;
    }
    const char *cmd = argv[1];
    sq_status st;
    if (!strcmp(cmd, "help") || !strcmp(cmd, "--help") || !strcmp(cmd, "-h")) {
        printf("semquad %s", sq_version());
        fputs(usage, stdout);
        return 0;
    } else if (!strcmp(cmd, "--version") || !strcmp(cmd, "version")) {
        printf("semquad %s\n", sq_version());
        return 0;
    } else if (!strcmp(cmd, "info")) {
        st = sq_cmd_info(argc - 2, argv + 2, &err);
    } else if (!strcmp(cmd, "converge")) {
        st = sq_cmd_converge(argc - 2, argv + 2, &err);
    } else if (!strcmp(cmd, "mesh")) {
        st = sq_cmd_mesh(argc - 2, argv + 2, &err);
    } else if (!strcmp(cmd, "layout")) {
        st = sq_cmd_layout(argc - 2, argv + 2, &err);
    } else if (!strcmp(cmd, "field")) {
        st = sq_cmd_field(argc - 2, argv + 2, &err);
    } else if (!strcmp(cmd, "triangulate")) {
        st = sq_cmd_triangulate(argc - 2, argv + 2, &err);
    } else {
        st = SQ_FAIL(&err, SQ_ERR_USAGE, "unknown command '%s' (try: semquad help)", cmd);
    }
    if (st != SQ_OK) fprintf(stderr, "semquad: %s: %s\n", sq_status_name(st), err.msg);
    return (int)st;
}
