#include "write_layout.h"

#include "outfile.h"
#include "svg.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static const char *role_origin(const sq_layout *L, int k)
{
    switch (L->role[k]) {
    case SQ_LROLE_MIDPOINT: return "midpoint";
    case SQ_LROLE_VALENCE2: return "valence2-split";
    case SQ_LROLE_CROSSING: return "crossing";
    case SQ_LROLE_TJUNCTION: return "t-junction";
    default: return sq_origin_name(L->sing[k].origin);
    }
}

static void json_point(sq_json *j, const char *key, double x, double y)
{
    sq_json_key(j, key);
    sq_json_begin_array(j);
    sq_json_number(j, x);
    sq_json_number(j, y);
    sq_json_end_array(j);
}

/* The valence-3/valence-5 pairs kept over the Gauss–Bonnet minimum, where
 * and why (issue 14: a report names the pairs it had to keep). */
static void json_kept_pairs(sq_json *j, const sq_layout_result *r)
{
    sq_json_key(j, "kept_pair_list");
    sq_json_begin_array(j);
    for (int k = 0; k < r->nkept; k++) {
        const sq_kept_pair *p = &r->kept[k];
        sq_json_begin_object(j);
        json_point(j, "valence3", p->x3, p->y3);
        json_point(j, "valence5", p->x5, p->y5);
        sq_json_key_number(j, "distance", p->distance);
        sq_json_key_string(j, "reason", r->report.kept_why);
        sq_json_end_object(j);
    }
    sq_json_end_array(j);
}

static void json_layout_keys(sq_json *j, const sq_layout_result *r)
{
    const sq_layout *L = &r->layout;
    sq_json_key(j, "singularities");
    sq_json_begin_array(j);
    for (int k = 0; k < L->nsing; k++) {
        if (L->role[k] == SQ_LROLE_CROSSING) continue; /* regular valence-4 nodes */
        sq_json_begin_object(j);
        sq_json_key_number(j, "x", L->sing[k].x);
        sq_json_key_number(j, "y", L->sing[k].y);
        sq_json_key_int(j, "valence", L->sing[k].valence);
        sq_json_key(j, "origin");
        sq_json_string(j, role_origin(L, k));
        sq_json_end_object(j);
    }
    sq_json_end_array(j);
    sq_json_key(j, "corners");
    sq_json_begin_array(j);
    const sq_face_info *info = r->info;
    for (int k = 0; k < info->nvertices; k++) {
        if (info->vertices[k].smooth) continue;
        sq_json_begin_object(j);
        sq_json_key_number(j, "x", info->vertices[k].x);
        sq_json_key_number(j, "y", info->vertices[k].y);
        sq_json_key_number(j, "angle_deg", info->vertices[k].angle_deg);
        sq_json_key_int(j, "valence", r->vertex_quads[k]);
        sq_json_end_object(j);
    }
    sq_json_end_array(j);
    const sq_layout_stats *s = &L->stats;
    sq_json_key(j, "layout");
    sq_json_begin_object(j);
    sq_json_key(j, "valid");
    sq_json_bool(j, r->valid);
    sq_json_key_int(j, "separatrices_traced", r->trace_stats.traced);
    sq_json_key_int(j, "merges", r->trace_stats.merges);
    sq_json_key_int(j, "integration_steps", r->trace_stats.steps);
    sq_json_key_int(j, "separatrices", s->separatrices);
    sq_json_key_int(j, "patches", s->patches);
    sq_json_key_int(j, "quad_patches", s->quad_patches);
    sq_json_key_int(j, "t_junctions", s->t_junctions);
    sq_json_key_int(j, "limit_cycles_cut", s->limit_cycles_cut);
    sq_json_key_int(j, "triangles_repaired", s->triangles_repaired);
    sq_json_key_int(j, "valence2_split", s->valence2_split);
    sq_json_key_int(j, "annuli_cut", s->annuli_cut);
    sq_json_key_int(j, "duplicates_removed", s->duplicates_removed);
    sq_json_key_int(j, "crossings_split", s->crossings_split);
    sq_json_key_int(j, "straight_stems", s->straight_stems);
    sq_json_key_int(j, "separatrices_removed", s->separatrices_removed);
    sq_json_key_int(j, "iterations", s->iterations);
    /* only on the all-quad last resort: other reports keep their keys */
    if (s->all_quad_splits > 0) sq_json_key_int(j, "all_quad_splits", s->all_quad_splits);
    /* the pattern's route (layout_pipeline.h, docs/layout.md) */
    const sq_layout_report *rep = &r->report;
    static const char *pattern[] = {"natural", "pairs-cancelled", "gauss-bonnet-minimal",
                                    "imposed"};
    sq_json_key_int(j, "gauss_bonnet_min", rep->gauss_bonnet_min);
    sq_json_key_int(j, "cancelled_pairs", rep->cancelled_pairs);
    sq_json_key_int(j, "kept_pairs",
                    r->nsing > rep->gauss_bonnet_min ? (r->nsing - rep->gauss_bonnet_min) / 2 : 0);
    json_kept_pairs(j, r);
    sq_json_key_int(j, "unresolved_points", rep->unresolved);
    sq_json_key(j, "two_step");
    sq_json_bool(j, rep->two_step);
    sq_json_key(j, "pattern");
    sq_json_string(j, pattern[rep->pattern]);
    sq_json_end_object(j);
}

