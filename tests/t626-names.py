#!/usr/bin/python3
"""t626: named boundaries (docs/formats.md, "Named boundaries"): `semquad
mesh --names FILE`.  A 2 x 1 rectangle built here with Gmsh's OCC kernel
(edges 0 bottom, 1 right, 2 top, 3 left, as `semquad info` numbers them),
its edges named inlet (left), outlet (right), wall (bottom and top), once by
edge index and once by points near them, meshed at order 4:

  - both files are the same bytes;
  - read back with Gmsh's reader: the physical names inlet, outlet, wall and
    domain exist, wall's group holds 2 curves, and the lengths of each
    group's line elements sum to its edges' lengths (1, 1, 4) to 1e-12
    relative: the edges are straight, so each element is a straight segment
    whose end nodes lie on the edge; the sum telescopes, and only round-off
    in the node coordinates (1e-16 each) remains;
  - the report's "groups" lists the three with their edges;
  - the Nektar++ XML has one composite per group, NAME="wall" etc. (the
    attribute Nektar++'s MeshGraphIOXml::ReadComposites reads), holding as
    many edges as the MSH group has line elements;
  - bad inputs: an unreadable file exits 3, a malformed line 2 naming
    file:line, an unknown edge 2, a point far from the boundary 2, a bad
    name 2, and none writes the mesh;
  - without --names the file is the same bytes as before this option (the
    generic boundary_N groups).
usage: t626-names.py SEMQUAD"""
import json
import math
import os
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET

try:
    import gmsh
except ImportError:
    sys.exit(77)

SQ = sys.argv[1]
fails = []


def run(args):
    return subprocess.run([SQ, "mesh"] + args + ["-q"], capture_output=True, text=True)


def composites(xml):
    """NAME -> number of edges of each named composite."""
    out = {}
    for c in ET.parse(xml).getroot().iter("C"):
        if "NAME" not in c.attrib:
            continue
        n = 0
        for part in c.text.strip()[2:-1].split(","):
            a, _, b = part.partition("-")
            n += int(b or a) - int(a) + 1
        out[c.attrib["NAME"]] = n
    return out


def groups(msh):
    gmsh.open(msh)
    out = {}
    for dim, tag in gmsh.model.getPhysicalGroups(1):
        name = gmsh.model.getPhysicalName(dim, tag)
        curves = gmsh.model.getEntitiesForPhysicalGroup(dim, tag)
        length, nel = 0.0, 0
        for c in curves:
            _, tags, nodes = gmsh.model.mesh.getElements(1, c)
            nel += len(tags[0])
            for k in range(0, len(nodes[0]), len(nodes[0]) // len(tags[0])):
                a = gmsh.model.mesh.getNode(nodes[0][k])[0]
                b = gmsh.model.mesh.getNode(nodes[0][k + 1])[0]
                length += math.hypot(b[0] - a[0], b[1] - a[1])
        out[name] = (len(curves), length, nel)
    names2 = [gmsh.model.getPhysicalName(2, t) for _, t in gmsh.model.getPhysicalGroups(2)]
    return out, names2


gmsh.initialize()
gmsh.option.setNumber("General.Terminal", 0)
with tempfile.TemporaryDirectory() as tmp:
    step = os.path.join(tmp, "rect.step")
    gmsh.model.occ.addRectangle(0, 0, 0, 2, 1)
    gmsh.model.occ.synchronize()
    gmsh.write(step)
    gmsh.clear()
    files = {"index": "# by edge index\n3 inlet\n1 outlet\n\n0 wall\n2 wall\n",
             "point": "0 0.5 inlet\n2.0 0.52 outlet  # right\n1 0 wall\n1 1.01 wall\n"}
    mshs = {}
    for kind, text in files.items():
        nf, msh = os.path.join(tmp, kind + ".txt"), os.path.join(tmp, kind + ".msh")
        open(nf, "w").write(text)
        rep = os.path.join(tmp, kind + ".json")
        r = run([step, "--order", "4", "--names", nf, "-o", msh, "--report", rep])
        if r.returncode != 0:
            fails.append("%s: exit %d: %s" % (kind, r.returncode, r.stderr.strip()))
            continue
        mshs[kind] = open(msh, "rb").read()
        g, surf = groups(msh)
        expect = {"inlet": (1, 1.0), "outlet": (1, 1.0), "wall": (2, 4.0)}
        if set(g) != set(expect) or surf != ["domain"]:
            fails.append("%s: groups %s, surfaces %s" % (kind, sorted(g), surf))
            continue
        for name, (nc, length) in expect.items():
            if g[name][0] != nc or abs(g[name][1] - length) > 1e-12 * length:
                fails.append("%s: %s has %d curves of length %.17g, expected %d, %g"
                             % (kind, name, g[name][0], g[name][1], nc, length))
        xml = os.path.join(tmp, kind + ".xml")
        r = run([step, "--order", "4", "--names", nf, "-o", xml])
        comp = composites(xml) if r.returncode == 0 else {}
        if comp != {name: g[name][2] for name in expect}:
            fails.append("%s: Nektar++ composites %s, MSH groups %s" % (kind, comp, g))
        rg = {x["name"]: x["edges"] for x in json.load(open(rep))["groups"]}
        if rg != {"wall": [0, 2], "outlet": [1], "inlet": [3]}:
            fails.append("%s: report groups %s" % (kind, rg))
    if len(mshs) == 2 and mshs["index"] != mshs["point"]:
        fails.append("names by index and by point give different files")

    bad = {"3 inlet\n0 a b c\n": (2, "bad.txt:2"), "9 inlet\n": (2, "edge 9"),
           "5 5 far\n": (2, "far"), "0 w@ll\n": (2, "w@ll"), "x y z\n": (2, "bad.txt:1")}
    for text, (code, needle) in bad.items():
        nf, out = os.path.join(tmp, "bad.txt"), os.path.join(tmp, "bad.msh")
        open(nf, "w").write(text)
        r = run([step, "--names", nf, "-o", out])
        if r.returncode != code or needle not in r.stderr or os.path.exists(out):
            fails.append("%r: exit %d (expected %d), stderr %r, output written %s"
                         % (text, r.returncode, code, r.stderr.strip(), os.path.exists(out)))
    r = run([step, "--names", os.path.join(tmp, "missing.txt"), "-o", os.path.join(tmp, "m.msh")])
    if r.returncode != 3 or len(r.stderr.strip().splitlines()) != 1:
        fails.append("missing file: exit %d, stderr %r" % (r.returncode, r.stderr))

    plain = os.path.join(tmp, "plain.msh")
    r = run([step, "--order", "4", "-o", plain])
    g, _ = groups(plain) if r.returncode == 0 else ({}, None)
    if sorted(g) != ["boundary_%d" % t for t in range(4)]:
        fails.append("without names: groups %s" % sorted(g))
gmsh.finalize()
for f in fails:
    print("FAIL", f)
sys.exit(1 if fails else 0)
