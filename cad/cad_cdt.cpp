// semquad cad/ — constrained Delaunay triangulation and refinement (CGAL).
//
// design:
//  1. insert the input points (duplicates share one vertex, which keeps the
//     first input index), then the constrained segments;
//  2. mark the domain: the faces reachable from the hole seeds and from the
//     infinite face without crossing a constraint are outside;
//  3. refine step by step with CGAL's Delaunay mesher and our criteria:
//     a triangle is bad when its smallest angle is below the bound (the
//     circumradius-to-shortest-edge ratio exceeds B = 1/(2 sin angle), i.e.
//     B^2 = 1/(4 sin^2 angle)), and imperatively bad when its longest edge
//     exceeds min(max_size, size(centroid));
//  4. output the vertices used by the triangles in the domain (input index or
//     -1, and for Steiner points on an input segment that segment's index) and
//     the triangles counter-clockwise.
// OpenCASCADE headers define a Handle macro that breaks CGAL: only cad.h here.
#include "cad.h"

#include <CGAL/Box_intersection_d/Box_with_info_d.h>
#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_mesh_face_base_2.h>
#include <CGAL/Delaunay_mesh_vertex_base_2.h>
#include <CGAL/Delaunay_mesher_2.h>
#include <CGAL/Delaunay_mesher_no_edge_refinement_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Mesh_2/Face_badness.h>
#include <CGAL/box_intersection_d.h>
#include <CGAL/intersections.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <new>
#include <unordered_map>
#include <vector>

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Delaunay_mesh_vertex_base_2<K> Vb;
typedef CGAL::Delaunay_mesh_face_base_2<K> Fb;
typedef CGAL::Triangulation_data_structure_2<Vb, Fb> Tds;
typedef CGAL::Constrained_Delaunay_triangulation_2<K, Tds> CDT;
typedef CDT::Point Point;
typedef CDT::Vertex_handle Vertex_handle;
typedef CDT::Face_handle Face_handle;

// Meshing criteria (the MeshingCriteria_2 concept): minimum angle and a
// (possibly graded) bound on the longest edge.
class Criteria {
  public:
    typedef CDT::Face_handle Face_handle;

    // sine2: squared sine of the smallest angle; size: (longest edge / bound)^2
    // (0 when there is no bound).  q1 < q2 means q1 is refined first.
    struct Quality {
        double sine2 = 1, size = 0;
        Quality() = default;
        bool operator<(const Quality &q) const
        {
            if (size > 1) return q.size > 1 ? size > q.size : true;
            if (q.size > 1) return false;
            return sine2 < q.sine2;
        }
    };

    class Is_bad {
      public:
        Is_bad(double sine2_bound, double max_size, cad_size_fn fn, void *ctx, double floor)
            : b_(sine2_bound), max_size_(max_size), fn_(fn), ctx_(ctx), floor_(floor)
        {
        }
        CGAL::Mesh_2::Face_badness operator()(const Quality q) const
        {
            if (q.size > 1) return CGAL::Mesh_2::IMPERATIVELY_BAD;
            return q.sine2 < b_ ? CGAL::Mesh_2::BAD : CGAL::Mesh_2::NOT_BAD;
        }
        CGAL::Mesh_2::Face_badness operator()(const Face_handle &fh, Quality &q) const
        {
            const Point &pa = fh->vertex(0)->point(), &pb = fh->vertex(1)->point(),
                        &pc = fh->vertex(2)->point();
            double a = CGAL::to_double(CGAL::squared_distance(pb, pc));
            double b = CGAL::to_double(CGAL::squared_distance(pc, pa));
            double c = CGAL::to_double(CGAL::squared_distance(pa, pb));
            double l[3] = {a, b, c};
            std::sort(l, l + 3); // l[2] longest, l[1] second
            double h = max_size_;
            if (fn_) {
                double xy[2] = {(CGAL::to_double(pa.x()) + CGAL::to_double(pb.x()) +
                                 CGAL::to_double(pc.x())) / 3.0,
                                (CGAL::to_double(pa.y()) + CGAL::to_double(pb.y()) +
                                 CGAL::to_double(pc.y())) / 3.0};
                double hl = fn_(xy, ctx_);
                if (hl > 0 && std::isfinite(hl)) h = h > 0 ? std::min(h, hl) : hl;
            }
            if (h > 0 && h < floor_) h = floor_;
            q.size = h > 0 ? l[2] / (h * h) : 0;
            if (q.size > 1) {
                q.sine2 = 1;
                return CGAL::Mesh_2::IMPERATIVELY_BAD;
            }
            double area2 = 2 * CGAL::to_double(CGAL::area(pa, pb, pc));
            // sin(smallest angle) = 2 area / (product of the two longer edges)
            q.sine2 = l[2] > 0 && l[1] > 0 ? area2 * area2 / (l[2] * l[1]) : 0;
            return q.sine2 < b_ ? CGAL::Mesh_2::BAD : CGAL::Mesh_2::NOT_BAD;
        }

