/* semquad mesh FILE [--face N] [--order Q] [--size h] [--field-order P]
 *   [--method auto|cg|dg] [--merge-distance K] [--nodes gll|equispaced]
 *   [--bl E1,E2,... --bl-first d --bl-ratio r --bl-layers n] [--max-quads N]
 *   [--road auto|layout|split] [-o out.msh|.xml|.vtu] [--svg F] [--report F] [-q] */
#include "cli.h"
#include "quad_mesher.h"
#include "quad_split.h"
#include "write_mesh_report.h"
#include "write_msh.h"
#include "write_nektar.h"
#include "write_quad_svg.h"
#include "write_quad_vtu.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

/* without --size: halvings of the default size tried when quads fold */
#define DEFAULT_SIZE_HALVINGS 3

/* Appended to a cusp's refusal: why healing left it, the option that
 * would blunt it (cad.h: a segment of CAD_CUSP_MIN_SEGMENT of the face's
 * size at least; the 2D box's diagonal bounds that size from above). */
static void cusp_hint(const cad_model *model, const sq_face_info *fi, sq_error *err)
{
    size_t len = strlen(err->msg);
    double tol = cad_model_heal_tolerance(model);
    double need = CAD_CUSP_MIN_SEGMENT * hypot(fi->bbox[2] - fi->bbox[0], fi->bbox[3] - fi->bbox[1]);
    if (tol <= 0)
        snprintf(err->msg + len, sizeof err->msg - len, "; --no-heal keeps it (healing blunts it)");
    else
        snprintf(err->msg + len, sizeof err->msg - len,
                 "; healing could not blunt it within the tolerance %.3g (--heal-tolerance %.2g "
                 "would, if the edges part by that within half their length)",
                 tol, fmax(1.05 * need, tol * 1.5));
}

static int ends_with(const char *s, const char *suffix)
{
    size_t n = strlen(s), k = strlen(suffix);
    return n >= k && !strcmp(s + n - k, suffix);
}

static sq_status write_mesh(const char *path, const sq_quad_mesh *m, sq_error *err)
{
    if (ends_with(path, ".msh")) return sq_write_msh(path, m, err);
    if (ends_with(path, ".xml")) return sq_write_nektar(path, m, err);
    if (ends_with(path, ".vtu")) return sq_write_quad_vtu(path, m, err);
    return SQ_FAIL(err, SQ_ERR_USAGE, "%s: unknown mesh format (use .msh, .xml or .vtu)", path);
}

static void progress(int quiet, const char *fmt, const char *a, double t)
{
    if (!quiet) {
        fprintf(stderr, fmt, a);
        fprintf(stderr, " (%.3f s)\n", t);
    }
}

typedef enum { ROAD_AUTO = 0, ROAD_LAYOUT, ROAD_SPLIT } road_kind;

/* Falls back on the split road (quad_split.h): what the layout road could
 * not do on a face the split road may mesh; not a usage, input or output
 * error, not a pattern the user imposed, not boundary layers (which need
 * the layout's chords). */
static int takes_split_road(sq_status st, const sq_layout_options *lo, const sq_mesher_options *mo)
{
    return (st == SQ_ERR_LAYOUT || st == SQ_ERR_INTERNAL || st == SQ_ERR_GEOMETRY ||
            st == SQ_ERR_PATTERN) &&
           !lo->singularities && mo->nbl == 0;
}

static void layout_progress(const sq_layout_result *r, const sq_mesh_timings *t)
{
    fprintf(stderr, "semquad: %s field %s P=%d on %d triangles (%.3f s)\n", r->field.kind,
            r->field.method == SEM_CG ? "CG" : "DG", r->field.order, r->field.triangles,
            t->triangulate + t->solve);
    fprintf(stderr, "semquad: %d singular points, %d separatrices, %d quad patches (%.3f s)\n",
            r->nsing, r->layout.stats.separatrices, r->layout.stats.quad_patches,
            t->critical_points + t->trace + t->layout);
}

/* Mesh by `mesh(ctx, &m)` at mo's size; without --size the default,
 * sqrt(area)/8, can be too coarse for a small curved feature (an aerofoil
 * in a large box: its curved quads fold): halve it, a few times, rather
 * than fail. */
