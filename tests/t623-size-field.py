"""t623: the user's size field (docs/sizes.md) against known answers.

1. Linear growth from an edge: on the rectangle [0, 4] x [0, 1], --grow
   3:h0:g on its left edge x = 0 gives h = h0 + a x, a = g - 1 (far size
   never reached).  The bottom side's segments n = round(int_0^L dx / h)
   with int = ln(1 + a L / h0) / a; node k sits where the integral is k/n of
   the total: x_k = (h0 / a) ((1 + a L / h0)^(k/n) - 1).  Tolerance: the
   mesher keeps the cumulative integral at 33 samples (SIZE_SAMPLES) and
   interpolates it linearly, an error of at most D^2/8 max|(1/h)'| =
   D^2 a / (8 h0^2) cells, D = L/32 the sample spacing: 0.16 cells here.
2. Refinement at a corner of the unit square: the first segments along the
   two sides meeting there lie within the gradation g of the target h (the
   rounding of n moves a segment by at most 1/n of the side's integral,
   far below that factor).
3. Same bytes: --size-gradation alone, with no source, changes nothing; a
   size file gives the bytes of the same sources on the command line.
4. Bad values: exit 2 (usage), a missing size file exit 3, one line each.
Usage: t623-size-field.py SEMQUAD"""
import math
import os
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from step_face import Step  # noqa: E402

try:
    import gmsh
except ImportError:
    sys.exit(77)

SEMQUAD = sys.argv[1]


def run(*args):
    return subprocess.run([SEMQUAD, *args], capture_output=True, text=True)


def bottom_nodes(path, y=0.0, axis=0):
    gmsh.open(path)
    _, xyz, _ = gmsh.model.mesh.getNodes()
    other = 1 - axis
    return sorted({round(xyz[3 * i + axis], 12) for i in range(len(xyz) // 3)
                   if abs(xyz[3 * i + other] - y) < 1e-9})


def main():
    gmsh.initialize()
    gmsh.option.setNumber("General.Terminal", 0)
    fails = []
    with tempfile.TemporaryDirectory() as d:
        rect, sq = os.path.join(d, "rect.step"), os.path.join(d, "sq.step")
        s = Step()
        s.write(rect, [s.polygon([(0, 0), (4, 0), (4, 1), (0, 1)])])
        s = Step()
        s.write(sq, [s.polygon([(0, 0), (1, 0), (1, 1), (0, 1)])])

        # 1. linear growth from edge 3 (x = 0)
        h0, g, L = 0.05, 1.2, 4.0
        a = g - 1.0
        out = os.path.join(d, "rect.msh")
        r = run("mesh", rect, "-q", "--order", "1", "--size", "1", "--grow", "3:%g:%g" % (h0, g),
                "-o", out)
        if r.returncode:
            fails.append("grow: exit %d: %s" % (r.returncode, r.stderr.strip()))
        else:
            xs = bottom_nodes(out)
            n, total = len(xs) - 1, math.log(1 + a * L / h0) / a
            if abs(n - total) > 1.0:
                fails.append("grow: %d segments, integral of 1/h %.4f" % (n, total))
            tol = (L / 32) ** 2 * a / (8 * h0 * h0)
            for k, x in enumerate(xs):
                exact = h0 / a * ((1 + a * L / h0) ** (k / n) - 1)
                cells = abs(x - exact) / (h0 + a * exact)
                if cells > tol:
                    fails.append("grow: node %d at %.6g, expected %.6g (%.3f cells > %.3f)"
                                 % (k, x, exact, cells, tol))

        # 2. refinement at the corner (0, 0)
        h, gr = 0.02, 1.3
        out = os.path.join(d, "sq.msh")
        r = run("mesh", sq, "-q", "--order", "1", "--size", "0.1", "--refine", "0,0,0.05,%g" % h,
                "-o", out)
        if r.returncode:
            fails.append("refine: exit %d: %s" % (r.returncode, r.stderr.strip()))
        else:
            for axis in (0, 1):
                first = bottom_nodes(out, 0.0, axis)[1]
                if not h / gr <= first <= h * gr:
                    fails.append("refine: first segment along axis %d is %.4g, target %g"
                                 % (axis, first, h))

        # 3. same bytes
        a_msh, b_msh = os.path.join(d, "a.msh"), os.path.join(d, "b.msh")
        run("mesh", sq, "-q", "-o", a_msh)
        run("mesh", sq, "-q", "--size-gradation", "1.5", "-o", b_msh)
        if open(a_msh, "rb").read() != open(b_msh, "rb").read():
            fails.append("--size-gradation without sources changed the mesh")
        sizes = os.path.join(d, "sizes.txt")
        with open(sizes, "w") as f:
            f.write("# a corner refined, an edge graded\npoint 0 0 0.05 0.02\ngrow 1 0.04 1.2\n")
        run("mesh", sq, "-q", "--size", "0.1", "--refine", "0,0,0.05,0.02", "--grow", "1:0.04:1.2",
            "-o", a_msh)
        run("mesh", sq, "-q", "--size", "0.1", "--sizes", sizes, "-o", b_msh)
        if open(a_msh, "rb").read() != open(b_msh, "rb").read():
            fails.append("--sizes FILE and the same options give different meshes")

        # 4. bad values
        bad = os.path.join(d, "bad.txt")
        with open(bad, "w") as f:
            f.write("circle 0 0 1\n")
        for args, code in [(["--grow", "0:-1:1.2"], 2), (["--refine", "1,2,3"], 2),
                           (["--edge-size", "9:0.1"], 2), (["--refine-box", "1,1,0,0,0.1"], 2),
                           (["--grow", "0:0.1:0.5"], 2), (["--sizes", bad], 2),
                           (["--size-gradation", "1"], 2),
                           (["--sizes", os.path.join(d, "none.txt")], 3)]:
            r = run("mesh", sq, "-q", "--no-output", *args)
            lines = r.stderr.strip().splitlines()
            if r.returncode != code or len(lines) != 1:
                fails.append("%s: exit %d (expected %d), stderr %r" % (args, r.returncode, code,
                                                                       r.stderr))
    gmsh.finalize()
    for f in fails:
        print("FAIL", f)
    return 1 if fails else 0


if __name__ == "__main__":
    sys.exit(main())
