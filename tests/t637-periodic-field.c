/* t637: the guiding field and the separatrices of a face with periodic
 * edges, on the identified domain (src/field/identified_edges.h,
 * docs/domains.md), on the project's own cascade passage
 * (tests/cascade_aerofoil.py: pitch lines of four segments, 0.8 apart).
 *
 *  - `auto` finds the four pairs, all translations, all identified;
 *  - the triangulation agreed on the pairs (the glue needs every element
 *    edge on a to meet one on b at the same arc lengths);
 *  - continuity: w = u + iv at a at arc s and at b at L − s (the image
 *    point) agree to 1e-9 with CG.  Why: the glued mesh has one unknown per
 *    matching vertex and edge mode, so the two traces are one polynomial of
 *    the edge's parameter; the two points are located in their elements by
 *    Newton to about 1e-13 of the element, and |∇w| h is O(1): a few 1e-13.
 *    The face's own field (pitch lines aligned) differs there by O(1): the
 *    check is not idle (> 0.05 asserted);
 *  - Poincaré–Hopf holds for the identified field (for chains of pairs
 *    ending on the boundary the face's count and the identified domain's
 *    agree, docs/domains.md), and no critical point sits on a pitch line
 *    (no spurious zero at the cut: within 1e-3 of the pitch);
 *  - separatrices: each that ends on an edge of a pair (not at a corner) is
 *    continued by one that starts on the partner at the image of its end
 *    (1e-12 of the pitch: one affine map of the end point) with the same
 *    direction (a translation), or, where that continuation merged with a
 *    line traced from its other end, the merged line ends there arriving
 *    in the opposite direction; and some do (the passage's lines cross
 *    the pitch lines).
 *  - bends (sq_periodic_bends): the outlet kinks, two classes of two
 *    vertices whose angles sum to 360 deg (the pitch lines' other kinks
 *    round to 2 quads already), each turning by pi - its angle over at
 *    most half of each edge and at most the distance to its partner (a
 *    pitch: the partner is boundary off its edges); the face's own field
 *    with them gives each bent kink 2 quads by eq. (15) with the ramp's
 *    corrections (without them, 3 at the reflex and 1 at the convex
 *    kinks), and Poincare-Hopf still holds.
 * usage: t637-periodic-field CASCADE_STEP */
#include "degenerate_split.h"
#include "field_analysis.h"
#include "periodic.h"
#include "test_util.h"
#include "trace.h"

static sq_status analyse(const cad_face *f, const sq_periodic *per, int identified,
                         sq_field_analysis *a, sq_error *err)
{
    sq_field_options fo;
    sq_field_options_default(&fo);
    fo.order = fo.tri.order = 4; /* the mesh command's order */
    fo.method = SQ_METHOD_CG;
    if (identified) fo.periodic = (sq_identification){per->nidentified, per->identified};
    return sq_field_analyse(f, &fo, a, err);
}

/* largest |w(a at s) − w(b at L − s)| over 33 points of every pair */
static double jump(const cad_face *f, const sq_periodic *per, const sq_field_analysis *a)
{
    double worst = 0.0;
    sq_error err;
    for (int k = 0; k < per->npairs; k++) {
        const int ea = per->pairs[k].a, eb = per->pairs[k].b;
        const double La = cad_face_edge_length(f, ea), Lb = cad_face_edge_length(f, eb);
        for (int i = 0; i <= 32; i++) {
            double x[2], y[2], wx[2], wy[2];
            int e1 = -1, e2 = -1;
            SQ_TEST_OK(cad_face_edge_eval(f, ea, La * i / 32.0, x, NULL, NULL, &err), err);
            SQ_TEST_OK(cad_face_edge_eval(f, eb, Lb * (1.0 - i / 32.0), y, NULL, NULL, &err), err);
            if (sq_guiding_field_eval(&a->field, x, &e1, wx, NULL) ||
                sq_guiding_field_eval(&a->field, y, &e2, wy, NULL)) {
                printf("pair %d: a point at %d/32 is outside the triangulation\n", k, i);
                return HUGE_VAL;
            }
            worst = fmax(worst, hypot(wx[0] - wy[0], wx[1] - wy[1]));
        }
    }
    return worst;
}

/* distance from p to the nearest pitch-line edge (sampled finely) */
static double to_pairs(const cad_face *f, const sq_periodic *per, double x, double y)
{
    double d = HUGE_VAL;
    sq_error err;
    for (int k = 0; k < per->npairs; k++)
        for (int side = 0; side < 2; side++) {
            const int e = side ? per->pairs[k].b : per->pairs[k].a;
            double s, foot[2], dist;
            const double p[2] = {x, y};
            SQ_TEST_OK(cad_face_edge_project(f, e, p, &s, foot, &dist, &err), err);
            d = fmin(d, dist);
        }
    return d;
}

