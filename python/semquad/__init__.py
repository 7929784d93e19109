"""semquad: block-structured high-order quad meshes of planar CAD faces.

A thin ctypes layer over libsemquad's public C API (include/semquad.h); arrays
come out as numpy arrays, copied from the library's borrowed pointers::

    import semquad
    with semquad.open("examples/half_disc.step") as model:
        mesh = model.face().mesh(order=4, size=0.1)
        print(mesh.nodes.shape, mesh.elements.shape, mesh.report["quality"])
        mesh.write("half_disc.msh")

The library is found through $SEMQUAD_LIBRARY (a path to libsemquad.so), then
the build tree beside this package (build/src/libsemquad.so), then the system
(ctypes.util.find_library).  Every non-OK status raises semquad.Error.
"""
import ctypes
import ctypes.util
import json
import os
import weakref

__all__ = ["Error", "Model", "Face", "Mesh", "open", "version", "gmsh_order"]


class Error(Exception):
    """A semquad failure: .status is the C status (the `semquad` command's
    exit status: 1 internal, 2 usage, 3 input, 4 geometry, 5 pattern,
    6 layout, 7 output, 8 quality below the floor, 9 periodic edges that
    do not match), str() semquad's
    one-line message."""

    def __init__(self, status, message):
        super().__init__(message)
        self.status = status


class _Error(ctypes.Structure):
    _fields_ = [("code", ctypes.c_int), ("file", ctypes.c_char_p), ("line", ctypes.c_int),
                ("func", ctypes.c_char_p), ("msg", ctypes.c_char * 512)]


_LOG_FN = ctypes.CFUNCTYPE(None, ctypes.c_void_p, ctypes.c_int, ctypes.c_char_p)
_PROGRESS_FN = ctypes.CFUNCTYPE(None, ctypes.c_void_p, ctypes.c_char_p, ctypes.c_long,
                                ctypes.c_long)


class _Options(ctypes.Structure):
    """sq_options, field for field (semquad.h)."""
    _fields_ = [
        ("heal", ctypes.c_int), ("heal_tolerance", ctypes.c_double),
        ("tri_order", ctypes.c_int), ("tri_size", ctypes.c_double),
        ("tri_min_angle_deg", ctypes.c_double), ("tri_max_turn_deg", ctypes.c_double),
        ("field", ctypes.c_char_p), ("singularities", ctypes.c_char_p),
        ("method", ctypes.c_char_p), ("field_order", ctypes.c_int),
        ("field_grading", ctypes.c_int), ("allow_misaligned", ctypes.c_int),
        ("merge_distance", ctypes.c_double),
        ("road", ctypes.c_char_p), ("order", ctypes.c_int), ("size", ctypes.c_double),
        ("nsizes", ctypes.c_int), ("sizes", ctypes.c_void_p),
        ("nnames", ctypes.c_int), ("names", ctypes.c_void_p), ("periodic", ctypes.c_char_p),
        ("size_gradation", ctypes.c_double), ("curvature_elements", ctypes.c_double),
        ("nodes", ctypes.c_char_p), ("max_quads", ctypes.c_double),
        ("nbl", ctypes.c_int), ("bl_edges", ctypes.POINTER(ctypes.c_int)),
        ("bl_first", ctypes.c_double), ("bl_ratio", ctypes.c_double), ("bl_layers", ctypes.c_int),
        ("min_quality", ctypes.c_double),
        ("study_solution", ctypes.c_char_p), ("study_methods", ctypes.c_char_p),
        ("study_pmin", ctypes.c_int), ("study_pmax", ctypes.c_int),
        ("study_nsizes", ctypes.c_int), ("study_sizes", ctypes.POINTER(ctypes.c_double)),
        ("study_geom_order", ctypes.c_int),
        ("log", _LOG_FN), ("log_data", ctypes.c_void_p),
        ("progress", _PROGRESS_FN), ("progress_data", ctypes.c_void_p),
        ("threads", ctypes.c_int), ("relax_max_quads", ctypes.c_double),
        ("nface_names", ctypes.c_int), ("face_names", ctypes.c_void_p)]


def _find_library():
    env = os.environ.get("SEMQUAD_LIBRARY")
    if env:
        return env
    here = os.path.dirname(os.path.abspath(__file__))
    built = os.path.join(here, "..", "..", "build", "src", "libsemquad.so")
    if os.path.exists(built):
        return built
    found = ctypes.util.find_library("semquad")
    if found:
        return found
    raise ImportError("semquad: libsemquad not found (set SEMQUAD_LIBRARY to libsemquad.so)")


