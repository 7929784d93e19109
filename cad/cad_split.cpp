// semquad cad/ — cutting a planar face into sub-faces along curves given in
// its 2D frame (the separatrices of a quad layout), and writing the pieces
// as STEP.
//
// design:
//  1. tolerance: tol = 1e-7 x the diagonal of the face's bounding box; it is
//     the fuzzy value of the Boolean operation and the distance within which
//     end points are taken to be on the boundary or on one another;
//  2. end points: each curve end is snapped onto the face boundary if it lies
//     within tol of it (cad_face_edge_project: feet at an edge's end are the
//     exact corner), else onto an earlier end point within tol; end points
//     that coincide share one TopoDS_Vertex.  An end point that is neither on
//     the boundary, nor at another curve's end, nor on another curve (a
//     T-junction) is "dangling": SQ_ERR_LAYOUT, nothing is split.  Interior
//     points must lie in the face (IN or ON: BRepTopAdaptor_FClass2d, whose
//     boundary polygon sends points near the boundary to the exact
//     BRepClass_FaceClassifier);
//  3. curves: 2D points -> 3D with the frame; 2 points: a degree-1 B-spline
//     (the segment), more: a cubic B-spline interpolating them
//     (GeomAPI_Interpolate, chord-length parameters), whose ends are exactly
//     the (snapped) end points, so the edges are built on the shared vertices;
//  4. split: BRepAlgoAPI_Splitter, the face as the argument and the edges as
//     tools, non-destructive (the model's face is not touched), fuzzy value
//     tol; every tool is intersected with the others, so crossing curves and
//     T-junctions are split where they meet.  A sub-face holding an INTERNAL
//     edge (a curve piece that cuts nothing) is reported as dangling;
//  5. area: Green's theorem, 1/2 int (x dy - y dx) along each sub-face's
//     edges in the 2D frame (origin moved to the face's centre), 10-point
//     Gauss-Legendre on the edges' knot spans: one rule per span on lines
//     and polynomial B-splines (exact), adaptive on the others; the areas
//     must add up to the face's (1e-8 relative);
//  6. corners: along each wire (BRepTools_WireExplorer) the turning angle
//     between the tangent at the end of one edge and at the start of the next;
//  7. STEP: the sub-faces in one shell (they share their split edges), in the
//     file's 3D frame, written in the model's unit without scaling and
//     without pcurves (a plane's are its 3D curves projected), to a
//     temporary file beside the target, then renamed over it.
#include "cad_private.hxx"

#include <BRepAdaptor_Curve.hxx>
#include <BRepAlgoAPI_Splitter.hxx>
#include <BRepBndLib.hxx>
#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepClass_FaceClassifier.hxx>
#include <BRepTools_WireExplorer.hxx>
#include <BRepTopAdaptor_FClass2d.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <ElSLib.hxx>
#include <GeomAPI_Interpolate.hxx>
#include <GeomAPI_ProjectPointOnCurve.hxx>
#include <Geom_BSplineCurve.hxx>
#include <Geom_Plane.hxx>
#include <IFSelect_ReturnStatus.hxx>
#include <Interface_Static.hxx>
#include <Message.hxx>
#include <Message_Alert.hxx>
#include <Message_Messenger.hxx>
#include <Message_Report.hxx>
#include <STEPControl_Writer.hxx>
#include <StepData_StepModel.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array1OfPnt.hxx>
#include <TColgp_HArray1OfPnt.hxx>
#include <TopAbs.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopTools_ListOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Iterator.hxx>
#include <TopoDS_Shell.hxx>
#include <TopoDS_Vertex.hxx>
#include <TopoDS_Wire.hxx>
#include <gp_Pnt.hxx>
#include <gp_Pnt2d.hxx>
#include <gp_Vec.hxx>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <memory>

namespace {

// Silence OpenCASCADE's default messenger while alive (printers restored).
class Quiet {
  public:
    Quiet() : msgr_(Message::DefaultMessenger())
    {
        if (!msgr_.IsNull()) {
            saved_ = msgr_->Printers();
            msgr_->ChangePrinters().Clear();
        }
    }
    ~Quiet()
    {
        if (!msgr_.IsNull()) msgr_->ChangePrinters() = saved_;
    }
    Quiet(const Quiet &) = delete;
    Quiet &operator=(const Quiet &) = delete;