      private:
        double b_, max_size_;
        cad_size_fn fn_;
        void *ctx_;
        double floor_;
    };

    Criteria(double sine2_bound = 0, double max_size = 0, cad_size_fn fn = NULL, void *ctx = NULL,
             double floor = 0)
        : b_(sine2_bound), max_size_(max_size), fn_(fn), ctx_(ctx), floor_(floor)
    {
    }
    Is_bad is_bad_object() const { return Is_bad(b_, max_size_, fn_, ctx_, floor_); }

  private:
    double b_, max_size_;
    cad_size_fn fn_;
    void *ctx_;
    double floor_;
};

typedef CGAL::Delaunay_mesher_2<CDT, Criteria> Mesher;
typedef CGAL::Delaunay_mesher_no_edge_refinement_2<CDT, Criteria> Face_mesher;

const size_t MAX_VERTICES = 20000000; // default work bound: a tiny size bound must not run away

// CGAL's refinement of the domain outside the holes' seeds, one step at a
// time so that the work bound is checked as it goes.
template <class M>
sq_status refine(CDT &cdt, const Criteria &crit, const std::vector<Point> &seeds,
                 const cad_cdt_input *in, size_t max_vertices, sq_error *err)
{
    M mesher(cdt, crit);
    // CGAL's no-edge-refinement mesher leaves its seeds' mark unset until
    // told (UBSan: an invalid bool): clear it first
    mesher.clear_seeds();
    if (!seeds.empty()) mesher.set_seeds(seeds.begin(), seeds.end(), false);
    mesher.init();
    while (!mesher.is_refinement_done()) {
        mesher.step_by_step_refine_mesh();
        if (cdt.number_of_vertices() > max_vertices)
            return SQ_FAIL(err, SQ_ERR_GEOMETRY,
                           "a triangulation with angles above %g degrees needs more than %zu "
                           "vertices: the face has features far below the size %g (a thin part, "
                           "near-touching boundaries, a needle corner)",
                           in->min_angle_deg, max_vertices, in->max_size);
    }
    return SQ_OK;
}

