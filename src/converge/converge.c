#include "converge.h"

#include "gauss.h"
#include "outfile.h"
#include "plot_svg.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

/* ---- exact harmonic solutions (value and gradient) ---- */

static void sol_exp_sin(const double x[2], void *ctx, double *u, double g[2])
{
    (void)ctx;
    const double e = exp(x[0]), sn = sin(x[1]);
    *u = e * sn;
    g[0] = e * sn;
    g[1] = e * cos(x[1]);
}

/* Re z^5; d/dx Re z^5 = Re 5z^4, d/dy Re z^5 = Re 5iz^4 = -Im 5z^4 */
static void sol_re_z5(const double x[2], void *ctx, double *u, double g[2])
{
    (void)ctx;
    const double a = x[0], b = x[1], a2 = a * a, b2 = b * b;
    *u = a * (a2 * a2 - 10.0 * a2 * b2 + 5.0 * b2 * b2);
    const double re4 = a2 * a2 - 6.0 * a2 * b2 + b2 * b2, im4 = 4.0 * a * b * (a2 - b2);
    g[0] = 5.0 * re4;
    g[1] = -5.0 * im4;
}

static void sol_poly(const double x[2], void *ctx, double *u, double g[2])
{
    (void)ctx;
    const double a = x[0], b = x[1];
    *u = a * a * a - 3.0 * a * b * b + a * b;
    g[0] = 3.0 * a * a - 3.0 * b * b + b;
    g[1] = -6.0 * a * b + a;
}

static void sol_sin_sinh(const double x[2], void *ctx, double *u, double g[2])
{
    (void)ctx;
    *u = sin(x[0]) * sinh(x[1]);
    g[0] = cos(x[0]) * sinh(x[1]);
    g[1] = sin(x[0]) * cosh(x[1]);
}

static const struct {
    const char *name;
    sem_exact_fn fn;
} solutions[] = {{"exp-sin", sol_exp_sin}, {"re-z5", sol_re_z5}, {"poly", sol_poly},
                 {"sin-sinh", sol_sin_sinh}};
#define NSOL ((int)(sizeof solutions / sizeof solutions[0]))

const char *sq_converge_solution_names(void) { return "exp-sin, re-z5, poly, sin-sinh"; }

sq_status sq_converge_solution(const char *name, sem_exact_fn *fn, sq_error *err)
{
    for (int k = 0; k < NSOL; k++)
        if (name && !strcmp(name, solutions[k].name)) {
            *fn = solutions[k].fn;
            return SQ_OK;
        }
    return SQ_FAIL(err, SQ_ERR_USAGE, "unknown solution '%s' (known: %s)", name ? name : "",
                   sq_converge_solution_names());
}

void sq_converge_options_default(sq_converge_options *opt)
{
    memset(opt, 0, sizeof *opt);
    opt->solution = "exp-sin";
    opt->methods = SQ_CONV_CG | SQ_CONV_DG;
    opt->pmin = 1;
    opt->pmax = 12;
    sq_tri_options_default(&opt->tri);
}

void sq_converge_result_free(sq_converge_result *r)
{
    if (!r) return;
    free(r->runs);
    memset(r, 0, sizeof *r);
}

/* Dirichlet data: the exact solution itself */
static double boundary_value(const double x[2], const double n[2], int tag, void *ctx)
{
    (void)n, (void)tag;
    sem_exact_fn fn = *(sem_exact_fn *)ctx;
    double u, g[2];
    fn(x, NULL, &u, g);
    return u;
}

