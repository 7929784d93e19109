/* semquad mesh: the user's sizes (docs/sizes.md) — --edge-size, --grow,
 * --refine, --refine-box and the size file --sizes, each one source of
 * sq_options.sizes. */
#include "cli.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* n numbers of val separated by any of seps, whole; 1 when exactly n. */
static int numbers(const char *val, const char *seps, double *out, int n)
{
    const char *p = val;
    for (int i = 0; i < n; i++) {
        char *end;
        out[i] = strtod(p, &end);
        if (end == p) return 0;
        p = end;
        if (i < n - 1) {
            if (!*p || !strchr(seps, *p)) return 0;
            p++;
        }
    }
    while (*p == ' ' || *p == '\t' || *p == '\n' || *p == '\r') p++;
    return *p == '\0';
}

/* The next source of a->opt.sizes, or SQ_ERR_USAGE when the list is full. */
static sq_status next_source(const char *opt, sq_cli_args *a, sq_size_source **s, sq_error *err)
{
    if (a->opt.nsizes >= SQ_CLI_MAX_LIST)
        return SQ_FAIL(err, SQ_ERR_USAGE, "%s: more than %d size sources", opt, SQ_CLI_MAX_LIST);
    a->opt.sizes = a->size_sources;
    *s = &a->size_sources[a->opt.nsizes++];
    memset(*s, 0, sizeof **s);
    return SQ_OK;
}

/* One source from its kind's name and its numbers (v[]: nv of them). */
static sq_status add_source(const char *opt, const char *kind, const double *v, int nv,
                            sq_cli_args *a, sq_error *err)
{
    sq_size_source *s = NULL;
    SQ_TRY(next_source(opt, a, &s, err));
    if (!strcmp(kind, "edge") || !strcmp(kind, "grow")) {
        if (v[0] != (int)v[0]) return SQ_FAIL(err, SQ_ERR_USAGE, "%s: edge %g is not an integer", opt, v[0]);
        *s = (sq_size_source){.kind = SQ_SIZE_EDGE, .edge = (int)v[0], .h = v[1],
                              .ratio = nv == 3 ? v[2] : 0.0};
        if (nv == 3 && !(v[2] >= 1.0))
            return SQ_FAIL(err, SQ_ERR_USAGE, "%s: growth ratio %g, expects >= 1", opt, v[2]);
    } else if (!strcmp(kind, "point")) {
        *s = (sq_size_source){.kind = SQ_SIZE_POINT, .x = {v[0], v[1]}, .r = v[2], .h = v[3]};
    } else {
        *s = (sq_size_source){.kind = SQ_SIZE_BOX, .x = {v[0], v[1]}, .x1 = {v[2], v[3]}, .h = v[4]};
    }
    if (!(s->h > 0.0)) return SQ_FAIL(err, SQ_ERR_USAGE, "%s: size %g, expects > 0", opt, s->h);
    if (s->kind == SQ_SIZE_POINT && !(s->r >= 0.0))
        return SQ_FAIL(err, SQ_ERR_USAGE, "%s: radius %g, expects >= 0", opt, s->r);
    if (s->kind == SQ_SIZE_BOX && !(s->x1[0] > s->x[0] && s->x1[1] > s->x[1]))
        return SQ_FAIL(err, SQ_ERR_USAGE, "%s: empty box (expects x0 < x1 and y0 < y1)", opt);
    return SQ_OK;
}

/* --edge-size N:h, --grow N:h0:ratio, --refine x,y,r,h, --refine-box
 * x0,y0,x1,y1,h. */
sq_status sq_cli_parse_size(const char *opt, const char *val, sq_cli_args *a, sq_error *err)
{
    static const struct { const char *opt, *kind, *seps, *form; int n; } forms[] = {
        {"edge-size", "edge", ":", "N:H", 2},
        {"grow", "grow", ":", "N:H0:RATIO", 3},
        {"refine", "point", ",", "X,Y,R,H", 4},
        {"refine-box", "box", ",", "X0,Y0,X1,Y1,H", 5},
    };
    const char *name = opt + strspn(opt, "-");
    for (size_t i = 0; i < sizeof forms / sizeof forms[0]; i++) {
        if (strcmp(name, forms[i].opt)) continue;
        double v[5];
        if (!numbers(val, forms[i].seps, v, forms[i].n))
            return SQ_FAIL(err, SQ_ERR_USAGE, "--%s expects %s, got '%s'", name, forms[i].form, val);
        return add_source(opt, forms[i].kind, v, forms[i].n, a, err);
    }
    return SQ_FAIL(err, SQ_ERR_INTERNAL, "option %s is not a size option", opt);
}

/* One line of a size file: "KIND numbers...", "gradation G", blank or #. */
static sq_status size_line(const char *path, int lineno, char *line, sq_cli_args *a,
                           sq_error *err)
{
    char *hash = strchr(line, '#');
    if (hash) *hash = '\0';
    char kind[32];
    int off = 0;
    if (sscanf(line, " %31s %n", kind, &off) < 1) return SQ_OK; /* blank */
    static const struct { const char *kind; int n; } kinds[] = {
        {"edge", 2}, {"grow", 3}, {"point", 4}, {"box", 5}, {"gradation", 1}, {"curvature", 1}};
    char where[320];
    snprintf(where, sizeof where, "%.256s:%d", path, lineno);
    for (size_t i = 0; i < sizeof kinds / sizeof kinds[0]; i++) {
        if (strcmp(kind, kinds[i].kind)) continue;
        double v[5];
        if (!numbers(line + off, " \t", v, kinds[i].n))
            return SQ_FAIL(err, SQ_ERR_USAGE, "%s: '%s' expects %d numbers", where, kind, kinds[i].n);
        if (!strcmp(kind, "gradation")) {
            if (!(v[0] > 1.0))
                return SQ_FAIL(err, SQ_ERR_USAGE, "%s: gradation %g, expects > 1", where, v[0]);
            a->opt.size_gradation = v[0];
            return SQ_OK;
        }
        if (!strcmp(kind, "curvature")) {
            if (!(v[0] >= 0.0 && v[0] <= 1e6))
                return SQ_FAIL(err, SQ_ERR_USAGE, "%s: curvature %g elements per radian, expects "
                               "0..1e6", where, v[0]);
            a->opt.curvature_elements = v[0];
            return SQ_OK;
        }
        return add_source(where, kind, v, kinds[i].n, a, err);
    }
    return SQ_FAIL(err, SQ_ERR_USAGE, "%s: unknown size kind '%s' (edge, grow, point, box, gradation, curvature)",
                   where, kind);
}

/* --sizes FILE: one source per line (docs/sizes.md). */
sq_status sq_cli_parse_size_file(const char *opt, const char *val, sq_cli_args *a, sq_error *err)
{
    (void)opt;
    FILE *f = fopen(val, "r");
    if (!f) return SQ_FAIL(err, SQ_ERR_INPUT, "%s: cannot read the size file", val);
    char line[1024];
    sq_status st = SQ_OK;
    for (int lineno = 1; st == SQ_OK && fgets(line, sizeof line, f); lineno++) {
        /* a line longer than the buffer would be read as two: refused */
        if (!strchr(line, '\n') && !feof(f))
            st = SQ_FAIL(err, SQ_ERR_USAGE, "%s:%d: line too long", val, lineno);
        else
            st = size_line(val, lineno, line, a, err);
    }
    fclose(f);
    return st;
}
