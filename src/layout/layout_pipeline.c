#include "layout_pipeline.h"

#include "degenerate_split.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

void sq_layout_options_default(sq_layout_options *opt)
{
    memset(opt, 0, sizeof *opt);
    sq_field_options_default(&opt->field);
    sq_trace_options_default(&opt->trace);
    sq_htheta_options_default(&opt->htheta);
}

/* The mesh command's fields.  The mesh needs the layout's topology and
 * its singular points to a fraction of a quad: order 4 gives the guiding
 * field's layouts and mesh quality of order 8 on every example at a small
 * fraction of the solve.  The H/theta field's geometry stays at order 8:
 * at 6 on geometry 6 its e^H sizes drift (disc: 429 quads at 4, 300 at 6
 * and 8) and the holonomy check (0.01 deg) fails on obtuse_quad_v2
 * (0.016 deg); H and θ themselves are tried at 6 first (below).  Its
 * triangulation is
 * graded to 1e-2 of the size at the singular corners (1e-3 by default;
 * coarser breaks that check too), and only to 1/4 of it at the imposed
 * points, whose log and arg terms H and θ carry in closed form: the same
 * layouts as with the defaults (t416), meshes with the same counts and η̄
 * within 0.002, the disc's H/θ on 105 elements instead of 556 (0.17 ->
 * 0.04 s).  docs/mesh.md. */
#define MESH_FIELD_ORDER 4
#define MESH_HTHETA_ORDER 8
/* H and θ at order 6 on the same order-8 geometry first, 8 only where 6
 * gives no valid layout: at 6 every H/θ layout measured is valid (the
 * disc, the pattern files and the 20 corpus faces of the H/θ path, with
 * their irregular counts; 2 of the 20 change their quad counts) at 60 %
 * of the solve's time (docs/benchmarks.md, "H and θ at order 6 first") */
#define MESH_HTHETA_FIRST_ORDER 6
#define MESH_HTHETA_GRADING 1e-2
#define MESH_HTHETA_POINT_GRADING 0.25

void sq_layout_options_for_mesh(sq_layout_options *opt)
{
    sq_layout_options_default(opt);
    opt->field.order = MESH_FIELD_ORDER;
    opt->htheta.order = MESH_HTHETA_ORDER;
    opt->htheta_first_order = MESH_HTHETA_FIRST_ORDER;
    opt->htheta.grading = MESH_HTHETA_GRADING;
    opt->htheta.point_grading = MESH_HTHETA_POINT_GRADING;
}

void sq_layout_result_free(sq_layout_result *r)
{
    if (!r) return;
    sq_layout_free(&r->layout);
    sq_htheta_free(&r->htheta);
    sq_separatrix_set_free(&r->traced);
    free(r->sing);
    free(r->vertex_quads);
    free(r->kept);
    sq_field_analysis_free(&r->analysis);
    memset(r, 0, sizeof *r);
}

/* Frees what one attempt left in out, keeping the guiding analysis. */
static void clear_attempt(sq_layout_result *out)
{
    sq_field_analysis a = out->analysis;
    out->analysis = (sq_field_analysis){0};
    const sq_layout_report rep = out->report;
    const int ndeg = out->ndegenerate;
    sq_layout_result_free(out);
    out->analysis = a;
    out->report = rep;
    out->ndegenerate = ndeg;
}

/* The guiding field's pattern: its critical points and corner valences. */
static sq_status guiding_pattern(const cad_face *face, sq_layout_result *out, sq_error *err)
{
    const sq_field_analysis *a = &out->analysis;
    out->vertex_quads = calloc((size_t)a->info.nvertices + 1, sizeof *out->vertex_quads);
    if (!out->vertex_quads) return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    /* Regular points (index 0) carry no separatrix; points on the boundary
     * are reported by the field stage but cannot start a layout. */
    SQ_TRY(sq_elementary_points(face, a, &out->sing, &out->nsing, NULL, err));
    for (int k = 0; k < a->info.nvertices; k++) out->vertex_quads[k] = a->corners[k].valence;
    out->info = &a->info;
    out->field = (sq_field_summary){"guiding", a->field.method, a->field.order,
                                    a->tri.mesh->ntris, a->field.ndofs, a->t_triangulate,
                                    a->t_solve, a->t_critical};
    return SQ_OK;
}

/* The H/θ field (Jezdimirović 2021 §4-5) of a pattern; from_analysis: a
 * pattern of the guiding field's (out->analysis, already computed). */