static void json_field_summary(sq_json *j, const sq_layout_result *r)
{
    sq_json_key_int(j, "chi", r->info->chi);
    sq_json_key(j, "field");
    sq_json_begin_object(j);
    sq_json_key(j, "kind");
    sq_json_string(j, r->field.kind);
    sq_json_key(j, "method");
    sq_json_string(j, r->field.method == SEM_CG ? "cg" : "dg");
    sq_json_key_int(j, "order", r->field.order);
    sq_json_key_int(j, "triangles", r->field.triangles);
    if (r->field.dofs > 0) sq_json_key_int(j, "dofs", r->field.dofs);
    if (r->analysis.field.twist != 0.0) sq_json_key_number(j, "twist_deg", SQ_GUIDING_TWIST_DEG);
    sq_json_end_object(j);
}

void sq_json_layout_head(sq_json *j, const char *input, int face, const sq_layout_result *r)
{
    sq_json_key(j, "input");
    sq_json_string(j, input);
    sq_json_key_int(j, "face", face);
    json_field_summary(j, r);
    json_layout_keys(j, r);
}

sq_status sq_write_layout_report(const char *path, const char *input, int face,
                                 const sq_layout_result *r, double t_read, double t_split,
                                 sq_error *err)
{
    sq_outfile f;
    SQ_TRY(sq_outfile_open(path, &f, err));
    sq_json j;
    sq_json_init(&j, f.fp);
    sq_json_begin_object(&j);
    sq_json_layout_head(&j, input, face, r);
    sq_json_key(&j, "timings_s");
    sq_json_begin_object(&j);
    sq_json_key_number(&j, "read", t_read);
    sq_json_key_number(&j, "triangulate", r->field.t_triangulate);
    sq_json_key_number(&j, "solve", r->field.t_solve);
    sq_json_key_number(&j, "critical_points", r->field.t_critical);
    sq_json_key_number(&j, "trace", r->t_trace);
    sq_json_key_number(&j, "layout", r->t_layout);
    if (t_split >= 0.0) sq_json_key_number(&j, "split", t_split);
    sq_json_end_object(&j);
    sq_json_end_object(&j);
    return sq_outfile_commit(&f, err);
}

/* A pleasant, distinct fill per patch (golden-angle hues). */
static void patch_colour(int p, char *buf, size_t n)
{
    double h = fmod(p * 137.508, 360.0);
    snprintf(buf, n, "hsl(%.0f,60%%,82%%)", h);
}

/* The polygon of a patch's outer cycle: its edges' polylines in walking
 * order.  Returns the point count (caller frees *xy). */
static int patch_polygon(const sq_layout *L, const sq_layout_patch *p, double **xy)
{
    int end = p->ncycles > 0 ? p->cycle_start[1] : p->nhalf, n = 0;
    for (int h = 0; h < end; h++) n += L->edges[p->half[h].edge].npts;
    *xy = malloc(sizeof(double) * 2 * (size_t)(n + 1));
    if (!*xy) return 0;
    int k = 0;
    for (int h = 0; h < end; h++) {
        const sq_layout_edge *e = &L->edges[p->half[h].edge];
        for (int i = 0; i < e->npts; i++) {
            int q = p->half[h].reversed ? e->npts - 1 - i : i;
            (*xy)[2 * k] = e->xy[2 * q];
            (*xy)[2 * k + 1] = e->xy[2 * q + 1];
            k++;
        }
    }
    return k;
}

