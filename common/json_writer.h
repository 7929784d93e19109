/* semquad — a small streaming JSON writer (commas and nesting handled). */
#ifndef SQ_JSON_WRITER_H
#define SQ_JSON_WRITER_H

#include <stdio.h>

#define SQ_JSON_MAX_DEPTH 16

typedef struct {
    FILE *fp;
    int depth;
    int count[SQ_JSON_MAX_DEPTH]; /* items written at each level */
    int after_key;
} sq_json;

void sq_json_init(sq_json *j, FILE *fp);
/* A writer adding keys to a top-level object already open on fp with
 * items in it (a report printed by hand): its first key after a comma. */
void sq_json_init_in_object(sq_json *j, FILE *fp);
void sq_json_begin_object(sq_json *j);
void sq_json_end_object(sq_json *j);
void sq_json_begin_array(sq_json *j);
void sq_json_end_array(sq_json *j);
void sq_json_key(sq_json *j, const char *key);
void sq_json_string(sq_json *j, const char *s);
void sq_json_number(sq_json *j, double x); /* 15 significant digits; NaN/inf as null */
void sq_json_int(sq_json *j, long x);
void sq_json_bool(sq_json *j, int b);
void sq_json_null(sq_json *j);

/* "key": value pairs in one call. */
void sq_json_key_number(sq_json *j, const char *key, double x);
void sq_json_key_int(sq_json *j, const char *key, long x);
void sq_json_key_string(sq_json *j, const char *key, const char *s);
void sq_json_key_bool(sq_json *j, const char *key, int b);

#endif