def _load():
    lib = ctypes.CDLL(_find_library())
    P, I, D, S = ctypes.c_void_p, ctypes.c_int, ctypes.c_double, ctypes.c_char_p
    E = ctypes.POINTER(_Error)
    O = ctypes.POINTER(_Options)
    PP = ctypes.POINTER(ctypes.c_void_p)
    PS = ctypes.POINTER(ctypes.c_char_p)
    sigs = {
        "sq_version": (S, []), "sq_free": (None, [P]),
        "sq_options_init": (None, [O]), "sq_options_check": (I, [O, E]),
        "sq_model_open": (I, [S, O, PP, E]), "sq_model_free": (None, [PP]),
        "sq_model_num_faces": (I, [P]), "sq_model_default_face": (I, [P, PS]),
        "sq_model_unit": (S, [P]), "sq_model_heal_tolerance": (D, [P]),
        "sq_model_face_status": (S, [P, I, PS]), "sq_model_info": (I, [P, I, I, PP, E]),
        "sq_face_mesh": (I, [P, I, O, PP, E]), "sq_mesh_free": (None, [PP]),
        "sq_mesh_order": (I, [P]), "sq_mesh_road": (S, [P]), "sq_mesh_face": (I, [P]),
        "sq_mesh_num_nodes": (I, [P]), "sq_mesh_nodes": (ctypes.POINTER(D), [P]),
        "sq_mesh_frame": (None, [P, ctypes.POINTER(D), ctypes.POINTER(D), ctypes.POINTER(D)]),
        "sq_mesh_num_quads": (I, [P]), "sq_mesh_quads": (ctypes.POINTER(I), [P]),
        "sq_mesh_num_boundary_sides": (I, [P]),
        "sq_mesh_boundary_sides": (ctypes.POINTER(I), [P]), "sq_mesh_num_tags": (I, [P]),
        "sq_mesh_scaled_jacobians": (ctypes.POINTER(D), [P]),
        "sq_mesh_eta": (ctypes.POINTER(D), [P]),
        "sq_mesh_report": (I, [P, PP, E]), "sq_mesh_describe": (I, [P, PP, E]),
        "sq_mesh_write": (I, [P, S, E]), "sq_mesh_check_quality": (I, [P, O, E]),
        "sq_mesh_refine": (I, [P, I, I, O, PP, E]),
        "sq_face_field": (I, [P, I, O, PP, E]), "sq_field_free": (None, [PP]),
        "sq_field_num_singular_points": (I, [P]),
        "sq_field_singular_xy": (ctypes.POINTER(D), [P]),
        "sq_field_singular_valence": (ctypes.POINTER(I), [P]),
        "sq_face_layout": (I, [P, I, O, PP, E]), "sq_quad_layout_free": (None, [PP]),
        "sq_quad_layout_num_patches": (I, [P]),
    }
    for name, (res, args) in sigs.items():
        fn = getattr(lib, name)
        fn.restype, fn.argtypes = res, args
    return lib


# Before numpy: libsemquad links OpenBLAS's serial build by the sonames
# libblas.so.3 and libopenblas.so.0, and numpy, loaded first, would have
# those names taken by the threaded build (whose threads change round-off).
_lib = _load()

import numpy as np  # noqa: E402


def _loaded(soname):
    """A library this process has already loaded, or None."""
    try:
        return ctypes.CDLL(soname, mode=os.RTLD_NOLOAD | os.RTLD_LAZY)
    except OSError:
        return None


_gomp = _loaded("libgomp.so.1")  # CHOLMOD's OpenMP
# the OpenBLAS in use: the threaded one if numpy was imported before semquad
_openblas = _loaded("libopenblas.so.0")


def _serial(fn, *args):
    """fn(*args) on one thread, as the `semquad` command runs (main.c): no
    OpenMP parallel region (CHOLMOD's) started from this thread and one
    OpenBLAS thread.  Threads change the round-off of the solves, which the
    layout and relaxation carry on to the nodes (naca0012: 5e-8), and cost
    more than they save on small systems."""
    levels = _gomp.omp_get_max_active_levels() if _gomp else None
    threads = _openblas.openblas_get_num_threads() if _openblas else None
    if _gomp:
        _gomp.omp_set_max_active_levels(0)
    if _openblas:
        _openblas.openblas_set_num_threads(1)
    try:
        return fn(*args)
    finally:
        if _gomp:
            _gomp.omp_set_max_active_levels(levels)
        if _openblas:
            _openblas.openblas_set_num_threads(threads)


def version():
    """The linked library's "MAJOR.MINOR.PATCH"."""
    return _lib.sq_version().decode()


def _check(status, err):
    if status != 0:
        raise Error(status, err.msg.decode(errors="replace"))


