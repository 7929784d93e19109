/* semquad field FILE: the guiding field or the H/theta field of a pattern,
 * its singular points (sq_face_field). */
#include "cli.h"

static sq_status run_field(sq_cli_args *a, sq_error *err)
{
    sq_model *m = NULL;
    SQ_TRY(sq_cli_open(a, &m, err));
    sq_field *f = NULL;
    sq_status st = sq_face_field(m, a->face, &a->opt, &f, err);
    if (st == SQ_OK && a->output) st = sq_field_write(f, a->output, err);
    if (st == SQ_OK && a->svg) st = sq_field_write(f, a->svg, err);
    if (st == SQ_OK && a->report) st = sq_field_write_report(f, a->report, err);
    char *text = NULL;
    if (st == SQ_OK && !a->quiet) st = sq_cli_print(sq_field_describe(f, &text, err), &text, a);
    sq_field_free(&f);
    sq_model_free(&m);
    return st;
}

static const sq_cli_opt field_opts[] = {
    {.name = "output", .short_name = 'o', .kind = SQ_CLI_OUTPUT, .value = "FILE", .def = "none",
     .help = "the field as VTU (.vtu: u, v, psi; H, theta with --singularities) or SVG",
     .target = SQ_CLI_AT(output)},
    {.name = "vtu", .kind = SQ_CLI_OUTPUT, .value = "FILE", .def = "none",
     .help = "the same as -o", .target = SQ_CLI_AT(output)},
    SQ_CLI_OPT_FIELD_ORDER("8"),
    SQ_CLI_OPT_METHOD,
    SQ_CLI_OPT_FIELD_SIZE,
    {.name = "geom-order", .kind = SQ_CLI_INT, .value = "G", .lo = 1, .hi = 12,
     .def = "the field's order, at most 12", .help = "order of the curved triangles (1..12)",
     .target = SQ_CLI_AT(opt.tri_order)},
    SQ_CLI_OPT_SINGULARITIES,
    SQ_CLI_OPT_ALLOW_MISALIGNED,
    {.name = "no-grading", .kind = SQ_CLI_FLAG, .set = 0, .def = "graded",
     .help = "no hp grading of the triangulation towards singular corners",
     .target = SQ_CLI_AT(opt.field_grading)},
    SQ_CLI_OPT_SVG("crosses, zero contours and singular points"),
    SQ_CLI_OPT_REPORT,
    SQ_CLI_OPTS_READING,
    SQ_CLI_OPT_ORDER_ALIAS,
    {0}};

const sq_cli_command sq_cli_field = {
    .name = "field",
    .summary = "The guiding field (u,v) = (cos 4t, sin 4t) of Marcon et al. 2019, its critical "
               "points with valences, the corner valences, the Poincare-Hopf check. With "
               "--singularities, the H and theta fields of an imposed pattern (FILE: lines "
               "'x y valence' and 'corner x y quads'; natural: the guiding field's points): "
               "Gauss-Bonnet check (exit 5), branch cut, holonomy.",
    .example = "semquad field examples/half_disc.step --field-order 8 --svg field.svg",
    .opts = field_opts,
    .run = run_field};
