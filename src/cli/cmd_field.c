/* semquad field FILE [--face N] [--order P] [--method auto|cg|dg] [--size H]
 *   [--singularities FILE|natural] [--allow-misaligned]
 *   [--report out.json] [--vtu out.vtu] [--svg out.svg] [--quiet] */
#include "cli.h"

#include <stdio.h>
#include <string.h>

sq_status sq_cmd_field(int argc, char **argv, sq_error *err)
{
    const char *val;
    sq_cli_args args;
    sq_cli_args_init(&args);
    sq_options *o = &args.opt;
    for (int i = 0; i < argc; i++) {
        const char *a = argv[i];
        int taken;
        SQ_TRY(sq_cli_take("field", argc, argv, &i, &args, &taken, err));
        if (taken) continue;
        if (!strcmp(a, "--order")) {
            SQ_TRY(sq_cli_value(argc, argv, &i, &val, err));
            SQ_TRY(sq_cli_int(a, val, 1, 16, &o->field_order, err));
        } else if (!strcmp(a, "--geom-order")) {
            SQ_TRY(sq_cli_value(argc, argv, &i, &val, err));
            SQ_TRY(sq_cli_int(a, val, 1, 12, &o->tri_order, err));
        } else if (!strcmp(a, "--method")) {
            SQ_TRY(sq_cli_value(argc, argv, &i, &o->method, err));
        } else if (!strcmp(a, "--size")) {
            SQ_TRY(sq_cli_value(argc, argv, &i, &val, err));
            SQ_TRY(sq_cli_double(a, val, 1e-300, 1e300, &o->tri_size, err));
        } else if (!strcmp(a, "--vtu")) { /* alias of -o */
            SQ_TRY(sq_cli_value(argc, argv, &i, &args.output, err));
        } else if (!strcmp(a, "--singularities")) {
            SQ_TRY(sq_cli_value(argc, argv, &i, &o->singularities, err));
        } else if (!strcmp(a, "--no-grading")) {
            o->field_grading = 0; /* uniform triangulation near singular vertices */
        } else if (!strcmp(a, "--allow-misaligned")) {
            o->allow_misaligned = 1;
        } else {
            return sq_cli_unknown("field", a, err);
        }
    }
    SQ_TRY(sq_cli_need_input("field", &args, err));
    sq_model *m = NULL;
    SQ_TRY(sq_cli_open(&args, &m, err));
    sq_field *f = NULL;
    sq_status st = sq_face_field(m, args.face, o, &f, err);
    if (st == SQ_OK && args.output) st = sq_field_write(f, args.output, err);
    if (st == SQ_OK && args.svg) st = sq_field_write(f, args.svg, err);
    if (st == SQ_OK && args.report) st = sq_field_write_report(f, args.report, err);
    char *text = NULL;
    if (st == SQ_OK && !args.quiet) st = sq_cli_print(sq_field_describe(f, &text, err), &text);
    sq_field_free(&f);
    sq_model_free(&m);
    return st;
}