def _take_text(ptr):
    """A library string handed over (char **): copied, then sq_free'd."""
    if not ptr.value:
        return None
    try:
        return ctypes.string_at(ptr.value).decode()
    finally:
        _lib.sq_free(ptr)


def _array(ptr, shape, dtype):
    """Copy of a borrowed C array (empty when the count is 0)."""
    n = int(np.prod(shape))
    if n == 0:
        return np.zeros(shape, dtype=dtype)
    return np.ctypeslib.as_array(ptr, shape=(n,)).astype(dtype, copy=True).reshape(shape)


def _enc(s):
    return None if s is None else os.fsencode(s) if isinstance(s, os.PathLike) else str(s).encode()


def _options(**kw):
    """sq_options from the defaults plus keywords (None: the default),
    checked by sq_options_check; the caller keeps the returned keep-alive
    list until the C call returns."""
    o = _Options()
    _lib.sq_options_init(ctypes.byref(o))
    types = dict(_Options._fields_)
    keep = []
    for key, value in kw.items():
        if value is None:
            continue
        if key == "bl_edges":
            arr = (ctypes.c_int * len(value))(*value)
            keep.append(arr)
            o.nbl, o.bl_edges = len(value), ctypes.cast(arr, ctypes.POINTER(ctypes.c_int))
        elif key == "log":
            cb = _LOG_FN(lambda _d, level, line: value(level, line.decode()))
            keep.append(cb)
            o.log = cb
        elif types[key] is ctypes.c_char_p:
            keep.append(_enc(value))
            setattr(o, key, keep[-1])
        else:
            try:
                setattr(o, key, int(value) if isinstance(value, bool) else value)
            except TypeError:
                raise Error(2, "%s expects a number, got %r" % (key, value)) from None
    err = _Error()
    _check(_lib.sq_options_check(ctypes.byref(o), ctypes.byref(err)), err)
    return o, keep


def open(path, heal=True, heal_tolerance=None):
    """Read a STEP, IGES or BREP file (by content), healing its planar faces
    within the file's own tolerance (or heal_tolerance, in the file's unit)
    unless heal is False.  Raises Error (status 3) if it cannot be read."""
    o, keep = _options(heal=bool(heal), heal_tolerance=heal_tolerance)
    h, err = ctypes.c_void_p(), _Error()
    _check(_lib.sq_model_open(_enc(path), ctypes.byref(o), ctypes.byref(h), ctypes.byref(err)),
           err)
    return Model(h, path)


class _Handle:
    """An owned C handle freed once (by its sq_*_free, named _free), by
    close(), `with` or garbage collection."""
    _free = None

    def __init__(self, h):
        self._h = h

    def close(self):
        h, self._h = getattr(self, "_h", None), None
        if h is not None and h.value and _lib is not None:  # _lib: None at exit
            getattr(_lib, self._free)(ctypes.byref(h))

    def __del__(self):
        self.close()

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()

    def _handle(self):
        if self._h is None:
            raise Error(2, "%s is closed" % type(self).__name__)
        return self._h


class Model(_Handle):
    """A CAD file as read (sq_model).  Its meshes borrow it: closing the
    model closes them first."""
    _free = "sq_model_free"

    def __init__(self, h, path):
        super().__init__(h)
        self.path = str(path)
        self._results = weakref.WeakSet()

    def close(self):
        for r in list(getattr(self, "_results", ())):
            r.close()
        super().close()

    @property
    def num_faces(self):
        return _lib.sq_model_num_faces(self._handle())

    @property
    def unit(self):
        """The file's length unit ("mm", "m", "inch", ...)."""
        return _lib.sq_model_unit(self._handle()).decode()

    @property
    def heal_tolerance(self):
        return _lib.sq_model_heal_tolerance(self._handle())

    @property
    def default_face(self):
        """The face meshed when none is named: the only planar one, or the largest."""
        return _lib.sq_model_default_face(self._handle(), None)

    def face_status(self, i):
        """("ok" | "healed" | "not planar" | "broken", reason or None)."""
        reason = ctypes.c_char_p()
        s = _lib.sq_model_face_status(self._handle(), i, ctypes.byref(reason))
        if s is None:
            raise Error(2, "face %d: %s has %d faces" % (i, self.path, self.num_faces))
        return s.decode(), reason.value.decode() if reason.value else None

    def info(self, face=-1, as_json=False):
        """What `semquad info` prints for every face (face < 0) or one:
        text, or the parsed JSON with as_json=True."""
        text, err = ctypes.c_void_p(), _Error()
        _check(_lib.sq_model_info(self._handle(), face, int(as_json), ctypes.byref(text),
                                  ctypes.byref(err)), err)
        s = _take_text(text)
        return json.loads(s) if as_json else s

    def face(self, i=None):
        """Face i (0..num_faces-1), or the default face."""
        if i is not None and not 0 <= i < self.num_faces:
            raise Error(2, "face %d: %s has %d faces" % (i, self.path, self.num_faces))
        return Face(self, self.default_face if i is None else i)


