/* semquad — status codes and error reports shared by every layer: those
 * of the public API (include/semquad.h: sq_status, sq_error, SQ_FAIL,
 * SQ_TRY).  Every fallible function returns an sq_status and, on failure,
 * fills the caller's sq_error (last argument, may be NULL); the codes are
 * the exit statuses of the `semquad` command.  Libraries never print and
 * never exit. */
#ifndef SQ_STATUS_H
#define SQ_STATUS_H

#include "semquad.h"

#endif
