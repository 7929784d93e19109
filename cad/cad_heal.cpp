// semquad cad/ — healing the planar faces of a model within a tolerance,
// with OpenCASCADE's shape analysis and fixing tools (docs/healing.md).
//
// design, per planar face (once per file, at read time):
//  1. analyse each wire at the face's own precision (the largest tolerance
//     of its edges: what cad_face_create accepts at a junction) with
//     ShapeAnalysis_Wire on its edges in the order of travel: gaps between
//     consecutive 3D curve ends (CheckGap3d), consecutive edges that do not
//     share their vertex, edges shorter than that precision (CheckSmall),
//     degenerated edges a planar face cannot have (CheckDegenerated);
//  2. no defect: the face is left exactly as read (examples stay
//     byte-identical);
//  3. a defect larger than the healing tolerance: the face is broken, with
//     a one-line reason naming the defect, its size, the tolerance and the
//     --heal-tolerance that would allow it;
//  4. else ShapeFix_Wire on each wire (reorder, small, connect, gaps 3D/2D,
//     degenerated, self-intersection; ShapeFix_Edge for the vertex
//     tolerances and same parameter) of a deep copy of the face
//     (shared edges and vertices of the other faces keep their tolerances),
//     precision = the face's own, maximal tolerance = the healing tolerance;
//     the fixed face is analysed again (step 1 at its new edge tolerances)
//     and replaces the face in the model; if a defect is left (an edge that
//     became small as the fix grew the tolerances), the face as read is kept
//     (its defects are all within the tolerance) with one record "as read"
//     naming that defect;
//  5. every planar face, healed or not, is then checked to be a face at all
//     (loops that cross, a hole not inside the outer loop, holes that
//     overlap make it broken, with the loops and a point named): its
//     loops' p-curves are intersected pairwise, non-adjacent edges only
//     (ShapeAnalysis_Wire::CheckIntersectingEdges, boxes first), then a
//     point of each hole edge is classified against the other loops
//     (BRepTopAdaptor_FClass2d).  The STEP reader's own healing splits a
//     file's face whose loops cross into several faces; those are broken
//     too (cad_model.cpp marks them);
//  6. between 4 and 5: cusps (consecutive edges tangent at their vertex,
//     the face between them) are blunted within the healing tolerance
//     (cad_cusp.cpp), if the blunted face's loops are sound.
#include "cad_private.hxx"

#include <BRepAdaptor_Curve.hxx>
#include <BRepGProp.hxx>
#include <BRepTopAdaptor_FClass2d.hxx>
#include <Bnd_Box2d.hxx>
#include <BndLib_Add2dCurve.hxx>
#include <GProp_GProps.hxx>
#include <Geom2d_Curve.hxx>
#include <Geom_Surface.hxx>
#include <Geom2dAdaptor_Curve.hxx>
#include <IntRes2d_SequenceOfIntersectionPoint.hxx>
#include <ShapeAnalysis_Edge.hxx>
#include <TColStd_SequenceOfReal.hxx>
#include <TColgp_SequenceOfPnt.hxx>
#include <BRepBuilderAPI_Copy.hxx>
#include <BRepTools_WireExplorer.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <GCPnts_AbscissaPoint.hxx>
#include <ShapeAnalysis_Wire.hxx>
#include <Standard_ErrorHandler.hxx>
#include <ShapeExtend_WireData.hxx>
#include <ShapeFix_Edge.hxx>
#include <ShapeFix_Wire.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Iterator.hxx>
#include <TopoDS_Vertex.hxx>
#include <TopoDS_Wire.hxx>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <memory>

