#include "pattern.h"

#include "critical_points.h"
#include "degenerate_split.h"

#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

void sq_pattern_free(sq_pattern *p)
{
    if (!p) return;
    free(p->points);
    free(p->lines);
    free(p->corners);
    free(p->vertex_quads);
    memset(p, 0, sizeof *p);
}

void sq_pattern_balance_free(sq_pattern_balance *bal)
{
    if (!bal) return;
    free(bal->quads);
    memset(bal, 0, sizeof *bal);
}

int sq_default_quads(double angle_deg)
{
    int n = (int)lround(angle_deg / 90.0);
    return n < 1 ? 1 : n;
}

/* Next whitespace-separated token of s (NUL-terminated in place). */
static char *token(char **s)
{
    char *p = *s;
    while (*p && isspace((unsigned char)*p)) p++;
    if (!*p) return NULL;
    char *t = p;
    while (*p && !isspace((unsigned char)*p)) p++;
    if (*p) *p++ = '\0';
    *s = p;
    return t;
}

static int parse_double(const char *t, double *v)
{
    char *end;
    errno = 0;
    *v = strtod(t, &end);
    return t && *t && !*end && errno == 0 && isfinite(*v);
}

static int parse_int(const char *t, long *v)
{
    char *end;
    errno = 0;
    *v = strtol(t, &end, 10);
    return t && *t && !*end && errno == 0;
}

sq_status sq_pattern_parse(const char *text, const char *name, sq_pattern *out, sq_error *err)
{
    memset(out, 0, sizeof *out);
    size_t len = strlen(text);
    char *buf = malloc(len + 1);
    int cap = 16;
    out->points = malloc(sizeof *out->points * (size_t)cap);
    out->lines = malloc(sizeof *out->lines * (size_t)cap);
    out->corners = malloc(sizeof *out->corners * (size_t)cap);
    if (!buf || !out->points || !out->lines || !out->corners) {
        free(buf);
        sq_pattern_free(out);
        return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    }
    memcpy(buf, text, len + 1);
    sq_status st = SQ_OK;
    int lineno = 0;
    for (char *line = buf; line && st == SQ_OK; lineno++) {
        char *nl = strchr(line, '\n');
        if (nl) *nl = '\0';
        char *hash = strchr(line, '#');
        if (hash) *hash = '\0';
        char *cur = line, *tok[5];
        int nt = 0;
        while (nt < 5 && (tok[nt] = token(&cur)) != NULL) nt++;
        line = nl ? nl + 1 : NULL;
        if (nt == 0) continue;
        if (out->npoints == cap || out->ncorners == cap) {
            cap *= 2;
            void *a = realloc(out->points, sizeof *out->points * (size_t)cap);
            if (a) out->points = a;
            void *b = realloc(out->lines, sizeof *out->lines * (size_t)cap);
            if (b) out->lines = b;
            void *c = realloc(out->corners, sizeof *out->corners * (size_t)cap);
            if (c) out->corners = c;
            if (!a || !b || !c) {
                st = SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
                break;
            }
        }
        double x, y;
        long v;
        if (!strcmp(tok[0], "corner")) {
            if (nt != 4 || !parse_double(tok[1], &x) || !parse_double(tok[2], &y) ||
                !parse_int(tok[3], &v)) {
                st = SQ_FAIL(err, SQ_ERR_PATTERN,
                             "%s:%d: expected 'corner x y quads' with reals x, y and an integer",
                             name, lineno + 1);
            } else if (v < 0 || v > 32) {
                st = SQ_FAIL(err, SQ_ERR_PATTERN, "%s:%d: corner quads %ld out of range 0..32",
                             name, lineno + 1, v);
            } else {
                sq_corner_override *c = &out->corners[out->ncorners++];
                c->x = x;
                c->y = y;
                c->quads = (int)v;
                c->line = lineno + 1;
            }
            continue;
        }
        if (nt != 3 || !parse_double(tok[0], &x) || !parse_double(tok[1], &y) ||
            !parse_int(tok[2], &v)) {
            st = SQ_FAIL(err, SQ_ERR_PATTERN,
                         "%s:%d: expected 'x y valence' (reals x, y, integer valence) or "
                         "'corner x y quads'",
                         name, lineno + 1);
        } else if (v < 1 || v > 32) {
            st = SQ_FAIL(err, SQ_ERR_PATTERN, "%s:%d: valence %ld out of range 1..32", name,
                         lineno + 1, v);
        } else {
            sq_singularity *s = &out->points[out->npoints];
            s->x = x;
            s->y = y;
            s->valence = (int)v;
            s->origin = SQ_ORIGIN_IMPOSED;
            out->lines[out->npoints++] = lineno + 1;
        }
    }
    free(buf);
    if (st != SQ_OK) sq_pattern_free(out);
    return st;
}

