#!/usr/bin/python3
"""semquad info and mesh on the project's own cascade passage and aerofoil
box (tests/cascade_aerofoil.py), asserting what t310 and t614 assert on
NekMesh's T106 cascade and aerofoil box, so that every clone checks it:

info: metres, one face, chi 0, the area (the generator's exact one), the
outer lines' corners at the generator's points and angles, the blade's
B-splines meeting tangentially (smooth junctions), the aerofoil's trailing
edge corner at the angle of the B-splines' clamped end tangents.

aerofoil box, default size: meshed by the layout road at that size itself
(no "quads fold", as NekMesh's: its leading-edge sides cover half their
CAD edge or more), 2 interior irregular vertices = its Gauss-Bonnet
minimum, none inverted.

cascade, default size: the T106 route.  Gauss-Bonnet minimum 4, the
guiding field's 6 points kept with the one valence-3/valence-5 pair the
two-step route cannot cancel, named in kept_pair_list (its distance, the
reason), two valence-5 points near the rounded trailing edge (as T106's:
once dropped as "on the boundary", exit 6), 6 interior irregular vertices,
none inverted; the 4 remaining valence-5 points imposed with
--singularities: exit 5, one line, no file.  At --size 0.1: exit 0, valid.
Which road the layout takes here hangs on details (a blade 0.19 or 0.21
thick instead of 0.2 takes the split road): the generator's shape is one
where it does what T106 does, as T106 is.

Every mesh is read back by tests/msh_quad_stats.py (Gmsh's reader): the same
quads and interior irregular vertices as the report, none inverted, Euler
characteristic 0 (one hole).
Tolerances: the area, 1e-9 relative (the code's arc-length slack, t305);
corners are the generator's 17-digit points, 1e-12; angles between
straight edges to a few U (1e-9 deg); the trailing edge's angle from the
B-splines' end poles, exact to their 17 digits over a first span of 1e-3
(1e-13 rad: 1e-9 deg); smooth junctions 180 deg to the generator's 1e-8 rad
tangents (1e-6 deg); the kept pair's distance is its points' own (1e-12).
usage: t616-mesh-own-cascade.py SEMQUAD CASCADE.step AEROFOIL_BOX.step MSH_QUAD_STATS"""
import json
import math
import os
import subprocess
import sys
import tempfile

sq, cascade, aerofoil, stats = sys.argv[1:5]
fails = []


def check(cond, what):
    if not cond:
        fails.append(what)
    return cond


def near(what, got, want, tol):
    check(abs(got - want) <= tol, "%s: %.17g, expected %.17g (tolerance %.3g)" % (what, got, want, tol))


def facts(step):
    """NAME.facts beside NAME.step: corners [(x, y, angle)], other keys."""
    out = {"corner": []}
    with open(os.path.splitext(step)[0] + ".facts") as fh:
        for line in fh:
            k, *v = line.split()
            if k == "corner":
                out["corner"].append(tuple(map(float, v)))
            else:
                out[k] = [float(x) for x in v] if len(v) > 1 else float(v[0])
    return out


def info(name, step, k, nlines):
    p = subprocess.run([sq, "info", step, "--json", "-q"], capture_output=True, text=True)
    if not check(p.returncode == 0, "%s: info exit %d: %s" % (name, p.returncode, p.stderr)):
        return
    d = json.loads(p.stdout)
    f = d["faces"][0]
    check(d["unit"] == "m" and len(d["faces"]) == 1 and f["status"] == "ok" and f["chi"] == 0,
          "%s: unit %s, %d faces, status %s, chi %s" % (name, d["unit"], len(d["faces"]), f["status"],
                                                        f["chi"]))
    near(name + ": area (m^2)", f["area"], k["area"], 1e-9 * k["area"])
    types = [[e["type"] for e in lp["edges"]] for lp in f["loops"]]
    check(types == [["line"] * nlines, ["bspline"] * 2], "%s: edges %s" % (name, types))
    outer = [c for c in f["corners"] if c["loop"] == 0]
    check(len(outer) == len(k["corner"]), "%s: %d outer corners, expected %d"
          % (name, len(outer), len(k["corner"])))
    for x, y, a in k["corner"]:
        c = min(outer, key=lambda c: math.hypot(c["x"] - x, c["y"] - y))
        near("%s: corner (%g, %g) position" % (name, x, y), math.hypot(c["x"] - x, c["y"] - y), 0, 1e-12)
        near("%s: corner (%g, %g) angle (deg)" % (name, x, y), c["angle_deg"], a, 1e-9)
    for j in f["smooth_junctions"]:
        near("%s: smooth junction (%g, %g) angle (deg)" % (name, j["x"], j["y"]), j["angle_deg"], 180, 1e-6)
    return f


def gauss_bonnet_min(f):
    """|4 chi - sum_corners (2 - n_i)|, n_i = max(1, round(angle / 90))."""
    return abs(4 * f["chi"] - sum(2 - max(1, math.floor(c["angle_deg"] / 90 + 0.5)) for c in f["corners"]))


def mesh(name, step, tmp, *opts):
    """semquad mesh: (exit status, stderr, report or None, msh path)."""
    msh, rep = os.path.join(tmp, name + ".msh"), os.path.join(tmp, name + ".json")
    p = subprocess.run([sq, "mesh", step, "-o", msh, "--report", rep, *opts], capture_output=True,
                       text=True)
    r = json.load(open(rep)) if p.returncode == 0 and os.path.exists(rep) else None
    return p.returncode, p.stderr, r, msh


