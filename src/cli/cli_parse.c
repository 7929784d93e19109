/* The one option parser of the commands: getopt_long over a command's
 * table (cli.h), values checked by their kind, outputs checked before any
 * work, an unknown option answered with the closest valid one. */
#include "cli.h"

#include <getopt.h>
#include <stdio.h>
#include <string.h>

#define MAX_OPTS 64
#define VAL_BASE 256 /* getopt_long's val of row k: VAL_BASE + k */

const sq_cli_opt *sq_cli_find(const sq_cli_command *c, const char *name)
{
    for (const sq_cli_opt *o = c->opts; o->name; o++)
        if (!strcmp(o->name, name)) return o;
    return NULL;
}

/* Levenshtein distance of a and b (the first 63 characters of each). */
static int edit_distance(const char *a, const char *b)
{
    int row[64], n = (int)strnlen(b, 63), m = (int)strnlen(a, 63);
    for (int j = 0; j <= n; j++) row[j] = j;
    for (int i = 1; i <= m; i++) {
        int diag = row[0];
        row[0] = i;
        for (int j = 1; j <= n; j++) {
            int up = row[j], best = diag + (a[i - 1] != b[j - 1]);
            if (up + 1 < best) best = up + 1;
            if (row[j - 1] + 1 < best) best = row[j - 1] + 1;
            diag = up;
            row[j] = best;
        }
    }
    return row[n];
}

/* The usage error for arg, an option c does not take, naming the closest
 * option of c's table when one is near enough to be a misspelling. */
static sq_status unknown_option(const sq_cli_command *c, const char *arg, sq_error *err)
{
    char name[64];
    const char *s = arg + strspn(arg, "-");
    snprintf(name, sizeof name, "%.*s", (int)strcspn(s, "="), s);
    const sq_cli_opt *best = NULL, *prefix[2] = {NULL, NULL};
    int dbest = 1 << 20, nprefix = 0;
    for (const sq_cli_opt *o = c->opts; o->name; o++) {
        int d = edit_distance(name, o->name);
        if (d < dbest) dbest = d, best = o;
        if (*name && !strncmp(o->name, name, strlen(name)) && !o->alias_of && nprefix++ < 2)
            prefix[nprefix - 1] = o;
    }
    if (nprefix > 1) /* getopt_long takes a unique prefix only */
        return SQ_FAIL(err, SQ_ERR_USAGE, "%s: option --%s is ambiguous (--%s, --%s%s)", c->name,
                       name, prefix[0]->name, prefix[1]->name, nprefix > 2 ? ", ..." : "");
    int near = best && dbest <= 1 + (int)strlen(name) / 4 && dbest < (int)strlen(best->name);
    if (near) /* a deprecated spelling is answered with the current one */
        return SQ_FAIL(err, SQ_ERR_USAGE, "%s: unknown option %.*s (did you mean --%s?)", c->name,
                       (int)strcspn(arg, "="), arg, best->alias_of ? best->alias_of : best->name);
    return SQ_FAIL(err, SQ_ERR_USAGE, "%s: unknown option %.*s (try: semquad %s --help)", c->name,
                   (int)strcspn(arg, "="), arg, c->name);
}

/* Store val (NULL for a flag) as row o says. */
static sq_status apply(const sq_cli_command *c, const sq_cli_opt *o, const char *val,
                       sq_cli_args *a, sq_error *err)
{
    char opt[72];
    snprintf(opt, sizeof opt, "--%s", o->name);
    if (o->alias_of) {
        a->deprecated = o->name;
        o = sq_cli_find(c, o->alias_of);
    }
    void *at = (char *)a + o->target;
    switch (o->kind) {
    case SQ_CLI_FLAG: *(int *)at = o->set; return SQ_OK;
    case SQ_CLI_INT: return sq_cli_int(opt, val, (int)o->lo, (int)o->hi, at, err);
    case SQ_CLI_REAL: return sq_cli_double(opt, val, o->lo, o->hi, at, err);
    case SQ_CLI_WORD:
    case SQ_CLI_OUTPUT: *(const char **)at = val; return SQ_OK;
    case SQ_CLI_CUSTOM: return o->parse(opt, val, a, err);
    }
    return SQ_FAIL(err, SQ_ERR_INTERNAL, "option --%s of unknown kind", o->name);
}

/* getopt_long's tables of c: long options with val VAL_BASE + row, short
 * ones in the option string; -h/--help added. */