  private:
    Handle(Message_Messenger) msgr_;
    Message_SequenceOfPrinters saved_;
};

// 10-point Gauss-Legendre rule on [-1, 1], nodes and weights of the positive half.
const double GLX[5] = {0.1488743389816312108848260, 0.4333953941292471907992659,
                       0.6794095682990244062343274, 0.8650633666889845107320967,
                       0.9739065285171717200779640};
const double GLW[5] = {0.2955242247147528701738930, 0.2692667193099963550912269,
                       0.2190863625159820439955349, 0.1494513491505805931457763,
                       0.0666713443086881375935688};

struct Frame {
    double O[3], X[3], Y[3];
    double c[2] = {0, 0}; // centre used as the origin of the area integrals

    gp_Pnt to3d(const double xy[2]) const
    {
        return gp_Pnt(O[0] + xy[0] * X[0] + xy[1] * Y[0], O[1] + xy[0] * X[1] + xy[1] * Y[1],
                      O[2] + xy[0] * X[2] + xy[1] * Y[2]);
    }
    void to2d(const gp_Pnt &p, double xy[2]) const
    {
        double d[3] = {p.X() - O[0], p.Y() - O[1], p.Z() - O[2]};
        xy[0] = d[0] * X[0] + d[1] * X[1] + d[2] * X[2];
        xy[1] = d[0] * Y[0] + d[1] * Y[1] + d[2] * Y[2];
    }
    void vec2d(const gp_Vec &v, double xy[2]) const
    {
        xy[0] = v.X() * X[0] + v.Y() * X[1] + v.Z() * X[2];
        xy[1] = v.X() * Y[0] + v.Y() * Y[1] + v.Z() * Y[2];
    }
};

// 1/2 int (x y' - y x') du over [a, b] of the curve (coordinates about f.c),
// one 10-point rule.
double green_rule(const BRepAdaptor_Curve &c, const Frame &f, double a, double b)
{
    double m = 0.5 * (a + b), h = 0.5 * (b - a), sum = 0;
    for (int i = 0; i < 10; ++i) {
        double u = i < 5 ? m - h * GLX[i] : m + h * GLX[i - 5];
        gp_Pnt p;
        gp_Vec d1;
        c.D1(u, p, d1);
        double xy[2], v[2];
        f.to2d(p, xy);
        f.vec2d(d1, v);
        xy[0] -= f.c[0];
        xy[1] -= f.c[1];
        sum += GLW[i % 5] * (xy[0] * v[1] - xy[1] * v[0]);
    }
    return 0.5 * h * sum;
}

double green_adapt(const BRepAdaptor_Curve &c, const Frame &f, double a, double b, double whole,
                   double tol, int depth)
{
    double m = 0.5 * (a + b);
    double l = green_rule(c, f, a, m), r = green_rule(c, f, m, b);
    if (depth >= 20 || std::fabs(l + r - whole) <= tol) return l + r;
    return green_adapt(c, f, a, m, l, 0.5 * tol, depth + 1) +
           green_adapt(c, f, m, b, r, 0.5 * tol, depth + 1);
}

// True if x y' - y x' is a polynomial of degree <= 19 on each knot span of
// the curve (a line, or a non-rational B-spline or Bezier curve of degree <=
// 10), so that one 10-point Gauss-Legendre rule per span is exact.
bool green_polynomial(const BRepAdaptor_Curve &c)
{
    switch (c.GetType()) {
    case GeomAbs_Line:
        return true;
    case GeomAbs_BSplineCurve:
    case GeomAbs_BezierCurve:
        return !c.IsRational() && c.Degree() <= 10;
    default:
        return false;
    }
}

// Signed Green integral along an edge as oriented (FORWARD: first -> last):
// on the knot spans (where the curve is C-infinity), one rule per span where
// that is exact (the separatrices' cubic B-splines), else adaptive.
double edge_green(const TopoDS_Edge &e, const Frame &f, double tol)
{
    BRepAdaptor_Curve c(e);
    double u0 = c.FirstParameter(), u1 = c.LastParameter();
    int n = c.NbIntervals(GeomAbs_CN);
    TColStd_Array1OfReal iv(1, n + 1);
    c.Intervals(iv, GeomAbs_CN);
    std::vector<double> br(1, u0);
    for (int i = 1; i <= n + 1; ++i)
        if (iv(i) > br.back() && iv(i) < u1) br.push_back(iv(i));
    br.push_back(u1);
    const bool exact = green_polynomial(c);
    double sum = 0;
    for (size_t k = 0; k + 1 < br.size(); ++k) {
        if (exact) {
            sum += green_rule(c, f, br[k], br[k + 1]);
            continue;
        }
        const int pieces = 2;
        double h = (br[k + 1] - br[k]) / pieces;
        for (int j = 0; j < pieces; ++j) {
            double a = br[k] + j * h, b = j + 1 == pieces ? br[k + 1] : a + h;
            sum += green_adapt(c, f, a, b, green_rule(c, f, a, b), tol, 0);
        }
    }
    return e.Orientation() == TopAbs_REVERSED ? -sum : sum;
}

// Area of a planar face by Green's theorem on its boundary edges.
double face_area(const TopoDS_Face &face, const Frame &f, double size)
{
    double tol = 1e-16 * size * size, sum = 0;
    for (TopExp_Explorer ex(face, TopAbs_EDGE); ex.More(); ex.Next()) {
        const TopoDS_Edge &e = TopoDS::Edge(ex.Current());
        TopAbs_Orientation o = e.Orientation();
        if (o != TopAbs_FORWARD && o != TopAbs_REVERSED) continue;
        if (BRep_Tool::Degenerated(e)) continue;
        sum += edge_green(e, f, tol);
    }
    return std::fabs(sum);
}

// Unit tangent (2D) of an edge at its start or end, in the direction of travel.
void edge_tangent(const BRepAdaptor_Curve &c, bool reversed, bool at_end, const Frame &f,
                  double t[2])
{
    double u0 = c.FirstParameter(), u1 = c.LastParameter();
    // Travel from u0 to u1 (forward) or u1 to u0 (reversed).
    double u = (at_end != reversed) ? u1 : u0;
    gp_Pnt p;
    gp_Vec d1;
    c.D1(u, p, d1);
    double v[2];
    f.vec2d(d1, v);
    double n = std::hypot(v[0], v[1]);
    // A vanishing derivative (compared with a short chord's mean speed):
    // take the direction of that chord instead.
    double du = 1e-6 * (u1 - u0);
    gp_Pnt q = c.Value((at_end != reversed) ? u - du : u + du);
    gp_Vec w = (at_end != reversed) ? gp_Vec(q, p) : gp_Vec(p, q);
    if (!(n > 1e-6 * w.Magnitude() / du)) {
        f.vec2d(w, v);
        n = std::hypot(v[0], v[1]);
    }
    double sg = reversed ? -1.0 : 1.0;
    t[0] = n > 0 ? sg * v[0] / n : 0;
    t[1] = n > 0 ? sg * v[1] / n : 0;
}

const char *step_unit_name(const char *unit, double *mm)
{
    struct {
        const char *unit, *step;
        double mm;
    } const table[] = {{"mm", "MM", 1.0},     {"m", "M", 1000.0},     {"cm", "CM", 10.0},
                       {"inch", "INCH", 25.4}, {"foot", "FT", 304.8}, {"micrometre", "UM", 1e-3}};
    for (const auto &t : table)
        if (unit && !std::strcmp(unit, t.unit)) {
            *mm = t.mm;
            return t.step;
        }
    *mm = 1.0; // unknown (BREP): written as millimetres, numbers unchanged
    return "MM";
}

// An Interface_Static setting changed while alive (the old value restored).
class StaticText {
  public:
    StaticText(const char *name, const char *value) : name_(name)
    {
        const char *old = Interface_Static::CVal(name);
        had_ = old != nullptr;
        if (had_) saved_ = old;
        Interface_Static::SetCVal(name, value);
    }
    ~StaticText()
    {
        if (had_) Interface_Static::SetCVal(name_, saved_.c_str());
    }
    StaticText(const StaticText &) = delete;
    StaticText &operator=(const StaticText &) = delete;