sq_status sq_write_layout_svg(const char *path, const sq_layout_result *r, sq_error *err)
{
    const sq_layout *L = &r->layout;
    sq_outfile f;
    SQ_TRY(sq_outfile_open(path, &f, err));
    sq_svg svg;
    sq_svg_begin(&svg, f.fp, r->info->bbox, 900.0, 700.0);
    for (int p = 0; p < L->npatches; p++) {
        double *xy = NULL;
        int n = patch_polygon(L, &L->patches[p], &xy);
        char fill[40];
        if (L->patches[p].ncorners == 4 && L->patches[p].ncycles == 1) patch_colour(p, fill, sizeof fill);
        else snprintf(fill, sizeof fill, "#ff9f9f"); /* not a quad: shown in alarm red */
        if (n > 2) sq_svg_polyline(&svg, n, xy, 1, "none", 0.0, fill);
        free(xy);
    }
    for (int e = 0; e < L->nedges; e++) {
        const sq_layout_edge *ed = &L->edges[e];
        int bnd = ed->cad_edge >= 0;
        sq_svg_polyline(&svg, ed->npts, ed->xy, 0, bnd ? "#1a1a1a" : "#2b2b8f", bnd ? 2.2 : 1.4,
                        "none");
    }
    for (int k = 0; k < L->nsing; k++) {
        const sq_singularity *s = &L->sing[k];
        if (L->role[k] == SQ_LROLE_CROSSING) {
            sq_svg_circle(&svg, s->x, s->y, 3.0, "#2b2b8f");
            continue;
        }
        sq_svg_circle(&svg, s->x, s->y, 6.5, sq_svg_valence_color(s->valence));
        if (L->role[k] == SQ_LROLE_MIDPOINT) /* a repair: labelled */
            sq_svg_text(&svg, s->x, s->y, 8.0, 14.0, 12.0, "#b00000", "midpoint");
        else if (L->role[k] == SQ_LROLE_VALENCE2)
            sq_svg_text(&svg, s->x, s->y, 8.0, 14.0, 12.0, "#b00000", "valence-2 split");
        else if (L->role[k] == SQ_LROLE_TJUNCTION)
            sq_svg_text(&svg, s->x, s->y, 8.0, 14.0, 12.0, "#b00000", "T");
    }
    /* the boundary point of a valence-2 split, where its spoke ends */
    for (int k = 0; k < L->seps.n; k++) {
        const sq_separatrix *sp = &L->seps.s[k];
        if (sp->start.kind != SQ_END_SINGULAR || L->role[sp->start.id] != SQ_LROLE_VALENCE2 ||
            sp->end.kind != SQ_END_CORNER)
            continue;
        const double *q = &sp->xy[2 * sp->npts - 2];
        sq_svg_circle(&svg, q[0], q[1], 4.5, "#b00000");
        sq_svg_text(&svg, q[0], q[1], 8.0, -8.0, 12.0, "#b00000", "valence-2 point");
    }
    /* the caption names only the repairs made, so it fits one line */
    const sq_layout_stats *st = &L->stats;
    const struct {
        int n;
        const char *what;
    } rep[] = {{st->limit_cycles_cut, "limit cycles cut"},
               {st->t_junctions, "T-junctions"},
               {st->triangles_repaired, "midpoint divisions"},
               {st->valence2_split, "valence-2 points split"},
               {st->annuli_cut, "annuli cut"},
               {st->duplicates_removed, "duplicates"},
               {st->crossings_split, "crossings"},
               {st->straight_stems, "straight stems"},
               {st->separatrices_removed, "separatrices removed"},
               {st->all_quad_splits, "all-quad splits"}};
    char caption[320];
    int len = snprintf(
        caption, sizeof caption,
        "%s layout: %d separatrices, %d/%d quad patches; repairs:", r->valid ? "valid" : "INVALID",
        st->separatrices, st->quad_patches, st->patches);
    int any = 0;
    for (size_t k = 0; k < sizeof rep / sizeof rep[0] && len < (int)sizeof caption; k++)
        if (rep[k].n > 0)
            len += snprintf(caption + len, sizeof caption - (size_t)len, "%s %d %s",
                            any++ ? "," : "", rep[k].n, rep[k].what);
    if (!any && len < (int)sizeof caption)
        snprintf(caption + len, sizeof caption - (size_t)len, " none");
    sq_svg_text(&svg, r->info->bbox[0], r->info->bbox[1], 0.0, 16.0, 11.0, "#333333", caption);
    sq_svg_end(&svg);
    return sq_outfile_commit(&f, err);
}