sq_status cdt_mesh(const cad_cdt_input *in, cad_cdt_output *out, sq_error *err)
{
    const int np = in->npoints, ns = in->nsegments;
    for (int i = 0; i < 2 * np; ++i)
        if (!std::isfinite(in->xy[i]))
            return SQ_FAIL(err, SQ_ERR_USAGE, "cad_cdt_mesh: point %d is not finite", i / 2);
    for (int i = 0; i < 2 * ns; ++i)
        if (in->seg[i] < 0 || in->seg[i] >= np)
            return SQ_FAIL(err, SQ_ERR_USAGE, "cad_cdt_mesh: segment %d refers to point %d of %d",
                           i / 2, in->seg[i], np);

    double lo[2] = {in->xy[0], in->xy[1]}, hi[2] = {in->xy[0], in->xy[1]};
    for (int i = 1; i < np; ++i)
        for (int d = 0; d < 2; ++d) {
            lo[d] = std::min(lo[d], in->xy[2 * i + d]);
            hi[d] = std::max(hi[d], in->xy[2 * i + d]);
        }
    double diam = std::hypot(hi[0] - lo[0], hi[1] - lo[1]);
    if (!(diam > 0)) return SQ_FAIL(err, SQ_ERR_GEOMETRY, "cad_cdt_mesh: all points coincide");

    CDT cdt;
    std::vector<Vertex_handle> vh((size_t)np);
    // Input vertices and the first input index of each (duplicates share one).
    std::unordered_map<const void *, int> input_index;
    for (int i = 0; i < np; ++i) {
        vh[(size_t)i] = cdt.insert(Point(in->xy[2 * i], in->xy[2 * i + 1]));
        input_index.emplace(&*vh[(size_t)i], i);
    }
    int nseg_used = 0;
    try {
        for (int k = 0; k < ns; ++k) {
            Vertex_handle a = vh[(size_t)in->seg[2 * k]], b = vh[(size_t)in->seg[2 * k + 1]];
            if (a == b) continue; // zero-length segment (duplicate points)
            cdt.insert_constraint(a, b);
            ++nseg_used;
        }
    }
    catch (const CDT::Intersection_of_constraints_exception &) {
        return SQ_FAIL(err, SQ_ERR_GEOMETRY,
                       "cad_cdt_mesh: constrained segments cross each other (self-intersecting "
                       "boundary)");
    }
    if (nseg_used < 3 || cdt.dimension() < 2)
        return SQ_FAIL(err, SQ_ERR_GEOMETRY, "cad_cdt_mesh: the segments bound no area");

    double sine2 = 0;
    if (in->min_angle_deg > 0) {
        double s = std::sin(in->min_angle_deg * M_PI / 180.0);
        sine2 = s * s;
    }
    Criteria crit(sine2, in->max_size > 0 ? in->max_size : 0, in->size, in->size_ctx, 1e-7 * diam);
    std::vector<Point> seeds;
    for (int h = 0; h < in->nholes; ++h) seeds.push_back(Point(in->holes[2 * h], in->holes[2 * h + 1]));
    const size_t max_vertices = in->max_vertices > 0 ? (size_t)in->max_vertices : MAX_VERTICES;
    if (cdt.number_of_vertices() > max_vertices)
        return SQ_FAIL(err, SQ_ERR_GEOMETRY,
                       "the boundary alone needs %zu points, more than the %zu allowed (a size "
                       "bound far below the face's size)",
                       cdt.number_of_vertices(), max_vertices);
    sq_status st = in->keep_segments ? refine<Face_mesher>(cdt, crit, seeds, in, max_vertices, err)
                                     : refine<Mesher>(cdt, crit, seeds, in, max_vertices, err);
    if (st != SQ_OK) return st;

    // Output: vertices used by the triangles in the domain.
    std::unordered_map<const void *, int> id;
    std::vector<Vertex_handle> verts;
    std::vector<int> tris;
    for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
        if (!f->is_in_domain()) continue;
        for (int j = 0; j < 3; ++j) {
            Vertex_handle v = f->vertex(j);
            auto r = id.emplace(&*v, (int)verts.size());
            if (r.second) verts.push_back(v);
            tris.push_back(r.first->second);
        }
        // CGAL faces are counter-clockwise already; check anyway.
        size_t t = tris.size() - 3;
        if (CGAL::orientation(f->vertex(0)->point(), f->vertex(1)->point(),
                              f->vertex(2)->point()) == CGAL::CLOCKWISE)
            std::swap(tris[t + 1], tris[t + 2]);
    }
    if (tris.empty())
        return SQ_FAIL(err, SQ_ERR_GEOMETRY,
                       "cad_cdt_mesh: no triangle in the domain (holes cover everything?)");

    size_t nv = verts.size(), nt = tris.size() / 3;
    out->xy = (double *)std::malloc(2 * nv * sizeof(double));
    out->source = (int *)std::malloc(nv * sizeof(int));
    out->on_segment = (int *)std::malloc(nv * sizeof(int));
    out->tri = (int *)std::malloc(3 * nt * sizeof(int));
    if (!out->xy || !out->source || !out->on_segment || !out->tri) {
        cad_cdt_output_free(out);
        return SQ_FAIL(err, SQ_ERR_INTERNAL, "cad_cdt_mesh: out of memory");
    }
    out->nverts = (int)nv;
    out->ntris = (int)nt;
    std::memcpy(out->tri, tris.data(), tris.size() * sizeof(int));
    for (size_t i = 0; i < nv; ++i) {
        const Vertex_handle &v = verts[i];
        double x = CGAL::to_double(v->point().x()), y = CGAL::to_double(v->point().y());
        out->xy[2 * i] = x;
        out->xy[2 * i + 1] = y;
        auto it = input_index.find(&*v);
        out->source[i] = it == input_index.end() ? -1 : it->second;
        out->on_segment[i] = -1;
        if (out->source[i] >= 0) continue;
        // Steiner point: on a constrained edge?  Then find its input segment.
        bool constrained = false;
        CDT::Edge_circulator ec = cdt.incident_edges(v), done = ec;
        if (ec != 0) do {
                if (cdt.is_constrained(*ec)) constrained = true;
            } while (!constrained && ++ec != done);
        if (!constrained) continue;
        double best = HUGE_VAL;
        for (int k = 0; k < ns; ++k) {
            const double *p = in->xy + 2 * in->seg[2 * k], *q = in->xy + 2 * in->seg[2 * k + 1];
            double dx = q[0] - p[0], dy = q[1] - p[1], l2 = dx * dx + dy * dy;
            if (!(l2 > 0)) continue;
            double t = ((x - p[0]) * dx + (y - p[1]) * dy) / l2;
            if (t <= 0 || t >= 1) continue;
            double d = std::fabs((x - p[0]) * dy - (y - p[1]) * dx) / std::sqrt(l2);
            if (d <= 1e-9 * std::sqrt(l2) && d < best) {
                best = d;
                out->on_segment[i] = k;
            }
        }
    }
    return SQ_OK;
}