sq_status sq_pattern_read(const char *path, sq_pattern *out, sq_error *err)
{
    memset(out, 0, sizeof *out);
    FILE *fp = fopen(path, "rb");
    if (!fp) return SQ_FAIL(err, SQ_ERR_INPUT, "cannot open pattern file %s", path);
    size_t cap = 4096, n = 0;
    char *text = malloc(cap);
    while (text) {
        size_t got = fread(text + n, 1, cap - n - 1, fp);
        n += got;
        if (n + 1 < cap) break;
        char *t = realloc(text, cap *= 2);
        if (!t) {
            free(text);
            text = NULL;
        } else {
            text = t;
        }
    }
    int bad = ferror(fp);
    fclose(fp);
    if (!text) return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    if (bad) {
        free(text);
        return SQ_FAIL(err, SQ_ERR_INPUT, "cannot read pattern file %s", path);
    }
    text[n] = '\0';
    if (strlen(text) != n) {
        free(text);
        return SQ_FAIL(err, SQ_ERR_PATTERN, "%s: not a text file (NUL byte)", path);
    }
    sq_status st = sq_pattern_parse(text, path, out, err);
    free(text);
    return st;
}

sq_status sq_pattern_from_analysis(const cad_face *face, const sq_field_analysis *a,
                                   sq_pattern *out, sq_error *err)
{
    memset(out, 0, sizeof *out);
    int nv = a->info.nvertices;
    SQ_TRY(sq_elementary_points(face, a, &out->points, &out->npoints, &out->ndegenerate, err));
    out->lines = calloc((size_t)out->npoints + 1, sizeof *out->lines);
    out->vertex_quads = malloc(sizeof *out->vertex_quads * (size_t)(nv + 1));
    if (!out->lines || !out->vertex_quads) {
        sq_pattern_free(out);
        return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    }
    out->nvertex_quads = nv;
    for (int k = 0; k < nv; k++) out->vertex_quads[k] = a->corners[k].valence;
    return SQ_OK;
}

/* Crossing-number test against the boundary sampled at 256 points per
 * edge (points this close to the boundary are refused before). */
static sq_status inside_face(const cad_face *face, const double p[2], int *inside, sq_error *err)
{
    const int ns = 256;
    int c = 0;
    for (int e = 0; e < cad_face_num_edges(face); e++) {
        double L = cad_face_edge_length(face, e), a[2], b[2];
        SQ_TRY(cad_face_edge_eval(face, e, 0.0, a, NULL, NULL, err));
        for (int k = 1; k <= ns; k++) {
            SQ_TRY(cad_face_edge_eval(face, e, L * k / ns, b, NULL, NULL, err));
            if ((a[1] > p[1]) != (b[1] > p[1])) {
                double xc = a[0] + (p[1] - a[1]) * (b[0] - a[0]) / (b[1] - a[1]);
                if (xc > p[0]) c ^= 1;
            }
            a[0] = b[0];
            a[1] = b[1];
        }
    }
    *inside = c;
    return SQ_OK;
}

/* "one valence-3 point" / "2 valence-5 points" */
static void count_phrase(char *buf, size_t n, int count, int valence)
{
    if (count == 1) snprintf(buf, n, "one valence-%d point", valence);
    else snprintf(buf, n, "%d valence-%d points", count, valence);
}

