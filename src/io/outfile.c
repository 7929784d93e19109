#include "outfile.h"

#include <errno.h>
#include <fcntl.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

sq_status sq_outfile_check(const char *path, sq_error *err)
{
    struct stat s;
    if (!strcmp(path, "-") || stat(path, &s) != 0 || S_ISREG(s.st_mode)) return SQ_OK;
    const char *what = S_ISDIR(s.st_mode)                         ? "a directory"
                       : S_ISFIFO(s.st_mode)                      ? "a FIFO"
                       : S_ISCHR(s.st_mode) || S_ISBLK(s.st_mode) ? "a device"
                                                                  : "not a regular file";
    return SQ_FAIL(err, SQ_ERR_USAGE,
                   "%s is %s: outputs are written to regular files (or - for standard output)",
                   path, what);
}

sq_status sq_outfile_open(const char *path, sq_outfile *out, sq_error *err)
{
    memset(out, 0, sizeof *out);
    SQ_TRY(sq_outfile_check(path, err));
    if (!strcmp(path, "-")) {
        out->fp = stdout;
        return SQ_OK;
    }
    size_t n = strlen(path);
    out->path = strdup(path);
    out->tmp = malloc(n + 32);
    if (!out->path || !out->tmp) {
        sq_outfile_abort(out);
        return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    }
    /* same directory as the target, so the rename is atomic; created with
     * O_EXCL and mode 0666 so the umask applies as for any new file
     * (mkstemp would leave it readable by its owner only) */
    int fd = -1, e = 0;
    for (int k = 0; k < 100 && fd < 0; k++) {
        snprintf(out->tmp, n + 32, "%s.tmp%ld.%d", path, (long)getpid(), k);
        fd = open(out->tmp, O_WRONLY | O_CREAT | O_EXCL, 0666);
        e = errno;
        if (fd < 0 && e != EEXIST) break;
    }
    if (fd < 0) {
        free(out->tmp);
        out->tmp = NULL;
        sq_outfile_abort(out);
        return SQ_FAIL(err, SQ_ERR_OUTPUT, "cannot write %s: %s", path, strerror(e));
    }
    out->fp = fdopen(fd, "w");
    if (!out->fp) {
        close(fd);
        sq_outfile_abort(out);
        return SQ_FAIL(err, SQ_ERR_OUTPUT, "cannot write %s", path);
    }
    return SQ_OK;
}

sq_status sq_outfile_commit(sq_outfile *out, sq_error *err)
{
    if (out->fp == stdout) {
        int bad = fflush(stdout) != 0 || ferror(stdout);
        out->fp = NULL;
        return bad ? SQ_FAIL(err, SQ_ERR_OUTPUT, "cannot write to standard output") : SQ_OK;
    }
    int bad = ferror(out->fp) != 0;
    bad |= fclose(out->fp) != 0;
    out->fp = NULL;
    if (!bad && rename(out->tmp, out->path) == 0) {
        free(out->tmp);
        out->tmp = NULL;
        free(out->path);
        out->path = NULL;
        return SQ_OK;
    }
    int e = errno;
    sq_status st = SQ_FAIL(err, SQ_ERR_OUTPUT, "cannot write %s: %s", out->path, strerror(e));
    sq_outfile_abort(out);
    return st;
}

void sq_outfile_abort(sq_outfile *out)
{
    if (!out) return;
    if (out->fp && out->fp != stdout) fclose(out->fp);
    if (out->tmp) remove(out->tmp);
    free(out->tmp);
    free(out->path);
    memset(out, 0, sizeof *out);
}
