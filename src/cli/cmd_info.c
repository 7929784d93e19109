/* semquad info FILE [--face N] [--json] [--no-heal] [--heal-tolerance T] [-q]:
 * what a CAD file holds, every face with its status (sq_model_info). */
#include "cli.h"

#include <stdio.h>
#include <string.h>

sq_status sq_cmd_info(int argc, char **argv, sq_error *err)
{
    int json = 0;
    sq_cli_args a;
    sq_cli_args_init(&a);
    for (int i = 0; i < argc; i++) {
        int taken;
        SQ_TRY(sq_cli_take("info", argc, argv, &i, &a, &taken, err));
        if (taken) continue;
        if (!strcmp(argv[i], "--json"))
            json = 1;
        else
            return sq_cli_unknown("info", argv[i], err);
    }
    SQ_TRY(sq_cli_need_input("info", &a, err));
    if (a.output || a.svg || a.report)
        return SQ_FAIL(err, SQ_ERR_USAGE, "info: writes to standard output only (no -o, --svg, --report)");
    sq_model *m = NULL;
    SQ_TRY(sq_cli_open(&a, &m, err));
    char *text = NULL;
    sq_status st = sq_cli_print(sq_model_info(m, a.face, json, &text, err), &text);
    if (st == SQ_OK && fflush(stdout) != 0)
        st = SQ_FAIL(err, SQ_ERR_OUTPUT, "cannot write to standard output");
    sq_model_free(&m);
    return st;
}