// Design of cad_segments_crossing: CGAL's box intersection finds the pairs
// of segments whose boxes overlap, the kernel's exact predicates decide
// whether they meet; an end point the two share (by index or by
// coordinates) is where consecutive segments meet, no crossing.
sq_status segments_crossing(int np, const double *xy, int ns, const int *seg, int max_pairs,
                            int **pairs, int *npairs, sq_error *err)
{
    typedef CGAL::Box_intersection_d::Box_with_info_d<double, 2, int> Box;
    std::vector<Box> boxes;
    boxes.reserve((size_t)ns);
    for (int k = 0; k < ns; ++k) {
        const int a = seg[2 * k], b = seg[2 * k + 1];
        if (a < 0 || a >= np || b < 0 || b >= np)
            return SQ_FAIL(err, SQ_ERR_USAGE, "cad_segments_crossing: segment %d refers to point "
                           "%d or %d of %d", k, a, b, np);
        boxes.push_back(Box(Point(xy[2 * a], xy[2 * a + 1]).bbox() +
                                Point(xy[2 * b], xy[2 * b + 1]).bbox(),
                            k));
    }
    std::vector<int> found;
    auto same = [&](int i, int j) {
        return i == j || (xy[2 * i] == xy[2 * j] && xy[2 * i + 1] == xy[2 * j + 1]);
    };
    auto report = [&](const Box &p, const Box &q) {
        if (max_pairs > 0 && (int)found.size() >= 2 * max_pairs) return;
        const int k = p.info(), l = q.info();
        const int a = seg[2 * k], b = seg[2 * k + 1], c = seg[2 * l], d = seg[2 * l + 1];
        const K::Segment_2 s(Point(xy[2 * a], xy[2 * a + 1]), Point(xy[2 * b], xy[2 * b + 1]));
        const K::Segment_2 t(Point(xy[2 * c], xy[2 * c + 1]), Point(xy[2 * d], xy[2 * d + 1]));
        if (s.is_degenerate() || t.is_degenerate() || !CGAL::do_intersect(s, t)) return;
        // segments sharing an end meet there: a crossing only if they run
        // on along the same line (or share both ends)
        const int shared = same(a, c) ? a : same(a, d) ? a : same(b, c) ? b : same(b, d) ? b : -1;
        if (shared >= 0 && !((same(a, c) && same(b, d)) || (same(a, d) && same(b, c)))) {
            const Point P(xy[2 * shared], xy[2 * shared + 1]);
            const Point X = shared == a ? s.target() : s.source();
            const Point Y = same(shared, c) ? t.target() : t.source();
            if (!CGAL::collinear(P, X, Y) || CGAL::angle(X, P, Y) != CGAL::ACUTE) return;
        }
        found.push_back(std::min(k, l));
        found.push_back(std::max(k, l));
    };
    CGAL::box_self_intersection_d(boxes.begin(), boxes.end(), report);
    // box order is CGAL's: sort so the answer does not depend on it
    std::vector<std::pair<int, int>> pr;
    for (size_t i = 0; i < found.size(); i += 2) pr.push_back(std::make_pair(found[i], found[i + 1]));
    std::sort(pr.begin(), pr.end());
    *npairs = (int)pr.size();
    *pairs = (int *)std::malloc(sizeof(int) * (2 * pr.size() + 1));
    if (!*pairs) return SQ_FAIL(err, SQ_ERR_INTERNAL, "cad_segments_crossing: out of memory");
    for (size_t i = 0; i < pr.size(); ++i) {
        (*pairs)[2 * i] = pr[i].first;
        (*pairs)[2 * i + 1] = pr[i].second;
    }
    return SQ_OK;
}

} // namespace