class Face:
    """One face of a Model; its stages make results that borrow the model."""

    def __init__(self, model, index):
        self.model, self.index = model, index

    def _run(self, fn, opts):
        o, keep = _options(**opts)
        h, err = ctypes.c_void_p(), _Error()
        st = _serial(fn, self.model._handle(), self.index, ctypes.byref(o), ctypes.byref(h),
                     ctypes.byref(err))
        del keep
        return st, h, err

    def mesh(self, order=4, size=None, road="auto", field="auto", singularities=None,
             nodes="gll", max_quads=None, field_order=None, method=None, merge_distance=None,
             allow_misaligned=False, bl_edges=None, bl_first=None, bl_ratio=None,
             bl_layers=None, curvature=None, log=None):
        """High-order quad mesh of order `order` (1..10), quads of about
        `size` (None: sqrt(area)/8, halved while curved quads fold), by
        `road` ("auto", "layout", "split"), field "auto" or "htheta" (with
        `singularities`: "natural" or a pattern file), nodes "gll" or
        "equispaced"; boundary layers on CAD edges `bl_edges` (bl_first,
        bl_ratio, bl_layers); `curvature` elements per radian of the CAD
        curves' turning (docs/sizes.md).  log(level, line) receives progress lines
        (level 0 info, 1 note, 2 warning).  Options as `semquad mesh`
        (semquad help); a bad value raises Error with status 2."""
        st, h, err = self._run(_lib.sq_face_mesh, dict(
            order=order, size=size, road=road, field=field, singularities=singularities,
            nodes=nodes, max_quads=max_quads, field_order=field_order, method=method,
            merge_distance=merge_distance, allow_misaligned=bool(allow_misaligned),
            bl_edges=bl_edges, bl_first=bl_first, bl_ratio=bl_ratio, bl_layers=bl_layers,
            curvature_elements=curvature, log=log))
        _check(st, err)
        return Mesh(h, self.model)

    def field(self, field="auto", singularities=None, order=None, method=None):
        """The guiding (or H/θ) field's singular points: (xy (n,2) float64
        in the face's frame, valence (n,) int)."""
        st, h, err = self._run(_lib.sq_face_field, dict(
            field=field, singularities=singularities, field_order=order, method=method))
        _check(st, err)
        try:
            n = _lib.sq_field_num_singular_points(h)
            return (_array(_lib.sq_field_singular_xy(h), (n, 2), np.float64),
                    _array(_lib.sq_field_singular_valence(h), (n,), np.int64))
        finally:
            _lib.sq_field_free(ctypes.byref(h))

    def layout(self, order=None, method=None, singularities=None, merge_distance=None):
        """Number of quad patches of the face's layout (Error status 6 if none)."""
        st, h, err = self._run(_lib.sq_face_layout, dict(
            field_order=order, method=method, singularities=singularities,
            merge_distance=merge_distance))
        try:
            _check(st, err)
            return _lib.sq_quad_layout_num_patches(h)
        finally:
            _lib.sq_quad_layout_free(ctypes.byref(h))


