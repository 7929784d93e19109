/* semquad mesh FILE: the block-structured high-order quad mesh of a face,
 * or of several as one conforming mesh (sq_model_mesh), written where -o says, else beside the current
 * directory's other files as <input stem>.msh. */
#include "cli.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static sq_status parse_bl(const char *opt, const char *val, sq_cli_args *a, sq_error *err)
{
    a->opt.bl_edges = a->bl;
    return sq_cli_int_list(opt, val, 0, 1000000, a->bl, SQ_CLI_MAX_LIST, &a->opt.nbl, err);
}

static sq_status parse_orders(const char *opt, const char *val, sq_cli_args *a, sq_error *err)
{
    return sq_cli_int_list(opt, val, 1, 10, a->orders, SQ_CLI_MAX_LIST, &a->norders, err);
}

static sq_status parse_threads(const char *opt, const char *val, sq_cli_args *a, sq_error *err)
{
    a->threads_set = 1;
    return sq_cli_int(opt, val, 0, 256, &a->opt.threads, err);
}

/* Without --threads, SEMQUAD_THREADS where set (0: every processor). */
static sq_status threads_from_env(sq_cli_args *a, sq_error *err)
{
    const char *env = getenv("SEMQUAD_THREADS");
    if (a->threads_set || !env || !*env) return SQ_OK;
    return sq_cli_int("SEMQUAD_THREADS", env, 0, 256, &a->opt.threads, err);
}

static sq_status parse_faces(const char *opt, const char *val, sq_cli_args *a, sq_error *err)
{
    return sq_cli_int_list(opt, val, 0, 1000000, a->faces, SQ_CLI_MAX_LIST, &a->nfaces, err);
}

/* The mesh's format word: --format, else -o's extension ("" without
 * one), else msh. */
static const char *format_word(const sq_cli_args *a)
{
    const char *ext = a->output ? strrchr(a->output, '.') : NULL;
    return a->format ? a->format : a->output ? (ext ? ext + 1 : "") : "msh";
}

/* The mesh file: -o, else <input stem>.<format> in the current directory
 * (name[n] holds it), none with --no-output; its format --format, else
 * -o's extension.  Checked before any work. */
static sq_status mesh_file(sq_cli_args *a, char *name, size_t n, sq_error *err)
{
    if (a->no_output && a->output)
        return SQ_FAIL(err, SQ_ERR_USAGE, "mesh: -o and --no-output exclude each other");
    char probe[32];
    snprintf(probe, sizeof probe, "mesh.%.20s", a->format ? a->format : "");
    if (a->format && !sq_mesh_format_known(probe))
        return SQ_FAIL(err, SQ_ERR_USAGE, "--format expects msh, xml or vtu, got '%s'", a->format);
    if (a->output && !a->format && strcmp(a->output, "-") && !sq_mesh_format_known(a->output))
        return SQ_FAIL(err, SQ_ERR_USAGE, "%s: unknown mesh format (use .msh, .xml or .vtu)",
                       a->output);
    if (a->output && !strcmp(a->output, "-") && !a->format) a->format = "msh";
    if (a->binary && !a->no_output && strcmp(format_word(a), "msh") && strcmp(format_word(a), "xml"))
        return SQ_FAIL(err, SQ_ERR_USAGE, "--binary writes MSH or XML only: drop it, or write msh or xml");
    if (a->no_output || a->output) return SQ_OK;
    const char *base = strrchr(a->input, '/') ? strrchr(a->input, '/') + 1 : a->input;
    const char *dot = strrchr(base, '.');
    int stem = dot && dot != base ? (int)(dot - base) : (int)strlen(base);
    if (snprintf(name, n, "%.*s.%s", stem, base, a->format ? a->format : "msh") >= (int)n)
        return SQ_FAIL(err, SQ_ERR_USAGE, "%s: file name too long", a->input);
    a->output = name;
    return sq_output_check(name, err);
}

const char *sq_cli_mesh_format(const sq_cli_args *a)
{
    if (!a->binary) return a->format;
    return strcmp(format_word(a), "xml") ? "msh-binary" : "xml-compressed";
}