static double now_s(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static sq_status one_run(const sq_triangulation *t, sem_method method, int P, sem_exact_fn fn,
                         sq_converge_run *run, sq_error *err)
{
    sem_poisson *s = NULL;
    sem_field *u = NULL;
    const double t0 = now_s();
    sq_status st = sem_poisson_create(t->mesh, P, method, NULL, NULL, &s, err);
    if (st == SQ_OK) st = sem_field_create(t->mesh, P, 1, &u, err);
    if (st == SQ_OK) {
        sem_poisson_data d = {NULL, NULL, boundary_value, &fn, 0, NULL, 0};
        st = sem_poisson_solve(s, &d, u, err);
    }
    run->seconds = now_s() - t0;
    if (st == SQ_OK) {
        run->dofs = sem_poisson_ndofs(s);
        st = sem_field_error(u, 0, fn, NULL, 0, &run->l2, &run->h1, err);
    }
    sem_field_free(&u);
    sem_poisson_free(&s);
    return st;
}

sq_status sq_converge_study(const cad_face *face, const sq_converge_options *opt,
                            sq_converge_result *out, sq_error *err)
{
    memset(out, 0, sizeof *out);
    sem_exact_fn fn;
    SQ_TRY(sq_converge_solution(opt->solution, &fn, err));
    if (opt->pmin < 1 || opt->pmax > SEM_MAX_ORDER || opt->pmin > opt->pmax)
        return SQ_FAIL(err, SQ_ERR_USAGE, "orders %d-%d: expected 1 <= A <= B <= %d", opt->pmin,
                       opt->pmax, SEM_MAX_ORDER);
    if (!(opt->methods & (SQ_CONV_CG | SQ_CONV_DG)))
        return SQ_FAIL(err, SQ_ERR_USAGE, "no method chosen");
    if (opt->geom_order < 0 || opt->geom_order > 12)
        return SQ_FAIL(err, SQ_ERR_USAGE, "geometry order %d: expected 1..12", opt->geom_order);
    for (int i = 0; i < opt->nsizes; i++)
        if (!(opt->sizes[i] > 0.0) || !isfinite(opt->sizes[i]))
            return SQ_FAIL(err, SQ_ERR_USAGE, "size %g: expected a positive number", opt->sizes[i]);
    const int nsz = opt->nsizes > 0 ? opt->nsizes : 1, nP = opt->pmax - opt->pmin + 1;
    const sem_method meth[2] = {SEM_CG, SEM_DG};
    const int use[2] = {(opt->methods & SQ_CONV_CG) != 0, (opt->methods & SQ_CONV_DG) != 0};
    const int nm = use[0] + use[1];
    out->runs = calloc((size_t)(nm * nP * nsz), sizeof *out->runs);
    if (!out->runs) return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    out->nsizes = nsz;
    out->nruns = nm * nP * nsz;

    sq_status st = SQ_OK;
    /* sizes outermost: one triangulation per (size, geometry order), and
     * the geometry order only grows with P */
    for (int i = 0; i < nsz && st == SQ_OK; i++) {
        sq_triangulation t;
        memset(&t, 0, sizeof t);
        for (int P = opt->pmin; P <= opt->pmax && st == SQ_OK; P++) {
            int g = opt->geom_order ? opt->geom_order : (P > 8 ? P : 8);
            if (g > 12) g = 12;
            if (!t.mesh || t.mesh->order != g) {
                sq_triangulation_free(&t);
                sq_tri_options to = opt->tri;
                to.order = g;
                to.size = opt->nsizes > 0 ? opt->sizes[i] : 0.0;
                st = sq_triangulate(face, &to, &t, err);
                if (st != SQ_OK) break;
            }
            for (int m = 0, im = 0; m < 2 && st == SQ_OK; m++) {
                if (!use[m]) continue;
                sq_converge_run *r = &out->runs[((size_t)im * nP + (P - opt->pmin)) * nsz + i];
                im++;
                r->method = meth[m];
                r->P = P;
                r->h = t.size;
                r->size_index = i;
                r->ntris = t.mesh->ntris;
                r->geom_order = g;
                st = one_run(&t, meth[m], P, fn, r, err);
            }
        }
        sq_triangulation_free(&t);
    }
    if (st != SQ_OK) sq_converge_result_free(out);
    return st;
}

int sq_converge_rate(const sq_converge_result *r, sem_method method, int P, int norm,
                     double *rate)
{
    /* least squares of y = log e against x = log h_eff = -log(dofs)/2 */
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    int n = 0;
    for (int k = 0; k < r->nruns; k++) {
        const sq_converge_run *u = &r->runs[k];
        const double e = norm ? u->h1 : u->l2;
        if (u->method != method || u->P != P || !(e > 0.0) || u->dofs <= 0) continue;
        const double x = -0.5 * log((double)u->dofs), y = log(e);
        sx += x, sy += y, sxx += x * x, sxy += x * y, n++;
    }
    const double d = n * sxx - sx * sx;
    if (n < 2 || !(fabs(d) > 0.0)) return -1;
    *rate = (n * sxy - sx * sy) / d;
    return 0;
}

sq_status sq_converge_write_csv(const char *path, const sq_converge_result *r, sq_error *err)
{
    sq_outfile o;
    SQ_TRY(sq_outfile_open(path, &o, err));
    fputs("method,P,h,dofs,L2,H1\n", o.fp);
    for (int k = 0; k < r->nruns; k++) {
        const sq_converge_run *u = &r->runs[k];
        fprintf(o.fp, "%s,%d,%.6g,%ld,%.6e,%.6e\n", u->method == SEM_CG ? "cg" : "dg", u->P, u->h,
                u->dofs, u->l2, u->h1);
    }
    return sq_outfile_commit(&o, err);
}

sq_status sq_converge_write_svg(const char *path, const sq_converge_result *r, const char *title,
                                sq_error *err)
{
    /* group runs into series: key (method, P or -1, norm) */
    const int href = r->nsizes > 1;
    const int maxs = 2 * r->nruns + 2;
    sq_plot_series *s = calloc((size_t)maxs, sizeof *s);
    double *xy = malloc(sizeof(double) * 4 * (size_t)(r->nruns + 1));
    char(*labels)[48] = calloc((size_t)maxs, sizeof *labels);
    int *idx = malloc(sizeof(int) * (size_t)(r->nruns + 1));
    if (!s || !xy || !labels || !idx) {
        free(s), free(xy), free(labels), free(idx);
        return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    }
    int ns = 0, used = 0;
    const int group = href ? r->nsizes : r->nruns; /* runs are sorted: method, P, size */
    for (int k0 = 0; k0 < r->nruns;) {
        /* a p-series is all runs of one method at size 0; an h-series is
         * the nsizes consecutive runs of one (method, P) */
        int n = 0;
        if (href) {
            for (int k = k0; k < k0 + group && k < r->nruns; k++) idx[n++] = k;
            k0 += group;
        } else {
            int k = k0;
            for (; k < r->nruns && r->runs[k].method == r->runs[k0].method; k++) idx[n++] = k;
            k0 = k;
        }
        const sq_converge_run *a = &r->runs[idx[0]];
        /* h-refinement: one colour per P, the marker tells the method */
        const char *color = href ? sq_plot_color(a->P - r->runs[0].P)
                                 : sq_plot_color(a->method == SEM_CG ? 0 : 1);
        for (int norm = 0; norm < 2; norm++) {
            double *x = xy + used, *y = xy + used + n;
            used += 2 * n;
            for (int j = 0; j < n; j++) {
                x[j] = (double)r->runs[idx[j]].dofs;
                y[j] = norm ? r->runs[idx[j]].h1 : r->runs[idx[j]].l2;
            }
            if (href)
                snprintf(labels[ns], sizeof labels[ns], "%s P=%d %s",
                         a->method == SEM_CG ? "CG" : "DG", a->P, norm ? "H1" : "L2");
            else
                snprintf(labels[ns], sizeof labels[ns], "%s %s", a->method == SEM_CG ? "CG" : "DG",
                         norm ? "H1" : "L2");
            s[ns] = (sq_plot_series){labels[ns], n, x, y, color,
                                     a->method == SEM_CG ? SQ_MARK_CIRCLE : SQ_MARK_SQUARE,
                                     norm, norm};
            ns++;
        }
    }
    sq_plot p = {title, "degrees of freedom", "error (L2 solid, H1 seminorm dashed)", 0, 0};
    if (ns > 16) p.height = 500 + 18 * (ns - 16);
    sq_status st = sq_plot_loglog_file(path, &p, ns, s, err);
    free(s), free(xy), free(labels), free(idx);
    return st;
}
