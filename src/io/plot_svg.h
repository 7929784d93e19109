/* semquad — a small log-log plot writer (SVG): axes spanning whole decades,
 * major ticks and labels 10^k, minor ticks 2..9 when few decades are shown,
 * a light grid, a legend to the right, several series drawn as polylines
 * with markers.  Points with a non-positive or non-finite coordinate are
 * skipped (they have no place on a log axis). */
#ifndef SQ_PLOT_SVG_H
#define SQ_PLOT_SVG_H

#include "sq_status.h"

#include <stdio.h>

typedef enum {
    SQ_MARK_CIRCLE = 0,
    SQ_MARK_SQUARE,
    SQ_MARK_TRIANGLE,
    SQ_MARK_DIAMOND,
    SQ_MARK_TRIANGLE_DOWN,
    SQ_MARK_CROSS,
    SQ_MARK_PLUS,
    SQ_MARK_COUNT
} sq_plot_marker;

typedef struct {
    const char *label; /* legend text (may be NULL: not in the legend) */
    int n;
    const double *x, *y;
    const char *color; /* SVG colour; NULL: the palette colour of the series index */
    sq_plot_marker marker;
    int open;   /* 1: hollow marker */
    int dashed; /* 1: dashed line */
} sq_plot_series;

typedef struct {
    const char *title, *xlabel, *ylabel; /* may be NULL */
    int width, height;                   /* pixels; <= 0: 760 x 500 */
} sq_plot;

/* The i-th colour of a palette of well-separated colours (cycles). */
const char *sq_plot_color(int i);

/* Write the whole SVG document to fp. */
void sq_plot_loglog(FILE *fp, const sq_plot *plot, int nseries, const sq_plot_series *series);

/* The same into `path`, atomically (SQ_ERR_OUTPUT if it cannot be written). */
sq_status sq_plot_loglog_file(const char *path, const sq_plot *plot, int nseries,
                              const sq_plot_series *series, sq_error *err);

#endif
