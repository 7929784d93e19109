/* semquad — command-line entry: dispatch commands, map statuses to exit
 * codes (docs/conventions.md, "Exit statuses"), print errors as one line. */
#include "cli.h"

#include <omp.h>
#include <stdio.h>
#include <string.h>

const sq_cli_command *const *sq_cli_commands(void)
{
    static const sq_cli_command *const all[] = {&sq_cli_info,   &sq_cli_triangulate,
                                                &sq_cli_field,  &sq_cli_converge,
                                                &sq_cli_mesh,   &sq_cli_layout,
                                                NULL};
    return all;
}

static const sq_cli_command *command_named(const char *name)
{
    for (const sq_cli_command *const *c = sq_cli_commands(); *c; c++)
        if (!strcmp((*c)->name, name)) return *c;
    return NULL;
}

/* `semquad CMD ARGS...`: parse, then run (or print the usage). */
static sq_status run_command(const sq_cli_command *c, int argc, char **argv, sq_error *err)
{
    sq_cli_args a;
    sq_cli_args_init(&a, c->name);
    SQ_TRY(sq_cli_parse(c, argc, argv, &a, err));
    if (a.help) {
        sq_cli_usage(c);
        return SQ_OK;
    }
    sq_status st = c->run(&a, err);
    sq_cli_progress_clear(&a.bar);
    return st;
}

/* help, --version, completion; else a command. */
static sq_status dispatch(int argc, char **argv, sq_error *err)
{
    const char *cmd = argv[1];
    if (!strcmp(cmd, "help") || !strcmp(cmd, "--help") || !strcmp(cmd, "-h")) {
        const sq_cli_command *c = argc > 2 ? command_named(argv[2]) : NULL;
        if (argc > 2 && !c)
            return SQ_FAIL(err, SQ_ERR_USAGE, "help: unknown command '%s' (try: semquad help)",
                           argv[2]);
        if (c) sq_cli_usage(c);
        else sq_cli_overview();
        return SQ_OK;
    }
    if (!strcmp(cmd, "--version") || !strcmp(cmd, "version")) {
        printf("semquad %s\n", sq_version());
        return SQ_OK;
    }
    if (!strcmp(cmd, "completion")) {
        if (argc != 3)
            return SQ_FAIL(err, SQ_ERR_USAGE, "completion: expects bash, zsh or table");
        return sq_cli_completion(argv[2], err);
    }
    const sq_cli_command *c = command_named(cmd);
    if (!c) return SQ_FAIL(err, SQ_ERR_USAGE, "unknown command '%s' (try: semquad help)", cmd);
    return run_command(c, argc - 1, argv + 1, err);
}

int main(int argc, char **argv)
{
    sq_error err;
    sq_error_clear(&err);
    /* CHOLMOD's supernodal loops ask OpenMP for 4 threads, a number fixed
     * when it was built (CHOLMOD_OMP_NUM_THREADS), whatever the machine: on
     * small supernodes (the DG guiding field) and 2 cores their barriers
     * cost more than the loops, naca0012's whole run 0.25-0.29 s against
     * 0.21-0.22 s with every parallel region run by the calling thread */
    omp_set_max_active_levels(0);
    if (argc < 2) {
        fputs("semquad: usage error: missing command (try: semquad help)\n", stderr);
        return SQ_ERR_USAGE;
    }
    sq_status st = dispatch(argc, argv, &err);
    if (st != SQ_OK) fprintf(stderr, "semquad: %s: %s\n", sq_status_name(st), err.msg);
    return (int)st;
}
