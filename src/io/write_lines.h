/* semquad — a text section of many similar lines (a writer's nodes or
 * elements), formatted on several threads and written in order: each line
 * is formatted into its own slot, so the bytes are those of a loop on one
 * thread whatever the thread count (the files are byte-identical). */
#ifndef SQ_WRITE_LINES_H
#define SQ_WRITE_LINES_H

#include "sq_progress.h"
#include "sq_status.h"

#include <stdio.h>

/* Line k of the section into buf (room for the max_len given below), its
 * newline included; its length (0: no line for k). */
typedef int (*sq_line_fn)(const void *ctx, long k, char *buf);

/* The progress of a writer: "write" events of `done` items of `total`. */
typedef struct {
    const sq_progress *progress;
    long done, total;
} sq_write_count;

/* Lines 0..n-1 of fn (each at most max_len bytes) to fp in order,
 * formatted on `threads` threads (sq_parallel.h), the count (NULL: none)
 * advanced by one per line written. */
sq_status sq_write_lines(FILE *fp, long n, int max_len, sq_line_fn fn, const void *ctx,
                         int threads, sq_write_count *count, sq_error *err);

#endif
