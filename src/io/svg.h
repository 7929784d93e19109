/* semquad — SVG drawing in world coordinates (y up), scaled to fit. */
#ifndef SQ_SVG_H
#define SQ_SVG_H

#include <stdio.h>

typedef struct {
    FILE *fp;
    double x0, y1;   /* world point at the top-left corner */
    double scale;    /* pixels per world unit */
    double margin;   /* pixels */
} sq_svg;

/* Start a picture of the world box bbox[4] = {xmin, ymin, xmax, ymax} at
 * most width_px wide and height_px high, with a white background. */
void sq_svg_begin(sq_svg *s, FILE *fp, const double bbox[4], double width_px, double height_px);
void sq_svg_end(sq_svg *s);

/* Polyline through n world points xy[2n]; closed: 1 for a polygon. fill may
 * be "none". */
void sq_svg_polyline(sq_svg *s, int n, const double *xy, int closed, const char *stroke,
                     double width_px, const char *fill);
void sq_svg_circle(sq_svg *s, double x, double y, double r_px, const char *fill);
void sq_svg_text(sq_svg *s, double x, double y, double dx_px, double dy_px, double size_px,
                 const char *fill, const char *text);

/* Colour of a singular point of valence v in every picture: 3 blue, 5 red,
 * 6 orange, 8 yellow, others grey. */
const char *sq_svg_valence_color(int v);

#endif
