/* Progress on stderr (sq_options.progress): a bar for a stage that runs
 * past about a second where stderr is a terminal, or one JSON object per
 * event for batch tools (--progress=json); the logger clears a bar before
 * printing its line, so stage lines stay as they were. */
#include "cli.h"

#include <stdio.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#define BAR_AFTER_S 1.0 /* a stage shorter than this shows no bar */
#define BAR_WIDTH 30

static double seconds(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

void sq_cli_progress_clear(sq_cli_progress *p)
{
    if (p->shown) fputs("\r\033[K", stderr);
    p->shown = 0;
}

void sq_cli_progress_event(void *data, const char *stage, long done, long total)
{
    sq_cli_progress *p = data;
    if (p->json) {
        fprintf(stderr, "{\"stage\": \"%s\", \"done\": %ld, \"total\": %ld}\n", stage, done, total);
        return;
    }
    if (strcmp(p->stage, stage) || done < p->done) { /* a stage begins (again) */
        sq_cli_progress_clear(p);
        snprintf(p->stage, sizeof p->stage, "%s", stage);
        p->t0 = seconds();
    }
    p->done = done;
    if (done >= total) { /* the stage's end: its line (or the summary) follows */
        sq_cli_progress_clear(p);
        return;
    }
    if (seconds() - p->t0 < BAR_AFTER_S) return;
    int pct = (int)(100 * done / total), fill = (int)(BAR_WIDTH * done / total);
    if (p->shown && pct == p->pct) return;
    fprintf(stderr, "\r\033[Ksemquad: %s [%.*s%*s] %3d%%", stage, fill,
            "##############################", BAR_WIDTH - fill, "", pct);
    fflush(stderr);
    p->shown = 1;
    p->pct = pct;
}

sq_status sq_cli_progress_init(sq_cli_args *a, sq_error *err)
{
    const char *how = a->progress ? a->progress : "auto";
    a->opt.log_data = &a->bar;
    if (!strcmp(how, "json")) {
        a->bar.json = 1;
    } else if (!strcmp(how, "none") || (!strcmp(how, "auto") && (a->quiet || !isatty(2)))) {
        return SQ_OK;
    } else if (strcmp(how, "auto")) {
        return SQ_FAIL(err, SQ_ERR_USAGE, "--progress expects auto, json or none, got '%s'", how);
    }
    a->opt.progress = sq_cli_progress_event;
    a->opt.progress_data = &a->bar;
    return SQ_OK;
}
