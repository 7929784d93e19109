#include "plot_svg.h"

#include "outfile.h"

#include <math.h>
#include <string.h>

/* Okabe & Ito's colour-blind-safe palette (2008), black moved last. */
static const char *palette[] = {"#0072B2", "#D55E00", "#009E73", "#CC79A7",
                                "#E69F00", "#56B4E9", "#8C564B", "#000000"};

const char *sq_plot_color(int i)
{
    int n = (int)(sizeof palette / sizeof palette[0]);
    return palette[((i % n) + n) % n];
}

static int usable(double x, double y) { return isfinite(x) && isfinite(y) && x > 0.0 && y > 0.0; }

static void put_escaped(FILE *fp, const char *t)
{
    for (; t && *t; t++) {
        if (*t == '<') fputs("&lt;", fp);
        else if (*t == '>') fputs("&gt;", fp);
        else if (*t == '&') fputs("&amp;", fp);
        else fputc(*t, fp);
    }
}

typedef struct {
    double left, top, w, h; /* plot area in pixels */
    double lx0, lx1, ly0, ly1; /* decades shown */
} frame;

static double fx(const frame *f, double x) { return f->left + (log10(x) - f->lx0) / (f->lx1 - f->lx0) * f->w; }
static double fy(const frame *f, double y) { return f->top + (f->ly1 - log10(y)) / (f->ly1 - f->ly0) * f->h; }

static void marker(FILE *fp, double x, double y, sq_plot_marker m, const char *color, int open)
{
    const double r = 4.0;
    char style[96];
    snprintf(style, sizeof style, "fill=\"%s\" stroke=\"%s\" stroke-width=\"1.3\"",
             open ? "white" : color, color);
    switch (m) {
    case SQ_MARK_SQUARE:
        fprintf(fp, "<rect x=\"%.2f\" y=\"%.2f\" width=\"%.2f\" height=\"%.2f\" %s/>\n", x - 0.85 * r,
                y - 0.85 * r, 1.7 * r, 1.7 * r, style);
        break;
    case SQ_MARK_TRIANGLE:
        fprintf(fp, "<polygon points=\"%.2f,%.2f %.2f,%.2f %.2f,%.2f\" %s/>\n", x, y - 1.15 * r,
                x - r, y + 0.75 * r, x + r, y + 0.75 * r, style);
        break;
    case SQ_MARK_TRIANGLE_DOWN:
        fprintf(fp, "<polygon points=\"%.2f,%.2f %.2f,%.2f %.2f,%.2f\" %s/>\n", x, y + 1.15 * r,
                x - r, y - 0.75 * r, x + r, y - 0.75 * r, style);
        break;
    case SQ_MARK_DIAMOND:
        fprintf(fp, "<polygon points=\"%.2f,%.2f %.2f,%.2f %.2f,%.2f %.2f,%.2f\" %s/>\n", x,
                y - 1.2 * r, x + r, y, x, y + 1.2 * r, x - r, y, style);
        break;
    case SQ_MARK_CROSS:
        fprintf(fp, "<path d=\"M%.2f,%.2fL%.2f,%.2fM%.2f,%.2fL%.2f,%.2f\" stroke=\"%s\" "
                "stroke-width=\"1.6\" fill=\"none\"/>\n",
                x - r, y - r, x + r, y + r, x - r, y + r, x + r, y - r, color);
        break;
    case SQ_MARK_PLUS:
        fprintf(fp, "<path d=\"M%.2f,%.2fL%.2f,%.2fM%.2f,%.2fL%.2f,%.2f\" stroke=\"%s\" "
                "stroke-width=\"1.6\" fill=\"none\"/>\n",
                x - 1.2 * r, y, x + 1.2 * r, y, x, y - 1.2 * r, x, y + 1.2 * r, color);
        break;
    default:
        fprintf(fp, "<circle cx=\"%.2f\" cy=\"%.2f\" r=\"%.2f\" %s/>\n", x, y, r, style);
    }
}

/* "10" with a raised exponent, anchored at (x, y) ("end" or "middle"). */
static void decade_label(FILE *fp, double x, double y, int k, const char *anchor)
{
    fprintf(fp, "<text x=\"%.2f\" y=\"%.2f\" font-family=\"sans-serif\" font-size=\"12\" "
            "text-anchor=\"%s\">10<tspan dy=\"-6\" font-size=\"9\">%d</tspan></text>\n",
            x, y, anchor, k);
}