static sq_status htheta_pattern(const cad_face *face, const sq_layout_options *opt,
                                const sq_pattern *pat, int from_analysis, sq_layout_result *out,
                                sq_error *err)
{
    SQ_TRY(sq_htheta_compute(face, pat, &opt->htheta, &out->htheta, err));
    SQ_TRY(sq_htheta_check_alignment(&out->htheta, opt->allow_misaligned, err));
    const sq_htheta *h = &out->htheta;
    out->sing = calloc((size_t)h->npoints + 1, sizeof *out->sing);
    out->vertex_quads = calloc((size_t)h->info.nvertices + 1, sizeof *out->vertex_quads);
    if (!out->sing || !out->vertex_quads) return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    for (int k = 0; k < h->npoints; k++)
        if (h->points[k].valence != 4)
            out->sing[out->nsing++] = (sq_singularity){h->points[k].x, h->points[k].y,
                                                       h->points[k].valence, h->points[k].origin};
    for (int k = 0; k < h->info.nvertices; k++) out->vertex_quads[k] = h->balance.quads[k];
    out->info = &h->info;
    out->field = (sq_field_summary){"H-theta", SEM_CG, opt->htheta.order, h->tri.mesh->ntris,
                                    0, h->t_triangulate, h->t_solve, 0.0};
    if (from_analysis) { /* the guiding field's stage ran first */
        out->field.t_triangulate += out->analysis.t_triangulate;
        out->field.t_solve += out->analysis.t_solve;
        out->field.t_critical = out->analysis.t_critical;
    }
    return SQ_OK;
}

/* Separatrices and layout on the field the attempt set up. */
static sq_status trace_and_build(const cad_face *face, const sq_layout_options *opt,
                                 const sq_cross_field *field, sq_layout_result *out, sq_error *err)
{
    double t0 = sq_now();
    sq_status st =
        sq_trace_separatrices_stats(field, face, out->info, out->vertex_quads, out->nsing,
                                    out->sing, &opt->trace, &out->traced, &out->trace_stats, err);
    double t1 = sq_now();
    if (st == SQ_OK)
        st = sq_layout_build(face, out->info, out->vertex_quads, out->nsing, out->sing,
                             &out->traced, field, &opt->trace, &out->layout, err);
    out->t_trace = t1 - t0;
    out->t_layout = sq_now() - t1;
    out->valid = st == SQ_OK;
    return st;
}

/* One attempt: the guiding field's own points (pat NULL) or the H/θ field
 * of pat.  On failure out keeps what was built (SQ_ERR_LAYOUT: the last
 * layout, for pictures and reports). */
static sq_status attempt_once(const cad_face *face, const sq_layout_options *opt,
                              const sq_pattern *pat, int from_analysis, sq_layout_result *out,
                              sq_error *err)
{
    clear_attempt(out);
    sq_cross_field field;
    sq_status st;
    if (pat) {
        st = htheta_pattern(face, opt, pat, from_analysis, out, err);
        field = sq_htheta_cross_field(&out->htheta);
    } else {
        st = guiding_pattern(face, out, err);
        field = sq_guiding_cross_field(&out->analysis.field);
    }
    if (st == SQ_OK) st = trace_and_build(face, opt, &field, out, err);
    return st;
}

/* attempt_once, the H/θ field at htheta_first_order first where one is
 * set: whatever fails there (an invalid layout, a hole's holonomy broken
 * by the lower order's error) is tried again at the full order, whose
 * outcome stands (a refused pattern is refused again before anything is
 * solved). */
static sq_status attempt(const cad_face *face, const sq_layout_options *opt, const sq_pattern *pat,
                         int from_analysis, sq_layout_result *out, sq_error *err)
{
    const int first = opt->htheta_first_order;
    if (!pat || first <= 0 || first >= opt->htheta.order)
        return attempt_once(face, opt, pat, from_analysis, out, err);
    sq_layout_options low = *opt;
    low.htheta.order = first;
    if (attempt_once(face, &low, pat, from_analysis, out, err) == SQ_OK) return SQ_OK;
    return attempt_once(face, opt, pat, from_analysis, out, err);
}

/* Gauss–Bonnet's least number of interior irregular vertices for these
 * corner quads: |4χ − Σ (2 − n_c)| (every point of valence 3 or 5). */
static int gauss_bonnet_min(const sq_face_info *info, const int *quads)
{
    int s = 4 * info->chi;
    for (int k = 0; k < info->nvertices; k++) s -= 2 - quads[k];
    return abs(s);
}

/* The natural pattern and its two-step variants (Jezdimirović 2021 §4):
 * pats[0] the natural points (degenerate zeros split), pats[1] with the
 * valence-3/valence-5 pairs closer than `near` cancelled, pats[2] the
 * Gauss–Bonnet-minimal one (every pair cancelled, nearest first). */
