/* semquad — numbers as text without the C library's slow path (the text
 * writers spend most of their time formatting).
 *
 * sq_format_double writes the bytes printf's "%.17g" writes (17 significant
 * digits, correctly rounded, ties to even; trailing zeros dropped; the
 * exponent form below 1e-4 and from 1e17): the same files as before, and
 * text that reads back to the same double (17 digits always do: IEEE 754-2008,
 * 5.12.2).  Exact integer arithmetic does it for 1e-11 <= |v| < 1e44, the
 * magnitudes of mesh coordinates; other values, non-finite ones and
 * subnormals go to snprintf. */
#ifndef SQ_FORMAT_NUMBER_H
#define SQ_FORMAT_NUMBER_H

/* Room for any result, with its terminating NUL. */
#define SQ_DOUBLE_CHARS 32

/* v as "%.17g" into buf (SQ_DOUBLE_CHARS at least), NUL-terminated; the
 * length written. */
int sq_format_double(char *buf, double v);

/* A point of the plane as "x y 0" (each "%.17g"), the way the mesh
 * writers give coordinates; not terminated, the length written. */
#define SQ_XY0_CHARS (2 * SQ_DOUBLE_CHARS + 4)
int sq_format_xy0(char *buf, double x, double y);

/* v in decimal (printf's "%ld") into buf (24 chars at least), not
 * terminated; the length written. */
int sq_format_long(char *buf, long v);

#endif