void sq_plot_loglog(FILE *fp, const sq_plot *p, int ns, const sq_plot_series *s)
{
    const int W = p->width > 0 ? p->width : 760, H = p->height > 0 ? p->height : 500;
    /* data range in whole decades */
    double xmin = INFINITY, xmax = -INFINITY, ymin = INFINITY, ymax = -INFINITY;
    size_t maxlabel = 0;
    for (int i = 0; i < ns; i++) {
        for (int k = 0; k < s[i].n; k++) {
            if (!usable(s[i].x[k], s[i].y[k])) continue;
            xmin = fmin(xmin, s[i].x[k]);
            xmax = fmax(xmax, s[i].x[k]);
            ymin = fmin(ymin, s[i].y[k]);
            ymax = fmax(ymax, s[i].y[k]);
        }
        if (s[i].label && strlen(s[i].label) > maxlabel) maxlabel = strlen(s[i].label);
    }
    if (!(xmin <= xmax)) xmin = 1.0, xmax = 10.0;
    if (!(ymin <= ymax)) ymin = 1.0, ymax = 10.0;
    frame f;
    /* a small tolerance so 1e4 stays on its own decade line */
    f.lx0 = floor(log10(xmin) + 1e-9), f.lx1 = ceil(log10(xmax) - 1e-9);
    f.ly0 = floor(log10(ymin) + 1e-9), f.ly1 = ceil(log10(ymax) - 1e-9);
    if (f.lx1 <= f.lx0) f.lx0 -= 0.5, f.lx1 += 0.5;
    if (f.ly1 <= f.ly0) f.ly0 -= 0.5, f.ly1 += 0.5;
    const double legend_w = maxlabel ? 48.0 + 7.0 * (double)maxlabel : 0.0;
    f.left = 72.0;
    f.top = p->title ? 36.0 : 16.0;
    f.w = W - f.left - 20.0 - legend_w;
    f.h = H - f.top - 52.0;

    fprintf(fp, "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
                "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%d\" height=\"%d\" "
                "viewBox=\"0 0 %d %d\">\n<rect width=\"100%%\" height=\"100%%\" fill=\"white\"/>\n",
            W, H, W, H);
    if (p->title) {
        fprintf(fp, "<text x=\"%.1f\" y=\"22\" font-family=\"sans-serif\" font-size=\"15\" "
                "text-anchor=\"middle\">", f.left + f.w / 2);
        put_escaped(fp, p->title);
        fputs("</text>\n", fp);
    }
    /* grid, ticks and labels: every decade gets a tick, labels every `step` */
    const int nxd = (int)lround(f.lx1 - f.lx0), nyd = (int)lround(f.ly1 - f.ly0);
    const int xstep = nxd > 8 ? (nxd + 7) / 8 : 1, ystep = nyd > 10 ? (nyd + 9) / 10 : 1;
    const double bottom = f.top + f.h;
    for (int axis = 0; axis < 2; axis++) {
        const double a0 = axis ? f.ly0 : f.lx0, a1 = axis ? f.ly1 : f.lx1;
        const int nd = axis ? nyd : nxd, step = axis ? ystep : xstep;
        for (int k = (int)ceil(a0 - 1e-9); k <= (int)floor(a1 + 1e-9); k++) {
            for (int m = 1; m <= 9; m++) {
                if (m > 1 && nd > 6) break;
                const double v = m * pow(10.0, k), lv = log10(v);
                if (lv < a0 - 1e-9 || lv > a1 + 1e-9) continue;
                const double len = m == 1 ? 6.0 : 3.0;
                if (axis == 0) {
                    const double X = fx(&f, v);
                    if (m == 1)
                        fprintf(fp, "<line x1=\"%.2f\" y1=\"%.2f\" x2=\"%.2f\" y2=\"%.2f\" "
                                "stroke=\"#e4e4e4\"/>\n", X, f.top, X, bottom);
                    fprintf(fp, "<line x1=\"%.2f\" y1=\"%.2f\" x2=\"%.2f\" y2=\"%.2f\" "
                            "stroke=\"black\"/>\n", X, bottom, X, bottom - len);
                    if (m == 1 && (k % step) == 0) decade_label(fp, X, bottom + 18.0, k, "middle");
                } else {
                    const double Y = fy(&f, v);
                    if (m == 1)
                        fprintf(fp, "<line x1=\"%.2f\" y1=\"%.2f\" x2=\"%.2f\" y2=\"%.2f\" "
                                "stroke=\"#e4e4e4\"/>\n", f.left, Y, f.left + f.w, Y);
                    fprintf(fp, "<line x1=\"%.2f\" y1=\"%.2f\" x2=\"%.2f\" y2=\"%.2f\" "
                            "stroke=\"black\"/>\n", f.left, Y, f.left + len, Y);
                    if (m == 1 && (k % step) == 0) decade_label(fp, f.left - 6.0, Y + 4.0, k, "end");
                }
            }
        }
    }
    fprintf(fp, "<rect x=\"%.2f\" y=\"%.2f\" width=\"%.2f\" height=\"%.2f\" fill=\"none\" "
            "stroke=\"black\"/>\n", f.left, f.top, f.w, f.h);
    if (p->xlabel) {
        fprintf(fp, "<text x=\"%.1f\" y=\"%.1f\" font-family=\"sans-serif\" font-size=\"13\" "
                "text-anchor=\"middle\">", f.left + f.w / 2, bottom + 42.0);
        put_escaped(fp, p->xlabel);
        fputs("</text>\n", fp);
    }
    if (p->ylabel) {
        fprintf(fp, "<text x=\"16\" y=\"%.1f\" font-family=\"sans-serif\" font-size=\"13\" "
                "text-anchor=\"middle\" transform=\"rotate(-90 16 %.1f)\">",
                f.top + f.h / 2, f.top + f.h / 2);
        put_escaped(fp, p->ylabel);
        fputs("</text>\n", fp);
    }
    /* series */
    for (int i = 0; i < ns; i++) {
        const char *c = s[i].color ? s[i].color : sq_plot_color(i);
        int first = 1;
        fprintf(fp, "<polyline fill=\"none\" stroke=\"%s\" stroke-width=\"1.5\"%s points=\"", c,
                s[i].dashed ? " stroke-dasharray=\"6,4\"" : "");
        for (int k = 0; k < s[i].n; k++) {
            if (!usable(s[i].x[k], s[i].y[k])) continue;
            fprintf(fp, "%s%.2f,%.2f", first ? "" : " ", fx(&f, s[i].x[k]), fy(&f, s[i].y[k]));
            first = 0;
        }
        fputs("\"/>\n", fp);
        for (int k = 0; k < s[i].n; k++)
            if (usable(s[i].x[k], s[i].y[k]))
                marker(fp, fx(&f, s[i].x[k]), fy(&f, s[i].y[k]), s[i].marker, c, s[i].open);
    }
    /* legend */
    if (legend_w > 0.0) {
        const double lx = f.left + f.w + 14.0;
        double ly = f.top + 8.0;
        int nl = 0;
        for (int i = 0; i < ns; i++) nl += s[i].label != NULL;
        fprintf(fp, "<rect x=\"%.2f\" y=\"%.2f\" width=\"%.2f\" height=\"%.2f\" fill=\"white\" "
                "stroke=\"#999999\"/>\n", lx - 6.0, f.top, legend_w, 18.0 * nl + 10.0);
        for (int i = 0; i < ns; i++) {
            if (!s[i].label) continue;
            const char *c = s[i].color ? s[i].color : sq_plot_color(i);
            const double yy = ly + 9.0;
            fprintf(fp, "<line x1=\"%.2f\" y1=\"%.2f\" x2=\"%.2f\" y2=\"%.2f\" stroke=\"%s\" "
                    "stroke-width=\"1.5\"%s/>\n", lx, yy, lx + 28.0, yy, c,
                    s[i].dashed ? " stroke-dasharray=\"6,4\"" : "");
            marker(fp, lx + 14.0, yy, s[i].marker, c, s[i].open);
            fprintf(fp, "<text x=\"%.2f\" y=\"%.2f\" font-family=\"sans-serif\" font-size=\"12\">",
                    lx + 36.0, yy + 4.0);
            put_escaped(fp, s[i].label);
            fputs("</text>\n", fp);
            ly += 18.0;
        }
    }
    fputs("</svg>\n", fp);
}

sq_status sq_plot_loglog_file(const char *path, const sq_plot *plot, int nseries,
                              const sq_plot_series *series, sq_error *err)
{
    sq_outfile o;
    SQ_TRY(sq_outfile_open(path, &o, err));
    sq_plot_loglog(o.fp, plot, nseries, series);
    return sq_outfile_commit(&o, err);
}
