#include "svg.h"

void sq_svg_begin(sq_svg *s, FILE *fp, const double bbox[4], double width_px, double height_px)
{
    double w = bbox[2] - bbox[0], h = bbox[3] - bbox[1];
    if (w <= 0.0) w = 1.0;
    if (h <= 0.0) h = 1.0;
    s->fp = fp;
    s->margin = 20.0;
    double sx = (width_px - 2 * s->margin) / w, sy = (height_px - 2 * s->margin) / h;
    s->scale = sx < sy ? sx : sy;
    s->x0 = bbox[0];
    s->y1 = bbox[3];
    double W = w * s->scale + 2 * s->margin, H = h * s->scale + 2 * s->margin;
    fprintf(fp,
            "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
            "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%.0f\" height=\"%.0f\" "
            "viewBox=\"0 0 %.0f %.0f\">\n"
            "<rect width=\"100%%\" height=\"100%%\" fill=\"white\"/>\n",
            W, H, W, H);
}

void sq_svg_end(sq_svg *s) { fputs("</svg>\n", s->fp); }

static double px(const sq_svg *s, double x) { return s->margin + (x - s->x0) * s->scale; }
static double py(const sq_svg *s, double y) { return s->margin + (s->y1 - y) * s->scale; }

void sq_svg_polyline(sq_svg *s, int n, const double *xy, int closed, const char *stroke,
                     double width_px, const char *fill)
{
    fprintf(s->fp, "<%s fill=\"%s\" stroke=\"%s\" stroke-width=\"%.2f\" "
            "stroke-linejoin=\"round\" points=\"",
            closed ? "polygon" : "polyline", fill, stroke, width_px);
    for (int i = 0; i < n; i++)
        fprintf(s->fp, "%s%.2f,%.2f", i ? " " : "", px(s, xy[2 * i]), py(s, xy[2 * i + 1]));
    fputs("\"/>\n", s->fp);
}

void sq_svg_circle(sq_svg *s, double x, double y, double r_px, const char *fill)
{
    fprintf(s->fp, "<circle cx=\"%.2f\" cy=\"%.2f\" r=\"%.2f\" fill=\"%s\"/>\n", px(s, x),
            py(s, y), r_px, fill);
}

void sq_svg_text(sq_svg *s, double x, double y, double dx_px, double dy_px, double size_px,
                 const char *fill, const char *text)
{
    fprintf(s->fp, "<text x=\"%.2f\" y=\"%.2f\" font-family=\"sans-serif\" font-size=\"%.1f\" "
            "fill=\"%s\">",
            px(s, x) + dx_px, py(s, y) + dy_px, size_px, fill);
    for (const char *c = text; *c; c++) {
        if (*c == '<') fputs("&lt;", s->fp);
        else if (*c == '>') fputs("&gt;", s->fp);
        else if (*c == '&') fputs("&amp;", s->fp);
        else fputc(*c, s->fp);
    }
    fputs("</text>\n", s->fp);
}

const char *sq_svg_valence_color(int v)
{
    switch (v) {
    case 3: return "#1f5fd6";
    case 5: return "#d62020";
    case 6: return "#f08c00";
    case 8: return "#e6c700";
    default: return "#555555";
    }
}
