/* semquad — all-or-nothing output files: write to a temporary file beside
 * the target, rename over it on success, remove it on failure, so a failed
 * run never leaves a half-written output.  Outputs are regular files only
 * (a rename would replace a FIFO, a device node or a socket with a file),
 * or "-": standard output, written as it comes. */
#ifndef SQ_OUTFILE_H
#define SQ_OUTFILE_H

#include "sq_status.h"

#include <stdio.h>

typedef struct {
    FILE *fp;          /* write here */
    char *path;        /* final name (NULL for standard output) */
    char *tmp;         /* temporary name (NULL for standard output) */
} sq_outfile;

/* SQ_ERR_USAGE if path names something that exists and is not a regular
 * file (a directory, a FIFO, a device, a socket); "-" and new files pass. */
sq_status sq_outfile_check(const char *path, sq_error *err);

/* Check path (sq_outfile_check), then open a temporary file in the
 * target's directory, or standard output for "-".  SQ_ERR_OUTPUT if it
 * cannot be created. */
sq_status sq_outfile_open(const char *path, sq_outfile *out, sq_error *err);

/* Flush, close and rename onto the target (SQ_ERR_OUTPUT on any write or
 * rename error, the temporary file removed).  Always releases out. */
sq_status sq_outfile_commit(sq_outfile *out, sq_error *err);

/* Close and remove the temporary file; NULL-safe, idempotent. */
void sq_outfile_abort(sq_outfile *out);

#endif
