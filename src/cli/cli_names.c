/* semquad mesh --names FILE: boundary names (docs/formats.md, "Named
 * boundaries"), each line one entry of sq_options.names, and face names
 * (lines starting 'face'), each one entry of sq_options.face_names. */
#include "cli.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The place words w[0..n-2] of a line ("INDEX" or "X Y", what names the
 * thing) into *index (the point: -1) or (*x, *y); its last word the name. */
static sq_status place_and_name(const char *where, const char *what, char w[][128], int n,
                                int *index, double *x, double *y, sq_error *err)
{
    const char *name = w[n - 1];
    if (strlen(name) > 63 || name[strspn(name, SQ_NAME_CHARS)])
        return SQ_FAIL(err, SQ_ERR_USAGE, "%s: name '%s', expects [A-Za-z0-9_-]+ (at most 63)",
                       where, name);
    char *end0, *end1 = NULL;
    if (n == 2) {
        long e = strtol(w[0], &end0, 10);
        if (*end0 || e < 0 || e > 1000000)
            return SQ_FAIL(err, SQ_ERR_USAGE, "%s: %s '%s', expects an index >= 0", where, what,
                           w[0]);
        *index = (int)e;
        return SQ_OK;
    }
    *x = strtod(w[0], &end0), *y = strtod(w[1], &end1);
    if (*end0 || *end1 || end0 == w[0] || end1 == w[1])
        return SQ_FAIL(err, SQ_ERR_USAGE, "%s: point '%s %s', expects two numbers", where, w[0], w[1]);
    *index = -1;
    return SQ_OK;
}

/* One line: "EDGE NAME", "X Y NAME", "face FACE NAME", "face X Y NAME",
 * blank or # comment. */
static sq_status names_line(const char *where, char *line, sq_cli_args *a, sq_error *err)
{
    char *hash = strchr(line, '#');
    if (hash) *hash = '\0';
    char w[4][128];
    int n = sscanf(line, " %127s %127s %127s %127s", w[0], w[1], w[2], w[3]);
    if (n <= 0) return SQ_OK; /* blank */
    int face = !strcmp(w[0], "face");
    char extra[2];
    /* a word past the last one a line may have (3, or 4 after 'face') */
    if (n < 2 + face || sscanf(line, face ? " %*s %*s %*s %*s %1s" : " %*s %*s %*s %1s", extra) == 1)
        return SQ_FAIL(err, SQ_ERR_USAGE,
                       "%s: expects 'EDGE NAME', 'X Y NAME', 'face FACE NAME' or 'face X Y NAME'",
                       where);
    int *count = face ? &a->opt.nface_names : &a->opt.nnames;
    if (*count >= SQ_CLI_MAX_LIST)
        return SQ_FAIL(err, SQ_ERR_USAGE, "%s: more than %d %s names", where, SQ_CLI_MAX_LIST,
                       face ? "face" : "boundary");
    int index = -1;
    double x = 0.0, y = 0.0;
    SQ_TRY(place_and_name(where, face ? "face" : "edge", w + face, n - face, &index, &x, &y, err));
    const char *name = w[n - 1];
    if (face) {
        strcpy(a->face_name_text[*count], name);
        a->face_names[*count] = (sq_face_name){index, x, y, a->face_name_text[*count]};
        a->opt.face_names = a->face_names;
    } else {
        strcpy(a->name_text[*count], name);
        a->names[*count] = (sq_boundary_name){index, x, y, a->name_text[*count]};
        a->opt.names = a->names;
    }
    ++*count;
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
