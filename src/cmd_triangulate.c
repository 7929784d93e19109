/* semquad triangulate FILE [--face N] [--order P] [--size H] [--min-angle A]
 *   [--max-turn T] [-o out.vtu] [--svg out.svg] [--report out.json] */
#include "cli.h"
#include "write_tri.h"

#include <stdio.h>
#include <string.h>

sq_status sq_cmd_triangulate(int argc, char **argv, sq_error *err)
{
    const char *val;
    sq_tri_options opt;
    sq_tri_options_default(&opt);
    sq_cli_args args;
    sq_cli_args_init(&args);
    for (int i = 0; i < argc; i++) {
        const char *a = argv[i];
        int taken;
        SQ_TRY(sq_cli_take("triangulate", argc, argv, &i, &args, &taken, err));
        if (taken) continue;
        if (!strcmp(a, "--order")) {
            SQ_TRY(sq_cli_value(argc, argv, &i, &val, err));
            SQ_TRY(sq_cli_int(a, val, 1, 12, &opt.order, err));
        } else if (!strcmp(a, "--size")) {
            SQ_TRY(sq_cli_value(argc, argv, &i, &val, err));
            SQ_TRY(sq_cli_double(a, val, 1e-300, 1e300, &opt.size, err));
        } else if (!strcmp(a, "--min-angle")) {
            SQ_TRY(sq_cli_value(argc, argv, &i, &val, err));
            SQ_TRY(sq_cli_double(a, val, 1.0, 30.0, &opt.min_angle_deg, err));
        } else if (!strcmp(a, "--max-turn")) {
            SQ_TRY(sq_cli_value(argc, argv, &i, &val, err));
            SQ_TRY(sq_cli_double(a, val, 1.0, 90.0, &opt.max_turn_deg, err));
        } else {
            return sq_cli_unknown("triangulate", a, err);
        }
    }
    SQ_TRY(sq_cli_need_input("triangulate", &args, err));

    cad_model *m = NULL;
    cad_face *f = NULL;
    const char *note;
    SQ_TRY(sq_cli_open_face(args.input, args.face, &args.read, &m, &f, &args.face, &note, err));
    if (note && !args.quiet) fprintf(stderr, "semquad: note: %s\n", note);
    sq_triangulation t;
    sq_status st = sq_triangulate(f, &opt, &t, err);
    if (st == SQ_OK && args.output) st = sq_write_tri_vtu(args.output, &t, err);
    if (st == SQ_OK && args.svg) st = sq_write_tri_svg(args.svg, &t, err);
    if (st == SQ_OK && args.report)
        st = sq_write_tri_report(args.report, args.input, args.face, &t, err);
    if (st == SQ_OK && !args.quiet)
        printf("%s face %d: %d triangles of order %d, min angle %.2f deg, min scaled Jacobian "
               "%.4f, area %.12g\n",
               args.input, args.face, t.mesh->ntris, t.mesh->order, t.min_angle_deg,
               t.min_scaled_jacobian, t.area);
    sq_triangulation_free(&t);
    cad_face_free(&f);
    cad_model_free(&m);
    return st;
}