static sq_status getopt_tables(const sq_cli_command *c, struct option *lo, char *shorts,
                               sq_error *err)
{
    int k = 0, s = 0;
    shorts[s++] = ':'; /* a missing value returns ':' */
    shorts[s++] = 'h';
    for (const sq_cli_opt *o = c->opts; o->name; o++, k++) {
        if (k + 2 >= MAX_OPTS) return SQ_FAIL(err, SQ_ERR_INTERNAL, "%s: too many options", c->name);
        int has = o->kind != SQ_CLI_FLAG;
        lo[k] = (struct option){o->name, has ? required_argument : no_argument, NULL, VAL_BASE + k};
        if (o->short_name) {
            shorts[s++] = o->short_name;
            if (has) shorts[s++] = ':';
        }
    }
    lo[k++] = (struct option){"help", no_argument, NULL, 'h'};
    lo[k] = (struct option){NULL, 0, NULL, 0};
    shorts[s] = '\0';
    return SQ_OK;
}

static const sq_cli_opt *row_of(const sq_cli_command *c, int val)
{
    if (val >= VAL_BASE) return &c->opts[val - VAL_BASE];
    for (const sq_cli_opt *o = c->opts; o->name; o++)
        if (o->short_name && o->short_name == val) return o;
    return NULL;
}

/* Every output names a regular file (or "-", standard output, where the
 * row allows it, at most once): refused before any work otherwise. */
static sq_status check_outputs(const sq_cli_command *c, sq_cli_args *a, sq_error *err)
{
    for (const sq_cli_opt *o = c->opts; o->name; o++) {
        const char *path = o->kind == SQ_CLI_OUTPUT ? *(const char **)((char *)a + o->target) : NULL;
        if (!path) continue;
        if (!strcmp(path, "-") && !o->stdout_ok)
            return SQ_FAIL(err, SQ_ERR_USAGE, "%s --%s: cannot go to standard output (-): name a file",
                           c->name, o->name);
        if (!strcmp(path, "-") && a->to_stdout++)
            return SQ_FAIL(err, SQ_ERR_USAGE, "%s: only one output can go to standard output (-)",
                           c->name);
        SQ_TRY(sq_output_check(path, err));
    }
    return SQ_OK;
}

sq_status sq_cli_parse(const sq_cli_command *c, int argc, char **argv, sq_cli_args *a,
                       sq_error *err)
{
    struct option lo[MAX_OPTS];
    char shorts[2 * MAX_OPTS + 3];
    SQ_TRY(getopt_tables(c, lo, shorts, err));
    opterr = 0;
    optind = 0; /* GNU: start afresh */
    for (;;) {
        int k = getopt_long(argc, argv, shorts, lo, NULL);
        if (k == -1) break;
        if (k == 'h') {
            a->help = 1;
            return SQ_OK;
        }
        if (k == '?' && optopt >= VAL_BASE) /* --flag=value */
            return SQ_FAIL(err, SQ_ERR_USAGE, "option --%s takes no value",
                           row_of(c, optopt)->name);
        if (k == '?') {
            char arg[3] = {'-', (char)optopt, '\0'};
            return unknown_option(c, optopt ? arg : argv[optind - 1], err);
        }
        if (k == ':' && optopt >= VAL_BASE)
            return SQ_FAIL(err, SQ_ERR_USAGE, "option --%s needs a value", row_of(c, optopt)->name);
        if (k == ':') return SQ_FAIL(err, SQ_ERR_USAGE, "option -%c needs a value", optopt);
        SQ_TRY(apply(c, row_of(c, k), optarg, a, err));
    }
    if (optind < argc) a->input = argv[optind++];
    if (optind < argc) return SQ_FAIL(err, SQ_ERR_USAGE, "%s: one input file expected", c->name);
    if (!a->input) return SQ_FAIL(err, SQ_ERR_USAGE, "%s: missing input file", c->name);
    if (a->quiet) a->opt.log = NULL;
    if (a->deprecated && !a->quiet)
        fprintf(stderr, "semquad: warning: %s: --%s is deprecated, use --%s (it goes in the next "
                        "release)\n",
                c->name, a->deprecated, sq_cli_find(c, a->deprecated)->alias_of);
    SQ_TRY(sq_cli_progress_init(a, err));
    return check_outputs(c, a, err);
}
