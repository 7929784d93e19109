#ifndef SEM_LIB_LOCK_H
#define SEM_LIB_LOCK_H

/* One lock around every call into a library that is not safe for
 * concurrent callers: BLAS and LAPACK (direct, or through CHOLMOD's
 * supernodal kernels) and CHOLMOD's analysis (its nested dissection runs
 * METIS).
 *
 * - OpenBLAS's serial build, which semquad links, hands its level-3 and
 *   LAPACK routines work buffers from one process-wide table without a
 *   lock unless it is built with USE_LOCKING (Debian 12's 0.3.21 is not):
 *   two threads inside it at once can be given the same buffer (OpenBLAS
 *   issues #1755, #2126, fixed by that option in PR #2136).
 * - METIS seeds and draws from one process-wide random number generator:
 *   two analyses at once interleave its draws, and the ordering, hence
 *   the factor's round-off, depends on the timing.
 *
 * Faces meshed on threads call both, so these calls take turns.  The lock
 * is process-wide because what it guards is: two callers with locks of
 * their own would still meet inside the libraries.  Uncontended it costs
 * tens of nanoseconds against microseconds for the smallest call it
 * guards. */
void sem_lib_lock(void);
void sem_lib_unlock(void);

#endif
