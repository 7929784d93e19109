#!/usr/bin/python3
"""t641: `semquad mesh --binary` with an XML output writes Nektar++'s
compressed XML (docs/formats.md, "Compressed Nektar++ XML"); library format
"xml-compressed".  The same mesh written as text XML and compressed XML,
both read by tests/nektar_xml.py (the text through xml.etree, the
compressed sections through base64, zlib and struct of the standard
library, not through semquad), must give

  - the same vertices, edges and quads: ids, vertex ids, edge ids;
  - the same curved edges and faces: entity ids, curve ids, point type and
    points, every coordinate bit for bit (the text's 17 significant digits
    read back to the same double: docs/formats.md);
  - the same COMPOSITE and DOMAIN;

and both files parse as XML.  Cases: the half disc at order 4 (GLL; one
curved edge per edge, one curved face per quad), at order 1 (no CURVED),
the nautilus at order 3 with equispaced nodes (PolyEvenlySpaced), and a
mesh of three faces sharing edges (tests/domain_faces.py three_row: one
composite per face).  The compressed file is the same bytes when written
twice, and the same with --format xml -o NAME.dat and on stdout (-o -);
--binary with a VTU output exits 2 and writes nothing.
usage: t641-nektar-compressed.py SEMQUAD EXAMPLES_DIR DOMAIN_FACES_PY"""
import os
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import nektar_xml  # noqa: E402

SQ, EXAMPLES, FACES = sys.argv[1:4]
fails = []


def mesh(args, **kw):
    r = subprocess.run([SQ, "mesh"] + args + ["-q"], capture_output=True, **kw)
    if r.returncode != 0:
        fails.append("%s: exit %d: %s" % (args, r.returncode, r.stderr))
    return r


def bits(x):
    """Nested entities with every float as its exact hex form."""
    if isinstance(x, float):
        return x.hex()
    if isinstance(x, (list, tuple)):
        return tuple(bits(y) for y in x)
    if isinstance(x, dict):
        return {k: bits(v) for k, v in x.items()}
    return x


def compare(name, text, packed, order):
    try:
        a, b = nektar_xml.read(text), nektar_xml.read(packed)
    except Exception as e:  # a malformed file is a failure, not a crash
        fails.append("%s: %s" % (name, e))
        return
    if a["compressed"] or not b["compressed"]:
        fails.append("%s: text compressed %s, packed compressed %s"
                     % (name, a["compressed"], b["compressed"]))
    for key in ("vertices", "edges", "quads", "curved_edges", "curved_faces",
                "composite", "domain"):
        if bits(a[key]) != bits(b[key]):
            fails.append("%s: %s differ (text %d, compressed %d items)"
                         % (name, key, len(a[key]), len(b[key])))
    nq, ne = len(a["quads"]), len(a["edges"])
    if not nq or not ne or len(a["vertices"]) < 4:
        fails.append("%s: empty mesh read" % name)
    curved = order >= 2
    if (len(b["curved_edges"]), len(b["curved_faces"])) != ((ne, nq) if curved else (0, 0)):
        fails.append("%s: %d curved edges, %d faces for %d edges, %d quads at order %d"
                     % (name, len(b["curved_edges"]), len(b["curved_faces"]), ne, nq, order))
    if any(len(p) != order + 1 for _, _, p in b["curved_edges"].values()) or \
       any(len(p) != (order + 1) ** 2 for _, _, p in b["curved_faces"].values()):
        fails.append("%s: curves without order + 1 points a side" % name)
    print("t641: %s: %d vertices, %d edges, %d quads, %d curved edges, %d curved faces; "
          "%d bytes text, %d compressed" % (name, len(b["vertices"]), ne, nq,
                                           len(b["curved_edges"]), len(b["curved_faces"]),
                                           os.path.getsize(text), os.path.getsize(packed)))


def both(name, d, args, order):
    text, packed = os.path.join(d, name + ".xml"), os.path.join(d, name + "_z.xml")
    mesh(args + ["--order", str(order), "-o", text])
    mesh(args + ["--order", str(order), "--binary", "-o", packed])
    compare(name, text, packed, order)
    return packed


def main():
    disc = os.path.join(EXAMPLES, "half_disc.step")
    with tempfile.TemporaryDirectory() as d:
        packed = both("half_disc", d, [disc, "--size", "0.3"], 4)
        with open(packed, "rb") as f:
            first = f.read()
        again = os.path.join(d, "again.dat")
        mesh([disc, "--size", "0.3", "--order", "4", "--binary", "--format", "xml", "-o", again])
        out = mesh([disc, "--size", "0.3", "--order", "4", "--binary", "--format", "xml", "-o", "-"])
        with open(again, "rb") as f:
            if f.read() != first or out.stdout != first:
                fails.append("half_disc: compressed file differs between runs or on stdout")
        both("half_disc_q1", d, [disc, "--size", "0.3"], 1)
        both("nautilus", d, [os.path.join(EXAMPLES, "nautilus.step"), "--nodes", "equispaced"], 3)
        row = os.path.join(d, "row.step")
        subprocess.run(["/usr/bin/python3", FACES, "three_row", row], check=True,
                       capture_output=True)
        both("three_row", d, [row, "--size", "0.25"], 4)
        vtu = os.path.join(d, "x.vtu")
        r = subprocess.run([SQ, "mesh", disc, "--binary", "-o", vtu, "-q"],
                           capture_output=True, text=True)
        if r.returncode != 2 or os.path.exists(vtu):
            fails.append("--binary -o x.vtu: exit %d (expected 2), file %s"
                         % (r.returncode, "written" if os.path.exists(vtu) else "absent"))
    for f in fails:
        print("t641: FAIL " + f)
    return 1 if fails else 0


if __name__ == "__main__":
    sys.exit(main())
