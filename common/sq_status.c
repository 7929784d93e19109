#include "sq_status.h"

#include <stdarg.h>
#include <stdio.h>

sq_status sq_error_set(sq_error *err, sq_status code, const char *file, int line,
                       const char *func, const char *fmt, ...)
{
    if (err) {
        err->code = code;
        err->file = file;
        err->line = line;
        err->func = func;
        va_list ap;
        va_start(ap, fmt);
        vsnprintf(err->msg, sizeof err->msg, fmt, ap);
        va_end(ap);
    }
    return code;
}

void sq_error_clear(sq_error *err)
{
    if (!err) return;
    err->code = SQ_OK;
    err->file = NULL;
    err->line = 0;
    err->func = NULL;
    err->msg[0] = '\0';
}

const char *sq_status_name(sq_status code)
{
    switch (code) {
    case SQ_OK: return "ok";
    case SQ_ERR_INTERNAL: return "internal error";
    case SQ_ERR_USAGE: return "usage error";
    case SQ_ERR_INPUT: return "input error";
    case SQ_ERR_GEOMETRY: return "unsupported geometry";
    case SQ_ERR_PATTERN: return "invalid singularity pattern";
    case SQ_ERR_LAYOUT: return "no valid layout";
    case SQ_ERR_OUTPUT: return "output error";
    case SQ_ERR_QUALITY: return "quality below the floor";
    case SQ_ERR_PERIODIC: return "periodic edges do not match";
    }
    return "unknown error";
}
