/* semquad field FILE [--face N] [--order P] [--method auto|cg|dg] [--size H]
 *   [--singularities FILE|natural] [--allow-misaligned]
 *   [--report out.json] [--vtu out.vtu] [--svg out.svg] [--quiet] */
#include "cli.h"
#include "write_field.h"
#include "write_htheta.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

/* The H/θ path (Jezdimirović 2021 §4–5): the pattern from a file or from
 * the guiding field (natural), then H, the branch cut and θ. */
static sq_status field_htheta(const char *path, int face, const cad_face *f,
                              const sq_field_options *opt, const char *sing, int allow_misaligned,
                              const char *vtu, const char *svg, const char *report, int quiet,
                              double t_read, sq_error *err)
{
    sq_pattern pat;
    sq_status st;
    if (!strcmp(sing, "natural")) {
        sq_field_analysis an;
        SQ_TRY(sq_field_analyse(f, opt, &an, err));
        st = sq_pattern_from_analysis(f, &an, &pat, err);
        sq_field_analysis_free(&an);
        SQ_TRY(st);
        if (pat.ndegenerate && !quiet)
            fprintf(stderr,
                    "semquad: note: %d degenerate singular point%s of the guiding field (|index| "
                    "> 1) split into elementary points\n",
                    pat.ndegenerate, pat.ndegenerate == 1 ? "" : "s");
    } else {
        SQ_TRY(sq_pattern_read(sing, &pat, err));
    }
    sq_htheta_options ho;
    sq_htheta_options_default(&ho);
    ho.order = opt->order;
    ho.tri.order = opt->tri.order;
    ho.tri.size = opt->tri.size;
    sq_htheta ht;
    st = sq_htheta_compute(f, &pat, &ho, &ht, err);
    sq_pattern_free(&pat);
    SQ_TRY(st);
    if (vtu) st = sq_write_htheta_vtu(vtu, &ht, err);
    if (st == SQ_OK && svg) st = sq_write_htheta_svg(svg, &ht, err);
    if (st == SQ_OK && report) st = sq_write_htheta_report(report, path, face, &ht, t_read, err);
    if (st == SQ_OK && !quiet) {
        printf("%s face %d: H-theta field CG P=%d on %d triangles (%ld dofs), branch cut of %d "
               "edges\n",
               path, face, ht.h.order, ht.tri.mesh->ntris, ht.h.ndofs, ht.theta.cut.nedges);
        printf("  Gauss-Bonnet: sum(4 - V) + sum(2 - n) = %d = 4 chi\n", ht.balance.lhs);
        printf("  %d singular point%s (jump of theta around each, expected (pi/2)(4 - V)):\n",
               ht.npoints, ht.npoints == 1 ? "" : "s");
        for (int k = 0; k < ht.npoints; k++)
            printf("    (%.9g, %.9g) valence %d %s: jump %.12f (error %.2e)\n", ht.points[k].x,
                   ht.points[k].y, ht.points[k].valence, sq_origin_name(ht.points[k].origin),
                   ht.points[k].jump, ht.points[k].jump - ht.points[k].c);
        for (int l = 0; l < ht.nloops; l++) {
            const sq_htheta_loop *L = &ht.loops[l];
            printf("  loop %d (%s): misalignment %.6f deg", l, l ? "hole" : "outer",
                   L->misalignment * 180.0 / M_PI);
            if (l)
                printf(", jump %.9f (expected %.9f, turning %.9f)", L->jump, L->expected_jump,
                       L->turning);
            printf(": %s\n", L->aligned ? "aligned" : "MISALIGNED");
        }
    }
    if (st == SQ_OK && !quiet) {
        sq_error w;
        if (sq_htheta_check_alignment(&ht, 0, &w) != SQ_OK)
            fprintf(stderr, "semquad: warning: %s%s\n", w.msg,
                    allow_misaligned ? " (proceeding: --allow-misaligned)" : "");
    }
    sq_htheta_free(&ht);
    return st;
}