/* separatrices re-entering: *n continued, returns the failures */
static int reentries(const cad_face *f, const sq_periodic *per, const sq_field_analysis *a,
                     int *n)
{
    sq_error err;
    sq_singularity *sing = NULL;
    int nsing = 0, fails = 0;
    SQ_TEST_OK(sq_elementary_points(f, a, &sing, &nsing, NULL, &err), err);
    int *quads = malloc(sizeof(int) * ((size_t)a->info.nvertices + 1));
    for (int k = 0; k < a->info.nvertices; k++) quads[k] = a->corners[k].valence;
    sq_trace_options to;
    sq_trace_options_default(&to);
    to.periodic = (sq_identification){per->nidentified, per->identified};
    sq_cross_field cf = sq_guiding_cross_field(&a->field);
    sq_separatrix_set set;
    SQ_TEST_OK(sq_trace_separatrices(&cf, f, &a->info, quads, nsing, sing, &to, &set, &err), err);
    const double pitch = hypot(per->pairs[0].affine[2], per->pairs[0].affine[5]);
    *n = 0;
    for (int i = 0; i < set.n; i++) {
        const sq_separatrix *s = &set.s[i];
        if (s->end.kind != SQ_END_BOUNDARY) continue;
        int k = 0;
        while (k < per->npairs && per->pairs[k].a != s->end.id && per->pairs[k].b != s->end.id) k++;
        if (k == per->npairs) continue;
        const int fwd = per->pairs[k].a == s->end.id, to_edge = fwd ? per->pairs[k].b : per->pairs[k].a;
        double T[6], q[2];
        if (fwd) memcpy(T, per->pairs[k].affine, sizeof T);
        else sq_affine_inverse(per->pairs[k].affine, T);
        sq_affine_map(T, &s->xy[2 * (s->npts - 1)], q);
        int found = 0;
        for (int j = 0; j < set.n && !found; j++) {
            const sq_separatrix *c = &set.s[j];
            const double *e = &c->xy[2 * (c->npts - 1)];
            /* the continuation, or a line merged with it (then its end is
             * there, arriving against the continuation's direction) */
            found = (c->start.kind == SQ_END_BOUNDARY && c->start.id == to_edge &&
                     hypot(c->xy[0] - q[0], c->xy[1] - q[1]) <= 1e-12 * pitch &&
                     fabs(remainder(c->start_angle - s->end_angle, 2.0 * M_PI)) <= 1e-12) ||
                    (c->end.kind == SQ_END_BOUNDARY && c->end.id == to_edge &&
                     hypot(e[0] - q[0], e[1] - q[1]) <= 1e-12 * pitch &&
                     fabs(remainder(c->end_angle + M_PI - s->end_angle, 2.0 * M_PI)) <= 1e-12);
        }
        if (!found) {
            printf("separatrix %d ends on edge %d at (%.9g, %.9g): no separatrix starts on edge "
                   "%d at its image (%.9g, %.9g) in its direction\n",
                   i, s->end.id, s->xy[2 * (s->npts - 1)], s->xy[2 * s->npts - 1], to_edge, q[0],
                   q[1]);
            fails++;
        }
        (*n)++;
    }
    sq_separatrix_set_free(&set);
    free(quads);
    free(sing);
    return fails;
}

