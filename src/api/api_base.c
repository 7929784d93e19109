/* semquad public API: version, memory, options, messages, the shared
 * helpers of api_private.h. */
#include "api_private.h"
#include "converge.h"
#include "outfile.h"
#include "size_field.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define SQ_STR_(x) #x
#define SQ_STR(x) SQ_STR_(x)

const char *sq_version(void)
{
    return SQ_STR(SEMQUAD_VERSION_MAJOR) "." SQ_STR(SEMQUAD_VERSION_MINOR) "." SQ_STR(
        SEMQUAD_VERSION_PATCH);
}

void sq_free(void *p) { free(p); }

void sq_options_init(sq_options *o)
{
    memset(o, 0, sizeof *o);
    o->heal = 1;
    o->field = "auto";
    o->method = "auto";
    o->field_grading = 1;
    o->road = "auto";
    o->order = 4;
    o->nodes = "gll";
    o->max_quads = SQ_MAX_QUADS;
    o->relax_max_quads = SQ_RELAX_MAX_QUADS;
    o->bl_ratio = 1.2;
    o->size_gradation = SQ_SIZE_GRADATION;
    o->min_quality = SQ_MIN_QUALITY;
}

const sq_options *sq_api_options(const sq_options *o, sq_options *def)
{
    if (o) return o;
    sq_options_init(def);
    return def;
}

void sq_api_log(const sq_options *o, sq_log_level level, const char *fmt, ...)
{
    if (!o || !o->log) return;
    char line[1280];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(line, sizeof line, fmt, ap);
    va_end(ap);
    o->log(o->log_data, level, line);
}

static sq_status parse_method(const char *val, sq_method *out, sq_error *err)
{
    if (!val || !strcmp(val, "auto"))
        *out = SQ_METHOD_AUTO;
    else if (!strcmp(val, "cg"))
        *out = SQ_METHOD_CG;
    else if (!strcmp(val, "dg"))
        *out = SQ_METHOD_DG;
    else
        return SQ_FAIL(err, SQ_ERR_USAGE, "--method expects auto, cg or dg, got '%s'", val);
    return SQ_OK;
}

/* The field names of this version (sq_options.field). */
static sq_status check_field(const sq_options *o, sq_error *err)
{
    if (!o->field || !strcmp(o->field, "auto") || !strcmp(o->field, "htheta")) return SQ_OK;
    return SQ_FAIL(err, SQ_ERR_USAGE, "unknown field '%s' (this version has: auto, htheta)",
                   o->field);
}

const char *sq_api_singularities(const sq_options *o)
{
    if (o->singularities) return o->singularities;
    return o->field && !strcmp(o->field, "htheta") ? "natural" : NULL;
}

sq_status sq_api_field_options(const sq_options *o, sq_field_options *fo, sq_error *err)
{
    sq_field_options_default(fo);
    SQ_TRY(check_field(o, err));
    SQ_TRY(parse_method(o->method, &fo->method, err));
    if (o->field_order) fo->order = o->field_order;
    if (o->tri_size > 0.0) fo->tri.size = o->tri_size;
    if (!o->field_grading) fo->grading = 0.0; /* uniform near singular vertices */
    fo->tri.order = o->tri_order ? o->tri_order : sq_tri_order_for(fo->order);
    return SQ_OK;
}

sq_status sq_api_layout_options(const sq_options *o, int for_mesh, sq_layout_options *lo,
                                sq_error *err)
{
    if (for_mesh)
        sq_layout_options_for_mesh(lo);
    else
        sq_layout_options_default(lo);
    SQ_TRY(check_field(o, err));
    SQ_TRY(parse_method(o->method, &lo->field.method, err));
    if (o->field_order) lo->field.order = o->field_order;
    if (o->field_order && for_mesh) { /* the user's order, alone */
        lo->htheta.order = o->field_order;
        lo->htheta_first_order = 0;
    }
    if (o->tri_size > 0.0) lo->field.tri.size = o->tri_size;
    if (o->merge_distance > 0.0) lo->trace.merge_distance = o->merge_distance;
    lo->trace.progress = (sq_progress){o->progress, o->progress_data};
    lo->singularities = sq_api_singularities(o);
    lo->allow_misaligned = o->allow_misaligned;
    lo->field.tri.order = sq_tri_order_for(lo->field.order);
    if (for_mesh) lo->htheta.tri.order = sq_tri_order_for(lo->htheta.order);
    return SQ_OK;
}

