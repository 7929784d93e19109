/* semquad — status codes and error reports shared by every layer.
 *
 * Every fallible function returns an sq_status and, on failure, fills the
 * caller's sq_error (last argument, may be NULL).  The codes are the exit
 * statuses of the `semquad` command (../shared/DESIGN.md, "Exit statuses").
 * Libraries never print and never exit. */
#ifndef SQ_STATUS_H
#define SQ_STATUS_H

#ifdef __cplusplus
extern "C" {
#endif

typedef enum {
    SQ_OK = 0,
    SQ_ERR_INTERNAL = 1, /* bug, allocation failure, numerical breakdown */
    SQ_ERR_USAGE = 2,    /* bad command line or bad argument to a function */
    SQ_ERR_INPUT = 3,    /* input file missing, unreadable or not valid CAD */
    SQ_ERR_GEOMETRY = 4, /* geometry not supported (no face, non-planar, ...) */
    SQ_ERR_PATTERN = 5,  /* invalid singularity pattern */
    SQ_ERR_LAYOUT = 6,   /* no valid layout could be built */
    SQ_ERR_OUTPUT = 7    /* output could not be written */
} sq_status;

typedef struct {
    sq_status code;
    const char *file; /* where the error was raised */
    int line;
    const char *func;
    char msg[512]; /* one line, no trailing newline */
} sq_error;

/* Fill err (if not NULL) and return code.  printf-style message. */
sq_status sq_error_set(sq_error *err, sq_status code, const char *file, int line,
                       const char *func, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 6, 7)))
#endif
    ;

/* Reset err to SQ_OK with an empty message. */
void sq_error_clear(sq_error *err);

/* Raise an error from the current function. */
#define SQ_FAIL(err, code, ...) sq_error_set((err), (code), __FILE__, __LINE__, __func__, __VA_ARGS__)

/* Propagate a failing status (the callee filled err). */
#define SQ_TRY(expr)                                                                               \
    do {                                                                                           \
        sq_status sq_try_status_ = (expr);                                                         \
        if (sq_try_status_ != SQ_OK) return sq_try_status_;                                        \
    } while (0)

/* Short human name of a status ("input", "geometry", ...). */
const char *sq_status_name(sq_status code);

#ifdef __cplusplus
}
#endif
#endif