static sq_status natural_patterns(const cad_face *face, const sq_field_analysis *a, double near,
                                  sq_pattern pats[3], int *ncancelled, sq_error *err)
{
    for (int k = 0; k < 3; k++) {
        SQ_TRY(sq_pattern_from_analysis(face, a, &pats[k], err));
        if (k == 1) *ncancelled = sq_cancel_pairs(pats[k].points, &pats[k].npoints, near);
        if (k == 2) sq_cancel_pairs(pats[k].points, &pats[k].npoints, HUGE_VAL);
    }
    return SQ_OK;
}

/* Default route: the guiding field's layout unless its points are poor
 * (degenerate, unresolved, or with pairs to cancel) or give no valid
 * layout; then the H/θ field of the Gauss–Bonnet-minimal pattern, then
 * of the natural points with near pairs cancelled: the valid layout with
 * the fewest points is kept (guiding last if not tried), each pattern
 * solved once. */
static sq_status two_step(const cad_face *face, const sq_layout_options *opt,
                          sq_layout_result *out, sq_error *err)
{
    const sq_field_analysis *a = &out->analysis;
    sq_layout_report *rep = &out->report;
    sq_pattern pats[3] = {{0}};
    sq_tri_options tri = opt->field.tri;
    int near = 0;
    sq_status st =
        natural_patterns(face, a, sq_tri_size(&tri, a->info.area), pats, &near, err);
    if (st != SQ_OK) goto done;
    out->ndegenerate = pats[0].ndegenerate;
    for (int k = 0; k < a->npoints; k++) rep->unresolved += a->points[k].unresolved;
    const int poor = pats[0].ndegenerate > 0 || rep->unresolved > 0 || near > 0;
    int tried_guiding = 0;
    if (!poor) {
        st = attempt(face, opt, NULL, 1, out, err);
        tried_guiding = 1;
        snprintf(rep->kept_why, sizeof rep->kept_why,
                 "farther apart than %g (the field's element size, within which pairs are "
                 "cancelled) on a valid guiding layout",
                 sq_tri_size(&tri, a->info.area));
        if (st == SQ_OK) goto done;
        snprintf(rep->reason, sizeof rep->reason, "no valid layout on the guiding field: %.120s",
                 err->msg);
    } else if (pats[0].ndegenerate > 0 || rep->unresolved > 0) {
        snprintf(rep->reason, sizeof rep->reason, "degenerate singular points");
    } else {
        snprintf(rep->reason, sizeof rep->reason, "%d valence-3/valence-5 pair%s closer than %g",
                 near, near == 1 ? "" : "s",
                 sq_tri_size(&tri, a->info.area));
    }
    rep->two_step = 1;
    /* the valid one of the fewest points: every pair cancelled (pats[2],
     * or pats[1] when that is the same pattern), then the near pairs
     * alone; st may hold the guiding field's failure, which a valid H/θ
     * layout clears */
    sq_error e = {0};
    const int least = pats[2].npoints < pats[1].npoints ? 2 : 1;
    if (attempt(face, opt, &pats[least], 1, out, &e) == SQ_OK) {
        rep->pattern = least;
        st = SQ_OK;
        goto done;
    }
    snprintf(rep->kept_why, sizeof rep->kept_why, "no valid H/theta layout of fewer points: %s",
             e.msg);
    if (least == 2 && attempt(face, opt, &pats[1], 1, out, &e) == SQ_OK) {
        rep->pattern = 1;
        st = SQ_OK;
        goto done;
    }
    /* no H/θ layout: the guiding field's own (its failure is the one told) */
    rep->pattern = 0;
    rep->two_step = !tried_guiding;
    st = attempt(face, opt, NULL, 1, out, err);
done:
    /* pairs cancelled in the pattern traced */
    rep->cancelled_pairs = (pats[0].npoints - pats[rep->pattern].npoints) / 2;
    if (rep->cancelled_pairs == 0) rep->pattern = 0;
    for (int k = 0; k < 3; k++) sq_pattern_free(&pats[k]);
    return st;
}

/* The guiding field's analysis.  Points that break Poincaré–Hopf mean
 * the search missed or misread one (a valence-3/valence-5 pair closer than
 * the order resolves: the mesh's order 4 can merge it into one zero): the
 * field is solved again at the default order before its points are used. */
static sq_status analyse(const cad_face *face, const sq_field_options *fo, sq_field_analysis *a,
                         sq_error *err)
{
    SQ_TRY(sq_field_analyse(face, fo, a, err));
    sq_field_options def;
    sq_field_options_default(&def);
    if (a->ph_lhs == a->ph_rhs || fo->order >= def.order) return SQ_OK;
    sq_field_options finer = *fo;
    finer.order = def.order;
    finer.tri.order = def.tri.order;
    sq_field_analysis b = {0};
    sq_status st = sq_field_analyse(face, &finer, &b, err);
    if (st != SQ_OK || b.ph_lhs != b.ph_rhs) {
        sq_field_analysis_free(&b);
        return SQ_OK; /* no better: the coarse points, as before */
    }
    sq_field_analysis_free(a);
    *a = b;
    return SQ_OK;
}

