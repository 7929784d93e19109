/* semquad — helpers shared by the subcommands of the `semquad` program. */
#ifndef SQ_CLI_H
#define SQ_CLI_H

#include <semquad.h>

/* Parse a whole-string integer/real option value; SQ_ERR_USAGE naming the
 * option otherwise. */
sq_status sq_cli_int(const char *opt, const char *val, int lo, int hi, int *out, sq_error *err);
sq_status sq_cli_double(const char *opt, const char *val, double lo, double hi, double *out,
                        sq_error *err);

/* Comma-separated integers in lo..hi into out[max]; *n their count. */
sq_status sq_cli_int_list(const char *opt, const char *val, int lo, int hi, int *out, int max,
                          int *n, sq_error *err);

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
    sq_options opt;     /* --no-heal, --heal-tolerance T; each command's own options;
                           its logger prints to stderr unless -q */
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

/* Print a line of the library's messages on stderr ("semquad: note: ..."). */
void sq_cli_log(void *data, sq_log_level level, const char *line);

/* Check the options (a usage error before any work), then read a->input. */
sq_status sq_cli_open(const sq_cli_args *a, sq_model **m, sq_error *err);

/* Print *text (if any) on stdout, free it, return st: the status of the
 * call that made it (sq_cli_print(sq_x_describe(x, &text, err), &text):
 * text is read after that call). */
sq_status sq_cli_print(sq_status st, char **text);

/* Subcommands: return an sq_status, print errors through err. */
sq_status sq_cmd_info(int argc, char **argv, sq_error *err);
sq_status sq_cmd_triangulate(int argc, char **argv, sq_error *err);
sq_status sq_cmd_field(int argc, char **argv, sq_error *err);
sq_status sq_cmd_layout(int argc, char **argv, sq_error *err);
sq_status sq_cmd_mesh(int argc, char **argv, sq_error *err);
sq_status sq_cmd_converge(int argc, char **argv, sq_error *err);

#endif
