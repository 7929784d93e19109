// semquad cad/ — private C++ declarations shared by the cad_*.cpp files.
// Never included from C.
#ifndef SQ_CAD_PRIVATE_HXX
#define SQ_CAD_PRIVATE_HXX

#include "cad.h"

#include <Standard_Failure.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Shape.hxx>
#include <gp_Pln.hxx>

#include <exception>
#include <new>
#include <string>
#include <vector>

struct cad_model {
    TopoDS_Shape shape;
    TopTools_IndexedMapOfShape faces; // 1-based inside OCCT
    std::string path;
    const char *unit = "unknown";
    std::vector<std::string> surface; // per face, type name
    std::vector<int> planar;          // per face, 1 if planar
    int default_face = 0;
    std::string note; // empty: no note
};

namespace sqcad {

// Name of the surface type of a face ("plane", ...).
const char *surface_name(const TopoDS_Face &face);

// True if the face lies in a plane; then *pln is that plane with its axis
// along the face's outward normal (the face orientation applied).
bool face_plane(const TopoDS_Face &face, gp_Pln *pln);

} // namespace sqcad

// Turn the exception being handled into an sq_status (use inside catch (...)).
#define SQCAD_CATCH(err)                                                                           \
    catch (const Standard_Failure &e_) {                                                           \
        return SQ_FAIL((err), SQ_ERR_INTERNAL, "OpenCASCADE: %s: %s", e_.DynamicType()->Name(),    \
                       e_.GetMessageString() ? e_.GetMessageString() : "");                        \
    }                                                                                              \
    SQCAD_CATCH_REST(err)

// The same without the Standard_Failure handler (write your own before it).
#define SQCAD_CATCH_REST(err)                                                                      \
    catch (const std::bad_alloc &) {                                                               \
        return SQ_FAIL((err), SQ_ERR_INTERNAL, "out of memory");                                   \
    }                                                                                              \
    catch (const std::exception &e_) {                                                             \
        return SQ_FAIL((err), SQ_ERR_INTERNAL, "%s", e_.what());                                   \
    }                                                                                              \
    catch (...) {                                                                                  \
        return SQ_FAIL((err), SQ_ERR_INTERNAL, "unknown C++ exception");                           \
    }

#endif