/* The pairs of the pattern traced over the Gauss–Bonnet minimum. */
static sq_status kept_pairs(sq_layout_result *out, sq_error *err)
{
    const int max = (out->nsing - out->report.gauss_bonnet_min) / 2;
    if (max <= 0) return SQ_OK;
    int(*pairs)[2] = malloc(sizeof *pairs * (size_t)max);
    out->kept = malloc(sizeof *out->kept * (size_t)max);
    if (!pairs || !out->kept) {
        free(pairs);
        return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    }
    sq_status st = sq_list_pairs(out->sing, out->nsing, max, pairs, &out->nkept, err);
    for (int k = 0; st == SQ_OK && k < out->nkept; k++) {
        const sq_singularity *a = &out->sing[pairs[k][0]], *b = &out->sing[pairs[k][1]];
        out->kept[k] = (sq_kept_pair){a->x, a->y, b->x, b->y, hypot(a->x - b->x, a->y - b->y)};
    }
    free(pairs);
    return st;
}

sq_status sq_layout_run(const cad_face *face, const sq_layout_options *opt, sq_layout_result *out,
                        sq_error *err)
{
    memset(out, 0, sizeof *out);
    sq_status st = SQ_OK;
    const int natural = opt->singularities && !strcmp(opt->singularities, "natural");
    if (!opt->singularities || natural) st = analyse(face, &opt->field, &out->analysis, err);
    sq_pattern pat = {0};
    if (st == SQ_OK && !opt->singularities && opt->field.periodic.npairs) {
        /* the H/θ fields know no identified edges: the guiding field's own */
        st = attempt(face, opt, NULL, 1, out, err);
    } else if (st == SQ_OK && !opt->singularities) {
        st = two_step(face, opt, out, err);
    } else if (st == SQ_OK) {
        st = natural ? sq_pattern_from_analysis(face, &out->analysis, &pat, err)
                     : sq_pattern_read(opt->singularities, &pat, err);
        out->ndegenerate = pat.ndegenerate;
        out->report.pattern = natural ? 0 : 3;
        if (st == SQ_OK) st = attempt(face, opt, &pat, natural, out, err);
        sq_pattern_free(&pat);
    }
    if (st != SQ_OK && st != SQ_ERR_LAYOUT) {
        sq_layout_result_free(out);
        return st;
    }
    out->report.gauss_bonnet_min = gauss_bonnet_min(out->info, out->vertex_quads);
    if (opt->singularities)
        snprintf(out->report.kept_why, sizeof out->report.kept_why, "imposed (%s)",
                 natural ? "--singularities natural" : "pattern file");
    sq_status ks = kept_pairs(out, err);
    return ks != SQ_OK ? ks : st;
}

int sq_layout_note(const sq_layout_result *r, char *buf, size_t n)
{
    const sq_layout_report *rep = &r->report;
    static const char *what[] = {"the natural points", "the natural points with near pairs cancelled",
                                 "the Gauss-Bonnet-minimal pattern"};
    int nsplit = 0, len = 0;
    for (int k = 0; k < r->nsing; k++) nsplit += r->sing[k].origin == SQ_ORIGIN_SPLIT;
    if (!rep->two_step && r->ndegenerate == 0 && !r->analysis.field.twist) return 0;
    if (r->analysis.field.twist)
        len += snprintf(buf + len, n - (size_t)len,
                        "guiding field degenerate (edges at multiples of 45 deg), solved with "
                        "one family turned by %g deg; ",
                        SQ_GUIDING_TWIST_DEG);
    if (r->ndegenerate && (size_t)len < n)
        len += snprintf(buf + len, n - (size_t)len,
                        "%d degenerate singular point%s of the guiding field (|index| > 1) split "
                        "into %d elementary points at %g x the distance to the boundary; ",
                        r->ndegenerate, r->ndegenerate == 1 ? "" : "s", nsplit,
                        SQ_SPLIT_FRACTION);
    if (rep->two_step && (size_t)len < n)
        len += snprintf(buf + len, n - (size_t)len,
                        "two-step (%s): layout traced on the %s field of %s (%d singular "
                        "points, Gauss-Bonnet minimum %d, %d pairs cancelled); ",
                        rep->reason, r->field.kind, what[rep->pattern], r->nsing,
                        rep->gauss_bonnet_min,
                        rep->cancelled_pairs);
    if (len >= 2 && (size_t)len < n) buf[len - 2] = '\0'; /* the last "; " */
    return 1;
}
