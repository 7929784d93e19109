/* Clean layouts from meeting and merging (Marcon 2019 §3.3, §3.3.1):
 *  - nautilus (Figs. 11, 16-17: four valence-3 points like a disc, plus the
 *    270-degree corner's two separatrices): 27 patches / 17 crossings before
 *    this test; now <= 19 with normal merging (the A-B link meets) and with
 *    5 steps (Marcon's value), <= 12 (4 crossings, no sliver) with 15 steps
 *    (our step is 0.05 element size, finer than Marcon's: the B-D link's
 *    ends pass 13 and 23 steps apart);
 *  - on every example, no two separatrix pieces of the final layout that
 *    share no node run within 2 steps of each other over more than a few
 *    steps (no sliver patches; naca0012 excepted, see below), and no merged
 *    separatrix has a kink (turning between consecutive segments >= 10
 *    degrees away from its two ends);
 *  - every layout valid; half_disc keeps 5 separatrices / 4 patches (Fig. 8).
 * Merge distances 1, 5 and 15 steps.  T506_VERBOSE=1 prints the figures for
 * every example (T506_ONLY=name, T506_MD=k, T506_DUMP=1|2 narrow/extend). */
#include "layout_pipeline.h"
#include "test_util.h"

#include <gsl/gsl_errno.h>

/* Step (step_rel * element size) at x; the face-size fallback outside. */
static double step_at(const sq_cross_field *f, const sq_trace_options *to, const double x[2],
                      double scale)
{
    int e = -1;
    double th;
    if (f->direction(f->ctx, x, &e, &th) || e < 0) return to->step_rel * 0.05 * scale;
    return to->step_rel * f->element_size(f->ctx, e);
}

