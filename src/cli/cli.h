/* semquad — what the commands of the `semquad` program share: one option
 * table per command, parsed by one parser (getopt_long), printed by --help,
 * `semquad help` and the shell completion scripts. */
#ifndef SQ_CLI_H
#define SQ_CLI_H

#include <semquad.h>

#include <stddef.h>

#define SQ_CLI_MAX_LIST 64 /* entries of --bl and --sizes */

/* What the progress bar shows (cli_progress.c). */
typedef struct {
    int json;      /* one JSON object per event instead of a bar */
    char stage[16]; /* the stage under way */
    double t0;     /* when it began */
    long done;
    int pct, shown; /* the bar on the terminal, if shown */
} sq_cli_progress;

/* What a command's options fill: the shared outputs and flags, and the
 * library's options. */
typedef struct {
    const char *cmd;       /* the command's name */
    const char *input;     /* the CAD file (the one positional argument) */
    int face;              /* --face N (-1: the default face) */
    int quiet;             /* -q, --quiet */
    int help;              /* -h, --help: print the command's usage, do nothing else */
    int json;              /* info --json */
    int no_output;         /* mesh --no-output */
    int to_stdout;         /* one output is "-": the summary goes to stderr */
    const char *output;    /* -o F, --output F */
    const char *svg;       /* --svg F */
    const char *report;    /* --report F */
    const char *csv;       /* converge --csv F */
    const char *format;    /* mesh --format msh|xml|vtu */
    int binary;            /* mesh --binary: MSH 4.1 binary */
    int threads_set;       /* mesh --threads given (else SEMQUAD_THREADS, else all) */
    const char *deprecated; /* the deprecated spelling used, warned about once */
    const char *progress;  /* --progress auto|json|none */
    sq_cli_progress bar;   /* its state (opt.progress_data and opt.log_data point here) */
    int bl[SQ_CLI_MAX_LIST];        /* mesh --bl (opt.bl_edges points here) */
    int faces[SQ_CLI_MAX_LIST];     /* mesh --face N,M,... */
    int nfaces;                     /* 0: every planar face */
    sq_size_source size_sources[SQ_CLI_MAX_LIST]; /* mesh's sizes (opt.sizes points here) */
    sq_boundary_name names[SQ_CLI_MAX_LIST]; /* mesh --names (opt.names points here) */
    char name_text[SQ_CLI_MAX_LIST][64];      /* their names */
    sq_face_name face_names[SQ_CLI_MAX_LIST]; /* its 'face' lines (opt.face_names) */
    char face_name_text[SQ_CLI_MAX_LIST][64]; /* their names */
    double sizes[SQ_CLI_MAX_LIST];  /* converge --sizes (opt.study_sizes points here) */
    int levels;                     /* mesh --levels L (0: one mesh) */
    int orders[SQ_CLI_MAX_LIST];    /* mesh --orders Q1,Q2,... */
    int norders;
    const char *manifest;           /* mesh --manifest F (a family's; default STEM_manifest.json) */
    sq_options opt;        /* the library's options; its logger prints to stderr unless -q */
} sq_cli_args;

/* Defaults: no outputs, the default face, the library's options with the
 * stderr logger. */
void sq_cli_args_init(sq_cli_args *a, const char *cmd);

typedef enum {
    SQ_CLI_FLAG,   /* no value: stores `set` into an int */
    SQ_CLI_INT,    /* an integer in lo..hi */
    SQ_CLI_REAL,   /* a number in [lo, hi] */
    SQ_CLI_WORD,   /* a name or an input file, kept as given */
    SQ_CLI_OUTPUT, /* an output file: a regular file (or "-", standard output) */
    SQ_CLI_CUSTOM  /* parsed by the row's own function */
} sq_cli_kind;

typedef sq_status (*sq_cli_parse_fn)(const char *opt, const char *val, sq_cli_args *a,
                                     sq_error *err);