def valid(name, st, err, r, msh, irregular=None):
    """Exit 0, none inverted, positive Jacobians; msh_quad_stats agrees."""
    if not check(st == 0 and r, "%s: exit %d: %s" % (name, st, err.strip())):
        return
    m = r["mesh"]
    check(m["inverted"] == 0 and m["min_scaled_jacobian"] > 0,
          "%s: %d inverted, min scaled Jacobian %g" % (name, m["inverted"], m["min_scaled_jacobian"]))
    if irregular is not None:
        check(m["irregular_interior_vertices"] == irregular, "%s: %d interior irregular vertices, "
              "expected %d" % (name, m["irregular_interior_vertices"], irregular))
    s = json.loads(subprocess.run([sys.executable, stats, msh], check=True, capture_output=True,
                                  text=True).stdout)
    check((s["quads"], s["interior_irregular"], s["inverted_quads"], s["euler_chi"]) ==
          (m["quads"], m["irregular_interior_vertices"], 0, 0),
          "%s: msh_quad_stats %s, report quads %d, irregular %d" % (name, s, m["quads"],
                                                                    m["irregular_interior_vertices"]))


ka, kc = facts(aerofoil), facts(cascade)
fa, fc = info("aerofoil box", aerofoil, ka, 4), info("cascade", cascade, kc, 10)
if fa:
    te = [c for c in fa["corners"] if c["loop"] == 1]
    x, y, angle = ka["trailing_edge"]
    check(len(te) == 1 and len(fa["smooth_junctions"]) == 1,
          "aerofoil box: hole corners %s, smooth junctions %s" % (te, fa["smooth_junctions"]))
    if te:
        near("aerofoil box: trailing edge x", te[0]["x"], x, 1e-12)
        near("aerofoil box: trailing edge angle (deg)", te[0]["angle_deg"], angle, 1e-9)
if fc:
    check(not [c for c in fc["corners"] if c["loop"] == 1] and len(fc["smooth_junctions"]) == 2,
          "cascade: the blade has corners or not two smooth junctions: %s" % fc["smooth_junctions"])
    check(gauss_bonnet_min(fc) == 4, "cascade: Gauss-Bonnet minimum %d" % gauss_bonnet_min(fc))

with tempfile.TemporaryDirectory() as tmp:
    # the aerofoil box at the default size
    st, err, r, msh = mesh("aerofoil", aerofoil, tmp)
    valid("aerofoil box", st, err, r, msh, irregular=2)
    check("quads fold at size" not in err, "aerofoil box: the default size was halved: " + err)
    check(r is None or (r["road"] == "layout" and r["layout"]["gauss_bonnet_min"] == 2),
          "aerofoil box: road %s, Gauss-Bonnet minimum %s" % (
              r and r["road"], r and r.get("layout", {}).get("gauss_bonnet_min")))

    # the cascade at the default size: T106's route
    st, err, r, msh = mesh("cascade", cascade, tmp, "-q")
    valid("cascade", st, err, r, msh, irregular=6)
    if r:
        L = r["layout"]
        check(r["road"] == "layout" and L["gauss_bonnet_min"] == 4 and L["kept_pairs"] == 1,
              "cascade: road %s, Gauss-Bonnet minimum %d, kept pairs %d"
              % (r["road"], L["gauss_bonnet_min"], L["kept_pairs"]))
        kept = L.get("kept_pair_list", [])
        if check(len(kept) == 1, "cascade: kept_pair_list %s" % kept):
            a, b = kept[0]["valence3"], kept[0]["valence5"]
            near("cascade: kept pair distance", kept[0]["distance"], math.hypot(a[0] - b[0], a[1] - b[1]),
                 1e-12)
            check("no valid H/theta layout of fewer points" in kept[0]["reason"],
                  "cascade: kept pair reason: " + kept[0]["reason"])
        sing = r["singularities"]
        five = [s for s in sing if s["valence"] == 5]
        check(len(sing) == 6 and len(five) == 5, "cascade: singular points %s" % sing)
        # te: the blade's rounded trailing edge's extreme point (the facts)
        near_te = [s for s in five if math.hypot(s["x"] - kc["te"][0], s["y"] - kc["te"][1]) < 0.02]
        check(len(near_te) == 2, "cascade: %d valence-5 points within 0.02 of the trailing edge %s"
              % (len(near_te), kc["te"]))
        # the remaining Gauss-Bonnet-minimal pattern imposed: exit 5, one line, no file
        pat = os.path.join(tmp, "min.txt")
        with open(pat, "w") as fh:
            for s in five:
                if [s["x"], s["y"]] != b:
                    fh.write("%.17g %.17g 5\n" % (s["x"], s["y"]))
        out = os.path.join(tmp, "m.msh")
        p = subprocess.run([sq, "mesh", cascade, "--singularities", pat, "-q", "-o", out],
                           capture_output=True, text=True)
        check(p.returncode == 5 and len(p.stderr.splitlines()) == 1 and not os.path.exists(out),
              "cascade, minimal pattern: exit %d (expected 5), stderr %r, file %s"
              % (p.returncode, p.stderr, os.path.exists(out)))

    # the cascade at --size 0.1
    st, err, r, msh = mesh("cascade01", cascade, tmp, "--size", "0.1", "-q")
    valid("cascade --size 0.1", st, err, r, msh)

for f in fails:
    print(f)
sys.exit(1 if fails else 0)
