#!/usr/bin/python3
"""t636: names read from the STEP file (docs/formats.md, "Named
boundaries"): the names of its EDGE_CURVE and ADVANCED_FACE items become
the boundary groups' names, listed by `semquad info`, written as MSH
physical names (read back by Gmsh's reader) and Nektar++ composite names;
`--names` overrides them.  The named files are made here: a rectangle
[0,2]x[0,1] and three rectangles in a row (tests/domain_faces.py
three_row) written by Gmsh's OCC kernel, then each EDGE_CURVE named after
where it lies (bottom_N, top_N, left, right, interface_N, with one name
holding a space and one 'NONE', the exporters' "no name") and each face
'plate_N'.  Asserted:

  - `semquad info` prints each edge's and face's name;
  - every line element of the physical group named X lies on the edges
    named X (all its nodes on that straight side, to 1e-12 of the size:
    the nodes of a straight side are exact up to the resampling's
    round-off), and every boundary line is in a group named after its edge;
    'left wall' arrives as 'left_wall', the 'NONE' edge as boundary_<t>;
  - in the three-face domain the interfaces are no group (they are no
    boundary), the boundary curves keep their file names;
  - `--names` with `0 inlet` renames edge 0 and leaves the others' file names;
  - the Nektar++ XML carries the names as composite NAMEs;
  - in the three-face domain each face is a surface group named as the
    file names the face (plate_N), in the MSH and the Nektar++ XML, and in
    the VTU (read by VTK's reader) the field data name each cell's face;
    `--names` lines `face N NAME` and `face X Y NAME` rename faces (a name
    another face has gets _N), and are refused (exit 2, one line, no file)
    for a face not meshed, a point in no face, and a mesh of one face.
usage: t636-step-names.py SEMQUAD DOMAIN_FACES_PY"""
import math
import os
import re
import subprocess
import sys
import tempfile

try:
    import gmsh
    import vtk
except ImportError:
    sys.exit(77)

SQ, GEN = sys.argv[1:3]
fails = []


def side_name(a, b, x_max):
    """The name of the straight edge from a to b of rectangles in [0, x_max] x [0, 1]."""
    mx, my = (a[0] + b[0]) / 2, (a[1] + b[1]) / 2
    if abs(a[1] - b[1]) < 1e-12:  # numbered by its rectangle: left ends 0, 1, 2.5
        return ("bottom_%d" if my < 0.5 else "top_%d") % int(min(a[0], b[0]))
    if abs(mx) < 1e-12:
        return "left wall"
    if abs(mx - x_max) < 1e-12:
        return "NONE"
    return "interface_%d" % int(mx)


def name_step(src, dst, x_max):
    """Copy src naming its edges after their place and its faces plate_N;
    {name as semquad takes it: [its segments]}."""
    s = open(src).read()
    pts = {m.group(1): tuple(float(v) for v in m.group(2).split(","))
           for m in re.finditer(r"#(\d+) = CARTESIAN_POINT\('[^']*',\(([^)]*)\)\)", s)}
    vp = {m.group(1): pts[m.group(2)] for m in re.finditer(r"#(\d+) = VERTEX_POINT\('[^']*',#(\d+)\)", s)}
    segs = {}

    def edge(m):
        a, b = vp[m.group(1)], vp[m.group(2)]
        name = side_name(a, b, x_max)
        segs.setdefault(name.replace(" ", "_"), []).append((a, b))
        return "EDGE_CURVE('%s',#%s,#%s" % (name, m.group(1), m.group(2))
    s = re.sub(r"EDGE_CURVE\('[^']*',#(\d+),#(\d+)", edge, s)
    count = iter(range(100))
    s = re.sub(r"ADVANCED_FACE\('[^']*'", lambda m: "ADVANCED_FACE('plate_%d'" % next(count), s)
    open(dst, "w").write(s)
    return segs


def groups(msh, dim=1):
    """{name: [its elements' node coordinates]} of the physical groups of
    dimension dim (1: the curves, 2: the surfaces)."""
    gmsh.clear()
    gmsh.open(msh)
    out = {}
    for _, tag in gmsh.model.getPhysicalGroups(dim):
        name = gmsh.model.getPhysicalName(dim, tag)
        for ent in gmsh.model.getEntitiesForPhysicalGroup(dim, tag):
            for _, _, en in zip(*gmsh.model.mesh.getElements(dim, ent)):
                for n in en:
                    out.setdefault(name, []).append(tuple(gmsh.model.mesh.getNode(int(n))[0][:2]))
    return out


