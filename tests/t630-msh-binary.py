#!/usr/bin/python3
"""t630: `semquad mesh --binary` (docs/formats.md, "Binary MSH"): the same
mesh written as MSH 4.1 text and binary, both read by Gmsh's own reader
(gmsh.open), must give

  - the same node tags and coordinates, bit for bit (the text's 17
    significant digits read back to the same double; the binary holds the
    doubles themselves);
  - the same element blocks: entity, element type, element tags and node
    lists, in order;
  - the same physical groups: dimension, tag, name and entities;

for the half disc at order 4 with its two edges named (--names), and a
mesh of three faces sharing edges (tests/domain_faces.py three_row: one
surface entity per face); meshio's reader (if installed) agrees too.  The binary file begins "$MeshFormat\\n4.1 1 8\\n"
and the int 1 (the byte-order mark); --binary with a VTU output exits 2
and writes nothing (with XML it writes compressed Nektar++ XML: t641).
usage: t630-msh-binary.py SEMQUAD EXAMPLES_DIR DOMAIN_FACES_PY"""
import os
import struct
import subprocess
import sys
import tempfile

try:
    import gmsh
except ImportError:
    sys.exit(77)

SQ, EXAMPLES, FACES = sys.argv[1:4]
fails = []


def mesh(args):
    r = subprocess.run([SQ, "mesh"] + args + ["-q"], capture_output=True, text=True)
    if r.returncode != 0:
        fails.append("%s: exit %d: %s" % (args, r.returncode, r.stderr.strip()))
    return r


def contents(path):
    """Everything Gmsh's reader gives back: nodes, element blocks, groups."""
    gmsh.clear()
    gmsh.open(path)
    tags, xyz, _ = gmsh.model.mesh.getNodes()
    order = sorted(range(len(tags)), key=lambda k: tags[k])
    nodes = [(int(tags[k]), tuple(xyz[3 * k:3 * k + 3])) for k in order]
    blocks = []
    for dim, ent in gmsh.model.getEntities():
        types, etags, enodes = gmsh.model.mesh.getElements(dim, ent)
        for t, et, en in zip(types, etags, enodes):
            blocks.append((dim, ent, int(t), [int(x) for x in et], [int(x) for x in en]))
    groups = []
    for dim, tag in gmsh.model.getPhysicalGroups():
        groups.append((dim, tag, gmsh.model.getPhysicalName(dim, tag),
                       sorted(int(e) for e in gmsh.model.getEntitiesForPhysicalGroup(dim, tag))))
    return nodes, blocks, groups


def compare(name, text, binary):
    with open(binary, "rb") as f:
        head = f.read(len(b"$MeshFormat\n4.1 1 8\n") + 4)
    if head[:-4] != b"$MeshFormat\n4.1 1 8\n" or struct.unpack("=i", head[-4:])[0] != 1:
        fails.append("%s: binary header %r" % (name, head))
    a, b = contents(text), contents(binary)
    for what, x, y in zip(("nodes", "elements", "physical groups"), a, b):
        if x != y:
            fails.append("%s: %s differ (text %d, binary %d items)" % (name, what, len(x), len(y)))
    nodes, blocks, groups = a
    quads = sum(len(b[3]) for b in blocks if b[0] == 2)
    lines = sum(len(b[3]) for b in blocks if b[0] == 1)
    if not nodes or not quads or not lines or len(groups) < 2:
        fails.append("%s: empty mesh read (%d nodes, %d quads, %d lines, %d groups)"
                     % (name, len(nodes), quads, lines, len(groups)))
    if any(b[2] != 37 for b in blocks if b[0] == 2):  # 25-node quads: order 4
        fails.append("%s: quads not of type 37" % name)
    try:  # meshio's reader too, where python3-meshio is installed
        import meshio
        ma, mb = meshio.read(text), meshio.read(binary)
        if not (ma.points == mb.points).all() or [c.type for c in ma.cells] != [
                c.type for c in mb.cells] or any((x.data != y.data).any()
                                                 for x, y in zip(ma.cells, mb.cells)):
            fails.append("%s: meshio reads text and binary differently" % name)
    except ImportError:
        pass
    print("t630: %s: %d nodes, %d quads, %d lines, groups %s: text and binary equal"
          % (name, len(nodes), quads, lines, [g[2] for g in groups]))


def main():
    gmsh.initialize(["-v", "0"])
    gmsh.option.setNumber("General.Terminal", 0)
    with tempfile.TemporaryDirectory() as d:
        names = os.path.join(d, "names.txt")
        with open(names, "w") as f:
            f.write("0 axis\n1 arc\n")
        disc = os.path.join(EXAMPLES, "half_disc.step")
        for fmt, out in (("", "disc.msh"), ("--binary", "disc_b.msh")):
            mesh([disc, "--order", "4", "--size", "0.1", "--names", names, "-o",
                  os.path.join(d, out)] + ([fmt] if fmt else []))
        compare("half_disc", os.path.join(d, "disc.msh"), os.path.join(d, "disc_b.msh"))

        row = os.path.join(d, "row.step")
        subprocess.run(["/usr/bin/python3", FACES, "three_row", row], check=True,
                       capture_output=True)
        mesh([row, "--order", "4", "--size", "0.25", "-o", os.path.join(d, "row.msh")])
        mesh([row, "--order", "4", "--size", "0.25", "--binary", "-o",
              os.path.join(d, "row_b.msh")])
        compare("three_row", os.path.join(d, "row.msh"), os.path.join(d, "row_b.msh"))

        for out in ("x.vtu",):
            r = subprocess.run([SQ, "mesh", disc, "--binary", "-o", os.path.join(d, out), "-q"],
                               capture_output=True, text=True)
            if r.returncode != 2 or os.path.exists(os.path.join(d, out)):
                fails.append("--binary -o %s: exit %d (expected 2), file %s" % (
                    out, r.returncode, "written" if os.path.exists(os.path.join(d, out)) else "absent"))
    gmsh.finalize()
    for f in fails:
        print("t630: FAIL " + f)
    return 1 if fails else 0


if __name__ == "__main__":
    sys.exit(main())