sq_status sq_cmd_field(int argc, char **argv, sq_error *err)
{
    const char *val, *sing = NULL;
    int tri_order = 0, allow_misaligned = 0;
    sq_field_options opt;
    sq_field_options_default(&opt);
    sq_cli_args args;
    sq_cli_args_init(&args);
    for (int i = 0; i < argc; i++) {
        const char *a = argv[i];
        int taken;
        SQ_TRY(sq_cli_take("field", argc, argv, &i, &args, &taken, err));
        if (taken) continue;
        if (!strcmp(a, "--order")) {
            SQ_TRY(sq_cli_value(argc, argv, &i, &val, err));
            SQ_TRY(sq_cli_int(a, val, 1, 16, &opt.order, err));
        } else if (!strcmp(a, "--geom-order")) {
            SQ_TRY(sq_cli_value(argc, argv, &i, &val, err));
            SQ_TRY(sq_cli_int(a, val, 1, 12, &tri_order, err));
        } else if (!strcmp(a, "--method")) {
            SQ_TRY(sq_cli_value(argc, argv, &i, &val, err));
            SQ_TRY(sq_cli_method(val, &opt.method, err));
        } else if (!strcmp(a, "--size")) {
            SQ_TRY(sq_cli_value(argc, argv, &i, &val, err));
            SQ_TRY(sq_cli_double(a, val, 1e-300, 1e300, &opt.tri.size, err));
        } else if (!strcmp(a, "--vtu")) { /* alias of -o */
            SQ_TRY(sq_cli_value(argc, argv, &i, &args.output, err));
        } else if (!strcmp(a, "--singularities")) {
            SQ_TRY(sq_cli_value(argc, argv, &i, &sing, err));
        } else if (!strcmp(a, "--no-grading")) {
            opt.grading = 0.0; /* uniform triangulation near singular vertices */
        } else if (!strcmp(a, "--allow-misaligned")) {
            allow_misaligned = 1;
        } else {
            return sq_cli_unknown("field", a, err);
        }
    }
    SQ_TRY(sq_cli_need_input("field", &args, err));
    /* isoparametric unless told otherwise (the triangulation stops at 12) */
    opt.tri.order = tri_order ? tri_order : (opt.order < 12 ? opt.order : 12);

    double t0 = sq_now();
    cad_model *m = NULL;
    cad_face *f = NULL;
    const char *note;
    SQ_TRY(sq_cli_open_face(args.input, args.face, &args.read, &m, &f, &args.face, &note, err));
    double t_read = sq_now() - t0;
    if (note && !args.quiet) fprintf(stderr, "semquad: note: %s\n", note);
    if (sing) {
        sq_status hs = field_htheta(args.input, args.face, f, &opt, sing, allow_misaligned,
                                    args.output, args.svg, args.report, args.quiet, t_read, err);
        cad_face_free(&f);
        cad_model_free(&m);
        return hs;
    }
    sq_field_analysis an;
    sq_status st = sq_field_analyse(f, &opt, &an, err);
    if (st == SQ_OK && args.output) st = sq_write_field_vtu(args.output, &an, err);
    if (st == SQ_OK && args.svg) st = sq_write_field_svg(args.svg, &an, err);
    if (st == SQ_OK && args.report)
        st = sq_write_field_report(args.report, args.input, args.face, &an, t_read, err);
    if (st == SQ_OK && !args.quiet) {
        printf("%s face %d: guiding field %s P=%d on %d triangles (%ld dofs per component)\n",
               args.input, args.face, an.field.method == SEM_CG ? "CG" : "DG", an.field.order,
               an.tri.mesh->ntris, an.field.ndofs);
        printf("  %d singular point%s\n", an.npoints, an.npoints == 1 ? "" : "s");
        for (int k = 0; k < an.npoints; k++)
            printf("    (%.9f, %.9f) valence %d%s\n", an.points[k].x, an.points[k].y,
                   an.points[k].valence, an.points[k].near_boundary ? " (on the boundary)" : "");
        printf("  corners:\n");
        for (int k = 0; k < an.info.nvertices; k++)
            if (!an.info.vertices[k].smooth)
                printf("    (%.6g, %.6g) %.2f deg: %d quad%s\n", an.info.vertices[k].x,
                       an.info.vertices[k].y, an.info.vertices[k].angle_deg, an.corners[k].valence,
                       an.corners[k].valence == 1 ? "" : "s");
        printf("  Poincare-Hopf: sum(4 - V) + sum(2 - n) = %d, 4 chi = %d: %s\n", an.ph_lhs,
               an.ph_rhs, an.ph_lhs == an.ph_rhs ? "holds" : "VIOLATED");
    }
    if (st == SQ_OK && an.ph_lhs != an.ph_rhs && !args.quiet)
        fprintf(stderr,
                "semquad: warning: Poincare-Hopf check fails (%d != %d): a singular point "
                "was missed or misclassified\n",
                an.ph_lhs, an.ph_rhs);
    sq_field_analysis_free(&an);
    cad_face_free(&f);
    cad_model_free(&m);
    return st;
}
