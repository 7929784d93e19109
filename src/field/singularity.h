/* semquad — the singularity pattern a layout is built on: interior
 * irregular points with their valences, wherever they came from. */
#ifndef SQ_SINGULARITY_H
#define SQ_SINGULARITY_H

typedef enum {
    SQ_ORIGIN_CRITICAL = 0, /* critical point of the guiding field */
    SQ_ORIGIN_IMPOSED,      /* from the user's pattern file */
    SQ_ORIGIN_MIDPOINT,     /* inserted by a layout repair (Marcon midpoint division) */
    SQ_ORIGIN_SPLIT         /* one of the elementary points a degenerate critical point
                               of the guiding field was split into (degenerate_split.h) */
} sq_origin;

typedef struct {
    double x, y;
    int valence; /* separatrices leaving it */
    sq_origin origin;
} sq_singularity;

const char *sq_origin_name(sq_origin o); /* "critical-point", "imposed", "midpoint",
                                            "split" */

#endif
