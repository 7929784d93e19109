/* The library decides as the command does (issue 21, "the tests that
 * compare reports pass unchanged through the CLI and through the library
 * call with default options"): for half_disc, annulus and naca0012, the
 * JSON report of sq_mesh_report with sq_options_init's defaults is, byte
 * for byte, the one `semquad mesh EX --report R.json -o X.msh` writes, once
 * the "timings_s" object (wall times) is blanked in both; every key, value
 * and its order, the input path included (both are given the same string).
 * The library's sq_mesh_write gives the command's MSH byte for byte too.
 * Tolerance 0: the same code on the same input must make the same digits.
 * usage: t953-api-report-parity SEMQUAD EXAMPLES_DIR */
#include <semquad.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

static int fails;

/* The whole of path, NUL-terminated, or NULL. */
static char *read_file(const char *path)
{
    FILE *fp = fopen(path, "rb");
    if (!fp) return NULL;
    char *s = NULL;
    long n = fseek(fp, 0, SEEK_END) == 0 ? ftell(fp) : -1;
    if (n >= 0 && fseek(fp, 0, SEEK_SET) == 0 && (s = malloc((size_t)n + 1))) {
        if (fread(s, 1, (size_t)n, fp) != (size_t)n) n = 0;
        s[n] = '\0';
    }
    fclose(fp);
    return s;
}

/* Empties the report's "timings_s" object in place ("timings_s": {});
 * 0 if the report has none. */
static int blank_timings(char *json)
{
    char *t = strstr(json, "\"timings_s\": {");
    char *end = t ? strchr(t, '}') : NULL;
    if (!end) return 0;
    char *open = strchr(t, '{') + 1;
    memmove(open, end, strlen(end) + 1);
    return 1;
}

/* Says where a and b part: the line number and both lines. */
static void first_difference(const char *what, const char *a, const char *b)
{
    int line = 1;
    const char *la = a, *lb = b;
    for (; *a && *a == *b; a++, b++)
        if (*a == '\n') line++, la = a + 1, lb = b + 1;
    printf("%s: the library's report and the command's differ at line %d:\n  library: %.*s\n"
           "  command: %.*s\n",
           what, line, (int)strcspn(la, "\n"), la, (int)strcspn(lb, "\n"), lb);
    fails++;
}

/* Runs `semquad mesh step --report report -o msh`; its exit status. */
static int run_command(const char *semquad, const char *step, const char *report, const char *msh)
{
    pid_t pid = fork();
    if (pid == 0) {
        char *argv[] = {(char *)semquad, "mesh", (char *)step, "--report",
                        (char *)report,  "-o",   (char *)msh,  NULL};
        execv(semquad, argv);
        _exit(127);
    }
    int status;
    if (pid < 0 || waitpid(pid, &status, 0) != pid || !WIFEXITED(status)) return -1;
    return WEXITSTATUS(status);
}

/* The library's report and MSH of step's default face with the default
 * options (lib_msh written), for sq_free; NULL when something failed
 * (said). */
static char *library_report(const char *step, const char *lib_msh)
{
    sq_options opt;
    sq_options_init(&opt);
    sq_error err;
    sq_model *model = NULL;
    sq_mesh *mesh = NULL;
    char *json = NULL;
    sq_status st = sq_model_open(step, &opt, &model, &err);
    if (st == SQ_OK) st = sq_face_mesh(model, -1, &opt, &mesh, &err);
    if (st == SQ_OK) st = sq_mesh_report(mesh, &json, &err);
    if (st == SQ_OK) st = sq_mesh_write(mesh, lib_msh, &err);
    if (st != SQ_OK) printf("%s: library: %s: %s\n", step, sq_status_name(st), err.msg), fails++;
    sq_mesh_free(&mesh);
    sq_model_free(&model);
    return json;
}

static void compare(const char *semquad, const char *dir, const char *examples, const char *name)
{
    char step[512], report[512], msh[512], lib_msh[512];
    snprintf(step, sizeof step, "%s/%s.step", examples, name);
    snprintf(report, sizeof report, "%s/%s.json", dir, name);
    snprintf(msh, sizeof msh, "%s/%s.msh", dir, name);
    snprintf(lib_msh, sizeof lib_msh, "%s/%s-lib.msh", dir, name);
    int rc = run_command(semquad, step, report, msh);
    char *lib = library_report(step, lib_msh), *cli = read_file(report);
    char *cli_msh = read_file(msh), *lib_mesh = read_file(lib_msh);
    if (rc != 0) printf("%s: semquad mesh exited %d\n", name, rc), fails++;
    if (lib && cli) {
        if (!strstr(lib, "\"quads\": ") || !blank_timings(lib) || !blank_timings(cli))
            printf("%s: a report without quads or timings_s\n", name), fails++;
        else if (strcmp(lib, cli))
            first_difference(name, lib, cli);
    } else {
        printf("%s: no report from the %s\n", name, lib ? "command" : "library"), fails++;
    }
    if (!cli_msh || !lib_mesh || strcmp(cli_msh, lib_mesh))
        printf("%s: the library's MSH is not the command's\n", name), fails++;
    sq_free(lib);
    free(cli);
    free(cli_msh);
    free(lib_mesh);
    remove(report);
    remove(msh);
    remove(lib_msh);
}

int main(int argc, char **argv)
{
    if (argc != 3) return 2;
    char dir[] = "/tmp/t953-XXXXXX";
    if (!mkdtemp(dir)) return 1;
    static const char *const names[] = {"half_disc", "annulus", "naca0012"};
    for (int k = 0; k < 3; k++)
        compare(argv[1], dir, argv[2], names[k]);
    rmdir(dir);
    return fails != 0;
}