/* The bends of the cascade's outlet kinks (header). */
static int bends(const cad_face *f, const sq_face_info *info, const sq_periodic *per)
{
    sq_error err;
    sq_bend *b = NULL;
    int nb = 0, fails = 0;
    SQ_TEST_OK(sq_periodic_bends(f, info, per, &b, &nb, &err), err);
    fails += sq_check_int("bends", "count", nb, 4);
    sq_field_options fo;
    sq_field_options_default(&fo);
    fo.order = fo.tri.order = 4;
    sq_field_analysis own, bent;
    SQ_TEST_OK(sq_field_analyse(f, &fo, &own, &err), err);
    fo.bends = b, fo.nbends = nb;
    SQ_TEST_OK(sq_field_analyse(f, &fo, &bent, &err), err);
    for (int k = 0; k < nb; k++) {
        const sq_vertex *v = &info->vertices[b[k].vertex];
        double partner = HUGE_VAL;
        for (int j = 0; j < nb; j++) {
            const sq_vertex *w = &info->vertices[b[j].vertex];
            if (j != k && fabs(v->angle_deg + w->angle_deg - 360.0) < 1e-3)
                partner = fmin(partner, hypot(v->x - w->x, v->y - w->y));
        }
        const int reflex = v->angle_deg > 180.0;
        printf("bend at vertex %d (%.2f deg): stretch %.4g, %.4g; partner %.4g; quads %d "
               "(face's own field %d)\n", b[k].vertex, v->angle_deg, b[k].len_in, b[k].len_out,
               partner, bent.corners[b[k].vertex].valence, own.corners[b[k].vertex].valence);
        fails += sq_check_abs("bend", "turn", b[k].turn, (180.0 - v->angle_deg) * M_PI / 180.0, 1e-12);
        if (!(b[k].len_in > 0.0 && b[k].len_in <= 0.5 * cad_face_edge_length(f, v->edge_in) &&
              b[k].len_out > 0.0 && b[k].len_out <= 0.5 * cad_face_edge_length(f, v->edge_out) &&
              b[k].len_in <= partner && b[k].len_out <= partner)) {
            printf("bend at vertex %d: stretch outside (0, min(half edge, partner)]\n", b[k].vertex);
            fails++;
        }
        fails += sq_check_int("bend", "quads", bent.corners[b[k].vertex].valence, 2);
        fails += sq_check_int("own field", "quads", own.corners[b[k].vertex].valence, reflex ? 3 : 1);
    }
    fails += sq_check_int("bent field", "Poincare-Hopf", bent.ph_lhs, bent.ph_rhs);
    sq_field_analysis_free(&own);
    sq_field_analysis_free(&bent);
    free(b);
    return fails;
}

int main(int argc, char **argv)
{
    if (argc < 2) {
        printf("usage: t637-periodic-field CASCADE_STEP\n");
        return 1;
    }
    sq_error err;
    cad_model *m = NULL;
    cad_face *f = NULL;
    SQ_TEST_OK(cad_model_read(argv[1], &m, &err), err);
    SQ_TEST_OK(cad_face_create(m, 0, &f, &err), err);
    sq_face_info info;
    SQ_TEST_OK(sq_face_info_compute(f, &info, &err), err);
    sq_periodic per;
    SQ_TEST_OK(sq_periodic_find(f, &info, "auto", &per, &err), err);
    int fails = sq_check_int("cascade", "pairs", per.npairs, 4);
    fails += sq_check_int("cascade", "pairs identified", per.nidentified, 4);
    sq_field_analysis own, id;
    SQ_TEST_OK(analyse(f, &per, 0, &own, &err), err);
    SQ_TEST_OK(analyse(f, &per, 1, &id, &err), err);
    if (id.identified_rounds < 1) fails += sq_check_int("cascade", "triangulation rounds", 0, 1);
    const double j_id = jump(f, &per, &id), j_own = jump(f, &per, &own);
    printf("cascade: |w(x) - w(T x)| on the pairs: %.3g identified, %.3g on the face alone; "
           "%d critical points, %d rounds\n",
           j_id, j_own, id.npoints, id.identified_rounds);
    if (!(j_id <= 1e-9)) fails += sq_check_abs("identified", "jump", j_id, 0.0, 1e-9);
    if (!(j_own > 0.05)) {
        printf("face alone: jump %.3g, expected > 0.05 (the pitch lines' own data)\n", j_own);
        fails++;
    }
    fails += sq_check_int("identified", "Poincare-Hopf", id.ph_lhs, id.ph_rhs);
    const double pitch = hypot(per.pairs[0].affine[2], per.pairs[0].affine[5]);
    for (int k = 0; k < id.npoints; k++) {
        const sq_critical_point *p = &id.points[k];
        const double d = to_pairs(f, &per, p->x, p->y);
        if (d < 1e-3 * pitch) {
            printf("critical point %d at (%.6g, %.6g) lies %.3g from a pitch line\n", k, p->x,
                   p->y, d);
            fails++;
        }
    }
    fails += bends(f, &info, &per);
    int n = 0;
    fails += reentries(f, &per, &id, &n);
    printf("cascade: %d separatrices re-entered through the partner edge\n", n);
    if (n == 0) fails += sq_check_int("cascade", "separatrices re-entering", 0, 1);
    sq_field_analysis_free(&own);
    sq_field_analysis_free(&id);
    sq_periodic_free(&per);
    sq_face_info_free(&info);
    cad_face_free(&f);
    cad_model_free(&m);
    return fails != 0;
}