/* The outputs -o (unless a family replaces it), --svg and --report, in
 * that order (the report's timings include the writes). */
static sq_status write_outputs(const sq_mesh *mesh, const sq_cli_args *a, int named, int family,
                               sq_error *err)
{
    if (a->output && !family) SQ_TRY(sq_mesh_write_format(mesh, a->output, sq_cli_mesh_format(a), err));
    if (a->output && !named && !a->quiet && !family)
        fprintf(stderr, "semquad: note: no -o given: wrote %s\n", a->output);
    if (a->svg) SQ_TRY(sq_mesh_write(mesh, a->svg, err));
    if (a->report) SQ_TRY(sq_mesh_write_report(mesh, a->report, err));
    return SQ_OK;
}

static sq_status run_mesh(sq_cli_args *a, sq_error *err)
{
    char name[4096], manifest[4096];
    int named = a->output != NULL, family = a->levels > 0 || a->norders > 0;
    SQ_TRY(threads_from_env(a, err));
    SQ_TRY(mesh_file(a, name, sizeof name, err));
    SQ_TRY(sq_cli_family_check(a, manifest, sizeof manifest, err));
    sq_model *m = NULL;
    SQ_TRY(sq_cli_open(a, &m, err));
    sq_mesh *mesh = NULL;
    sq_status st = sq_model_mesh(m, a->faces, a->nfaces, &a->opt, &mesh, err);
    if (st == SQ_OK) st = write_outputs(mesh, a, named, family, err);
    if (st == SQ_OK && family) st = sq_cli_family_write(mesh, a, err);
    char *text = NULL;
    if (st == SQ_OK && !a->quiet && !family) st = sq_cli_print(sq_mesh_describe(mesh, &text, err), &text, a);
    /* below the floor: written all the same, then the status */
    if (st == SQ_OK) st = sq_mesh_check_quality(mesh, &a->opt, err);
    sq_mesh_free(&mesh);
    sq_model_free(&m);
    return st;
}

