/* semquad layout FILE: separatrices, the quad layout and its repairs, the
 * face split into patches (sq_face_layout). */
#include "cli.h"

static sq_status run_layout(sq_cli_args *a, sq_error *err)
{
    sq_model *m = NULL;
    SQ_TRY(sq_cli_open(a, &m, err));
    sq_quad_layout *l = NULL;
    sq_status st = sq_face_layout(m, a->face, &a->opt, &l, err);
    /* an invalid layout is still drawn and reported, so it can be looked at */
    sq_status out = SQ_OK;
    if ((st == SQ_OK || st == SQ_ERR_LAYOUT) && a->svg) out = sq_quad_layout_write(l, a->svg, err);
    if (st == SQ_OK && out == SQ_OK && a->output) out = sq_quad_layout_write(l, a->output, err);
    if ((st == SQ_OK || st == SQ_ERR_LAYOUT) && out == SQ_OK && a->report)
        out = sq_quad_layout_write_report(l, a->report, err);
    char *text = NULL;
    if (st == SQ_OK && out == SQ_OK && !a->quiet)
        out = sq_cli_print(sq_quad_layout_describe(l, &text, err), &text, a);
    if (st == SQ_OK) st = out;
    sq_quad_layout_free(&l);
    sq_model_free(&m);
    return st;
}

static const sq_cli_opt layout_opts[] = {
    {.name = "output", .short_name = 'o', .kind = SQ_CLI_OUTPUT, .value = "FILE", .def = "none",
     .help = "the face split into its patches, as STEP (.step)", .target = SQ_CLI_AT(output)},
    SQ_CLI_OPT_FIELD_ORDER("8"),
    SQ_CLI_OPT_METHOD,
    SQ_CLI_OPT_FIELD_SIZE,
    SQ_CLI_OPT_MERGE_DISTANCE,
    SQ_CLI_OPT_SINGULARITIES,
    SQ_CLI_OPT_ALLOW_MISALIGNED,
    SQ_CLI_OPT_PERIODIC,
    SQ_CLI_OPT_SVG("the layout: patches, separatrices, singular points, repairs"),
    SQ_CLI_OPT_REPORT,
    SQ_CLI_OPT_PROGRESS,
    SQ_CLI_OPTS_READING,
    SQ_CLI_OPT_ORDER_ALIAS,
    {0}};

const sq_cli_command sq_cli_layout = {
    .name = "layout",
    .summary = "Quad layout: separatrices traced from the singular points and corners "
               "(Adams-Bashforth 4), merged, corrected until every patch is a quad; the face "
               "split into the patches (STEP). Exit 6 if no valid layout can be made; the "
               "invalid layout is still drawn (--svg) and reported (--report).",
    .example = "semquad layout examples/half_disc.step -o patches.step --svg layout.svg",
    .opts = layout_opts,
    .run = run_layout};