namespace {

// Largest tolerance of the face's edges: the precision at which the face is
// taken as it is (cad_face_create's closure test uses the same tolerances).
double face_precision(const TopoDS_Face &face)
{
    double p = 0;
    for (TopExp_Explorer ex(face, TopAbs_EDGE); ex.More(); ex.Next())
        p = std::max(p, BRep_Tool::Tolerance(TopoDS::Edge(ex.Current())));
    return p;
}

// Largest tolerance of the face's vertices and edges.
double face_tolerance(const TopoDS_Face &face)
{
    double t = face_precision(face);
    for (TopExp_Explorer ex(face, TopAbs_VERTEX); ex.More(); ex.Next())
        t = std::max(t, BRep_Tool::Tolerance(TopoDS::Vertex(ex.Current())));
    return t;
}

void midpoint(const gp_Pnt &a, const gp_Pnt &b, double at[3])
{
    at[0] = 0.5 * (a.X() + b.X()), at[1] = 0.5 * (a.Y() + b.Y()), at[2] = 0.5 * (a.Z() + b.Z());
}

sqcad::heal_record record(const char *kind, int wire, int a, int b, double size, const double at[3])
{
    sqcad::heal_record r;
    r.kind = kind;
    r.wire = wire;
    r.edge_a = a;
    r.edge_b = b;
    r.size = size;
    for (int d = 0; d < 3; ++d)
        r.at[d] = at[d];
    return r;
}

// Defects of one wire at precision prec (design 1), appended to out.
void analyse_wire(const TopoDS_Wire &wire, const TopoDS_Face &face, int w, double prec,
                  std::vector<sqcad::heal_record> &out)
{
    // The order of travel cad_face_create follows (BRepTools_WireExplorer:
    // shared vertices); if that chain misses edges, ShapeFix_Wire's
    // reordering by the curves' ends.  The order alone is not a defect.
    Handle(ShapeExtend_WireData) wd = new ShapeExtend_WireData;
    for (BRepTools_WireExplorer wx(wire, face); wx.More(); wx.Next())
        wd->Add(wx.Current());
    if (wd->NbEdges() < ShapeExtend_WireData(wire).NbEdges()) {
        ShapeFix_Wire order(wire, face, prec);
        order.FixReorder();
        wd = order.WireData();
    }
    ShapeAnalysis_Wire saw(wd, face, prec);
    const int n = wd->NbEdges();
    for (int i = 1; i <= n; ++i) {
        const int prev = i == 1 ? n : i - 1;
        const TopoDS_Edge e = wd->Edge(i), ep = wd->Edge(prev);
        const TopoDS_Vertex vp = TopExp::LastVertex(ep, Standard_True);
        const TopoDS_Vertex v = TopExp::FirstVertex(e, Standard_True);
        double at[3] = {0, 0, 0};
        if (!v.IsNull()) {
            gp_Pnt p = BRep_Tool::Pnt(v);
            at[0] = p.X(), at[1] = p.Y(), at[2] = p.Z();
        }
        if (n > 1 && saw.CheckGap3d(i)) {
            double t0, t1, s0, s1;
            Handle(Geom_Curve) cp = BRep_Tool::Curve(ep, t0, t1), c = BRep_Tool::Curve(e, s0, s1);
            if (!cp.IsNull() && !c.IsNull())
                midpoint(cp->Value(ep.Orientation() == TopAbs_REVERSED ? t0 : t1),
                         c->Value(e.Orientation() == TopAbs_REVERSED ? s1 : s0), at);
            out.push_back(record("gap", w, prev - 1, i - 1, saw.MinDistance3d(), at));
        } else if (n > 1 && !vp.IsNull() && !v.IsNull() && !vp.IsSame(v)) {
            double d = BRep_Tool::Pnt(vp).Distance(BRep_Tool::Pnt(v));
            out.push_back(record("connection", w, prev - 1, i - 1, d, at));
        }
        if (saw.CheckSmall(i, prec)) {
            double len = BRep_Tool::IsGeometric(e) ? GCPnts_AbscissaPoint::Length(BRepAdaptor_Curve(e))
                                                   : 0.0;
            out.push_back(record("small edge", w, i - 1, -1, len, at));
        }
        if (!BRep_Tool::Degenerated(e) && saw.CheckDegenerated(i))
            out.push_back(record("degenerated edge", w, i - 1, -1, 0, at));
    }
}

std::vector<sqcad::heal_record> analyse_face(const TopoDS_Face &face, double prec)
{
    std::vector<sqcad::heal_record> out;
    int w = 0;
    for (TopoDS_Iterator it(face); it.More(); it.Next())
        if (it.Value().ShapeType() == TopAbs_WIRE)
            analyse_wire(TopoDS::Wire(it.Value()), face, w++, prec, out);
    return out;
}

// The first defect healing cannot size against the tolerance, or larger
// than it; NULL if none.
const sqcad::heal_record *beyond(const std::vector<sqcad::heal_record> &d, double tol)
{
    for (const auto &r : d)
        if (r.kind == "degenerated edge" || r.size > tol) return &r;
    return NULL;
}

// "gap of 0.01 mm between edges 0 and 1 of wire 0 at (1, 0, 0)"
std::string describe(const sqcad::heal_record &r, const char *unit)
{
    char buf[400];
    if (r.edge_b >= 0)
        std::snprintf(buf, sizeof buf, "%s of %.3g%s between edges %d and %d of wire %d at (%.6g, %.6g, %.6g)",
                      r.kind.c_str(), r.size, unit, r.edge_a, r.edge_b, r.wire, r.at[0], r.at[1],
                      r.at[2]);
    else
        std::snprintf(buf, sizeof buf, "%s %d of wire %d (length %.3g%s) at (%.6g, %.6g, %.6g)",
                      r.kind.c_str(), r.edge_a, r.wire, r.size, unit, r.at[0], r.at[1], r.at[2]);
    return buf;
}

// The face rebuilt from its wires, each fixed by ShapeFix_Wire the way
// OpenCASCADE's own wire builder closes gaps (BRepBuilderAPI_MakeWire's
// healing: connect within the tolerance, then close the 3D gaps by the
// curves' ranges or ends, vertex tolerances and same-parameter fixed).
TopoDS_Face fix_face(const TopoDS_Face &face, double prec, double tol)
{
    TopoDS_Face out = TopoDS::Face(face.EmptyCopied());
    BRep_Builder b;
    for (TopoDS_Iterator it(face); it.More(); it.Next()) {
        if (it.Value().ShapeType() != TopAbs_WIRE) continue;
        ShapeFix_Wire w(TopoDS::Wire(it.Value()), face, prec);
        w.SetMaxTolerance(tol);
        w.ModifyTopologyMode() = Standard_True;
        w.ModifyGeometryMode() = Standard_True;
        w.ClosedWireMode() = Standard_True;
        w.FixReorder();
        w.FixSmall(Standard_False, prec);
        w.FixConnected(tol);
        w.FixGapsByRangesMode() = Standard_True;
        w.FixGaps3d();
        w.FixGaps2d();
        w.FixDegenerated();
        w.FixSelfIntersection();
        Handle(ShapeExtend_WireData) wd = w.WireData();
        ShapeFix_Edge fe;
        for (int i = 1; i <= wd->NbEdges(); ++i) {
            fe.FixVertexTolerance(wd->Edge(i), face);
            fe.FixSameParameter(wd->Edge(i), face);
        }
        b.Add(out, w.Wire());
    }
    return out;
}

// The edges of every wire of a face, wire by wire in the order of travel
// (wires numbered as in the file), and where each wire's edges start.
struct face_loops {
    Handle(ShapeExtend_WireData) edges = new ShapeExtend_WireData;
    std::vector<int> first; // per wire, 1-based index of its first edge; then the end
    std::vector<TopoDS_Wire> wires;
    int wire_of(int e) const
    {
        return (int)(std::upper_bound(first.begin(), first.end(), e) - first.begin()) - 1;
    }
};

face_loops collect_loops(const TopoDS_Face &face)
{
    face_loops L;
    for (TopoDS_Iterator it(face); it.More(); it.Next()) {
        if (it.Value().ShapeType() != TopAbs_WIRE) continue;
        L.first.push_back(L.edges->NbEdges() + 1);
        L.wires.push_back(TopoDS::Wire(it.Value()));
        for (BRepTools_WireExplorer wx(L.wires.back(), face); wx.More(); wx.Next())
            if (!BRep_Tool::Degenerated(wx.Current())) L.edges->Add(wx.Current());
    }
    L.first.push_back(L.edges->NbEdges() + 1);
    return L;
}

// True when edges i < j are consecutive along one wire (they meet at
// their shared vertex, which is no crossing).
bool adjacent(const face_loops &L, int i, int j)
{
    const int w = L.wire_of(i);
    if (L.wire_of(j) != w) return false;
    return j == i + 1 || (i == L.first[(size_t)w] && j == L.first[(size_t)w + 1] - 1);
}

std::string at_text(const gp_Pnt &p)
{
    char buf[120];
    std::snprintf(buf, sizeof buf, "(%.6g, %.6g, %.6g)", p.X(), p.Y(), p.Z());
    return buf;
}

// Two non-adjacent edges whose p-curves meet (design 5); empty if none.
std::string crossing_edges(const TopoDS_Face &face, const face_loops &L, double prec)
{
    const int n = L.edges->NbEdges();
    std::vector<Bnd_Box2d> box((size_t)n + 1);
    ShapeAnalysis_Edge sae;
    for (int i = 1; i <= n; ++i) {
        Handle(Geom2d_Curve) c;
        double a, b;
        if (sae.PCurve(L.edges->Edge(i), face, c, a, b, Standard_False))
            BndLib_Add2dCurve::Add(Geom2dAdaptor_Curve(c, a, b), prec, box[(size_t)i]);
    }
    ShapeAnalysis_Wire saw(L.edges, face, prec);
    for (int i = 1; i <= n; ++i)
        for (int j = i + 1; j <= n; ++j) {
            if (box[(size_t)i].IsOut(box[(size_t)j]) || adjacent(L, i, j)) continue;
            IntRes2d_SequenceOfIntersectionPoint p2;
            TColgp_SequenceOfPnt p3;
            TColStd_SequenceOfReal errs;
            if (!saw.CheckIntersectingEdges(i, j, p2, p3, errs) || p3.IsEmpty()) continue;
            const int wi = L.wire_of(i), wj = L.wire_of(j);
            char buf[200];
            if (wi == wj)
                std::snprintf(buf, sizeof buf, "wire %d crosses itself (edges %d and %d) at ", wi,
                              i - L.first[(size_t)wi], j - L.first[(size_t)wi]);
            else
                std::snprintf(buf, sizeof buf, "wires %d and %d cross (edges %d and %d) at ", wi,
                              wj, i - L.first[(size_t)wi], j - L.first[(size_t)wj]);
            return buf + at_text(p3(1));
        }
    return "";
}

// A wire alone, as a face of the plane, and its classifier: the loop's
// inside is where it classifies IN, or OUT for a clockwise (hole) wire,
// whose face holds the infinite point.
struct loop_region {
    TopoDS_Face face;
    std::unique_ptr<BRepTopAdaptor_FClass2d> fc;
    bool inverted = false;
    double area = 0;
};

void make_region(const TopoDS_Face &face, const TopoDS_Wire &w, double prec, loop_region &r)
{
    r.face = TopoDS::Face(face.EmptyCopied());
    BRep_Builder().Add(r.face, w);
    r.fc.reset(new BRepTopAdaptor_FClass2d(r.face, prec));
    r.inverted = r.fc->PerformInfinitePoint() == TopAbs_IN;
    GProp_GProps g;
    BRepGProp::SurfaceProperties(r.face, g);
    r.area = std::fabs(g.Mass());
}

// 1: uv strictly inside the loop, 0: strictly outside, -1: on it.
int inside(const loop_region &r, const gp_Pnt2d &uv)
{
    const TopAbs_State s = r.fc->Perform(uv);
    if (s != TopAbs_IN && s != TopAbs_OUT) return -1;
    return (s == TopAbs_IN) != r.inverted;
}

// A hole not strictly inside the outer loop, or inside another hole
// (design 5): its edges' midpoints classified (the loops do not cross
// here, so any point of an edge tells where the whole edge lies).
std::string misplaced_hole(const TopoDS_Face &face, const face_loops &L, double prec)
{
    const int nw = (int)L.wires.size();
    if (nw < 2) return "";
    std::vector<loop_region> r((size_t)nw);
    int outer = 0;
    for (int w = 0; w < nw; ++w) {
        make_region(face, L.wires[(size_t)w], prec, r[(size_t)w]);
        if (r[(size_t)w].area > r[(size_t)outer].area) outer = w;
    }
    ShapeAnalysis_Edge sae;
    for (int h = 0; h < nw; ++h) {
        if (h == outer) continue;
        for (int e = L.first[(size_t)h]; e < L.first[(size_t)h + 1]; ++e) {
            Handle(Geom2d_Curve) c;
            double a, b;
            if (!sae.PCurve(L.edges->Edge(e), face, c, a, b, Standard_False)) continue;
            const gp_Pnt2d uv = c->Value(0.5 * (a + b));
            const std::string at = at_text(BRep_Tool::Surface(face)->Value(uv.X(), uv.Y()));
            char buf[200];
            if (inside(r[(size_t)outer], uv) == 0) {
                std::snprintf(buf, sizeof buf, "hole wire %d is not inside the outer wire %d: its edge %d passes outside at ",
                              h, outer, e - L.first[(size_t)h]);
                return buf + at;
            }
            for (int g = 0; g < nw; ++g)
                if (g != outer && g != h && inside(r[(size_t)g], uv) == 1) {
                    std::snprintf(buf, sizeof buf, "hole wires %d and %d overlap: edge %d of wire %d lies inside wire %d at ",
                                  h, g, e - L.first[(size_t)h], h, g);
                    return buf + at;
                }
        }
    }
    return "";
}

// Why the face is no face (design 5): empty if its loops are sound.
std::string check_loops(const TopoDS_Face &face, double prec)
{
    const face_loops L = collect_loops(face);
    std::string why = crossing_edges(face, L, prec);
    return why.empty() ? misplaced_hole(face, L, prec) : why;
}

// Heal face i of the model (design 2-4, then the cusps: design 6).
void heal_face(cad_model *m, int i, double file_tol, bool given)
{
    const TopoDS_Face face = TopoDS::Face(m->faces(i + 1));
    // Gaps are sought down to 1e-8 of the face's size even where its
    // tolerances are larger (a face scaled to 1e-9 keeps the 1e-7 of its
    // writer), so that a gap the tolerances hide is still closed and said.
    const double prec = std::min(face_precision(face), 1e-8 * sqcad::face_size(face));
    std::vector<sqcad::heal_record> d = analyse_face(face, prec);
    // The file's own tolerance for this face: its uncertainty or the face's
    // vertex and edge tolerances, whichever is larger.
    const double tol = given ? file_tol : std::max(m->uncertainty, face_tolerance(face));
    // " mm" after a length, nothing when the file has no unit (BREP)
    const std::string us = std::strcmp(m->unit, "unknown") ? std::string(" ") + m->unit : "";
    const char *unit = us.c_str();
    if (const sqcad::heal_record *r = beyond(d, std::max(tol, prec))) {
        char buf[600];
        if (r->size > 0)
            std::snprintf(buf, sizeof buf, "%s exceeds the healing tolerance %.3g%s (--heal-tolerance %.2g would allow it)",
                          describe(*r, unit).c_str(), tol, unit, 1.5 * r->size);
        else
            std::snprintf(buf, sizeof buf, "%s cannot be healed (healing tolerance %.3g%s; --no-heal takes the face as read)",
                          describe(*r, unit).c_str(), tol, unit);
        m->status[(size_t)i] = CAD_FACE_BROKEN;
        m->reason[(size_t)i] = buf;
        return;
    }
    TopoDS_Face healed = face;
    if (!d.empty()) {
        healed = fix_face(TopoDS::Face(BRepBuilderAPI_Copy(face).Shape()), prec,
                          std::max(tol, prec));
        const double after = std::min(std::max(tol, prec), face_precision(healed));
        std::vector<sqcad::heal_record> left = analyse_face(healed, after);
        if (!left.empty() || healed.IsNull()) {
            // A defect within the tolerance that the fix left (an edge that
            // became small when closing gaps grew the tolerances): the face as
            // read, every defect of which is within the tolerance, is kept and
            // what the fix would leave is said (design 4; docs/healing.md).
            const double none[3] = {0, 0, 0};
            sqcad::heal_record r = left.empty() ? record("as read", 0, -1, -1, 0, none) : left[0];
            r.defect = left.empty() ? "no face" : left[0].kind;
            r.kind = "as read";
            healed = face;
            d.assign(1, r);
        }
    }
    // Cusps blunted within the tolerance (design 6); kept only if the
    // blunted face's loops are sound (the new segment crosses nothing).
    std::vector<sqcad::heal_record> cusps;
    TopoDS_Face blunted = sqcad::blunt_cusps(healed, tol, prec, cusps);
    if (!cusps.empty() && check_loops(blunted, std::min(face_precision(blunted), prec)).empty()) {
        healed = blunted;
        d.insert(d.end(), cusps.begin(), cusps.end());
    }
    if (d.empty()) return;
    m->heals[(size_t)i] = d;
    // A face kept as read is not healed: its status stays "ok", its record
    // says what healing would have left.
    if (healed.IsSame(face)) return;
    m->faces.Substitute(i + 1, healed);
    m->status[(size_t)i] = CAD_FACE_HEALED;
}

} // namespace