  private:
    const char *name_;
    bool had_;
    std::string saved_;
};

class StaticInt {
  public:
    StaticInt(const char *name, int value) : name_(name), saved_(Interface_Static::IVal(name))
    {
        Interface_Static::SetIVal(name, value);
    }
    ~StaticInt() { Interface_Static::SetIVal(name_, saved_); }
    StaticInt(const StaticInt &) = delete;
    StaticInt &operator=(const StaticInt &) = delete;

  private:
    const char *name_;
    int saved_;
};

struct CurveEnd {
    double xy[2];
    int vertex = -1;     // index into the shared vertices
    bool boundary = false;
};

} // namespace

struct cad_split {
    Frame frame;
    double size = 0, tol = 0;
    double face_area = 0;
    const char *unit = "unknown";
    TopoDS_Shell shell;
    std::vector<TopoDS_Face> faces;
    std::vector<double> area;
};

namespace {

std::string curve_label(int k) { return "curve " + std::to_string(k); }

sq_status split(const cad_model *model, int index, const cad_face *face, int ncurves,
                const int *npts, const double *const *xy, cad_split **out, sq_error *err)
{
    int nf = model->faces.Extent();
    if (index < 0 || index >= nf)
        return SQ_FAIL(err, SQ_ERR_USAGE, "face %d out of range (%s has %d face%s)", index,
                       model->path.c_str(), nf, nf == 1 ? "" : "s");
    if (ncurves < 0) return SQ_FAIL(err, SQ_ERR_USAGE, "cad_face_split: %d curves", ncurves);
    if (ncurves > 0 && (!npts || !xy))
        return SQ_FAIL(err, SQ_ERR_USAGE, "cad_face_split: NULL curve arrays");
    for (int k = 0; k < ncurves; ++k) {
        if (npts[k] < 2 || !xy[k])
            return SQ_FAIL(err, SQ_ERR_USAGE, "cad_face_split: curve %d has %d point%s", k,
                           npts[k], npts[k] == 1 ? "" : "s");
        for (int i = 0; i < 2 * npts[k]; ++i)
            if (!std::isfinite(xy[k][i]))
                return SQ_FAIL(err, SQ_ERR_USAGE, "cad_face_split: curve %d point %d is not finite",
                               k, i / 2);
    }

    // The face in its 2D frame (the caller's, or made here).
    cad_face *own = NULL;
    if (!face) {
        SQ_TRY(cad_face_create(model, index, &own, err));
        face = own;
    }
    struct FreeFace {
        cad_face *f;
        ~FreeFace() { cad_face_free(&f); }
    } free_face{own};

    std::unique_ptr<cad_split> s(new cad_split);
    Frame &fr = s->frame;
    cad_face_frame(face, fr.O, fr.X, fr.Y);
    s->unit = model->unit;

    const TopoDS_Face F = TopoDS::Face(model->faces(index + 1));
    Bnd_Box box;
    BRepBndLib::Add(F, box);
    if (box.IsVoid()) return SQ_FAIL(err, SQ_ERR_GEOMETRY, "face %d has no extent", index);
    {
        double x0, y0, z0, x1, y1, z1;
        box.Get(x0, y0, z0, x1, y1, z1);
        s->size = std::sqrt((x1 - x0) * (x1 - x0) + (y1 - y0) * (y1 - y0) + (z1 - z0) * (z1 - z0));
        double c[2];
        fr.to2d(gp_Pnt(0.5 * (x0 + x1), 0.5 * (y0 + y1), 0.5 * (z0 + z1)), c);
        fr.c[0] = c[0], fr.c[1] = c[1];
    }
    if (!(s->size > 0)) return SQ_FAIL(err, SQ_ERR_GEOMETRY, "face %d has no extent", index);
    const double tol = 1e-7 * s->size;
    s->tol = tol;

    // The frame must be the face's plane.
    gp_Pln pln;
    if (!sqcad::face_plane(F, &pln))
        return SQ_FAIL(err, SQ_ERR_GEOMETRY, "face %d is not planar", index);
    {
        gp_Vec X(fr.X[0], fr.X[1], fr.X[2]), Y(fr.Y[0], fr.Y[1], fr.Y[2]);
        gp_Vec N = X.Crossed(Y);
        double cosn = std::fabs(N.Dot(gp_Vec(pln.Axis().Direction())));
        if (!(cosn > 1 - 1e-9) || pln.Distance(gp_Pnt(fr.O[0], fr.O[1], fr.O[2])) > tol)
            return SQ_FAIL(err, SQ_ERR_USAGE,
                           "cad_face_split: the cad_face given is not face %d of the model", index);
    }
    s->face_area = face_area(F, fr, s->size);

    // 1. End points: on the boundary (snapped onto it) or shared.
    std::vector<CurveEnd> ends((size_t)(2 * ncurves));
    std::vector<std::array<double, 2>> vpos; // shared vertex positions (2D)
    std::vector<int> vcount;                 // curve ends at each
    const int nedges = cad_face_num_edges(face);
    for (int k = 0; k < ncurves; ++k)
        for (int j = 0; j < 2; ++j) {
            CurveEnd &ce = ends[(size_t)(2 * k + j)];
            const double *p = xy[k] + (j == 0 ? 0 : 2 * (npts[k] - 1));
            ce.xy[0] = p[0], ce.xy[1] = p[1];
            double best = HUGE_VAL, foot[2] = {p[0], p[1]};
            for (int e = 0; e < nedges; ++e) {
                double d, ft[2];
                SQ_TRY(cad_face_edge_project(face, e, p, NULL, ft, &d, err));
                if (d < best) best = d, foot[0] = ft[0], foot[1] = ft[1];
            }
            if (best <= tol) {
                ce.boundary = true;
                ce.xy[0] = foot[0], ce.xy[1] = foot[1];
            }
            int v = -1;
            for (size_t i = 0; i < vpos.size() && v < 0; ++i)
                if (std::hypot(vpos[i][0] - ce.xy[0], vpos[i][1] - ce.xy[1]) <= tol) v = (int)i;
            if (v < 0) {
                v = (int)vpos.size();
                vpos.push_back({ce.xy[0], ce.xy[1]});
                vcount.push_back(0);
            }
            ce.vertex = v;
            ce.xy[0] = vpos[(size_t)v][0], ce.xy[1] = vpos[(size_t)v][1];
            ++vcount[(size_t)v];
        }
    std::vector<TopoDS_Vertex> verts(vpos.size());
    {
        BRep_Builder bb;
        for (size_t i = 0; i < vpos.size(); ++i)
            bb.MakeVertex(verts[i], fr.to3d(vpos[i].data()), Precision::Confusion());
    }

    // 2. Interior points inside the face.
    // On a Geom_Plane (every planar STEP face here) the points are classified
    // in its (u, v) space by BRepTopAdaptor_FClass2d: the boundary's polygon
    // is built once, and a point within the polygon's measured deflection of
    // it goes to the exact BRepClass_FaceClassifier, so the answer is the
    // exact classifier's at a fraction of its cost per point.  Other planar
    // surfaces take the exact classifier for every point.
    TopLoc_Location floc;
    Handle(Geom_Plane) gpl = Handle(Geom_Plane)::DownCast(BRep_Tool::Surface(F, floc));
    std::unique_ptr<BRepTopAdaptor_FClass2d> fcls;
    if (!gpl.IsNull()) fcls.reset(new BRepTopAdaptor_FClass2d(F, tol));
    for (int k = 0; k < ncurves; ++k)
        for (int i = 1; i + 1 < npts[k]; ++i) {
            gp_Pnt P = fr.to3d(xy[k] + 2 * i);
            TopAbs_State st;
            if (fcls) {
                double u, v;
                ElSLib::Parameters(gpl->Pln(), P.Transformed(floc.Transformation().Inverted()), u,
                                   v);
                st = fcls->Perform(gp_Pnt2d(u, v), Standard_False);
            } else {
                st = BRepClass_FaceClassifier(F, P, tol).State();
            }
            if (st != TopAbs_IN && st != TopAbs_ON)
                return SQ_FAIL(err, SQ_ERR_LAYOUT,
                               "curve %d: point %d (%.17g, %.17g) lies outside face %d", k, i,
                               xy[k][2 * i], xy[k][2 * i + 1], index);
        }

    // 3. Curves -> B-spline edges on the shared vertices.
    std::vector<Handle(Geom_BSplineCurve)> curves((size_t)ncurves);
    std::vector<TopoDS_Edge> edges((size_t)ncurves);
    for (int k = 0; k < ncurves; ++k) {
        const CurveEnd &a = ends[(size_t)(2 * k)], &b = ends[(size_t)(2 * k + 1)];
        std::vector<gp_Pnt> P;
        P.push_back(fr.to3d(a.xy));
        for (int i = 1; i + 1 < npts[k]; ++i) {
            gp_Pnt q = fr.to3d(xy[k] + 2 * i);
            if (q.Distance(P.back()) > 1e-9 * s->size) P.push_back(q);
        }
        gp_Pnt last = fr.to3d(b.xy);
        while (P.size() > 1 && P.back().Distance(last) <= 1e-9 * s->size) P.pop_back();
        P.push_back(last);
        if (P.size() == 2 && P[0].Distance(P[1]) <= 1e-9 * s->size)
            return SQ_FAIL(err, SQ_ERR_LAYOUT, "curve %d has zero length", k);
        Handle(Geom_BSplineCurve) c;
        if (P.size() == 2) {
            TColgp_Array1OfPnt poles(1, 2);
            poles(1) = P[0], poles(2) = P[1];
            TColStd_Array1OfReal knots(1, 2);
            knots(1) = 0, knots(2) = P[0].Distance(P[1]);
            TColStd_Array1OfInteger mults(1, 2);
            mults(1) = mults(2) = 2;
            c = new Geom_BSplineCurve(poles, knots, mults, 1);
        } else {
            Handle(TColgp_HArray1OfPnt) pts = new TColgp_HArray1OfPnt(1, (int)P.size());
            for (size_t i = 0; i < P.size(); ++i) pts->SetValue((int)i + 1, P[i]);
            GeomAPI_Interpolate gi(pts, Standard_False, 1e-10 * s->size);
            gi.Perform();
            if (!gi.IsDone())
                return SQ_FAIL(err, SQ_ERR_LAYOUT, "curve %d: B-spline interpolation failed", k);
            c = gi.Curve();
        }
        curves[(size_t)k] = c;
        BRepBuilderAPI_MakeEdge me(c, verts[(size_t)a.vertex], verts[(size_t)b.vertex],
                                   c->FirstParameter(), c->LastParameter());
        if (!me.IsDone())
            return SQ_FAIL(err, SQ_ERR_LAYOUT, "curve %d: no edge could be built (error %d)", k,
                           (int)me.Error());
        edges[(size_t)k] = me.Edge();
    }

    // 4. Dangling ends: neither on the boundary, nor shared, nor on another curve.
    for (int k = 0; k < ncurves; ++k)
        for (int j = 0; j < 2; ++j) {
            const CurveEnd &ce = ends[(size_t)(2 * k + j)];
            if (ce.boundary || vcount[(size_t)ce.vertex] >= 2) continue;
            gp_Pnt P = fr.to3d(ce.xy);
            bool on = false;
            for (int m = 0; m < ncurves && !on; ++m) {
                if (m == k) continue;
                const Handle(Geom_BSplineCurve) &c = curves[(size_t)m];
                GeomAPI_ProjectPointOnCurve pr(P, c, c->FirstParameter(), c->LastParameter());
                if (pr.NbPoints() > 0 && pr.LowerDistance() <= tol) on = true;
            }
            if (!on)
                return SQ_FAIL(err, SQ_ERR_LAYOUT,
                               "curve %d: %s point (%.17g, %.17g) is neither on the boundary of "
                               "face %d nor on another curve (dangling)",
                               k, j == 0 ? "first" : "last", ce.xy[0], ce.xy[1], index);
        }

    // 5. Split.
    TopoDS_Shape result;
    if (ncurves == 0) {
        result = F;
    } else {
        Quiet quiet;
        BRepAlgoAPI_Splitter sp;
        TopTools_ListOfShape args, tools;
        args.Append(F);
        for (const TopoDS_Edge &e : edges) tools.Append(e);
        sp.SetArguments(args);
        sp.SetTools(tools);
        sp.SetFuzzyValue(tol);
        sp.SetNonDestructive(Standard_True);
        sp.SetRunParallel(Standard_False);
        sp.Build();
        if (sp.HasErrors() || !sp.IsDone()) {
            std::string why = "unknown error";
            const Message_ListOfAlert &al = sp.GetReport()->GetAlerts(Message_Fail);
            if (!al.IsEmpty() && al.First()->GetMessageKey()) why = al.First()->GetMessageKey();
            return SQ_FAIL(err, SQ_ERR_INTERNAL, "face %d: OpenCASCADE split failed (%s)", index,
                           why.c_str());
        }
        result = sp.Shape();
        // A curve piece left inside a sub-face cuts nothing: dangling.
        for (TopExp_Explorer fx(result, TopAbs_FACE); fx.More(); fx.Next())
            for (TopExp_Explorer ex(fx.Current(), TopAbs_EDGE); ex.More(); ex.Next()) {
                TopAbs_Orientation o = ex.Current().Orientation();
                if (o == TopAbs_FORWARD || o == TopAbs_REVERSED) continue;
                int which = -1;
                for (int k = 0; k < ncurves && which < 0; ++k) {
                    if (edges[(size_t)k].IsSame(ex.Current())) which = k;
                    for (TopTools_ListIteratorOfListOfShape it(sp.Modified(edges[(size_t)k]));
                         it.More() && which < 0; it.Next())
                        if (it.Value().IsSame(ex.Current())) which = k;
                }
                std::string who = which >= 0 ? curve_label(which) : std::string("a curve");
                return SQ_FAIL(err, SQ_ERR_LAYOUT,
                               "%s: a piece of it cuts nothing in face %d (dangling)",
                               who.c_str(), index);
            }
    }

    BRep_Builder bb;
    bb.MakeShell(s->shell);
    TopTools_IndexedMapOfShape fm;
    TopExp::MapShapes(result, TopAbs_FACE, fm);
    double total = 0;
    for (int i = 1; i <= fm.Extent(); ++i) {
        TopoDS_Face sf = TopoDS::Face(fm(i));
        s->faces.push_back(sf);
        bb.Add(s->shell, sf);
        double a = face_area(sf, fr, s->size);
        s->area.push_back(a);
        total += a;
    }
    if (s->faces.empty()) return SQ_FAIL(err, SQ_ERR_INTERNAL, "face %d: split gave no face", index);
    if (!(std::fabs(total - s->face_area) <= 1e-8 * s->face_area))
        return SQ_FAIL(err, SQ_ERR_INTERNAL,
                       "face %d: the %d sub-faces' areas add up to %.17g, not the face's %.17g",
                       index, (int)s->faces.size(), total, s->face_area);
    *out = s.release();
    return SQ_OK;
}

// Corners of sub-face i: points where the turning angle exceeds tol (radians).
int corners(const cad_split *s, int i, double tol, double *xy, int max)
{
    const TopoDS_Face &face = s->faces[(size_t)i];
    int n = 0;
    for (TopoDS_Iterator wi(face); wi.More(); wi.Next()) {
        if (wi.Value().ShapeType() != TopAbs_WIRE) continue;
        const TopoDS_Wire &w = TopoDS::Wire(wi.Value());
        struct Piece {
            double t0[2], t1[2], p0[2];
        };
        std::vector<Piece> pcs;
        for (BRepTools_WireExplorer wx(w, face); wx.More(); wx.Next()) {
            const TopoDS_Edge &e = wx.Current();
            TopAbs_Orientation o = wx.Orientation();
            if (o != TopAbs_FORWARD && o != TopAbs_REVERSED) continue;
            if (BRep_Tool::Degenerated(e)) continue;
            BRepAdaptor_Curve c(TopoDS::Edge(e.Oriented(TopAbs_FORWARD)));
            bool rev = o == TopAbs_REVERSED;
            Piece p;
            edge_tangent(c, rev, false, s->frame, p.t0);
            edge_tangent(c, rev, true, s->frame, p.t1);
            s->frame.to2d(c.Value(rev ? c.LastParameter() : c.FirstParameter()), p.p0);
            pcs.push_back(p);
        }
        for (size_t k = 0; k < pcs.size(); ++k) {
            const Piece &a = pcs[k], &b = pcs[(k + 1) % pcs.size()];
            double cr = a.t1[0] * b.t0[1] - a.t1[1] * b.t0[0];
            double dt = a.t1[0] * b.t0[0] + a.t1[1] * b.t0[1];
            if (std::atan2(std::fabs(cr), dt) > tol) {
                if (xy && n < max) xy[2 * n] = b.p0[0], xy[2 * n + 1] = b.p0[1];
                ++n;
            }
        }
    }
    return n;
}

sq_status write_step(const cad_split *s, const char *path, sq_error *err)
{
    static std::atomic<unsigned> counter(0);
    char tmp[4096];
    int len = std::snprintf(tmp, sizeof tmp, "%s.tmp-%ld-%u", path, (long)getpid(),
                            counter.fetch_add(1));
    if (len < 0 || len >= (int)sizeof tmp)
        return SQ_FAIL(err, SQ_ERR_OUTPUT, "%s: file name too long", path);
    int fd = open(tmp, O_WRONLY | O_CREAT | O_EXCL, 0666);
    if (fd < 0) return SQ_FAIL(err, SQ_ERR_OUTPUT, "%s: cannot write: %s", path, std::strerror(errno));
    close(fd);
    struct Unlink {
        const char *p;
        bool keep = false;
        ~Unlink()
        {
            if (!keep) unlink(p);
        }
    } guard{tmp};

    double mm = 1;
    const char *uname = step_unit_name(s->unit, &mm);
    IFSelect_ReturnStatus ts, ws;
    {
        Quiet quiet;
        STEPControl_Writer writer; // initialises the STEP statics
        Handle(StepData_StepModel) model = writer.Model();
        // Global settings, restored on leaving: the unit entity written; no
        // pcurves (the edges' 2D curves on the faces' planes, which a reader
        // gets exactly by projection; they were two thirds of the file); and
        // the length unit of the shapes in memory (the file's own unit: no
        // scaling).
        StaticText unit_static("write.step.unit", uname);
        StaticInt pcurve_static("write.surfacecurve.mode", 0);
        struct LocalUnit {
            Handle(StepData_StepModel) m;
            double saved;
            ~LocalUnit() { m->SetLocalLengthUnit(saved); }
        } local_unit{model, model->LocalLengthUnit()};
        model->SetLocalLengthUnit(mm);
        model->SetWriteLengthUnit(mm);
        ts = writer.Transfer(s->shell, STEPControl_AsIs);
        ws = ts == IFSelect_RetDone ? writer.Write(tmp) : IFSelect_RetVoid;
    }
    if (ts != IFSelect_RetDone)
        return SQ_FAIL(err, SQ_ERR_OUTPUT, "%s: the sub-faces could not be translated to STEP", path);
    if (ws != IFSelect_RetDone)
        return SQ_FAIL(err, SQ_ERR_OUTPUT, "%s: cannot write the STEP file", path);
    struct stat st;
    if (stat(tmp, &st) != 0 || st.st_size == 0)
        return SQ_FAIL(err, SQ_ERR_OUTPUT, "%s: cannot write the STEP file", path);
    if (std::rename(tmp, path) != 0)
        return SQ_FAIL(err, SQ_ERR_OUTPUT, "%s: cannot write: %s", path, std::strerror(errno));
    guard.keep = true;
    return SQ_OK;
}

} // namespace

