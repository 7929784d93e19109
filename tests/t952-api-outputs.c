/* The library's writers refuse outputs that are not regular files (issue
 * 21), so C and Python callers are protected as the command is: a FIFO, a
 * directory or a device named as the mesh, the report or the layout's STEP
 * gives SQ_ERR_USAGE and is left as it was, with no temporary file beside
 * it; sq_output_check says the same before any work; sq_mesh_write_format
 * writes the format named whatever the file's name; the progress callback
 * hears every looping stage, done never above total, tracing and patch
 * meshing to their end, writing begun and complete.  Public API only.
 * usage: t952-api-outputs EXAMPLES_DIR */
#include <semquad.h>

#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

static int fails;

/* The progress events heard, per stage. */
static const char *const STAGES[] = {"trace", "mesh", "relax", "write"};
typedef struct {
    int n[4];
    long done[4], total[4];
} heard;

static void on_progress(void *data, const char *stage, long done, long total)
{
    heard *h = data;
    for (int k = 0; k < 4; k++)
        if (!strcmp(stage, STAGES[k])) {
            h->n[k]++;
            h->done[k] = done;
            h->total[k] = total;
            if (done >= 0 && done <= total) return;
        }
    printf("progress event %s %ld of %ld\n", stage, done, total);
    fails++;
}

static void check_progress(const heard *h)
{
    for (int k = 0; k < 4; k++)
        if (h->n[k] == 0) printf("no %s event\n", STAGES[k]), fails++;
    for (int k = 0; k < 4; k++)
        if (k != 2 && h->done[k] != h->total[k]) /* a relaxation may converge early */
            printf("%s ended at %ld of %ld\n", STAGES[k], h->done[k], h->total[k]), fails++;
}

static void expect(const char *what, sq_status got, sq_status want, const sq_error *err)
{
    if (got == want) return;
    printf("%s: status %d, expected %d (%s)\n", what, (int)got, (int)want, err->msg);
    fails++;
}

/* path is still of type `type` (S_IFIFO, S_IFDIR). */
static void unchanged(const char *path, unsigned type)
{
    struct stat s;
    if (stat(path, &s) == 0 && (s.st_mode & S_IFMT) == type) return;
    printf("%s was replaced\n", path);
    fails++;
}

/* Files in dir: the two the test made and those it wrote. */
static int count_files(const char *dir)
{
    DIR *d = opendir(dir);
    int n = 0;
    for (struct dirent *e; d && (e = readdir(d));) n += e->d_name[0] != '.';
    if (d) closedir(d);
    return n;
}

static void writers(const char *dir, const sq_model *model, const sq_mesh *mesh)
{
    char fifo[512], sub[512], xml[512];
    snprintf(fifo, sizeof fifo, "%s/f.msh", dir);
    snprintf(sub, sizeof sub, "%s/d.json", dir);
    snprintf(xml, sizeof xml, "%s/mesh.dat", dir);
    if (mkfifo(fifo, 0600) != 0 || mkdir(sub, 0700) != 0) {
        printf("cannot make the FIFO and the directory in %s\n", dir);
        fails++;
        return;
    }
    sq_error err;
    expect("sq_mesh_write to a FIFO", sq_mesh_write(mesh, fifo, &err), SQ_ERR_USAGE, &err);
    expect("sq_mesh_write_report to a directory", sq_mesh_write_report(mesh, sub, &err),
           SQ_ERR_USAGE, &err);
    if (!strstr(err.msg, "is a directory")) printf("message: %s\n", err.msg), fails++;
    expect("sq_output_check(FIFO)", sq_output_check(fifo, &err), SQ_ERR_USAGE, &err);
    expect("sq_output_check(/dev/null)", sq_output_check("/dev/null", &err), SQ_ERR_USAGE, &err);
    expect("sq_output_check(-)", sq_output_check("-", &err), SQ_OK, &err);
    expect("sq_output_check(a new file)", sq_output_check(xml, &err), SQ_OK, &err);
    sq_quad_layout *l = NULL;
    sq_options o;
    sq_options_init(&o);
    expect("sq_face_layout", sq_face_layout(model, -1, &o, &l, &err), SQ_OK, &err);
    char step[512];
    snprintf(step, sizeof step, "%s/f.step", dir);
    rename(fifo, step);
    if (l) expect("layout STEP to a FIFO", sq_quad_layout_write(l, step, &err), SQ_ERR_USAGE, &err);
    sq_quad_layout_free(&l);
    unchanged(step, S_IFIFO);
    unchanged(sub, S_IFDIR);
    if (count_files(dir) != 2) printf("%d files in %s, expected 2\n", count_files(dir), dir), fails++;
    expect("sq_mesh_write_format(xml)", sq_mesh_write_format(mesh, xml, "xml", &err), SQ_OK, &err);
    FILE *fp = fopen(xml, "r");
    char head[64] = "";
    if (!fp || !fgets(head, sizeof head, fp) || strncmp(head, "<?xml", 5))
        printf("%s does not start as XML: %s\n", xml, head), fails++;
    if (fp) fclose(fp);
    expect("sq_mesh_write_format(stl)", sq_mesh_write_format(mesh, xml, "stl", &err), SQ_ERR_USAGE,
           &err);
    remove(xml);
    remove(step);
    rmdir(sub);
}

int main(int argc, char **argv)
{
    if (argc != 2) return 2;
    char step[512], dir[] = "/tmp/t952-XXXXXX";
    snprintf(step, sizeof step, "%s/half_disc.step", argv[1]);
    if (!mkdtemp(dir)) return 1;
    sq_error err;
    sq_model *model = NULL;
    sq_mesh *mesh = NULL;
    sq_options o;
    sq_options_init(&o);
    o.size = 0.3;
    heard h = {0};
    o.progress = on_progress;
    o.progress_data = &h;
    expect("sq_model_open", sq_model_open(step, &o, &model, &err), SQ_OK, &err);
    if (model) expect("sq_face_mesh", sq_face_mesh(model, -1, &o, &mesh, &err), SQ_OK, &err);
    if (mesh) writers(dir, model, mesh);
    check_progress(&h);
    sq_mesh_free(&mesh);
    sq_model_free(&model);
    rmdir(dir);
    return fails != 0;
}
