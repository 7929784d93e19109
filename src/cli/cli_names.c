/* semquad mesh --names FILE: boundary names (docs/formats.md, "Named
 * boundaries"), each line one entry of sq_options.names. */
#include "cli.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* One line: "EDGE NAME", "X Y NAME", blank or # comment. */
static sq_status names_line(const char *where, char *line, sq_cli_args *a, sq_error *err)
{
    char *hash = strchr(line, '#');
    if (hash) *hash = '\0';
    char w[3][128];
    int n = sscanf(line, " %127s %127s %127s", w[0], w[1], w[2]);
    if (n <= 0) return SQ_OK; /* blank */
    char extra[2];
    if (n < 2 || sscanf(line, " %*s %*s %*s %1s", extra) == 1)
        return SQ_FAIL(err, SQ_ERR_USAGE, "%s: expects 'EDGE NAME' or 'X Y NAME'", where);
    if (a->opt.nnames >= SQ_CLI_MAX_LIST)
        return SQ_FAIL(err, SQ_ERR_USAGE, "%s: more than %d names", where, SQ_CLI_MAX_LIST);
    const char *name = w[n - 1];
    if (strlen(name) >= sizeof a->name_text[0] ||
        name[strspn(name, SQ_NAME_CHARS)])
        return SQ_FAIL(err, SQ_ERR_USAGE, "%s: name '%s', expects [A-Za-z0-9_-]+ (at most %zu)",
                       where, name, sizeof a->name_text[0] - 1);
    sq_boundary_name *b = &a->names[a->opt.nnames];
    char *end0, *end1 = NULL;
    if (n == 2) {
        long e = strtol(w[0], &end0, 10);
        if (*end0 || e < 0 || e > 1000000)
            return SQ_FAIL(err, SQ_ERR_USAGE, "%s: edge '%s', expects an index >= 0", where, w[0]);
        *b = (sq_boundary_name){.edge = (int)e};
    } else {
        double x = strtod(w[0], &end0), y = strtod(w[1], &end1);
        if (*end0 || *end1 || end0 == w[0] || end1 == w[1])
            return SQ_FAIL(err, SQ_ERR_USAGE, "%s: point '%s %s', expects two numbers", where, w[0], w[1]);
        *b = (sq_boundary_name){.edge = -1, .x = x, .y = y};
    }
    strcpy(a->name_text[a->opt.nnames], name);
    b->name = a->name_text[a->opt.nnames];
    a->opt.names = a->names;
    a->opt.nnames++;
    return SQ_OK;
}

sq_status sq_cli_parse_names_file(const char *opt, const char *val, sq_cli_args *a, sq_error *err)
{
    (void)opt;
    FILE *f = fopen(val, "r");
    if (!f) return SQ_FAIL(err, SQ_ERR_INPUT, "%s: cannot read the names file", val);
    char line[1024], where[320];
    sq_status st = SQ_OK;
    for (int lineno = 1; st == SQ_OK && fgets(line, sizeof line, f); lineno++) {
        snprintf(where, sizeof where, "%.256s:%d", val, lineno);
        /* a line longer than the buffer would be read as two: refused */
        if (!strchr(line, '\n') && !feof(f))
            st = SQ_FAIL(err, SQ_ERR_USAGE, "%s: line too long", where);
        else
            st = names_line(where, line, a, err);
    }
    fclose(f);
    return st;
}