sq_status sq_pattern_check(const cad_face *face, const sq_face_info *info, const sq_pattern *p,
                           sq_pattern_balance *bal, sq_error *err)
{
    memset(bal, 0, sizeof *bal);
    const double diag = hypot(info->bbox[2] - info->bbox[0], info->bbox[3] - info->bbox[1]);
    const double tol = 1e-6 * diag;
    for (int k = 0; k < p->npoints; k++) {
        const double x[2] = {p->points[k].x, p->points[k].y};
        double d;
        int in;
        char where[64] = "";
        if (p->lines && p->lines[k] > 0) snprintf(where, sizeof where, "line %d: ", p->lines[k]);
        SQ_TRY(sq_face_boundary_distance(face, x, &d, err));
        if (d <= tol)
            return SQ_FAIL(err, SQ_ERR_PATTERN,
                           "%spoint (%g, %g) lies on the boundary of the face (distance %.3g): "
                           "singular points must be inside",
                           where, x[0], x[1], d);
        SQ_TRY(inside_face(face, x, &in, err));
        if (!in)
            return SQ_FAIL(err, SQ_ERR_PATTERN, "%spoint (%g, %g) lies outside the face", where,
                           x[0], x[1]);
        for (int q = 0; q < k; q++)
            if (hypot(p->points[q].x - x[0], p->points[q].y - x[1]) <= tol)
                return SQ_FAIL(err, SQ_ERR_PATTERN, "%spoint (%g, %g) is given twice", where,
                               x[0], x[1]);
    }
    bal->quads = malloc(sizeof(int) * (size_t)(info->nvertices + 1));
    if (!bal->quads) return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    for (int k = 0; k < info->nvertices; k++) {
        const sq_vertex *v = &info->vertices[k];
        bal->quads[k] = p->vertex_quads && p->nvertex_quads == info->nvertices
                            ? p->vertex_quads[k]
                            : sq_default_quads(v->angle_deg);
    }
    for (int c = 0; c < p->ncorners; c++) {
        const sq_corner_override *o = &p->corners[c];
        int best = -1;
        double bd = HUGE_VAL;
        for (int k = 0; k < info->nvertices; k++) {
            double d = hypot(info->vertices[k].x - o->x, info->vertices[k].y - o->y);
            if (d < bd) bd = d, best = k;
        }
        if (best < 0 || bd > 1e-6 * diag) {
            sq_pattern_balance_free(bal);
            return SQ_FAIL(err, SQ_ERR_PATTERN,
                           "line %d: no vertex of the face at (%g, %g) (nearest at distance %.3g)",
                           o->line, o->x, o->y, bd);
        }
        bal->quads[best] = o->quads;
    }
    for (int k = 0; k < p->npoints; k++) bal->lhs += 4 - p->points[k].valence;
    for (int k = 0; k < info->nvertices; k++) bal->lhs += 2 - bal->quads[k];
    bal->rhs = 4 * info->chi;
    if (bal->lhs == bal->rhs) return SQ_OK;
    /* the smallest change: |d| points of valence 3 (d > 0) or 5 (d < 0)
     * added, or as many of the other kind removed when the pattern has them */
    const int d = bal->rhs - bal->lhs, ad = abs(d);
    int have = 0;
    for (int k = 0; k < p->npoints; k++) have += p->points[k].valence == (d > 0 ? 5 : 3);
    char add[64], rem[64], fix[200];
    count_phrase(add, sizeof add, ad, d > 0 ? 3 : 5);
    count_phrase(rem, sizeof rem, ad, d > 0 ? 5 : 3);
    if (have >= ad) snprintf(fix, sizeof fix, "add %s or remove %s", add, rem);
    else snprintf(fix, sizeof fix, "add %s", add);
    sq_status st = SQ_FAIL(err, SQ_ERR_PATTERN,
                           "pattern breaks Gauss-Bonnet: sum (pi/2)(4 - V) + sum (pi - n pi/2) = "
                           "%.6f (%d x pi/2) but 2 pi chi = %.6f (%d x pi/2, chi = %d); "
                           "smallest fix: %s",
                           bal->lhs * M_PI_2, bal->lhs, bal->rhs * M_PI_2, bal->rhs, info->chi,
                           fix);
    sq_pattern_balance_free(bal);
    return st;
}
