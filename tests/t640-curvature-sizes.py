"""t640: curvature sizes (docs/sizes.md, issue 24): --curvature N sets
h = 1 / (N kappa) on the CAD curves, growing away from them by the
gradation g (slope g - 1), capped by the far size.

On examples/half_disc.step (radius R = 1: the arc, edge 1, and the
diameter, edge 0), --curvature 8 --size 1, g = 1.3 (the default):
1. The arc: h = R / N = 0.125 everywhere on it, so the report's target
   sizes are 0.125 to the field's sampling of the circle (a 256-segment
   polyline whose points lie within the sagitta R (1 - cos(pi / 256))
   = 7.5e-5 of the arc: h off by 0.3 of that), and its integral of 1/h is
   N pi = 25.13 up to the mesh's trapezoid rule on the arc's nodes: their
   polygon is shorter than the arc by (theta^2 / 24) relative for node
   spacings theta <= h / R = 0.125, under 7e-4 (asserted: 1e-3).
2. The diameter: a point (x, 0) lies 1 - |x| from the arc, so
   h = 0.125 + 0.3 (1 - |x|) and the integral of 1/h over it is
   2 / 0.3 ln(0.425 / 0.125) = 8.159.  The report's trapezoid rule on the
   edge's nodes (order 4: at most h / 2 apart near the arc, where 1/h is
   most curved, f'' = 2 b^2 / h^3 = 92) errs by at most
   L dx^2 max|f''| / 12 per half, dx <= 0.0625: 0.03 a half, 0.06 in all
   (asserted with that bound).
3. The chords obey the quantization bound of t628: over the k patch sides
   of an edge, its integral N and segments n satisfy N <= n + k / 2 (the
   counts are rounded, then only raised by opposite sides: the diameter's
   are, by the arc's); the arc's, the finest sides of their sheets, are
   not raised, so there also N >= n - k / 2.
4. The size file line "curvature 8" gives the same mesh, byte for byte,
   and a bad count is refused (exit 2, one line, no file).
5. All quads valid.
Usage: t640-curvature-sizes.py SEMQUAD EXAMPLES"""
import json
import math
import os
import subprocess
import sys
import tempfile

SEMQUAD, EXAMPLES = sys.argv[1:3]
fails = []


def check(ok, what):
    print(("ok   " if ok else "FAIL ") + what)
    if not ok:
        fails.append(what)


def mesh(tmp, stem, *args):
    out, rep = os.path.join(tmp, stem + ".msh"), os.path.join(tmp, stem + ".json")
    r = subprocess.run([SEMQUAD, "mesh", os.path.join(EXAMPLES, "half_disc.step"), "-q",
                        "-o", out, "--report", rep, "--size", "1", *args],
                       capture_output=True, text=True)
    return r, out, rep


with tempfile.TemporaryDirectory() as tmp:
    r, out, rep = mesh(tmp, "curv", "--curvature", "8")
    check(r.returncode == 0, "--curvature 8 meshes (exit %d: %s)" % (r.returncode, r.stderr.strip()))
    rp = json.load(open(rep))
    m = rp["mesh"]
    check(m["inverted"] == 0 and m["min_scaled_jacobian"] > 0,
          "all quads valid (min scaled Jacobian %.3g)" % m["min_scaled_jacobian"])
    edges = {e["edge"]: e for e in rp["sizes"]["edges"]}
    arc, dia = edges[1], edges[0]
    sag = 0.3 * (1 - math.cos(math.pi / 256))
    check(abs(arc["target_min"] - 0.125) <= sag and abs(arc["target_max"] - 0.125) <= sag,
          "arc target %.6g..%.6g = R/N = 0.125" % (arc["target_min"], arc["target_max"]))
    check(abs(arc["cells"] - 8 * math.pi) <= 1e-3 * 8 * math.pi,
          "arc integral of 1/h %.5g = N pi = %.5g" % (arc["cells"], 8 * math.pi))
    exact = 2 / 0.3 * math.log(0.425 / 0.125)
    check(abs(dia["cells"] - exact) <= 0.06,
          "diameter integral of 1/h %.5g = %.5g" % (dia["cells"], exact))
    check(abs(dia["target_min"] - 0.125) <= 1e-9 + sag,
          "diameter's least target %.6g at its ends = 0.125" % dia["target_min"])
    check(arc["segments"] - arc["cells"] <= arc["patch_sides"] / 2 + 1e-9,
          "arc not raised: %d segments for %.4g" % (arc["segments"], arc["cells"]))
    for e in (arc, dia):
        check(e["cells"] - e["segments"] <= e["patch_sides"] / 2 + 1e-9,
              "edge %d: %d segments for an integral %.4g over %d sides"
              % (e["edge"], e["segments"], e["cells"], e["patch_sides"]))

    sizes = os.path.join(tmp, "sizes.txt")
    with open(sizes, "w") as f:
        f.write("# curvature sizes\ncurvature 8\n")
    r2, out2, _ = mesh(tmp, "file", "--sizes", sizes)
    check(r2.returncode == 0 and open(out, "rb").read() == open(out2, "rb").read(),
          "the size file's 'curvature 8' gives the same mesh byte for byte")

    r3, out3, _ = mesh(tmp, "bad", "--curvature", "-1")
    lines = r3.stderr.strip().splitlines()
    check(r3.returncode == 2 and len(lines) == 1 and not os.path.exists(out3),
          "--curvature -1 refused: exit %d, %r" % (r3.returncode, r3.stderr.strip()))

sys.exit(1 if fails else 0)
