/* semquad public API: boundary names (the CAD file's, then
 * sq_options.names over them, docs/formats.md "Named boundaries") given to
 * the mesh's boundary curves, and the file's face names to a domain's
 * faces, which the writers turn into group names. */
#include "api_private.h"
#include "sq_segment.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

sq_status sq_api_names_check(const sq_options *o, sq_error *err)
{
    if (o->nnames < 0 || (o->nnames > 0 && !o->names))
        return SQ_FAIL(err, SQ_ERR_USAGE, "names: nnames %d without a list", o->nnames);
    for (int k = 0; k < o->nnames; k++) {
        const sq_boundary_name *b = &o->names[k];
        const char *s = b->name;
        if (!s || !*s || s[strspn(s, SQ_NAME_CHARS)])
            return SQ_FAIL(err, SQ_ERR_USAGE, "names[%d]: name '%s', expects [A-Za-z0-9_-]+", k,
                           s ? s : "");
        if (b->edge < -1 || (b->edge == -1 && !(isfinite(b->x) && isfinite(b->y))))
            return SQ_FAIL(err, SQ_ERR_USAGE, "names[%d] (%s): edge %d, expects >= 0, or -1 and a point",
                           k, s, b->edge);
    }
    if (o->nface_names < 0 || (o->nface_names > 0 && !o->face_names))
        return SQ_FAIL(err, SQ_ERR_USAGE, "face names: nface_names %d without a list", o->nface_names);
    for (int k = 0; k < o->nface_names; k++) {
        const sq_face_name *b = &o->face_names[k];
        const char *s = b->name;
        if (!s || !*s || s[strspn(s, SQ_NAME_CHARS)] || strlen(s) > 63)
            return SQ_FAIL(err, SQ_ERR_USAGE,
                           "face_names[%d]: name '%s', expects [A-Za-z0-9_-]+ (at most 63)", k,
                           s ? s : "");
        if (b->face < -1 || (b->face == -1 && !(isfinite(b->x) && isfinite(b->y))))
            return SQ_FAIL(err, SQ_ERR_USAGE,
                           "face_names[%d] (%s): face %d, expects >= 0, or -1 and a point", k, s,
                           b->face);
    }
    return SQ_OK;
}

/* The tag of the boundary curve nearest (x, y) (through the polylines of
 * its sides' nodes), refused when farther than the mean boundary side,
 * the mesh's size along its boundary. */
static sq_status nearest_tag(const sq_quad_mesh *m, const sq_boundary_name *b, int *tag,
                             sq_error *err)
{
    int Q = m->order, npe = (Q + 1) * (Q + 1);
    const double x[2] = {b->x, b->y};
    double best = HUGE_VAL, sides = 0.0;
    for (int s = 0; s < m->nbnd; s++) {
        const int *c = &m->conn[(size_t)m->bnd_quad[s] * npe];
        for (int k = 0; k < Q; k++) {
            const double *p = &m->xy[2 * (size_t)c[sq_quad_side_node(Q, m->bnd_side[s], k)]];
            const double *q = &m->xy[2 * (size_t)c[sq_quad_side_node(Q, m->bnd_side[s], k + 1)]];
            double d = sq_segment_distance(x, p, q, NULL);
            if (d < best) best = d, *tag = m->bnd_tag[s];
            sides += hypot(q[0] - p[0], q[1] - p[1]);
        }
    }
    double size = m->nbnd ? sides / m->nbnd : 0.0;
    if (!(best <= size))
        return SQ_FAIL(err, SQ_ERR_USAGE,
                       "name %s: point (%g, %g) is %g from every boundary curve, farther than the "
                       "mesh size %g",
                       b->name, b->x, b->y, best, size);
    return SQ_OK;
}

/* Curve t named name (a copy), tag_name made when missing. */
static sq_status name_tag(sq_quad_mesh *m, int t, const char *name, sq_error *err)
{
    if (!m->tag_name && !(m->tag_name = calloc((size_t)m->ntags, sizeof *m->tag_name)))
        return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    /* a later name of the curve wins */
    free(m->tag_name[t]);
    if (!(m->tag_name[t] = malloc(strlen(name) + 1)))
        return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    strcpy(m->tag_name[t], name);
    return SQ_OK;
}

/* Face r of a domain named name, or "<name>_<face number>" when another
 * face has that name (each face is its own group). */
