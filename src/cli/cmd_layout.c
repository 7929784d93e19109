/* semquad layout FILE [--face N] [--order P] [--method auto|cg|dg] [--size H]
 *   [--merge-distance K] [-o patches.step] [--svg layout.svg]
 *   [--report out.json] [--quiet] */
#include "cli.h"

#include <stdio.h>
#include <string.h>

sq_status sq_cmd_layout(int argc, char **argv, sq_error *err)
{
    const char *val;
    sq_cli_args args;
    sq_cli_args_init(&args);
    sq_options *o = &args.opt;
    for (int i = 0; i < argc; i++) {
        const char *a = argv[i];
        int taken;
        SQ_TRY(sq_cli_take("layout", argc, argv, &i, &args, &taken, err));
        if (taken) continue;
        if (!strcmp(a, "--order")) {
            SQ_TRY(sq_cli_value(argc, argv, &i, &val, err));
            SQ_TRY(sq_cli_int(a, val, 1, 16, &o->field_order, err));
        } else if (!strcmp(a, "--method")) {
            SQ_TRY(sq_cli_value(argc, argv, &i, &o->method, err));
        } else if (!strcmp(a, "--size")) {
            SQ_TRY(sq_cli_value(argc, argv, &i, &val, err));
            SQ_TRY(sq_cli_double(a, val, 1e-300, 1e300, &o->tri_size, err));
        } else if (!strcmp(a, "--singularities")) {
            SQ_TRY(sq_cli_value(argc, argv, &i, &o->singularities, err));
        } else if (!strcmp(a, "--allow-misaligned")) {
            o->allow_misaligned = 1;
        } else if (!strcmp(a, "--merge-distance")) {
            SQ_TRY(sq_cli_value(argc, argv, &i, &val, err));
            SQ_TRY(sq_cli_double(a, val, 0.1, 1000.0, &o->merge_distance, err));
        } else {
            return sq_cli_unknown("layout", a, err);
        }
    }
    SQ_TRY(sq_cli_need_input("layout", &args, err));
    sq_model *m = NULL;
    SQ_TRY(sq_cli_open(&args, &m, err));
    sq_quad_layout *l = NULL;
    sq_status st = sq_face_layout(m, args.face, o, &l, err);
    /* an invalid layout is still drawn and reported, so it can be looked at */
    sq_status out = SQ_OK;
    if ((st == SQ_OK || st == SQ_ERR_LAYOUT) && args.svg) out = sq_quad_layout_write(l, args.svg, err);
    if (st == SQ_OK && out == SQ_OK && args.output) out = sq_quad_layout_write(l, args.output, err);
    if ((st == SQ_OK || st == SQ_ERR_LAYOUT) && out == SQ_OK && args.report)
        out = sq_quad_layout_write_report(l, args.report, err);
    char *text = NULL;
    if (st == SQ_OK && out == SQ_OK && !args.quiet)
        out = sq_cli_print(sq_quad_layout_describe(l, &text, err), &text);
    if (st == SQ_OK) st = out;
    sq_quad_layout_free(&l);
    sq_model_free(&m);
    return st;
}
