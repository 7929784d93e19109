// semquad cad/ — edges that faces of a 2D domain share (docs/domains.md).
//
// A file whose faces were fragmented or sewn holds one OCCT edge per shared
// curve (TopoDS_Shape::IsSame); a file of faces written apart holds two
// coincident edges.  Both are found by comparing points of the two edges in
// 3D at fixed fractions of their arc length, which also says whether the
// faces travel the curve in the same sense.
#include "cad_private.hxx"

#include <cmath>

namespace {

const double FRACTIONS[5] = {0.0, 0.25, 0.5, 0.75, 1.0};

// The 3D point of edge e of face f at arc length s.
sq_status point3d(const cad_face *f, int e, double s, double P[3], sq_error *err)
{
    double xy[2], O[3], X[3], Y[3];
    SQ_TRY(cad_face_edge_eval(f, e, s, xy, nullptr, nullptr, err));
    cad_face_frame(f, O, X, Y);
    for (int d = 0; d < 3; d++) P[d] = O[d] + xy[0] * X[d] + xy[1] * Y[d];
    return SQ_OK;
}

// Largest distance between the edges' points at the fractions, b's taken
// forwards (rev 0) or backwards (rev 1).
sq_status max_gap(const cad_face *a, int ea, const cad_face *b, int eb, int rev, double *gap,
                  sq_error *err)
{
    double La = cad_face_edge_length(a, ea), Lb = cad_face_edge_length(b, eb);
    *gap = 0.0;
    for (double f : FRACTIONS) {
        double P[3], R[3];
        SQ_TRY(point3d(a, ea, f * La, P, err));
        SQ_TRY(point3d(b, eb, (rev ? 1.0 - f : f) * Lb, R, err));
        *gap = std::fmax(*gap, std::hypot(P[0] - R[0], std::hypot(P[1] - R[1], P[2] - R[2])));
    }
    return SQ_OK;
}

} // namespace

sq_status cad_edges_shared(const cad_face *a, int ea, const cad_face *b, int eb, double tol,
                           cad_shared_kind *kind, int *reversed, sq_error *err)
{
    *kind = CAD_SHARED_NONE;
    *reversed = 0;
    try {
        const TopoDS_Edge *A = sqcad::face_edge(a, ea), *B = sqcad::face_edge(b, eb);
        if (!A || !B) return SQ_FAIL(err, SQ_ERR_USAGE, "edge %d or %d out of range", ea, eb);
        bool same = A->IsSame(*B);
        double La = cad_face_edge_length(a, ea), Lb = cad_face_edge_length(b, eb);
        if (!same && std::fabs(La - Lb) > tol) return SQ_OK;
        double fwd, bwd;
        SQ_TRY(max_gap(a, ea, b, eb, 0, &fwd, err));
        SQ_TRY(max_gap(a, ea, b, eb, 1, &bwd, err));
        *reversed = bwd < fwd;
        if (same) *kind = CAD_SHARED_SAME;
        else if (std::fmin(fwd, bwd) <= tol) *kind = CAD_SHARED_COINCIDENT;
        return SQ_OK;
    }
    SQCAD_CATCH(err)
}
