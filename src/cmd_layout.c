/* semquad layout FILE [--face N] [--order P] [--method auto|cg|dg] [--size H]
 *   [--merge-distance K] [-o patches.step] [--svg layout.svg]
 *   [--report out.json] [--quiet] */
#include "cli.h"
#include "write_layout.h"

#include <stdio.h>
#include <string.h>

sq_status sq_cmd_layout(int argc, char **argv, sq_error *err)
{
    const char *val;
    sq_layout_options opt;
    sq_layout_options_default(&opt);
    sq_cli_args args;
    sq_cli_args_init(&args);
    for (int i = 0; i < argc; i++) {
        const char *a = argv[i];
        int taken;
        SQ_TRY(sq_cli_take("layout", argc, argv, &i, &args, &taken, err));
        if (taken) continue;
        if (!strcmp(a, "--order")) {
            SQ_TRY(sq_cli_value(argc, argv, &i, &val, err));
            SQ_TRY(sq_cli_int(a, val, 1, 16, &opt.field.order, err));
        } else if (!strcmp(a, "--method")) {
            SQ_TRY(sq_cli_value(argc, argv, &i, &val, err));
            SQ_TRY(sq_cli_method(val, &opt.field.method, err));
        } else if (!strcmp(a, "--size")) {
            SQ_TRY(sq_cli_value(argc, argv, &i, &val, err));
            SQ_TRY(sq_cli_double(a, val, 1e-300, 1e300, &opt.field.tri.size, err));
        } else if (!strcmp(a, "--singularities")) {
            SQ_TRY(sq_cli_value(argc, argv, &i, &opt.singularities, err));
        } else if (!strcmp(a, "--allow-misaligned")) {
            opt.allow_misaligned = 1;
        } else if (!strcmp(a, "--merge-distance")) {
            SQ_TRY(sq_cli_value(argc, argv, &i, &val, err));
            SQ_TRY(sq_cli_double(a, val, 0.1, 1000.0, &opt.trace.merge_distance, err));
        } else {
            return sq_cli_unknown("layout", a, err);
        }
    }
    SQ_TRY(sq_cli_need_input("layout", &args, err));
    opt.field.tri.order = opt.field.order < 12 ? opt.field.order : 12;

    double t0 = sq_now();
    cad_model *m = NULL;
    cad_face *f = NULL;
    const char *note;
    SQ_TRY(sq_cli_open_face(args.input, args.face, &args.read, &m, &f, &args.face, &note, err));
    double t_read = sq_now() - t0, t_split = -1.0;
    if (note && !args.quiet) fprintf(stderr, "semquad: note: %s\n", note);
    sq_layout_result r;
    sq_status st = sq_layout_run(f, &opt, &r, err);
    char split[512];
    if ((st == SQ_OK || st == SQ_ERR_LAYOUT) && !args.quiet &&
        sq_layout_note(&r, split, sizeof split))
        fprintf(stderr, "semquad: note: %s\n", split);
    /* an invalid layout is still drawn and reported, so it can be looked at */
    sq_status out = SQ_OK;
    if ((st == SQ_OK || st == SQ_ERR_LAYOUT) && args.svg)
        out = sq_write_layout_svg(args.svg, &r, err);
    if (st == SQ_OK && out == SQ_OK && args.output) {
        double t1 = sq_now();
        out = sq_write_layout_step(args.output, m, args.face, f, &r.layout, NULL, err);
        t_split = sq_now() - t1;
    }
    if ((st == SQ_OK || st == SQ_ERR_LAYOUT) && out == SQ_OK && args.report)
        out = sq_write_layout_report(args.report, args.input, args.face, &r, t_read, t_split, err);
    if (st == SQ_OK && out == SQ_OK && !args.quiet) {
        const sq_layout_stats *s = &r.layout.stats;
        printf("%s face %d: %d singular points, %d separatrices, %d quad patches; repairs: %d "
               "limit cycles, %d T-junctions, %d triangles, %d valence-2 points, %d annuli, %d "
               "duplicates, %d crossings\n",
               args.input, args.face, r.nsing, s->separatrices, s->quad_patches,
               s->limit_cycles_cut, s->t_junctions, s->triangles_repaired, s->valence2_split,
               s->annuli_cut, s->duplicates_removed, s->crossings_split);
    }
    if (st == SQ_OK) st = out;
    if (st == SQ_OK || st == SQ_ERR_LAYOUT) sq_layout_result_free(&r);
    cad_face_free(&f);
    cad_model_free(&m);
    return st;
}