def distance(p, seg):
    (ax, ay), (bx, by) = seg[0][:2], seg[1][:2]
    dx, dy = bx - ax, by - ay
    t = max(0.0, min(1.0, ((p[0] - ax) * dx + (p[1] - ay) * dy) / (dx * dx + dy * dy)))
    return math.hypot(ax + t * dx - p[0], ay + t * dy - p[1])


def run(args):
    return subprocess.run([SQ] + args, capture_output=True, text=True)


def check(label, step, segs, x_max, nbottom, tmp):
    info = run(["info", step])
    for want in ['"left_wall"', '"plate_0"'] + ['"bottom_%d"' % k for k in range(nbottom)]:
        if want not in info.stdout:
            fails.append("%s: info does not list %s" % (label, want))
    msh = os.path.join(tmp, label + ".msh")
    r = run(["mesh", step, "--order", "3", "--size", "0.25", "-o", msh, "-q"])
    if r.returncode:
        fails.append("%s: exit %d: %s" % (label, r.returncode, r.stderr.strip()))
        return
    g = groups(msh)
    names = sorted(g)
    print("%s: groups %s" % (label, names))
    want = sorted(["left_wall"] + ["bottom_%d" % k for k in range(nbottom)] +
                  ["top_%d" % k for k in range(nbottom)])
    named = [n for n in names if not n.startswith("boundary_")]
    if sorted(named) != want:
        fails.append("%s: named groups %s, expected %s" % (label, named, want))
    if len(names) != len(named) + 1:  # the NONE edge: boundary_<t>, and nothing else unnamed
        fails.append("%s: unnamed groups %s" % (label, [n for n in names if n not in named]))
    for name in named:
        far = max(min(distance(p, sg) for sg in segs[name]) for p in g[name])
        if far > 1e-12 * x_max:
            fails.append("%s: group %s holds a node %.3g off its edges" % (label, name, far))
    if nbottom > 1:  # a domain: each face's group named as the file names the face
        s = {name: (min(p[0] for p in ps), max(p[0] for p in ps))
             for name, ps in groups(msh, 2).items()}  # each face's x range
        print("%s: surface groups %s" % (label, s))
        plates = ["plate_%d" % k for k in range(nbottom)]
        if sorted(s) != plates:
            fails.append("%s: surface groups %s, expected %s" % (label, sorted(s), plates))
        # each group is one face of the row ([0,1], [1,2.5], [2.5,3] in x,
        # domain_faces.py): its nodes' x range that face's, to the
        # resampling's round-off (1e-12 of the size)
        spans = sorted(s.values())
        faces = [(0.0, 1.0), (1.0, 2.5), (2.5, 3.0)]
        if len(spans) != len(faces) or any(abs(a - c) > 1e-12 * x_max or abs(b - d) > 1e-12 * x_max
                                           for (a, b), (c, d) in zip(spans, faces)):
            fails.append("%s: surface groups span %s, not one face each" % (label, s))
    # --names over the file's: edge 0 renamed, the others keep theirs
    names_file = os.path.join(tmp, label + ".names")
    open(names_file, "w").write("0 inlet\n")
    r = run(["mesh", step, "--order", "3", "--size", "0.25", "-o", msh, "-q", "--names", names_file])
    if r.returncode == 0:
        g2 = sorted(groups(msh))
        if "inlet" not in g2 or len(g2) != len(names):
            fails.append("%s: with --names '0 inlet': groups %s" % (label, g2))
    else:
        fails.append("%s: --names: exit %d: %s" % (label, r.returncode, r.stderr.strip()))
    xml = os.path.join(tmp, label + ".xml")
    r = run(["mesh", step, "--order", "3", "--size", "0.25", "-o", xml, "-q"])
    if r.returncode or 'NAME="left_wall"' not in open(xml).read():
        fails.append("%s: Nektar++ XML without the composite NAME left_wall" % label)
    if nbottom > 1:
        text = open(xml).read()
        for name in plates:
            if 'NAME="%s"> Q[' % name not in text:
                fails.append("%s: Nektar++ XML without the face composite NAME %s" % (label, name))
        check_vtu(label, step, faces, x_max, tmp)
        check_face_names(label, step, tmp)