typedef sq_status (*mesh_fn)(void *ctx, const sq_mesher_options *mo, sq_quad_mesh **m, sq_error *err);

static sq_status mesh_halving(mesh_fn mesh, void *ctx, sq_mesher_options mo, double default_size,
                              int size_given, int quiet, sq_quad_mesh **m, sq_quad_quality *q,
                              sq_error *err)
{
    sq_status st = SQ_OK;
    for (int k = 0;; k++) {
        if (k > 0) {
            mo.size = default_size / (double)(1 << k);
            if (!quiet)
                fprintf(stderr, "semquad: note: %d quads fold at size %.4g; trying %.4g\n",
                        q->inverted, 2.0 * mo.size, mo.size);
            sq_quad_mesh_free(m);
        }
        st = mesh(ctx, &mo, m, err);
        if (st == SQ_OK) st = sq_quad_mesh_quality(*m, NULL, NULL, q, err);
        if (size_given || st != SQ_OK || q->inverted == 0 || k == DEFAULT_SIZE_HALVINGS) break;
    }
    if (st == SQ_OK && q->inverted > 0)
        st = SQ_FAIL(err, SQ_ERR_LAYOUT,
                     "%d quads have a non-positive Jacobian (min scaled Jacobian %.3g); try a "
                     "smaller --size",
                     q->inverted, q->min_scaled_jacobian);
    if (st != SQ_OK) sq_quad_mesh_free(m);
    return st;
}

typedef struct {
    const cad_face *face;
    const sq_layout_result *r;
} layout_ctx;

static sq_status mesh_by_layout(void *ctx, const sq_mesher_options *mo, sq_quad_mesh **m,
                                sq_error *err)
{
    const layout_ctx *c = ctx;
    return sq_mesh_layout(c->face, c->r->info, &c->r->layout, mo, m, err);
}

typedef struct {
    const cad_face *face;
    const sq_face_info *info;
} split_ctx;

static sq_status mesh_by_split(void *ctx, const sq_mesher_options *mo, sq_quad_mesh **m,
                               sq_error *err)
{
    const split_ctx *c = ctx;
    return sq_mesh_split(c->face, c->info, mo, m, err);
}

/* The layout road: field, layout (sq_layout_run), quads (sq_mesh_layout). */
static sq_status layout_road(const cad_face *f, const sq_layout_options *lo, sq_mesher_options *mo,
                             int size_given, int quiet, sq_layout_result *r, sq_quad_mesh **m,
                             sq_quad_quality *q, sq_mesh_timings *t, sq_error *err)
{
    sq_status st = sq_layout_run(f, lo, r, err);
    char split[512];
    if ((st == SQ_OK || st == SQ_ERR_LAYOUT) && !quiet && sq_layout_note(r, split, sizeof split))
        fprintf(stderr, "semquad: note: %s\n", split);
    if (st != SQ_OK) return st;
    t->triangulate = r->field.t_triangulate;
    t->solve = r->field.t_solve;
    t->critical_points = r->field.t_critical;
    t->trace = r->t_trace;
    t->layout = r->t_layout;
    if (!quiet) layout_progress(r, t);
    double t1 = sq_now();
    /* sizes from e^H where the H/θ field was traced */
    sq_cross_field cf;
    if (!strcmp(r->field.kind, "H-theta")) {
        cf = sq_htheta_cross_field(&r->htheta);
        mo->field = &cf;
    }
    layout_ctx c = {f, r};
    st = mesh_halving(mesh_by_layout, &c, *mo, sq_mesher_default_size(r->layout.face_area),
                      size_given, quiet, m, q, err);
    mo->field = NULL;
    t->mesh = sq_now() - t1;
    return st;
}

static sq_status split_road(const cad_face *f, const sq_face_info *fi, const sq_mesher_options *mo,
                            int size_given, int quiet, sq_quad_mesh **m, sq_quad_quality *q,
                            sq_error *err)
{
    split_ctx c = {f, fi};
    return mesh_halving(mesh_by_split, &c, *mo, sq_mesher_default_size(fi->area), size_given,
                        quiet, m, q, err);
}