def gmsh_order(order):
    """Lattice index (Q+1) j + i of each node of a quad in Gmsh's order
    (corners, sides counter-clockwise, interior recursively): the MSH
    writer's and meshio's quadN ordering."""
    ij = []

    def rec(q, off):
        if q < 0:
            return
        if q == 0:
            ij.append((off, off))
            return
        c = [(0, 0), (q, 0), (q, q), (0, q)]
        ij.extend((off + a, off + b) for a, b in c)
        for e in range(4):
            (a0, a1), (b0, b1) = c[e], c[(e + 1) % 4]
            ij.extend((off + a0 + s * (b0 - a0) // q, off + a1 + s * (b1 - a1) // q)
                      for s in range(1, q))
        rec(q - 2, off + 1)

    rec(order, 0)
    return np.array([(order + 1) * j + i for i, j in ij], dtype=np.int64)


class Mesh(_Handle):
    """A high-order quad mesh (sq_mesh).  Arrays (copies):
    nodes (n,3) float64 in the face's frame (z = 0; see frame);
    elements (nq,(Q+1)^2) int64, node (i,j) of quad q at column (Q+1) j + i,
    corners (0,0), (Q,0), (Q,Q), (0,Q) counter-clockwise;
    boundary (nb,3) int64 rows (quad, local side 0..3, CAD edge tag);
    scaled_jacobian and eta (nq,) float64.  order, road ("layout" or
    "split"), face, num_tags; report (dict) and describe() as the command
    prints them; write(path) to .msh, .xml, .vtu or .svg."""
    _free = "sq_mesh_free"

    def __init__(self, h, model):
        super().__init__(h)
        self.model = model
        model._results.add(self)
        Q = _lib.sq_mesh_order(h)
        nn, nq = _lib.sq_mesh_num_nodes(h), _lib.sq_mesh_num_quads(h)
        nb = _lib.sq_mesh_num_boundary_sides(h)
        self.order, self.road = Q, _lib.sq_mesh_road(h).decode()
        self.face, self.num_tags = _lib.sq_mesh_face(h), _lib.sq_mesh_num_tags(h)
        self.nodes = _array(_lib.sq_mesh_nodes(h), (nn, 3), np.float64)
        self.elements = _array(_lib.sq_mesh_quads(h), (nq, (Q + 1) ** 2), np.int64)
        self.boundary = _array(_lib.sq_mesh_boundary_sides(h), (nb, 3), np.int64)
        self.scaled_jacobian = _array(_lib.sq_mesh_scaled_jacobians(h), (nq,), np.float64)
        self.eta = _array(_lib.sq_mesh_eta(h), (nq,), np.float64)
        f = [(ctypes.c_double * 3)() for _ in range(3)]
        _lib.sq_mesh_frame(h, *f)
        self.frame = tuple(np.array(v[:]) for v in f)

    def _text(self, fn):
        text, err = ctypes.c_void_p(), _Error()
        _check(fn(self._handle(), ctypes.byref(text), ctypes.byref(err)), err)
        return _take_text(text)

    @property
    def report(self):
        """The JSON report (docs/formats.md) as a dict; timings as of now."""
        return json.loads(self._text(_lib.sq_mesh_report))

    def describe(self):
        """The command's one-line summary ("320 quads, order 4, ...")."""
        return self._text(_lib.sq_mesh_describe).rstrip("\n")

    def check_quality(self, min_quality=None):
        """Raise Error with status 8 (naming the worst quad and what made
        it) if the worst scaled Jacobian is below min_quality (None: the
        library's default floor; 0: none), as `semquad mesh --min-quality`
        does after writing its outputs."""
        o, keep = _options(min_quality=min_quality)
        err = _Error()
        _check(_lib.sq_mesh_check_quality(self._handle(), ctypes.byref(o), ctypes.byref(err)), err)
        del keep

    def refine(self, levels=1, order=None, max_quads=None):
        """A mesh of this one's block layout for a convergence study
        (docs/convergence-families.md): every quad split 2 x 2, `levels`
        times (0: the same quads), at `order` (None: this mesh's).  Nested:
        this mesh's vertices are nodes of the new one, bit for bit.  More
        quads than max_quads (None: 2e7) raises Error with status 2."""
        o, keep = _options(max_quads=max_quads)
        h, err = ctypes.c_void_p(), _Error()
        st = _serial(_lib.sq_mesh_refine, self._handle(), int(levels), int(order or 0),
                     ctypes.byref(o), ctypes.byref(h), ctypes.byref(err))
        del keep
        _check(st, err)
        return Mesh(h, self.model)

    def write(self, path):
        """Write .msh (Gmsh MSH 4.1, equispaced nodes), .xml (Nektar++),
        .vtu or .svg; nothing is left at path on failure."""
        err = _Error()
        _check(_serial(_lib.sq_mesh_write, self._handle(), _enc(path), ctypes.byref(err)), err)

    def to_meshio(self):
        """A meshio.Mesh: cells "quad" (order 1), "quad9" (2), "quad16",
        "quad25", ... "quad121" (10), nodes in Gmsh's order (gmsh_order),
        cell data "scaled_jacobian" and "eta".  These cell types interpolate
        equispaced nodes: mesh with nodes="equispaced" for files that other
        codes read as Lagrange elements."""
        try:
            import meshio
        except ImportError:
            raise ImportError("to_meshio needs meshio (Debian: apt-get install python3-meshio)")
        npe = (self.order + 1) ** 2
        kind = "quad" if self.order == 1 else "quad%d" % npe
        cells = self.elements[:, gmsh_order(self.order)]
        return meshio.Mesh(self.nodes, [(kind, cells)],
                           cell_data={"scaled_jacobian": [self.scaled_jacobian],
                                      "eta": [self.eta]})