/* One option of a command.  `value` names the value as help shows it:
 * words separated by '|' are its choices, upper-case ones stand for a
 * file or a number ("FILE|natural", "auto|cg|dg", "Q"). */
typedef struct {
    const char *name;     /* long name, without "--" */
    char short_name;      /* 'o', 'q' or 0 */
    sq_cli_kind kind;
    const char *value;    /* NULL for a flag */
    double lo, hi;        /* range of INT and REAL */
    int set;              /* what a FLAG stores */
    const char *def;      /* the default, as --help prints it (NULL: none) */
    const char *unit;     /* "file unit", "deg" or NULL */
    const char *help;     /* one line */
    size_t target;        /* offsetof(sq_cli_args, the field it fills) */
    sq_cli_parse_fn parse; /* CUSTOM */
    const char *alias_of; /* a deprecated spelling of that option (one release) */
    int shared;           /* one of the options every command reading a face takes */
    int stdout_ok;        /* OUTPUT: "-" (standard output) allowed (a text format) */
} sq_cli_opt;

#define SQ_CLI_AT(field) offsetof(sq_cli_args, field)

/* The rows several commands share. */
#define SQ_CLI_OPT_FACE                                                                            \
    {.name = "face", .kind = SQ_CLI_INT, .value = "N", .lo = 0, .hi = 1000000,                     \
     .def = "the only planar face, else 0", .help = "the face to work on (semquad info lists them)", \
     .target = SQ_CLI_AT(face), .shared = 1}
#define SQ_CLI_OPT_HEAL_TOLERANCE                                                                  \
    {.name = "heal-tolerance", .kind = SQ_CLI_REAL, .value = "T", .lo = 1e-300, .hi = 1e300,       \
     .def = "the file's own tolerance", .unit = "file unit",                                       \
     .help = "heal gaps, unshared vertices and small edges within T",                              \
     .target = SQ_CLI_AT(opt.heal_tolerance), .shared = 1}
#define SQ_CLI_OPT_NO_HEAL                                                                         \
    {.name = "no-heal", .kind = SQ_CLI_FLAG, .set = 0, .def = "heal",                              \
     .help = "take the faces as read, without healing", .target = SQ_CLI_AT(opt.heal),            \
     .shared = 1}
#define SQ_CLI_OPT_QUIET                                                                           \
    {.name = "quiet", .short_name = 'q', .kind = SQ_CLI_FLAG, .set = 1, .def = "off",              \
     .help = "print nothing but errors", .target = SQ_CLI_AT(quiet), .shared = 1}
/* The rows of every command that reads a face: --face, the healing
 * options, -q. */
#define SQ_CLI_OPTS_READING                                                                        \
    SQ_CLI_OPT_FACE, SQ_CLI_OPT_HEAL_TOLERANCE, SQ_CLI_OPT_NO_HEAL, SQ_CLI_OPT_QUIET
#define SQ_CLI_OPT_PROGRESS                                                                        \
    {.name = "progress", .kind = SQ_CLI_WORD, .value = "auto|json|none", .def = "auto",            \
     .help = "auto: a bar on stderr for a stage running past a second, where stderr is a "         \
             "terminal (none with -q); json: one JSON object per event on stderr, even with -q",   \
     .target = SQ_CLI_AT(progress)}
#define SQ_CLI_OPT_SVG(what)                                                                       \
    {.name = "svg", .kind = SQ_CLI_OUTPUT, .value = "FILE", .def = "none", .help = (what),         \
     .target = SQ_CLI_AT(svg)}
#define SQ_CLI_OPT_REPORT                                                                          \
    {.name = "report", .kind = SQ_CLI_OUTPUT, .value = "FILE", .def = "none",                      \
     .help = "the JSON report (docs/formats.md); - for standard output",                           \
     .target = SQ_CLI_AT(report), .stdout_ok = 1}