sq_status sq_api_mesher_options(const sq_options *o, sq_mesher_options *mo, sq_error *err)
{
    sq_mesher_options_default(mo);
    if (o->order < 1 || o->order > 10)
        return SQ_FAIL(err, SQ_ERR_USAGE, "order %d: expects 1..10", o->order);
    mo->order = o->order;
    mo->size = o->size;
    if (o->nsizes < 0 || (o->nsizes > 0 && !o->sizes))
        return SQ_FAIL(err, SQ_ERR_USAGE, "sizes: nsizes %d without a list", o->nsizes);
    SQ_TRY(sq_size_sources_check(o->sizes, o->nsizes, o->size_gradation, err));
    SQ_TRY(sq_size_curvature_check(o->curvature_elements, err));
    if (!o->nodes || !strcmp(o->nodes, "gll"))
        mo->nodes = SQ_NODES_GLL;
    else if (!strcmp(o->nodes, "equispaced"))
        mo->nodes = SQ_NODES_EQUISPACED;
    else
        return SQ_FAIL(err, SQ_ERR_USAGE, "--nodes expects gll or equispaced, got '%s'", o->nodes);
    mo->max_quads = o->max_quads;
    if (o->threads < 0 || o->threads > 256)
        return SQ_FAIL(err, SQ_ERR_USAGE, "threads %d: expects 0..256 (0: the processors online)",
                       o->threads);
    if (!(o->relax_max_quads >= 0.0 && o->relax_max_quads <= 1e15))
        return SQ_FAIL(err, SQ_ERR_USAGE, "relax_max_quads %g: expects 0..1e15", o->relax_max_quads);
    mo->threads = o->threads;
    mo->relax_max_quads = o->relax_max_quads;
    mo->progress = (sq_progress){o->progress, o->progress_data};
    mo->nbl = o->nbl;
    mo->bl_edges = o->bl_edges;
    mo->bl_first = o->bl_first;
    mo->bl_ratio = o->bl_ratio;
    mo->bl_layers = o->bl_layers;
    mo->bl_gradation = o->size_gradation;
    if (mo->nbl > 0 && (!(mo->bl_first > 0.0) || mo->bl_layers < 1))
        return SQ_FAIL(err, SQ_ERR_USAGE, "--bl needs --bl-first d > 0 and --bl-layers n >= 1");
    if (!(o->min_quality >= 0.0 && o->min_quality <= 1.0))
        return SQ_FAIL(err, SQ_ERR_USAGE, "--min-quality %g: expects 0..1", o->min_quality);
    return SQ_OK;
}

sq_status sq_api_text_open(sq_api_text *t, sq_error *err)
{
    t->buf = NULL;
    t->len = 0;
    t->fp = open_memstream(&t->buf, &t->len);
    return t->fp ? SQ_OK : SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
}

sq_status sq_api_text_close(sq_api_text *t, char **text, sq_error *err)
{
    int bad = ferror(t->fp);
    fclose(t->fp);
    if (bad) {
        free(t->buf);
        *text = NULL;
        return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    }
    *text = t->buf;
    return SQ_OK;
}

int sq_api_ends_with(const char *s, const char *suffix)
{
    size_t n = strlen(s), k = strlen(suffix);
    return n >= k && !strcmp(s + n - k, suffix);
}

sq_status sq_api_parse_road(const char *val, sq_api_road *road, sq_error *err)
{
    if (!val || !strcmp(val, "auto"))
        *road = SQ_API_ROAD_AUTO;
    else if (!strcmp(val, "layout"))
        *road = SQ_API_ROAD_LAYOUT;
    else if (!strcmp(val, "split"))
        *road = SQ_API_ROAD_SPLIT;
    else
        return SQ_FAIL(err, SQ_ERR_USAGE, "--road expects auto, layout or split, got '%s'", val);
    return SQ_OK;
}

sq_status sq_output_check(const char *path, sq_error *err)
{
    if (!path) return SQ_FAIL(err, SQ_ERR_USAGE, "no output file named");
    return sq_outfile_check(path, err);
}

/* A length, tolerance or size: finite and >= 0 (0 is the default); a
 * negative one used to read as the default. */
static sq_status check_length(const char *field, double v, sq_error *err)
{
    if (isfinite(v) && v >= 0.0) return SQ_OK;
    return SQ_FAIL(err, SQ_ERR_USAGE, "%s %g: expects a finite value >= 0 (0: the default)", field,
                   v);
}

static sq_status check_lengths(const sq_options *o, sq_error *err)
{
    SQ_TRY(check_length("heal_tolerance", o->heal_tolerance, err));
    SQ_TRY(check_length("tri_size", o->tri_size, err));
    SQ_TRY(check_length("merge_distance", o->merge_distance, err));
    SQ_TRY(check_length("size", o->size, err));
    SQ_TRY(check_length("bl_first", o->bl_first, err));
    for (int k = 0; o->study_sizes && k < o->study_nsizes; k++) {
        char name[32];
        snprintf(name, sizeof name, "study_sizes[%d]", k);
        SQ_TRY(check_length(name, o->study_sizes[k], err));
    }
    return SQ_OK;
}

sq_status sq_options_check(const sq_options *o, sq_error *err)
{
    SQ_TRY(check_lengths(o, err));
    sq_api_road road;
    sq_layout_options lo;
    sq_mesher_options mo;
    SQ_TRY(sq_api_parse_road(o->road, &road, err));
    SQ_TRY(sq_api_layout_options(o, 1, &lo, err));
    SQ_TRY(sq_api_mesher_options(o, &mo, err));
    SQ_TRY(sq_api_names_check(o, err));
    int methods;
    return sq_api_study_methods(o, &methods, err);
}

sq_status sq_api_study_methods(const sq_options *o, int *methods, sq_error *err)
{
    if (o->study_solution) {
        sem_exact_fn fn;
        SQ_TRY(sq_converge_solution(o->study_solution, &fn, err));
    }
    const char *v = o->study_methods;
    if (!v || !strcmp(v, "both"))
        *methods = SQ_CONV_CG | SQ_CONV_DG;
    else if (!strcmp(v, "cg"))
        *methods = SQ_CONV_CG;
    else if (!strcmp(v, "dg"))
        *methods = SQ_CONV_DG;
    else
        return SQ_FAIL(err, SQ_ERR_USAGE, "--method expects cg, dg or both, got '%s'", v);
    return SQ_OK;
}
