/* semquad — helpers shared by the subcommands of the `semquad` program. */
#ifndef SQ_CLI_H
#define SQ_CLI_H

#include "cad.h"
#include "guiding_field.h"

/* Parse a whole-string integer/real option value; SQ_ERR_USAGE naming the
 * option otherwise. */
sq_status sq_cli_int(const char *opt, const char *val, int lo, int hi, int *out, sq_error *err);
sq_status sq_cli_double(const char *opt, const char *val, double lo, double hi, double *out,
                        sq_error *err);

/* Comma-separated integers in lo..hi into out[max]; *n their count. */
sq_status sq_cli_int_list(const char *opt, const char *val, int lo, int hi, int *out, int max,
                          int *n, sq_error *err);

/* --method value: auto, cg or dg. */
sq_status sq_cli_method(const char *val, sq_method *out, sq_error *err);

/* Value of option argv[*i] (advances *i); SQ_ERR_USAGE if missing. */
sq_status sq_cli_value(int argc, char **argv, int *i, const char **val, sq_error *err);

/* What every command that reads a face shares on its command line. */
typedef struct {
    const char *input;  /* the CAD file (the one positional argument) */
    int face;           /* --face N (-1: the default face) */
    int quiet;          /* -q, --quiet */
    const char *output; /* -o F, --output F */
    const char *svg;    /* --svg F */
    const char *report; /* --report F */
    cad_read_options read; /* --no-heal, --heal-tolerance T */
} sq_cli_args;

void sq_cli_args_init(sq_cli_args *a);

/* If argv[*i] is a shared option (advancing *i past its value) or the
 * input file, take it and set *taken; otherwise leave it for the command.
 * A second input file is a usage error naming cmd. */
sq_status sq_cli_take(const char *cmd, int argc, char **argv, int *i, sq_cli_args *a, int *taken,
                      sq_error *err);

/* The usage error for an option no one took; and the one for a missing
 * input file. */
sq_status sq_cli_unknown(const char *cmd, const char *opt, sq_error *err);
sq_status sq_cli_need_input(const char *cmd, const sq_cli_args *a, sq_error *err);

/* Read `path` with options ro (NULL: the defaults) and open face `face`
 * (-1: the default face; *note set when the choice needs saying).  On
 * success the caller frees both. */
sq_status sq_cli_open_face(const char *path, int face, const cad_read_options *ro,
                           cad_model **model, cad_face **cface, int *face_index, const char **note,
                           sq_error *err);

/* The healing summary of face `face` in one line ("face 2 healed within
 * 0.0001 mm: closed a ... gap ...; ..."); 0 (buf empty) if it needed none. */
int sq_cli_heal_note(const cad_model *m, int face, char *buf, size_t n);

/* Subcommands: return an sq_status, print errors through err. */
sq_status sq_cmd_info(int argc, char **argv, sq_error *err);
sq_status sq_cmd_triangulate(int argc, char **argv, sq_error *err);
sq_status sq_cmd_field(int argc, char **argv, sq_error *err);
sq_status sq_cmd_layout(int argc, char **argv, sq_error *err);
sq_status sq_cmd_mesh(int argc, char **argv, sq_error *err);
sq_status sq_cmd_converge(int argc, char **argv, sq_error *err);

#endif