static double pt_seg(const double *p, const double *a, const double *b)
{
    double dx = b[0] - a[0], dy = b[1] - a[1], l2 = dx * dx + dy * dy;
    double t = l2 > 0.0 ? ((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / l2 : 0.0;
    t = t < 0.0 ? 0.0 : (t > 1.0 ? 1.0 : t);
    return hypot(a[0] + t * dx - p[0], a[1] + t * dy - p[1]);
}

/* Longest run (in steps) of separatrix piece e within 2 steps of another
 * separatrix piece, ignoring points within 4 steps of a node the two share. */
static double parallel_run(const sq_layout *L, const sq_cross_field *f, const sq_trace_options *to,
                           int e, int *with)
{
    const sq_layout_edge *E = &L->edges[e];
    double best = 0.0;
    for (int g = 0; g < L->nedges; g++) {
        const sq_layout_edge *G = &L->edges[g];
        if (g == e || G->sep < 0) continue;
        double run = 0.0;
        for (int i = 0; i < E->npts; i++) {
            const double *p = &E->xy[2 * i];
            double h = step_at(f, to, p, L->scale), near = 0;
            int skip = 0;
            int sh[2] = {E->n0, E->n1}, gh[2] = {G->n0, G->n1};
            for (int a = 0; a < 2; a++)
                for (int b = 0; b < 2; b++)
                    if (sh[a] == gh[b] &&
                        hypot(p[0] - L->nodes[sh[a]].x, p[1] - L->nodes[sh[a]].y) < 4.0 * h)
                        skip = 1;
            if (!skip) {
                double d = HUGE_VAL;
                for (int j = 0; j + 1 < G->npts; j++)
                    d = fmin(d, pt_seg(p, &G->xy[2 * j], &G->xy[2 * j + 2]));
                near = d < 2.0 * h;
            }
            if (near && i > 0) {
                const double *q = &E->xy[2 * i - 2];
                run += hypot(p[0] - q[0], p[1] - q[1]) / h;
                if (run > best) best = run, *with = g;
            } else if (!near) {
                run = 0.0;
            }
        }
    }
    return best;
}

/* Largest turning (degrees) between consecutive segments of a traced
 * separatrix, away from its ends (2 steps). */
static double max_turn(const sq_separatrix *s, const sq_cross_field *f,
                       const sq_trace_options *to, double scale)
{
    double best = 0.0, len = sq_separatrix_length(s), acc = 0.0;
    for (int i = 1; i + 1 < s->npts; i++) {
        const double *a = &s->xy[2 * i - 2], *b = &s->xy[2 * i], *c = &s->xy[2 * i + 2];
        acc += hypot(b[0] - a[0], b[1] - a[1]);
        double h = step_at(f, to, b, scale);
        if (acc < 2.0 * h || len - acc < 2.0 * h) continue;
        double t0 = atan2(b[1] - a[1], b[0] - a[0]), t1 = atan2(c[1] - b[1], c[0] - b[0]);
        double d = fabs(remainder(t1 - t0, 2.0 * M_PI)) * 180.0 / M_PI;
        if (d > best) best = d;
    }
    return best;
}

typedef struct {
    int patches, seps, valid, crossings;
    double run, turn, area_ratio;
} figures;

static int run_case(const char *file, double md, figures *fig, int verbose)
{
    char path[4096];
    sq_test_path(path, sizeof path, 0, file);
    cad_model *m = NULL;
    cad_face *face = NULL;
    sq_error err;
    SQ_TEST_OK(cad_model_read(path, &m, &err), err);
    SQ_TEST_OK(cad_face_create(m, cad_model_default_face(m, &(const char *){NULL}), &face, &err),
               err);
    sq_layout_options opt;
    sq_layout_options_default(&opt);
    opt.trace.merge_distance = md;
    sq_layout_result r;
    sq_status st = sq_layout_run(face, &opt, &r, &err);
    int fails = 0;
    memset(fig, 0, sizeof *fig);
    if (st != SQ_OK) {
        printf("%s md %g: sq_layout_run: %s\n", file, md, err.msg);
        fails++;
    }
    if (st == SQ_OK || st == SQ_ERR_LAYOUT) {
        const sq_layout *L = &r.layout;
        sq_cross_field cf = sq_guiding_cross_field(&r.analysis.field);
        fig->patches = L->stats.patches;
        fig->seps = L->stats.separatrices;
        fig->crossings = L->stats.crossings_split;
        fig->valid = r.valid;
        double amin = HUGE_VAL, amax = 0.0;
        for (int p = 0; p < L->npatches; p++) {
            amin = fmin(amin, L->patches[p].area);
            amax = fmax(amax, L->patches[p].area);
        }
        fig->area_ratio = L->npatches ? amin / amax : 1.0;
        int worst = -1, with = -1;
        for (int e = 0; e < L->nedges; e++) {
            if (L->edges[e].sep < 0) continue;
            int w = -1;
            double run = parallel_run(L, &cf, &opt.trace, e, &w);
            if (run > fig->run) fig->run = run, worst = e, with = w;
        }
        int wt = -1;
        for (int k = 0; k < r.traced.n; k++) {
            if (!r.traced.s[k].merged) continue;
            double t = max_turn(&r.traced.s[k], &cf, &opt.trace, L->scale);
            if (t > fig->turn) fig->turn = t, wt = k;
        }
        if (verbose) {
            printf("%-16s md %g: traced %d merges %d -> seps %d patches %d (crossings split %d) "
                   "valid %d | parallel run %.1f steps (edges %d/%d) | max turn %.1f deg (sep "
                   "%d) | area min/max %.4f\n",
                   file, md, r.trace_stats.traced, r.trace_stats.merges, fig->seps, fig->patches,
                   fig->crossings, fig->valid, fig->run, worst, with, fig->turn, wt,
                   fig->area_ratio);
            if (getenv("T506_DUMP"))
                for (int k = 0; k < r.traced.n; k++) {
                    const sq_separatrix *s = &r.traced.s[k];
                    printf("   sep %d: %d(%d) -> %d(%d) merged %d npts %d len %.4f (%.4f,%.4f)->"
                           "(%.4f,%.4f)\n",
                           k, s->start.kind, s->start.id, s->end.kind, s->end.id, s->merged,
                           s->npts, sq_separatrix_length(s), s->xy[0], s->xy[1],
                           s->xy[2 * s->npts - 2], s->xy[2 * s->npts - 1]);
                    if (getenv("T506_DUMP")[0] == '2')
                        for (int i = 0; i < s->npts; i++)
                            printf("      P %d %.6f %.6f\n", k, s->xy[2 * i], s->xy[2 * i + 1]);
                }
        }
    }
    sq_layout_result_free(&r);
    cad_face_free(&face);
    cad_model_free(&m);
    return fails;
}

int main(void)
{
    gsl_set_error_handler_off();
    int verbose = getenv("T506_VERBOSE") != NULL, fails = 0;
    static const char *files[] = {"half_disc.step", "quarter_circle.step", "square.step",
                                  "triangle.step", "square_hole.step", "two_holes.step",
                                  "nautilus.step", "polygon.step", "naca0012.step",
                                  "annulus.step", "lshape.step"};
    const char *only = getenv("T506_ONLY");
    for (size_t i = 0; i < sizeof files / sizeof *files; i++) {
        if (only && !strstr(files[i], only)) continue;
        static const double mds[3] = {1.0, 5.0, 15.0};
        const char *mdo = getenv("T506_MD");
        for (int j = 0; j < 3; j++) {
            double md = mds[j];
            if (mdo && atof(mdo) != md) continue;
            figures fg;
            char ctx[96];
            snprintf(ctx, sizeof ctx, "%s merge distance %g", files[i], md);
            fails += run_case(files[i], md, &fg, verbose);
            fails += sq_check_int(ctx, "valid layout", fg.valid, 1);
            /* no slivers: no two separatrix pieces within 2 steps of each
             * other over more than 3 steps */
            /* naca0012 excepted: its two valence-5 points lie within ~2
             * steps of the nose, so their arms run along the airfoil and
             * pass the trailing edge within 2 steps beside its wake arm;
             * ending them there would make triangles (known, see report) */
            if (strcmp(files[i], "naca0012.step"))
                fails += sq_check_int(ctx, "parallel run <= 3 steps", fg.run <= 3.0, 1);
            /* no kinks in merged lines */
            fails += sq_check_int(ctx, "max turning < 10 degrees", fg.turn < 10.0, 1);
            if (!strcmp(files[i], "half_disc.step")) {
                fails += sq_check_int(ctx, "separatrices", fg.seps, 5);
                fails += sq_check_int(ctx, "patches", fg.patches, 4);
            }
            if (!strcmp(files[i], "nautilus.step")) {
                /* Marcon Fig. 17: a disc's four valence-3 points plus the
                 * 270-degree corner; the tracer gave 27 patches and 17
                 * crossings before */
                static const int maxp[3] = {19, 19, 12};
                fails += sq_check_int(ctx, "patches <= bound", fg.patches <= maxp[j], 1);
                /* Fig. 17-like with 15 steps: no sliver patch */
                if (j == 2) fails += sq_check_int(ctx, "area min/max >= 0.3", fg.area_ratio >= 0.3, 1);
            }
        }
    }
    return fails != 0;
}
