#include "json_writer.h"

#include <math.h>

void sq_json_init(sq_json *j, FILE *fp)
{
    j->fp = fp;
    j->depth = 0;
    j->count[0] = 0;
    j->after_key = 0;
}

void sq_json_init_in_object(sq_json *j, FILE *fp)
{
    sq_json_init(j, fp);
    j->depth = 1;
    j->count[1] = 1;
}

/* Separator and indentation before a value or key at the current level. */
static void item(sq_json *j)
{
    if (j->after_key) {
        j->after_key = 0;
        return;
    }
    if (j->count[j->depth]++ > 0) fputc(',', j->fp);
    if (j->depth > 0) fprintf(j->fp, "\n%*s", 2 * j->depth, "");
}

static void open(sq_json *j, char c)
{
    item(j);
    fputc(c, j->fp);
    if (j->depth < SQ_JSON_MAX_DEPTH - 1) j->count[++j->depth] = 0;
}

static void close_(sq_json *j, char c)
{
    int had = j->count[j->depth] > 0;
    if (j->depth > 0) j->depth--;
    if (had) fprintf(j->fp, "\n%*s", 2 * j->depth, "");
    fputc(c, j->fp);
    if (j->depth == 0) fputc('\n', j->fp);
}

void sq_json_begin_object(sq_json *j) { open(j, '{'); }
void sq_json_end_object(sq_json *j) { close_(j, '}'); }
void sq_json_begin_array(sq_json *j) { open(j, '['); }
void sq_json_end_array(sq_json *j) { close_(j, ']'); }

static void quoted(FILE *fp, const char *s)
{
    fputc('"', fp);
    for (; *s; s++) {
        unsigned char c = (unsigned char)*s;
        if (c == '"' || c == '\\') fprintf(fp, "\\%c", c);
        else if (c < 0x20) fprintf(fp, "\\u%04x", c);
        else fputc(c, fp);
    }
    fputc('"', fp);
}

void sq_json_key(sq_json *j, const char *key)
{
    item(j);
    quoted(j->fp, key);
    fputs(": ", j->fp);
    j->after_key = 1;
}

void sq_json_string(sq_json *j, const char *s)
{
    item(j);
    quoted(j->fp, s);
}

void sq_json_number(sq_json *j, double x)
{
    item(j);
    if (isfinite(x)) fprintf(j->fp, "%.15g", x);
    else fputs("null", j->fp);
}

void sq_json_int(sq_json *j, long x)
{
    item(j);
    fprintf(j->fp, "%ld", x);
}

void sq_json_bool(sq_json *j, int b)
{
    item(j);
    fputs(b ? "true" : "false", j->fp);
}

void sq_json_null(sq_json *j)
{
    item(j);
    fputs("null", j->fp);
}

void sq_json_key_number(sq_json *j, const char *key, double x)
{
    sq_json_key(j, key);
    sq_json_number(j, x);
}

void sq_json_key_int(sq_json *j, const char *key, long x)
{
    sq_json_key(j, key);
    sq_json_int(j, x);
}

void sq_json_key_string(sq_json *j, const char *key, const char *s)
{
    sq_json_key(j, key);
    sq_json_string(j, s);
}

void sq_json_key_bool(sq_json *j, const char *key, int b)
{
    sq_json_key(j, key);
    sq_json_bool(j, b);
}
