/* semquad — text lines formatted on threads, written in order
 * (write_lines.h). */
#include "write_lines.h"

#include "sq_parallel.h"

#include <stdlib.h>

/* the slots of one chunk take at most this many bytes */
#define CHUNK_BYTES (4L << 20)
/* lines per range: formatting one takes about a microsecond */
#define LINES_GRAIN 512

typedef struct {
    sq_line_fn fn;
    const void *ctx;
    long first;  /* the chunk's first line */
    int max_len; /* bytes per slot */
    char *slot;
    int *len;
} chunk;

static sq_status format_range(void *arg, long begin, long end, sq_error *err)
{
    (void)err;
    const chunk *c = arg;
    for (long i = begin; i < end; i++)
        c->len[i] = c->fn(c->ctx, c->first + i, c->slot + i * (long)c->max_len);
    return SQ_OK;
}

sq_status sq_write_lines(FILE *fp, long n, int max_len, sq_line_fn fn, const void *ctx,
                         int threads, sq_write_count *count, sq_error *err)
{
    long per = CHUNK_BYTES / max_len > LINES_GRAIN ? CHUNK_BYTES / max_len : LINES_GRAIN;
    if (per > n) per = n > 0 ? n : 1;
    chunk c = {fn, ctx, 0, max_len, malloc((size_t)per * (size_t)max_len),
               malloc(sizeof(int) * (size_t)per)};
    sq_status st = c.slot && c.len ? SQ_OK : SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    for (c.first = 0; st == SQ_OK && c.first < n; c.first += per) {
        long m = n - c.first < per ? n - c.first : per;
        st = sq_parallel_for(threads, m, LINES_GRAIN, format_range, &c, err);
        for (long i = 0; st == SQ_OK && i < m; i++) {
            if (!c.len[i]) continue;
            fwrite(c.slot + i * (long)max_len, 1, (size_t)c.len[i], fp);
            if (count) sq_progress_every(count->progress, "write", ++count->done, count->total);
        }
    }
    free(c.slot);
    free(c.len);
    return st;
}