extern "C" {

sq_status cad_segments_crossing(int npoints, const double *xy, int nsegments, const int *seg,
                                int max_pairs, int **pairs, int *npairs, sq_error *err)
{
    *pairs = NULL;
    *npairs = 0;
    try {
        return segments_crossing(npoints, xy, nsegments, seg, max_pairs, pairs, npairs, err);
    }
    catch (const std::bad_alloc &) {
        return SQ_FAIL(err, SQ_ERR_INTERNAL, "cad_segments_crossing: out of memory");
    }
    catch (const std::exception &e) {
        return SQ_FAIL(err, SQ_ERR_INTERNAL, "cad_segments_crossing: CGAL failed: %s", e.what());
    }
}

sq_status cad_cdt_mesh(const cad_cdt_input *in, cad_cdt_output *out, sq_error *err)
{
    if (!out) return SQ_FAIL(err, SQ_ERR_USAGE, "cad_cdt_mesh: out is NULL");
    std::memset(out, 0, sizeof *out);
    if (!in || in->npoints < 3 || !in->xy || in->nsegments < 3 || !in->seg ||
        (in->nholes > 0 && !in->holes) || in->nholes < 0)
        return SQ_FAIL(err, SQ_ERR_USAGE,
                       "cad_cdt_mesh: need at least 3 points and 3 segments (and hole seeds if "
                       "nholes > 0)");
    if (in->min_angle_deg > 30.0)
        return SQ_FAIL(err, SQ_ERR_USAGE,
                       "cad_cdt_mesh: minimum angle %g degrees above 30 (no termination guarantee)",
                       in->min_angle_deg);
    try {
        sq_status s = cdt_mesh(in, out, err);
        if (s != SQ_OK) cad_cdt_output_free(out);
        return s;
    }
    catch (const CDT::Intersection_of_constraints_exception &) {
        cad_cdt_output_free(out);
        return SQ_FAIL(err, SQ_ERR_GEOMETRY,
                       "cad_cdt_mesh: constrained segments cross each other (self-intersecting "
                       "boundary)");
    }
    catch (const std::bad_alloc &) {
        cad_cdt_output_free(out);
        return SQ_FAIL(err, SQ_ERR_INTERNAL, "cad_cdt_mesh: out of memory");
    }
    catch (const std::exception &e) {
        cad_cdt_output_free(out);
        return SQ_FAIL(err, SQ_ERR_GEOMETRY, "cad_cdt_mesh: CGAL failed: %s", e.what());
    }
    catch (...) {
        cad_cdt_output_free(out);
        return SQ_FAIL(err, SQ_ERR_INTERNAL, "cad_cdt_mesh: unknown C++ exception");
    }
}

void cad_cdt_output_free(cad_cdt_output *out)
{
    if (!out) return;
    std::free(out->xy);
    std::free(out->source);
    std::free(out->on_segment);
    std::free(out->tri);
    std::memset(out, 0, sizeof *out);
}

} // extern "C"