#define SQ_CLI_OPT_METHOD                                                                          \
    {.name = "method", .kind = SQ_CLI_WORD, .value = "auto|cg|dg", .def = "auto",                  \
     .help = "the field's solver; auto: CG where every corner is a multiple of 90 deg, else DG",   \
     .target = SQ_CLI_AT(opt.method)}
#define SQ_CLI_OPT_FIELD_ORDER(dflt)                                                               \
    {.name = "field-order", .kind = SQ_CLI_INT, .value = "P", .lo = 1, .hi = 16, .def = (dflt),    \
     .help = "polynomial degree of the field (1..16)", .target = SQ_CLI_AT(opt.field_order)}
#define SQ_CLI_OPT_ORDER_ALIAS                                                                     \
    {.name = "order", .kind = SQ_CLI_INT, .value = "P", .lo = 1, .hi = 16,                         \
     .help = "deprecated spelling of --field-order (removed in the next release)",                 \
     .target = SQ_CLI_AT(opt.field_order), .alias_of = "field-order"}
#define SQ_CLI_OPT_FIELD_SIZE                                                                      \
    {.name = "size", .kind = SQ_CLI_REAL, .value = "H", .lo = 1e-300, .hi = 1e300,                 \
     .def = "sqrt(area)/3", .unit = "file unit", .help = "longest edge of the field's triangles",  \
     .target = SQ_CLI_AT(opt.tri_size)}
#define SQ_CLI_OPT_SINGULARITIES                                                                   \
    {.name = "singularities", .kind = SQ_CLI_WORD, .value = "FILE|natural", .def = "none",         \
     .help = "impose a singularity pattern (docs/singularity-patterns.md) and use its H/theta field", \
     .target = SQ_CLI_AT(opt.singularities)}
#define SQ_CLI_OPT_PERIODIC                                                                        \
    {.name = "periodic", .kind = SQ_CLI_WORD, .value = "auto|A:B[,C:D...]", .def = "none",         \
     .help = "periodic edges: auto, the pairs matching under a translation or rotation; A:B, "   \
             "edge B the image of edge A (exit 9 if not; of several faces, A and B number "      \
             "the domain's boundary curves, boundary_A); the field and separatrices of the "      \
             "identified domain (translations); MSH $Periodic (docs/domains.md)",                 \
     .target = SQ_CLI_AT(opt.periodic)}
#define SQ_CLI_OPT_ALLOW_MISALIGNED                                                                \
    {.name = "allow-misaligned", .kind = SQ_CLI_FLAG, .set = 1, .def = "off",                      \
     .help = "go on when a hole breaks the pattern's holonomy condition",                          \
     .target = SQ_CLI_AT(opt.allow_misaligned)}
#define SQ_CLI_OPT_MERGE_DISTANCE                                                                  \
    {.name = "merge-distance", .kind = SQ_CLI_REAL, .value = "K", .lo = 0.1, .hi = 1000.0,         \
     .def = "1", .unit = "local sizes",                                                            \
     .help = "merge separatrices closer than K (larger: more aggressive)",                         \
     .target = SQ_CLI_AT(opt.merge_distance)}

/* A command: its table (ended by a row without name), its help, and what
 * it does once the options are parsed. */
typedef struct {
    const char *name;
    const char *summary; /* one paragraph (help wraps it) */
    const char *example; /* a whole command line */
    const sq_cli_opt *opts;
    sq_status (*run)(sq_cli_args *a, sq_error *err);
} sq_cli_command;

extern const sq_cli_command sq_cli_info, sq_cli_triangulate, sq_cli_field, sq_cli_layout,
    sq_cli_mesh, sq_cli_converge;

/* Every command, in the order help lists them; NULL-terminated. */
const sq_cli_command *const *sq_cli_commands(void);

/* Parse argv[1..argc-1] (argv[0]: the command's name) into a by c's table
 * (cli_parse.c): GNU long options with "--opt value" or "--opt=value",
 * "--" ends the options, -h/--help sets a->help; outputs checked (regular
 * files or "-") before any work.  SQ_ERR_USAGE naming the closest option
 * for an unknown one. */
