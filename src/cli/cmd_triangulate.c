/* semquad triangulate FILE [--face N] [--order P] [--size H] [--min-angle A]
 *   [--max-turn T] [-o out.vtu] [--svg out.svg] [--report out.json] */
#include "cli.h"

#include <stdio.h>
#include <string.h>

sq_status sq_cmd_triangulate(int argc, char **argv, sq_error *err)
{
    const char *val;
    sq_cli_args args;
    sq_cli_args_init(&args);
    sq_options *o = &args.opt;
    for (int i = 0; i < argc; i++) {
        const char *a = argv[i];
        int taken;
        SQ_TRY(sq_cli_take("triangulate", argc, argv, &i, &args, &taken, err));
        if (taken) continue;
        if (!strcmp(a, "--order")) {
            SQ_TRY(sq_cli_value(argc, argv, &i, &val, err));
            SQ_TRY(sq_cli_int(a, val, 1, 12, &o->tri_order, err));
        } else if (!strcmp(a, "--size")) {
            SQ_TRY(sq_cli_value(argc, argv, &i, &val, err));
            SQ_TRY(sq_cli_double(a, val, 1e-300, 1e300, &o->tri_size, err));
        } else if (!strcmp(a, "--min-angle")) {
            SQ_TRY(sq_cli_value(argc, argv, &i, &val, err));
            SQ_TRY(sq_cli_double(a, val, 1.0, 30.0, &o->tri_min_angle_deg, err));
        } else if (!strcmp(a, "--max-turn")) {
            SQ_TRY(sq_cli_value(argc, argv, &i, &val, err));
            SQ_TRY(sq_cli_double(a, val, 1.0, 90.0, &o->tri_max_turn_deg, err));
        } else {
            return sq_cli_unknown("triangulate", a, err);
        }
    }
    SQ_TRY(sq_cli_need_input("triangulate", &args, err));
    sq_model *m = NULL;
    SQ_TRY(sq_cli_open(&args, &m, err));
    sq_triangles *t = NULL;
    sq_status st = sq_face_triangulate(m, args.face, o, &t, err);
    if (st == SQ_OK && args.output) st = sq_triangles_write(t, args.output, err);
    if (st == SQ_OK && args.svg) st = sq_triangles_write(t, args.svg, err);
    if (st == SQ_OK && args.report) st = sq_triangles_write_report(t, args.report, err);
    char *text = NULL;
    if (st == SQ_OK && !args.quiet) st = sq_cli_print(sq_triangles_describe(t, &text, err), &text);
    sq_triangles_free(&t);
    sq_model_free(&m);
    return st;
}