extern "C" {

sq_status cad_face_split(const cad_model *model, int face_index, const cad_face *face,
                         int ncurves, const int *npts, const double *const *xy, cad_split **out,
                         sq_error *err)
{
    if (!out) return SQ_FAIL(err, SQ_ERR_USAGE, "cad_face_split: out is NULL");
    *out = NULL;
    if (!model) return SQ_FAIL(err, SQ_ERR_USAGE, "cad_face_split: model is NULL");
    try {
        return split(model, face_index, face, ncurves, npts, xy, out, err);
    }
    catch (const Standard_Failure &e) {
        return SQ_FAIL(err, SQ_ERR_INTERNAL, "face %d: split: OpenCASCADE %s: %s", face_index,
                       e.DynamicType()->Name(), e.GetMessageString() ? e.GetMessageString() : "");
    }
    SQCAD_CATCH_REST(err)
}

void cad_split_free(cad_split **s)
{
    if (!s || !*s) return;
    try {
        delete *s;
    } catch (...) {
    }
    *s = NULL;
}

int cad_split_num_faces(const cad_split *s) { return s ? (int)s->faces.size() : 0; }

double cad_split_face_area(const cad_split *s, int i)
{
    if (!s || i < 0 || i >= (int)s->faces.size()) return 0;
    return s->area[(size_t)i];
}

double cad_split_total_area(const cad_split *s) { return s ? s->face_area : 0; }

int cad_split_face_corners(const cad_split *s, int i, double tol_deg, double *xy, int max)
{
    if (!s || i < 0 || i >= (int)s->faces.size()) return -1;
    try {
        return corners(s, i, tol_deg * M_PI / 180.0, xy, max);
    } catch (...) {
        return -1;
    }
}

int cad_split_face_num_corners(const cad_split *s, int i, double tol_deg)
{
    return cad_split_face_corners(s, i, tol_deg, NULL, 0);
}

int cad_split_locate(const cad_split *s, const double xy[2])
{
    if (!s || !xy) return -1;
    try {
        gp_Pnt P = s->frame.to3d(xy);
        int on = -1;
        for (size_t i = 0; i < s->faces.size(); ++i) {
            BRepClass_FaceClassifier cls(s->faces[i], P, s->tol);
            if (cls.State() == TopAbs_IN) return (int)i;
            if (cls.State() == TopAbs_ON && on < 0) on = (int)i;
        }
        return on;
    } catch (...) {
        return -1;
    }
}

sq_status cad_split_write_step(const cad_split *s, const char *path, sq_error *err)
{
    if (!s) return SQ_FAIL(err, SQ_ERR_USAGE, "cad_split_write_step: split is NULL");
    if (!path || !*path) return SQ_FAIL(err, SQ_ERR_USAGE, "cad_split_write_step: no file name");
    try {
        return write_step(s, path, err);
    }
    catch (const Standard_Failure &e) {
        return SQ_FAIL(err, SQ_ERR_OUTPUT, "%s: STEP export: OpenCASCADE %s: %s", path,
                       e.DynamicType()->Name(), e.GetMessageString() ? e.GetMessageString() : "");
    }
    SQCAD_CATCH_REST(err)
}

} // extern "C"
