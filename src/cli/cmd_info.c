/* semquad info FILE [--face N] [--json] [--no-heal] [--heal-tolerance T] [-q]:
 * what a CAD file holds, every face with its status (sq_model_info). */
#include "cli.h"

#include <stdio.h>

static sq_status run_info(sq_cli_args *a, sq_error *err)
{
    sq_model *m = NULL;
    SQ_TRY(sq_cli_open(a, &m, err));
    char *text = NULL;
    sq_status st = sq_cli_print(sq_model_info(m, a->face, a->json, &text, err), &text, a);
    if (st == SQ_OK && fflush(stdout) != 0)
        st = SQ_FAIL(err, SQ_ERR_OUTPUT, "cannot write to standard output");
    sq_model_free(&m);
    return st;
}

static const sq_cli_opt info_opts[] = {
    {.name = "face", .kind = SQ_CLI_INT, .value = "N", .lo = 0, .hi = 1000000, .def = "all faces",
     .help = "describe this face only", .target = SQ_CLI_AT(face), .shared = 1},
    {.name = "json", .kind = SQ_CLI_FLAG, .set = 1, .def = "text",
     .help = "print JSON (docs/conventions.md, the report)", .target = SQ_CLI_AT(json)},
    SQ_CLI_OPT_HEAL_TOLERANCE,
    SQ_CLI_OPT_NO_HEAL,
    SQ_CLI_OPT_QUIET,
    {0}};

const sq_cli_command sq_cli_info = {
    .name = "info",
    .summary = "Every face with its status (ok, healed, not planar, broken: reason), boundary "
               "loops, edges (name, type, length), corners (angle), chi, area, what was healed; "
               "on standard output (exit 0 even with broken faces).",
    .example = "semquad info examples/half_disc.step --json",
    .opts = info_opts,
    .run = run_info};
