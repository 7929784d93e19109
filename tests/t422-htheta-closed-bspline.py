#!/usr/bin/python3
"""The H field's curvature data on a closed B-spline edge (issue 14, T106's
class): a 4 x 3 rectangle with a hole bounded by one closed cubic B-spline
(tests/step_face.py; 12 poles of a three-lobed oval, clamped at one pole,
so the edge's ends meet at a corner of the hole), four valence-5 points
imposed near the rectangle's corners (Gauss-Bonnet: four 90-degree corners,
chi = 0).  The curvature data of every boundary element edge whose kappa the
field's rule does not resolve is the exact turning of the tangent between
its ends, including the element edge that spans the closing point, so

- `semquad field --singularities` exits 0, and
- the data's imbalance before its correction (report: h_data_imbalance) is
  below 1e-6 of the data size (h_data_size): the spans where the rule
  resolves kappa add at most KAPPA_RESOLVED = 1e-6 of their integral of
  |kappa| (src/field/h_field.c), the others their exact turning to
  round-off.  Pointwise kappa gave 4.6e-6 of the data here (6.3e-5).
usage: t422-htheta-closed-bspline.py SEMQUAD"""
import json
import math
import os
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from step_face import Step  # noqa: E402


def blob(path):
    s = Step("m")
    outer = s.polygon([(0, 0), (4, 0), (4, 3), (0, 3)])
    n = 12
    pts = [(2 + math.cos(2 * math.pi * k / n) * (1 + 0.3 * math.cos(6 * math.pi * k / n)),
            1.5 + 0.6 * math.sin(2 * math.pi * k / n)) for k in range(n)][::-1]  # clockwise
    poles = pts + [pts[0]]
    v = s.vertex(poles[0])
    spans = len(poles) - 3
    e = s.bspline(v, v, poles, list(range(spans + 1)), [4] + [1] * (spans - 1) + [4])
    s.write(path, [outer, s.loop([e])])


def main():
    sq = sys.argv[1]
    with tempfile.TemporaryDirectory() as tmp:
        step, pat, rep = (os.path.join(tmp, f) for f in ("blob.step", "p.txt", "r.json"))
        blob(step)
        with open(pat, "w") as fh:
            fh.write("0.5 0.5 5\n3.5 0.5 5\n3.5 2.5 5\n0.5 2.5 5\n")
        p = subprocess.run([sq, "field", step, "--singularities", pat, "--allow-misaligned",
                            "--report", rep], capture_output=True, text=True)
        if p.returncode != 0:
            print("field: exit %d: %s" % (p.returncode, p.stderr.strip()))
            return 1
        with open(rep) as fh:
            r = json.load(fh)

        def find(d, key):
            if isinstance(d, dict):
                if key in d:
                    return d[key]
                for v in d.values():
                    x = find(v, key)
                    if x is not None:
                        return x
            return None
        imb, size = find(r, "h_data_imbalance"), find(r, "h_data_size")
        if imb is None or size is None or not abs(imb) <= 1e-6 * size:
            print("H data imbalance %r of data size %r: not below 1e-6 of it" % (imb, size))
            return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
