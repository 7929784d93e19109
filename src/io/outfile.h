/* semquad — all-or-nothing output files: write to a temporary file beside
 * the target, rename over it on success, remove it on failure, so a failed
 * run never leaves a half-written output. */
#ifndef SQ_OUTFILE_H
#define SQ_OUTFILE_H

#include "sq_status.h"

#include <stdio.h>

typedef struct {
    FILE *fp;          /* write here */
    char *path;        /* final name */
    char *tmp;         /* temporary name */
} sq_outfile;

/* Open a temporary file in the target's directory.  SQ_ERR_OUTPUT if it
 * cannot be created. */
sq_status sq_outfile_open(const char *path, sq_outfile *out, sq_error *err);

/* Flush, close and rename onto the target (SQ_ERR_OUTPUT on any write or
 * rename error, the temporary file removed).  Always releases out. */
sq_status sq_outfile_commit(sq_outfile *out, sq_error *err);

/* Close and remove the temporary file; NULL-safe, idempotent. */
void sq_outfile_abort(sq_outfile *out);

#endif