def check_face_names(label, step, tmp):
    """--names 'face' lines over the file's face names: by number, by a
    point inside, a name another face has (gets _<face number>); refused
    for one face (exit 2, no file) and for a face that is not meshed."""
    names_file = os.path.join(tmp, label + ".faces")
    open(names_file, "w").write("face 1 solid\nface 2.8 0.5 outlet_block\nface 0 solid\n")
    msh = os.path.join(tmp, label + "_faces.msh")
    r = run(["mesh", step, "--order", "2", "--size", "0.25", "-o", msh, "-q", "--names", names_file])
    if r.returncode:
        fails.append("%s: face names: exit %d: %s" % (label, r.returncode, r.stderr.strip()))
        return
    s = {name: min(p[0] for p in ps) for name, ps in groups(msh, 2).items()}
    print("%s: surface groups with face names %s" % (label, sorted(s)))
    want = {"solid_0": 0.0, "solid": 1.0, "outlet_block": 2.5}  # each face's least x
    if sorted(s) != sorted(want) or any(abs(s[n] - want[n]) > 1e-12 * 3.0 for n in want):
        fails.append("%s: face names give surface groups %s, expected %s" % (label, s, want))
    for lines, why in (("face 7 x\n", "a face not meshed"), ("face 9 9 x\n", "a point in no face")):
        open(names_file, "w").write(lines)
        bad = os.path.join(tmp, label + "_bad.msh")
        r = run(["mesh", step, "--order", "2", "--size", "0.25", "-o", bad, "-q", "--names", names_file])
        if r.returncode != 2 or os.path.exists(bad) or len(r.stderr.strip().splitlines()) != 1:
            fails.append("%s: face names of %s: exit %d, file %s, stderr %r" % (
                label, why, r.returncode, os.path.exists(bad), r.stderr))
    r = run(["mesh", step, "--face", "0", "--order", "2", "-o", bad, "-q", "--names", names_file])
    if r.returncode != 2 or os.path.exists(bad):
        fails.append("%s: face names on one face: exit %d (expected 2), file %s" % (
            label, r.returncode, os.path.exists(bad)))


def check_vtu(label, step, faces, x_max, tmp):
    """The VTU read by VTK's own reader: every cell's `face` number named
    plate_k by the field data, and that face's cells inside its x range
    (to the resampling's round-off, 1e-12 of the size)."""
    vtu = os.path.join(tmp, label + ".vtu")
    r = run(["mesh", step, "--order", "3", "--size", "0.25", "-o", vtu, "-q"])
    if r.returncode:
        fails.append("%s: VTU: exit %d: %s" % (label, r.returncode, r.stderr.strip()))
        return
    rd = vtk.vtkXMLUnstructuredGridReader()
    rd.SetFileName(vtu)
    rd.Update()
    g = rd.GetOutput()
    fd = g.GetFieldData()
    names, numbers = fd.GetAbstractArray("face_name"), fd.GetArray("face_number")
    if names is None or numbers is None:
        fails.append("%s: VTU without face_name / face_number field data" % label)
        return
    name_of = {int(numbers.GetValue(i)): names.GetValue(i) for i in range(names.GetNumberOfValues())}
    print("%s: VTU face names %s" % (label, name_of))
    span = {}
    face = g.GetCellData().GetArray("face")
    for c in range(g.GetNumberOfCells()):
        name = name_of.get(int(face.GetValue(c)), "?")
        pts = g.GetCell(c).GetPoints()
        xs = [pts.GetPoint(k)[0] for k in range(pts.GetNumberOfPoints())]
        lo, hi = span.get(name, (math.inf, -math.inf))
        span[name] = (min(lo, min(xs)), max(hi, max(xs)))
    want = {"plate_%d" % k: f for k, f in enumerate(faces)}
    if sorted(span) != sorted(want) or any(
            abs(span[n][0] - want[n][0]) > 1e-12 * x_max or abs(span[n][1] - want[n][1]) > 1e-12 * x_max
            for n in want):
        fails.append("%s: VTU faces by name span %s, expected %s" % (label, span, want))


def main():
    gmsh.initialize(["-v", "0"])
    gmsh.option.setNumber("General.Terminal", 0)
    tmp = tempfile.mkdtemp()
    plain = os.path.join(tmp, "rect_plain.step")
    gmsh.model.occ.addRectangle(0, 0, 0, 2, 1)
    gmsh.model.occ.synchronize()
    gmsh.write(plain)
    rect = os.path.join(tmp, "rect.step")
    check("rectangle", rect, name_step(plain, rect, 2.0), 2.0, 1, tmp)
    plain = os.path.join(tmp, "three_plain.step")
    r = subprocess.run([sys.executable, GEN, "three_row", plain], capture_output=True, text=True)
    if r.returncode:
        sys.exit("domain_faces.py three_row: " + r.stderr)
    three = os.path.join(tmp, "three.step")
    check("three_row", three, name_step(plain, three, 3.0), 3.0, 3, tmp)
    gmsh.finalize()
    for f in fails:
        print("FAIL:", f)
    return 1 if fails else 0


if __name__ == "__main__":
    sys.exit(main())