static sq_status name_region(sq_quad_mesh *m, int r, const char *name, sq_error *err)
{
    if (!m->region_name && !(m->region_name = calloc((size_t)m->nregions, sizeof *m->region_name)))
        return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    int taken = 0;
    for (int u = 0; u < m->nregions && !taken; u++)
        taken = u != r && m->region_name[u] && !strcmp(m->region_name[u], name);
    size_t n = strlen(name) + 16;
    char *s = malloc(n);
    if (!s) return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    if (taken) snprintf(s, n, "%s_%d", name, m->region_face[r]);
    else snprintf(s, n, "%s", name);
    free(m->region_name[r]); /* a later name of the face wins */
    m->region_name[r] = s;
    return SQ_OK;
}

/* The faces of a domain named as the file names them. */
static sq_status name_regions(sq_quad_mesh *m, const cad_model *model, sq_error *err)
{
    for (int r = 0; r < m->nregions; r++) {
        const char *name = cad_model_face_name(model, m->region_face[r]);
        if (name) SQ_TRY(name_region(m, r, name, err));
    }
    return SQ_OK;
}

/* Whether (x, y) lies in the polygon of quad q's corners (crossing number:
 * a point on the boundary of two quads counts for one of them). */
static int in_quad(const sq_quad_mesh *m, int q, double x, double y)
{
    int Q = m->order, npe = (Q + 1) * (Q + 1), in = 0;
    const int corner[4] = {0, Q, npe - 1, npe - 1 - Q};
    for (int k = 0; k < 4; k++) {
        const double *a = &m->xy[2 * (size_t)m->conn[(size_t)q * npe + corner[k]]];
        const double *b = &m->xy[2 * (size_t)m->conn[(size_t)q * npe + corner[(k + 1) % 4]]];
        if ((a[1] > y) != (b[1] > y) && x < a[0] + (y - a[1]) * (b[0] - a[0]) / (b[1] - a[1]))
            in = !in;
    }
    return in;
}

/* The face r of a domain a face name means: its number, or the face of
 * the first quad whose corners' polygon holds its point. */
static sq_status named_region(const sq_quad_mesh *m, const sq_face_name *b, int *r, sq_error *err)
{
    for (*r = 0; b->face >= 0 && *r < m->nregions; ++*r)
        if (m->region_face[*r] == b->face) return SQ_OK;
    if (b->face >= 0)
        return SQ_FAIL(err, SQ_ERR_USAGE, "face name %s: face %d is not one of the faces meshed",
                       b->name, b->face);
    for (int q = 0; q < m->nquads; q++)
        if (in_quad(m, q, b->x, b->y)) {
            *r = m->region[q];
            return SQ_OK;
        }
    return SQ_FAIL(err, SQ_ERR_USAGE, "face name %s: point (%g, %g) lies in no face meshed",
                   b->name, b->x, b->y);
}

sq_status sq_api_name_faces(sq_quad_mesh *m, const sq_options *o, sq_error *err)
{
    if (o->nface_names <= 0) return SQ_OK;
    if (!m || m->nregions == 0)
        return SQ_FAIL(err, SQ_ERR_USAGE,
                       "face names name the faces of a domain; a mesh of one face has one group, "
                       "'domain'");
    for (int k = 0; k < o->nface_names; k++) {
        int r;
        SQ_TRY(named_region(m, &o->face_names[k], &r, err));
        SQ_TRY(name_region(m, r, o->face_names[k].name, err));
    }
    return SQ_OK;
}

sq_status sq_api_file_names(sq_quad_mesh *m, const cad_model *model, const cad_face *const *cad,
                            const sq_domain_curve *curves, int ncurves, sq_error *err)
{
    SQ_TRY(name_regions(m, model, err));
    for (int t = 0; !curves && t < m->ntags; t++) {
        const char *name = cad_face_edge_name(cad[0], t);
        if (name) SQ_TRY(name_tag(m, t, name, err));
    }
    for (int c = 0; curves && c < ncurves; c++) {
        const char *name = curves[c].tag >= 0 ? cad_face_edge_name(cad[curves[c].face[0]], curves[c].edge[0]) : NULL;
        if (name) SQ_TRY(name_tag(m, curves[c].tag, name, err));
    }
    return SQ_OK;
}

sq_status sq_api_name_tags(sq_quad_mesh *m, const sq_options *o, sq_error *err)
{
    if (o->nnames <= 0) return SQ_OK;
    SQ_TRY(sq_api_names_check(o, err));
    for (int k = 0; k < o->nnames; k++) {
        const sq_boundary_name *b = &o->names[k];
        int t = b->edge;
        if (t == -1) SQ_TRY(nearest_tag(m, b, &t, err));
        if (t >= m->ntags)
            return SQ_FAIL(err, SQ_ERR_USAGE, "name %s: edge %d, the boundary has edges 0..%d",
                           b->name, t, m->ntags - 1);
        SQ_TRY(name_tag(m, t, b->name, err));
    }
    return SQ_OK;
}