/* At most this many interpolation points per separatrix piece: OCCT's
 * interpolation cost grows quickly with the point count, and a cubic
 * B-spline through 48 arc-length samples of a traced line (steps of 1/20
 * of an element) is within round-off of the mesh's resolution. */
#define STEP_MAX_POINTS 48

/* xy resampled by arc length to n points, ends exact. */
static void resample(const double *xy, int npts, int n, double *out)
{
    double total = 0.0;
    for (int i = 1; i < npts; i++) total += hypot(xy[2 * i] - xy[2 * i - 2], xy[2 * i + 1] - xy[2 * i - 1]);
    int j = 0;
    double acc = 0.0;
    for (int k = 0; k < n; k++) {
        double target = total * k / (n - 1);
        while (j + 2 < npts) {
            double l = hypot(xy[2 * j + 2] - xy[2 * j], xy[2 * j + 3] - xy[2 * j + 1]);
            if (acc + l >= target) break;
            acc += l;
            j++;
        }
        double l = hypot(xy[2 * j + 2] - xy[2 * j], xy[2 * j + 3] - xy[2 * j + 1]);
        double t = l > 0.0 ? fmin(fmax((target - acc) / l, 0.0), 1.0) : 0.0;
        out[2 * k] = xy[2 * j] + t * (xy[2 * j + 2] - xy[2 * j]);
        out[2 * k + 1] = xy[2 * j + 1] + t * (xy[2 * j + 3] - xy[2 * j + 1]);
    }
    out[0] = xy[0], out[1] = xy[1];
    out[2 * (n - 1)] = xy[2 * (npts - 1)], out[2 * (n - 1) + 1] = xy[2 * (npts - 1) + 1];
}

sq_status sq_write_layout_step(const char *path, const cad_model *model, int face_index,
                               const cad_face *face, const sq_layout *L, int *nfaces,
                               sq_error *err)
{
    SQ_TRY(sq_outfile_check(path, err));
    if (!strcmp(path, "-"))
        return SQ_FAIL(err, SQ_ERR_USAGE, "STEP cannot be written to standard output: name a file");
    int nc = 0;
    for (int e = 0; e < L->nedges; e++) nc += L->edges[e].cad_edge < 0;
    int *npts = malloc(sizeof(int) * (size_t)(nc + 1));
    const double **xy = malloc(sizeof(double *) * (size_t)(nc + 1));
    double *pool = malloc(sizeof(double) * 2 * STEP_MAX_POINTS * (size_t)(nc + 1));
    if (!npts || !xy || !pool) {
        free(npts);
        free(xy);
        free(pool);
        return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    }
    int k = 0;
    for (int e = 0; e < L->nedges; e++) {
        const sq_layout_edge *E = &L->edges[e];
        if (E->cad_edge >= 0) continue;
        if (E->npts > STEP_MAX_POINTS) {
            double *p = pool + 2 * STEP_MAX_POINTS * (size_t)k;
            resample(E->xy, E->npts, STEP_MAX_POINTS, p);
            npts[k] = STEP_MAX_POINTS;
            xy[k++] = p;
        } else {
            npts[k] = E->npts;
            xy[k++] = E->xy;
        }
    }
    cad_split *split = NULL;
    sq_status st = cad_face_split(model, face_index, face, nc, npts, xy, &split, err);
    if (st == SQ_OK) {
        if (nfaces) *nfaces = cad_split_num_faces(split);
        st = cad_split_write_step(split, path, err);
    }
    cad_split_free(&split);
    free(npts);
    free(xy);
    free(pool);
    return st;
}