sq_status sq_cmd_mesh(int argc, char **argv, sq_error *err)
{
    const char *val;
    int bl[64], size_given = 0;
    road_kind road_choice = ROAD_AUTO;
    sq_layout_options lo;
    sq_layout_options_for_mesh(&lo);
    sq_mesher_options mo;
    sq_mesher_options_default(&mo);
    sq_cli_args args;
    sq_cli_args_init(&args);
    for (int i = 0; i < argc; i++) {
        const char *a = argv[i];
        int taken;
        SQ_TRY(sq_cli_take("mesh", argc, argv, &i, &args, &taken, err));
        if (taken) continue;
        if (!strcmp(a, "--order")) {
            SQ_TRY(sq_cli_value(argc, argv, &i, &val, err));
            SQ_TRY(sq_cli_int(a, val, 1, 10, &mo.order, err));
        } else if (!strcmp(a, "--size")) {
            SQ_TRY(sq_cli_value(argc, argv, &i, &val, err));
            SQ_TRY(sq_cli_double(a, val, 1e-300, 1e300, &mo.size, err));
            size_given = 1;
        } else if (!strcmp(a, "--field-order")) {
            SQ_TRY(sq_cli_value(argc, argv, &i, &val, err));
            SQ_TRY(sq_cli_int(a, val, 1, 16, &lo.field.order, err));
            lo.htheta.order = lo.field.order;
        } else if (!strcmp(a, "--method")) {
            SQ_TRY(sq_cli_value(argc, argv, &i, &val, err));
            SQ_TRY(sq_cli_method(val, &lo.field.method, err));
        } else if (!strcmp(a, "--singularities")) {
            SQ_TRY(sq_cli_value(argc, argv, &i, &lo.singularities, err));
        } else if (!strcmp(a, "--allow-misaligned")) {
            lo.allow_misaligned = 1;
        } else if (!strcmp(a, "--merge-distance")) {
            SQ_TRY(sq_cli_value(argc, argv, &i, &val, err));
            SQ_TRY(sq_cli_double(a, val, 0.1, 1000.0, &lo.trace.merge_distance, err));
        } else if (!strcmp(a, "--bl")) {
            SQ_TRY(sq_cli_value(argc, argv, &i, &val, err));
            SQ_TRY(sq_cli_int_list(a, val, 0, 1000000, bl, (int)(sizeof bl / sizeof *bl), &mo.nbl,
                                   err));
            mo.bl_edges = bl;
        } else if (!strcmp(a, "--bl-first")) {
            SQ_TRY(sq_cli_value(argc, argv, &i, &val, err));
            SQ_TRY(sq_cli_double(a, val, 1e-300, 1e300, &mo.bl_first, err));
        } else if (!strcmp(a, "--bl-ratio")) {
            SQ_TRY(sq_cli_value(argc, argv, &i, &val, err));
            SQ_TRY(sq_cli_double(a, val, 1.0, 10.0, &mo.bl_ratio, err));
        } else if (!strcmp(a, "--bl-layers")) {
            SQ_TRY(sq_cli_value(argc, argv, &i, &val, err));
            SQ_TRY(sq_cli_int(a, val, 1, 1000, &mo.bl_layers, err));
        } else if (!strcmp(a, "--max-quads")) {
            SQ_TRY(sq_cli_value(argc, argv, &i, &val, err));
            SQ_TRY(sq_cli_double(a, val, 1.0, 1e15, &mo.max_quads, err));
        } else if (!strcmp(a, "--road")) {
            SQ_TRY(sq_cli_value(argc, argv, &i, &val, err));
            if (!strcmp(val, "auto")) road_choice = ROAD_AUTO;
            else if (!strcmp(val, "layout")) road_choice = ROAD_LAYOUT;
            else if (!strcmp(val, "split")) road_choice = ROAD_SPLIT;
            else
                return SQ_FAIL(err, SQ_ERR_USAGE, "--road expects auto, layout or split, got '%s'",
                               val);
        } else if (!strcmp(a, "--nodes")) {
            SQ_TRY(sq_cli_value(argc, argv, &i, &val, err));
            if (!strcmp(val, "gll"))
                mo.nodes = SQ_NODES_GLL;
            else if (!strcmp(val, "equispaced"))
                mo.nodes = SQ_NODES_EQUISPACED;
            else
                return SQ_FAIL(err, SQ_ERR_USAGE, "--nodes expects gll or equispaced, got '%s'",
                               val);
        } else {
            return sq_cli_unknown("mesh", a, err);
        }
    }
    SQ_TRY(sq_cli_need_input("mesh", &args, err));
    if (mo.nbl > 0 && (!(mo.bl_first > 0.0) || mo.bl_layers < 1))
        return SQ_FAIL(err, SQ_ERR_USAGE, "--bl needs --bl-first d > 0 and --bl-layers n >= 1");
    if (args.output && !ends_with(args.output, ".msh") && !ends_with(args.output, ".xml") &&
        !ends_with(args.output, ".vtu"))
        return SQ_FAIL(err, SQ_ERR_USAGE, "%s: unknown mesh format (use .msh, .xml or .vtu)",
                       args.output);
    lo.field.tri.order = lo.field.order < 12 ? lo.field.order : 12;
    lo.htheta.tri.order = lo.htheta.order < 12 ? lo.htheta.order : 12;

    sq_mesh_timings t = {0};
    double t0 = sq_now();
    cad_model *model = NULL;
    cad_face *f = NULL;
    const char *note;
    SQ_TRY(sq_cli_open_face(args.input, args.face, &args.read, &model, &f, &args.face, &note, err));
    t.read = sq_now() - t0;
    if (note && !args.quiet) fprintf(stderr, "semquad: note: %s\n", note);
    char healed[1024];
    if (!args.quiet && sq_cli_heal_note(model, args.face, healed, sizeof healed))
        fprintf(stderr, "semquad: %s\n", healed);
    progress(args.quiet, "semquad: read %s", args.input, t.read);
    sq_face_info fi;
    sq_status st = sq_face_info_compute(f, &fi, err);
    if (st == SQ_OK && (st = sq_face_check_cusps(&fi, err)) != SQ_OK) cusp_hint(model, &fi, err);
    /* a --size that would exhaust memory is refused before any work */
    if (st == SQ_OK && size_given) st = sq_mesher_check_size(fi.area, mo.size, mo.max_quads, err);
    sq_layout_result r;
    memset(&r, 0, sizeof r);
    sq_quad_mesh *m = NULL;
    sq_quad_quality q;
    sq_mesh_road road = {road_choice == ROAD_SPLIT ? "split" : "layout", ""};
    int layout_ran = st == SQ_OK && road_choice != ROAD_SPLIT;
    if (layout_ran) st = layout_road(f, &lo, &mo, size_given, args.quiet, &r, &m, &q, &t, err);
    if (layout_ran && road_choice == ROAD_AUTO && takes_split_road(st, &lo, &mo)) {
        snprintf(road.reason, sizeof road.reason, "%s", err->msg);
        if (!args.quiet)
            fprintf(stderr, "semquad: note: the layout road failed (%s); meshing by the split road\n",
                    err->msg);
        road.name = "split";
        sq_quad_mesh_free(&m);
        st = SQ_OK;
    }
    if (st == SQ_OK && !strcmp(road.name, "split")) {
        double t1 = sq_now();
        st = split_road(f, &fi, &mo, size_given, args.quiet, &m, &q, err);
        t.mesh = sq_now() - t1;
        if (st != SQ_OK && road.reason[0]) {
            char split_msg[sizeof err->msg];
            snprintf(split_msg, sizeof split_msg, "%s", err->msg);
            st = SQ_FAIL(err, st, "%s (the split road; the layout road: %s)", split_msg, road.reason);
        }
    }
    if (st == SQ_OK) {
        char line[256];
        sq_quad_quality_line(m, &q, line, sizeof line);
        if (!args.quiet) fprintf(stderr, "semquad: meshed (%.3f s)\n", t.mesh);
        double t2 = sq_now();
        if (args.output) st = write_mesh(args.output, m, err);
        if (st == SQ_OK && args.svg) st = sq_write_quad_svg(args.svg, m, err);
        t.write = sq_now() - t2;
        t.total = sq_now() - t0;
        if (st == SQ_OK && args.report)
            st = sq_write_mesh_report(args.report, args.input, model, args.face, &fi, &road, &r, m,
                                      &q, &t, err);
        if (st == SQ_OK && !args.quiet) printf("%s\n", line);
    }
    sq_face_info_free(&fi);
    sq_quad_mesh_free(&m);
    sq_layout_result_free(&r);
    cad_face_free(&f);
    cad_model_free(&model);
    return st;
}
