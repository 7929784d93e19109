#include "cli.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

sq_status sq_cli_int(const char *opt, const char *val, int lo, int hi, int *out, sq_error *err)
{
    char *end;
    errno = 0;
    long v = strtol(val, &end, 10);
    if (errno || end == val || *end || v < lo || v > hi)
        return SQ_FAIL(err, SQ_ERR_USAGE, "%s expects an integer in %d..%d, got '%s'", opt, lo, hi,
                       val);
    *out = (int)v;
    return SQ_OK;
}

sq_status sq_cli_double(const char *opt, const char *val, double lo, double hi, double *out,
                        sq_error *err)
{
    char *end;
    errno = 0;
    double v = strtod(val, &end);
    if (errno || end == val || *end || !isfinite(v) || v < lo || v > hi)
        return SQ_FAIL(err, SQ_ERR_USAGE, "%s expects a number in [%g, %g], got '%s'", opt, lo, hi,
                       val);
    *out = v;
    return SQ_OK;
}

sq_status sq_cli_int_list(const char *opt, const char *val, int lo, int hi, int *out, int max,
                          int *n, sq_error *err)
{
    char buf[32];
    *n = 0;
    for (const char *p = val; *p;) {
        size_t len = strcspn(p, ",");
        if (len == 0 || len >= sizeof buf || *n == max)
            return SQ_FAIL(err, SQ_ERR_USAGE,
                           "%s expects up to %d comma-separated integers, got '%s'", opt, max, val);
        memcpy(buf, p, len);
        buf[len] = '\0';
        SQ_TRY(sq_cli_int(opt, buf, lo, hi, &out[(*n)++], err));
        p += len + (p[len] == ',');
    }
    if (*n == 0) return SQ_FAIL(err, SQ_ERR_USAGE, "%s expects a list of integers", opt);
    return SQ_OK;
}

void sq_cli_args_init(sq_cli_args *a, const char *cmd)
{
    memset(a, 0, sizeof *a);
    a->cmd = cmd;
    a->face = -1;
    sq_options_init(&a->opt);
    a->opt.log = sq_cli_log;
}

void sq_cli_log(void *data, sq_log_level level, const char *line)
{
    if (data) sq_cli_progress_clear(data);
    fprintf(stderr, "semquad: %s%s\n",
            level == SQ_LOG_NOTE ? "note: " : level == SQ_LOG_WARNING ? "warning: " : "", line);
}

sq_status sq_cli_open(const sq_cli_args *a, sq_model **m, sq_error *err)
{
    SQ_TRY(sq_options_check(&a->opt, err));
    return sq_model_open(a->input, &a->opt, m, err);
}

sq_status sq_cli_print(sq_status st, char **text, const sq_cli_args *a)
{
    if (*text) fputs(*text, a->to_stdout ? stderr : stdout);
    sq_free(*text);
    *text = NULL;
    return st;
}