sq_status sq_cli_parse(const sq_cli_command *c, int argc, char **argv, sq_cli_args *a,
                       sq_error *err);

/* The row of c's table called name (NULL if none). */
const sq_cli_opt *sq_cli_find(const sq_cli_command *c, const char *name);

/* Help (cli_help.c): `semquad CMD --help`, and `semquad help`. */
void sq_cli_usage(const sq_cli_command *c);
void sq_cli_overview(void);

/* `semquad completion bash|zsh|table` (cli_complete.c): the completion
 * scripts, or every command's table as tab-separated lines. */
sq_status sq_cli_completion(const char *shell, sq_error *err);

/* Parse a whole-string integer/real option value; SQ_ERR_USAGE naming the
 * option otherwise. */
sq_status sq_cli_int(const char *opt, const char *val, int lo, int hi, int *out, sq_error *err);
sq_status sq_cli_double(const char *opt, const char *val, double lo, double hi, double *out,
                        sq_error *err);

/* Comma-separated integers in lo..hi into out[max]; *n their count. */
sq_status sq_cli_int_list(const char *opt, const char *val, int lo, int hi, int *out, int max,
                          int *n, sq_error *err);

/* mesh's size options (cli_sizes.c, docs/sizes.md): --edge-size,
 * --grow, --refine, --refine-box add one source each; --sizes FILE its
 * lines. */
sq_status sq_cli_parse_size(const char *opt, const char *val, sq_cli_args *a, sq_error *err);
sq_status sq_cli_parse_size_file(const char *opt, const char *val, sq_cli_args *a, sq_error *err);

/* mesh --names FILE (cli_names.c, docs/formats.md): lines "EDGE NAME" or
 * "X Y NAME", each one entry of opt.names. */
sq_status sq_cli_parse_names_file(const char *opt, const char *val, sq_cli_args *a, sq_error *err);

/* Print a line of the library's messages on stderr ("semquad: note: ..."),
 * the progress bar (data, may be NULL) cleared first. */
void sq_cli_log(void *data, sq_log_level level, const char *line);

/* Progress (cli_progress.c): from --progress and -q, set opt.progress (a
 * bar where stderr is a terminal, JSON lines, or none); the callback; and
 * clearing the bar (before a line, at the end). */
sq_status sq_cli_progress_init(sq_cli_args *a, sq_error *err);
void sq_cli_progress_event(void *data, const char *stage, long done, long total);
void sq_cli_progress_clear(sq_cli_progress *p);

/* mesh --levels/--orders (cmd_mesh_family.c): the family's file names
 * from a->output's stem, checked before any work (the default manifest's
 * name goes into manifest[n]); then, from the mesh as made (level 1),
 * every file of the family and its manifest, one line per file on stdout;
 * SQ_ERR_QUALITY if a file's worst quad is below the floor (after writing
 * them all). */
/* The format sq_mesh_write_format gets for mesh's file: --format's (NULL:
 * by the extension), "msh-binary" or "xml-compressed" with --binary (cmd_mesh.c). */
const char *sq_cli_mesh_format(const sq_cli_args *a);
sq_status sq_cli_family_check(sq_cli_args *a, char *manifest, size_t n, sq_error *err);
sq_status sq_cli_family_write(const sq_mesh *mesh, const sq_cli_args *a, sq_error *err);

/* Check the options (a usage error before any work), then read a->input. */
sq_status sq_cli_open(const sq_cli_args *a, sq_model **m, sq_error *err);

/* Print *text (if any) on stdout (stderr when an output goes to standard
 * output), free it, return st: the status of the call that made it
 * (sq_cli_print(sq_x_describe(x, &text, err), &text, a): text is read
 * after that call). */
sq_status sq_cli_print(sq_status st, char **text, const sq_cli_args *a);

#endif
