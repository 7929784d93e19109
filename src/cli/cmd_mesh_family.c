/* semquad mesh --levels L --orders Q1,Q2,...: a family of meshes of one
 * block layout for a grid-convergence study (docs/convergence-families.md):
 * STEM_L1.msh .. STEM_LL.msh, STEM_Q4.msh .., or STEM_L2_Q4.msh .. with
 * both, and their manifest (STEM_manifest.json unless --manifest). */
#include "cli.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define FAMILY_NAME_MAX 4096

/* The stem: a->output without its extension. */
static int stem_length(const char *output)
{
    const char *slash = strrchr(output, '/'), *dot = strrchr(output, '.');
    if (dot && (!slash || dot > slash + 1)) return (int)(dot - output);
    return (int)strlen(output);
}

/* File name of level (0: no --levels) and order (0: no --orders). */
static sq_status family_name(const sq_cli_args *a, int level, int order, char *buf, size_t n,
                             sq_error *err)
{
    const char *ext = a->format ? a->format : strrchr(a->output, '.') + 1;
    char l[16] = "", q[16] = "";
    if (level) snprintf(l, sizeof l, "_L%d", level);
    if (order) snprintf(q, sizeof q, "_Q%d", order);
    if (snprintf(buf, n, "%.*s%s%s.%s", stem_length(a->output), a->output, l, q, ext) >= (int)n)
        return SQ_FAIL(err, SQ_ERR_USAGE, "%s: file name too long", a->output);
    return SQ_OK;
}

static int family_levels(const sq_cli_args *a) { return a->levels ? a->levels : 1; }
static int family_orders(const sq_cli_args *a) { return a->norders ? a->norders : 1; }

sq_status sq_cli_family_check(sq_cli_args *a, char *manifest, size_t n, sq_error *err)
{
    if (!a->levels && !a->norders) {
        if (a->manifest)
            return SQ_FAIL(err, SQ_ERR_USAGE, "--manifest lists a family: add --levels or --orders");
        return SQ_OK;
    }
    if (a->no_output || !strcmp(a->output, "-"))
        return SQ_FAIL(err, SQ_ERR_USAGE, "--levels and --orders write files: drop %s",
                       a->no_output ? "--no-output" : "-o -");
    char name[FAMILY_NAME_MAX];
    for (int l = 1; l <= family_levels(a); l++)
        for (int k = 0; k < family_orders(a); k++) {
            SQ_TRY(family_name(a, a->levels ? l : 0, a->norders ? a->orders[k] : 0, name,
                               sizeof name, err));
            SQ_TRY(sq_output_check(name, err));
        }
    if (!a->manifest) {
        if (snprintf(manifest, n, "%.*s_manifest.json", stem_length(a->output), a->output) >=
            (int)n)
            return SQ_FAIL(err, SQ_ERR_USAGE, "%s: file name too long", a->output);
        a->manifest = manifest;
    }
    return sq_output_check(a->manifest, err);
}

/* The files written so far (their meshes borrowed from `made` or the
 * caller) and every mesh this run made. */
typedef struct {
    int n, nmade;
    const sq_mesh **mesh;
    char **file;
    int *level;
    sq_mesh **made;
} family;

static sq_status family_init(family *f, const sq_cli_args *a, sq_error *err)
{
    size_t cap = (size_t)family_levels(a) * (size_t)(family_orders(a) + 1);
    memset(f, 0, sizeof *f);
    f->mesh = calloc(cap, sizeof *f->mesh);
    f->file = calloc(cap, sizeof *f->file);
    f->level = calloc(cap, sizeof *f->level);
    f->made = calloc(cap, sizeof *f->made);
    if (!f->mesh || !f->file || !f->level || !f->made)
        return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    return SQ_OK;
}

static void family_free(family *f)
{
    for (int k = 0; k < f->n; k++) free(f->file[k]);
    for (int k = 0; k < f->nmade; k++) sq_mesh_free(&f->made[k]);
    free(f->mesh);
    free(f->file);
    free(f->level);
    free(f->made);
}

/* m as the family's next file (named, not written yet). */
static sq_status add_file(family *f, const sq_mesh *m, int level, int order,
                          const sq_cli_args *a, sq_error *err)
{
    int k = f->n;
    f->file[k] = malloc(FAMILY_NAME_MAX);
    if (!f->file[k]) return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    f->mesh[k] = m;
    f->level[k] = level;
    f->n++;
    return family_name(a, a->levels ? level : 0, a->norders ? order : 0, f->file[k],
                       FAMILY_NAME_MAX, err);
}

/* Level `level` (the mesh `base`) at every order asked: the same quads,
 * raised or lowered from base's own maps. */
static sq_status add_level(family *f, const sq_mesh *base, int level, const sq_cli_args *a,
                           sq_error *err)
{
    int Q = sq_mesh_order(base);
    for (int k = 0; k < family_orders(a); k++) {
        int order = a->norders ? a->orders[k] : Q;
        const sq_mesh *m = base;
        if (order != Q) {
            SQ_TRY(sq_mesh_refine(base, 0, order, &a->opt, &f->made[f->nmade], err));
            m = f->made[f->nmade++];
        }
        SQ_TRY(add_file(f, m, level, order, a, err));
    }
    return SQ_OK;
}

/* Every mesh first, each level refining the last (so the family is
 * nested): a refusal (too many quads) leaves no file. */
static sq_status make_family(family *f, const sq_mesh *mesh, const sq_cli_args *a, sq_error *err)
{
    const sq_mesh *base = mesh;
    for (int l = 1; l <= family_levels(a); l++) {
        if (l > 1) {
            SQ_TRY(sq_mesh_refine(base, 1, 0, &a->opt, &f->made[f->nmade], err));
            base = f->made[f->nmade++];
        }
        SQ_TRY(add_level(f, base, l, a, err));
    }
    return SQ_OK;
}

/* The files, one line each on stdout, the manifest, then the quality
 * floor of every file. */
static sq_status write_family(const family *f, const sq_cli_args *a, sq_error *err)
{
    for (int k = 0; k < f->n; k++) {
        SQ_TRY(sq_mesh_write_format(f->mesh[k], f->file[k], sq_cli_mesh_format(a), err));
        char *text = NULL;
        SQ_TRY(sq_mesh_describe(f->mesh[k], &text, err));
        if (!a->quiet) printf("%s: %s", f->file[k], text);
        sq_free(text);
    }
    SQ_TRY(sq_mesh_family_write_manifest(a->manifest, f->n, f->mesh, (const char *const *)f->file,
                                         f->level, err));
    for (int k = 0; k < f->n; k++) {
        sq_status st = sq_mesh_check_quality(f->mesh[k], &a->opt, err);
        if (st != SQ_OK) { /* name the file: the line alone names a quad */
            char line[sizeof err->msg];
            snprintf(line, sizeof line, "%s", err->msg);
            return sq_error_set(err, st, __FILE__, __LINE__, __func__, "%s: %s", f->file[k],
                                line);
        }
    }
    return SQ_OK;
}

sq_status sq_cli_family_write(const sq_mesh *mesh, const sq_cli_args *a, sq_error *err)
{
    family f;
    sq_status st = family_init(&f, a, err);
    if (st == SQ_OK) st = make_family(&f, mesh, a, err);
    if (st == SQ_OK) st = write_family(&f, a, err);
    family_free(&f);
    return st;
}