namespace sqcad {

void heal_model(cad_model *m, double tol, bool given)
{
    const int nf = m->faces.Extent();
    m->status.assign((size_t)nf, CAD_FACE_OK);
    m->reason.assign((size_t)nf, std::string());
    m->heals.assign((size_t)nf, std::vector<heal_record>());
    for (int i = 0; i < nf; ++i) {
        if (!m->planar[(size_t)i]) {
            m->status[(size_t)i] = CAD_FACE_NOT_PLANAR;
            continue;
        }
        for (const auto &s : m->split)
            if (s.first.IsSame(m->faces(i + 1))) {
                m->status[(size_t)i] = CAD_FACE_BROKEN;
                m->reason[(size_t)i] = s.second;
            }
        if (m->status[(size_t)i] == CAD_FACE_BROKEN) continue;
        try {
            OCC_CATCH_SIGNALS
            if (tol > 0) heal_face(m, i, tol, given); // else healing off
            if (m->status[(size_t)i] == CAD_FACE_BROKEN) continue;
            const TopoDS_Face face = TopoDS::Face(m->faces(i + 1));
            std::string why =
                check_loops(face, std::min(face_precision(face), 1e-8 * sqcad::face_size(face)));
            if (!why.empty()) {
                m->status[(size_t)i] = CAD_FACE_BROKEN;
                m->reason[(size_t)i] = why;
            }
        } catch (const Standard_Failure &e) {
            m->status[(size_t)i] = CAD_FACE_BROKEN;
            m->reason[(size_t)i] = std::string("healing failed (OpenCASCADE ") +
                                   e.DynamicType()->Name() + "; --no-heal takes the face as read)";
        }
    }
}

} // namespace sqcad