static const sq_cli_opt mesh_opts[] = {
    {.name = "output", .short_name = 'o', .kind = SQ_CLI_OUTPUT, .value = "FILE",
     .def = "STEM.msh in the current directory",
     .help = "the mesh: Gmsh MSH 4.1 (.msh), Nektar++ XML (.xml) or VTU (.vtu); - for stdout",
     .target = SQ_CLI_AT(output), .stdout_ok = 1},
    {.name = "format", .kind = SQ_CLI_WORD, .value = "msh|xml|vtu", .def = "-o's extension, else msh",
     .help = "the mesh's format, whatever the file's name", .target = SQ_CLI_AT(format)},
    {.name = "binary", .kind = SQ_CLI_FLAG, .set = 1, .def = "off (text)",
     .help = "binary MSH 4.1 (the same groups, nodes and elements), or with xml Nektar++'s "
             "compressed XML (COMPRESSED=\"B64Z-LittleEndian\": the same vertices, edges, quads and curves)",
     .target = SQ_CLI_AT(binary)},
    {.name = "no-output", .kind = SQ_CLI_FLAG, .set = 1, .def = "off",
     .help = "mesh and report, but write no mesh file", .target = SQ_CLI_AT(no_output)},
    {.name = "order", .kind = SQ_CLI_INT, .value = "Q", .lo = 1, .hi = 10, .def = "4",
     .help = "element order of the quads (1..10)", .target = SQ_CLI_AT(opt.order)},
    {.name = "size", .kind = SQ_CLI_REAL, .value = "H", .lo = 1e-300, .hi = 1e300,
     .def = "sqrt(area)/8, halved up to 3 times while quads fold", .unit = "file unit",
     .help = "target quad size (the far size of the sizes below)", .target = SQ_CLI_AT(opt.size)},
    {.name = "edge-size", .kind = SQ_CLI_CUSTOM, .value = "N:H", .def = "none", .unit = "file unit",
     .help = "size H on CAD edge N (as semquad info numbers them), growing away by the gradation",
     .parse = sq_cli_parse_size},
    {.name = "grow", .kind = SQ_CLI_CUSTOM, .value = "N:H0:RATIO", .def = "none",
     .unit = "file unit",
     .help = "size H0 on CAD edge N growing by RATIO per cell (capped by the gradation)",
     .parse = sq_cli_parse_size},
    {.name = "refine", .kind = SQ_CLI_CUSTOM, .value = "X,Y,R,H", .def = "none", .unit = "file unit",
     .help = "size H within radius R of point (X,Y) of the face's frame, growing outside",
     .parse = sq_cli_parse_size},
    {.name = "refine-box", .kind = SQ_CLI_CUSTOM, .value = "X0,Y0,X1,Y1,H", .def = "none",
     .unit = "file unit", .help = "size H inside the box (X0,Y0)-(X1,Y1), growing outside",
     .parse = sq_cli_parse_size},
    {.name = "curvature", .kind = SQ_CLI_REAL, .value = "N", .lo = 0.0, .hi = 1e6, .def = "0 (none)",
     .unit = "elements per radian",
     .help = "size 1/(N kappa) on the CAD curves (N elements per radian of turning), growing "
             "away by the gradation",
     .target = SQ_CLI_AT(opt.curvature_elements)},
    {.name = "sizes", .kind = SQ_CLI_CUSTOM, .value = "FILE", .def = "none",
     .help = "size sources, one per line (docs/sizes.md)", .parse = sq_cli_parse_size_file},
    {.name = "names", .kind = SQ_CLI_CUSTOM, .value = "FILE", .def = "none",
     .help = "boundary names, lines 'EDGE NAME' or 'X Y NAME', and face names, 'face FACE NAME' or "
             "'face X Y NAME', over the STEP file's (docs/formats.md)",
     .parse = sq_cli_parse_names_file},
    SQ_CLI_OPT_PERIODIC,
    {.name = "size-gradation", .kind = SQ_CLI_REAL, .value = "G", .lo = 1.0001, .hi = 10.0,
     .def = "1.3", .help = "bound of the size ratio of neighbouring cells",
     .target = SQ_CLI_AT(opt.size_gradation)},
    SQ_CLI_OPT_FIELD_ORDER("4 (guiding field), 8 (H/theta field)"),
    SQ_CLI_OPT_METHOD,
    SQ_CLI_OPT_MERGE_DISTANCE,
    SQ_CLI_OPT_SINGULARITIES,
    SQ_CLI_OPT_ALLOW_MISALIGNED,
    {.name = "nodes", .kind = SQ_CLI_WORD, .value = "gll|equispaced", .def = "gll",
     .help = "nodes along the sides: Gauss-Lobatto-Legendre or equispaced",
     .target = SQ_CLI_AT(opt.nodes)},
    {.name = "bl", .kind = SQ_CLI_CUSTOM, .value = "E1,E2,...", .def = "none",
     .help = "boundary layers on these CAD edges (as semquad info numbers them)", .parse = parse_bl},
    {.name = "bl-first", .kind = SQ_CLI_REAL, .value = "D", .lo = 1e-300, .hi = 1e300,
     .def = "none (needed by --bl)", .unit = "file unit", .help = "first layer's height",
     .target = SQ_CLI_AT(opt.bl_first)},
    {.name = "bl-ratio", .kind = SQ_CLI_REAL, .value = "R", .lo = 1.0, .hi = 10.0, .def = "1.2",
     .help = "growth ratio of the layers (1..10); beyond them the cells grow by --size-gradation up to the size", .target = SQ_CLI_AT(opt.bl_ratio)},
    {.name = "bl-layers", .kind = SQ_CLI_INT, .value = "N", .lo = 1, .hi = 1000,
     .def = "none (needed by --bl)", .help = "layers growing by --bl-ratio (1..1000): the first cells of the blocks on the edges",
     .target = SQ_CLI_AT(opt.bl_layers)},
    {.name = "max-quads", .kind = SQ_CLI_REAL, .value = "N", .lo = 1.0, .hi = 1e15, .def = "2e7",
     .help = "refuse, before meshing, a size giving more quads (and name one that fits)",
     .target = SQ_CLI_AT(opt.max_quads)},
    {.name = "threads", .kind = SQ_CLI_CUSTOM, .value = "N", .def = "SEMQUAD_THREADS, else every processor",
     .help = "threads for the faces of a domain (each face's field, layout and mesh), a large "
             "mesh's refinement, the quality pass and the MSH text's formatting (0: every "
             "processor); the files are byte-identical for every N",
     .parse = parse_threads},
    {.name = "relax-max-quads", .kind = SQ_CLI_REAL, .value = "N", .lo = 0.0, .hi = 1e15,
     .def = "5e4",
     .help = "a layout-road mesh of more quads is relaxed with its chords quantized at 2^k times "
             "the size (the least k giving at most N quads), then split 2 x 2 k times along its "
             "quads' maps; "
             "0: relax the whole mesh (docs/mesh.md, Large meshes)",
     .target = SQ_CLI_AT(opt.relax_max_quads)},
    {.name = "road", .kind = SQ_CLI_WORD, .value = "auto|layout|split", .def = "auto",
     .help = "layout: field, layout, patches; split: triangles split into quads; auto: layout, "
             "else split, and the better of both when the layout's is below --min-quality",
     .target = SQ_CLI_AT(opt.road)},
    {.name = "min-quality", .kind = SQ_CLI_REAL, .value = "X", .lo = 0.0, .hi = 1.0, .def = "0.01",
     .help = "a mesh whose worst quad's scaled Jacobian (min det J / max det J, proven by Bezier "
             "bounds) is below X is written, then the run exits 8 naming that quad; 0: no floor",
     .target = SQ_CLI_AT(opt.min_quality)},
    {.name = "levels", .kind = SQ_CLI_INT, .value = "L", .lo = 1, .hi = 10,
     .def = "none (one mesh)",
     .help = "a nested family for convergence studies: STEM_L1.msh (the mesh) .. STEM_LL.msh, "
             "every quad of a level split 2 x 2 in the next (STEM: -o without extension); "
             "a domain of several faces too, face by face, merged again",
     .target = SQ_CLI_AT(levels)},
    {.name = "orders", .kind = SQ_CLI_CUSTOM, .value = "Q1,Q2,...", .def = "none",
     .help = "the same quads at each order (1..10): STEM_Q4.msh ..; with --levels STEM_L2_Q4.msh ..",
     .parse = parse_orders},
    {.name = "manifest", .kind = SQ_CLI_OUTPUT, .value = "FILE",
     .def = "STEM_manifest.json with --levels or --orders",
     .help = "the family's files with level, order, h, quads, nodes, dofs, area (JSON)",
     .target = SQ_CLI_AT(manifest)},
    SQ_CLI_OPT_SVG("a picture of the mesh, coloured by quality"),
    SQ_CLI_OPT_REPORT,
    SQ_CLI_OPT_PROGRESS,
    {.name = "face", .kind = SQ_CLI_CUSTOM, .value = "N[,M...]", .def = "every planar face",
     .help = "the faces to mesh as one conforming mesh, faces sharing an edge sharing its nodes "
             "(semquad info lists them)",
     .parse = parse_faces},
    SQ_CLI_OPT_HEAL_TOLERANCE, SQ_CLI_OPT_NO_HEAL, SQ_CLI_OPT_QUIET,
    {0}};

const sq_cli_command sq_cli_mesh = {
    .name = "mesh",
    .summary = "Block-structured high-order quad mesh of order Q: chords quantized, patches by "
               "transfinite interpolation, relaxed to the minimum of Winslow's energy with the "
               "boundary vertices sliding on the CAD curves (with size options, of an energy "
               "that keeps their grading: docs/sizes.md). Quality summary on stdout, "
               "progress on stderr. Where no valid layout is found, the split road meshes the "
               "face all the same, with a note, and where the layout road's worst quad is below "
               "--min-quality the split road is tried and the better mesh kept (--road auto).",
    .example = "semquad mesh examples/half_disc.step --order 4 --size 0.1 -o half_disc.msh",
    .opts = mesh_opts,
    .run = run_mesh};
