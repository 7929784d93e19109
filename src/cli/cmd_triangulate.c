/* semquad triangulate FILE: the coarse curved triangulation of a face
 * (sq_face_triangulate). */
#include "cli.h"

static sq_status run_triangulate(sq_cli_args *a, sq_error *err)
{
    sq_model *m = NULL;
    SQ_TRY(sq_cli_open(a, &m, err));
    sq_triangles *t = NULL;
    sq_status st = sq_face_triangulate(m, a->face, &a->opt, &t, err);
    if (st == SQ_OK && a->output) st = sq_triangles_write(t, a->output, err);
    if (st == SQ_OK && a->svg) st = sq_triangles_write(t, a->svg, err);
    if (st == SQ_OK && a->report) st = sq_triangles_write_report(t, a->report, err);
    char *text = NULL;
    if (st == SQ_OK && !a->quiet) st = sq_cli_print(sq_triangles_describe(t, &text, err), &text, a);
    sq_triangles_free(&t);
    sq_model_free(&m);
    return st;
}

static const sq_cli_opt triangulate_opts[] = {
    {.name = "output", .short_name = 'o', .kind = SQ_CLI_OUTPUT, .value = "FILE", .def = "none",
     .help = "the triangles as VTU (.vtu) or SVG (.svg)", .target = SQ_CLI_AT(output)},
    {.name = "order", .kind = SQ_CLI_INT, .value = "P", .lo = 1, .hi = 12, .def = "4",
     .help = "order of the curved triangles (1..12)", .target = SQ_CLI_AT(opt.tri_order)},
    {.name = "size", .kind = SQ_CLI_REAL, .value = "H", .lo = 1e-300, .hi = 1e300,
     .def = "sqrt(area)/3", .unit = "file unit", .help = "longest triangle edge",
     .target = SQ_CLI_AT(opt.tri_size)},
    {.name = "min-angle", .kind = SQ_CLI_REAL, .value = "A", .lo = 1.0, .hi = 30.0, .def = "20",
     .unit = "deg", .help = "smallest angle of CGAL's Delaunay refinement (1..30)",
     .target = SQ_CLI_AT(opt.tri_min_angle_deg)},
    {.name = "max-turn", .kind = SQ_CLI_REAL, .value = "T", .lo = 1.0, .hi = 90.0, .def = "30",
     .unit = "deg", .help = "largest turning of the boundary along one segment (1..90)",
     .target = SQ_CLI_AT(opt.tri_max_turn_deg)},
    SQ_CLI_OPT_SVG("a picture of the triangles"),
    SQ_CLI_OPT_REPORT,
    SQ_CLI_OPTS_READING,
    {0}};

const sq_cli_command sq_cli_triangulate = {
    .name = "triangulate",
    .summary = "Coarse curved triangulation of order P: CGAL constrained Delaunay refinement, "
               "high-order boundary nodes exactly on the CAD curves, every element's scaled "
               "Jacobian checked positive.",
    .example = "semquad triangulate examples/half_disc.step --order 6 -o half_disc.vtu",
    .opts = triangulate_opts,
    .run = run_triangulate};
