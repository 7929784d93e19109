#!/usr/bin/python3
"""Large meshes (docs/mesh.md, "Large meshes"; issue 22): a mesh of more quads
than --relax-max-quads is relaxed with its chords quantized at 2^k times the size and
then split 2 x 2 k times along its quads' own maps; --threads N gives the same
bytes for every N.  Exercised cheaply with a small threshold on
examples/square_hole.step (order 4).  No time is asserted.

1. Threads: `--size 0.04 --relax-max-quads 100` (about 600 quads, relaxed at
   about 40) with --threads 1, 2, 3 and with SEMQUAD_THREADS=3: the MSH files are
   the same bytes, the reports the same apart from their timings.
2. Nested, bit for bit: the same mesh is the third level of the family of the
   coarse mesh, `--size 0.16 --relax-max-quads 0 --levels 3 -o c.msh` (size 0.04 = 0.16 / 2^2
   quantizes to the same coarse chords; the family splits every quad 2 x 2 per
   level with the same code): STEM_L3.msh is byte-identical to part 1's file,
   and the report's relaxed_at_quads is level 1's quad count (the manifest's).
   Hence the coarse vertices are vertices of the fine mesh (exactly: copied).
3. Every quad valid at every level (manifest: inverted 0, a proven Bezier
   lower bound of det J > 0 in min_scaled_jacobian), and the area converging to
   `semquad info`'s exact area (Green's theorem on the CAD curves): the hole is a
   circle, so the area error of order-4 sides at Gauss-Lobatto-Legendre
   arc-length points falls like h^(2Q) = h^8 (tests/t622's derivation), a
   factor 256 per level; asserted: a fall by at least 2^4 per level while the
   error is 100 times above the round-off floor of the area (1e-13 of it, the
   sum of ~1e4 quad integrals of 17-digit nodes), else below that floor.
4. Below the threshold nothing changes: `--size 0.04` with the default
   threshold (5e4) gives the same bytes as `--relax-max-quads 0`, and its report
   has no relaxed_at_quads.
5. Threads where the sorts and the MSH text writer split their work:
   `--size 0.008 --relax-max-quads 5000` (about 15 000 quads relaxed at about
   4 000): the refinement's side sort (4 per coarse quad) and the quality's
   (4 per fine quad) run as N runs of sq_parallel_sort on N = 2, 3 threads
   (runs of at least 4096 items), the valences and angle sums as N ranges of
   the vertices (at least 4096 each), the MSH text as several chunks of about
   4 MB; --threads 1, 2, 3 give the same bytes and reports.
6. Bad values: --threads -1, --threads x, SEMQUAD_THREADS=x and
   --relax-max-quads -1 exit 2 with one line and no file.
usage: t631-large-mesh.py SEMQUAD EXAMPLES_DIR"""
import json
import os
import subprocess
import sys
import tempfile

SEMQUAD, EXAMPLES = sys.argv[1], sys.argv[2]
STEP = os.path.join(EXAMPLES, "square_hole.step")
failures = []


def check(cond, what):
    print(("ok   " if cond else "FAIL ") + what)
    if not cond:
        failures.append(what)


def run(*args, status=0, env=None):
    p = subprocess.run([SEMQUAD] + list(args), capture_output=True, text=True,
                       env=dict(os.environ, **(env or {})))
    if p.returncode != status:
        sys.exit("semquad %s: exit %d (expected %d)\n%s" % (" ".join(args), p.returncode, status,
                                                           p.stderr))
    return p


def read(path, mode="rb"):
    with open(path, mode) as f:
        return f.read()


def report(path):
    d = json.loads(read(path, "r"))
    d.pop("timings_s", None)
    d["mesh"].pop("timings_s", None)
    return d


def fine(d, tag, *extra, env=None):
    msh, rep = os.path.join(d, tag + ".msh"), os.path.join(d, tag + ".json")
    run("mesh", STEP, "-q", "--order", "4", "--size", "0.04", "-o", msh, "--report", rep,
        *extra, env=env)
    return read(msh), report(rep)


def part1(d):
    runs = [fine(d, "t%d" % n, "--relax-max-quads", "100", "--threads", str(n)) for n in (1, 2, 3)]
    runs.append(fine(d, "env3", "--relax-max-quads", "100", env={"SEMQUAD_THREADS": "3"}))
    msh1, rep1 = runs[0]
    quads = rep1["mesh"]["quads"]
    check(quads > 100 and 0 < rep1["mesh"].get("relaxed_at_quads", 0) <= 100,
          "%d quads relaxed at %s (threshold 100)" % (quads, rep1["mesh"].get("relaxed_at_quads")))
    for k, (msh, rep) in enumerate(runs[1:]):
        what = ("--threads %d" % (k + 2)) if k < 2 else "SEMQUAD_THREADS=3"
        check(msh == msh1, "%s: MSH byte-identical to --threads 1" % what)
        check(rep == rep1, "%s: report identical to --threads 1 (timings aside)" % what)
    return msh1, rep1


def part23(d, msh1, rep1):
    stem = os.path.join(d, "c")
    run("mesh", STEP, "-q", "--order", "4", "--size", "0.16", "--relax-max-quads", "0",
        "--levels", "3", "-o", stem + ".msh", "--threads", "2")
    check(read(stem + "_L3.msh") == msh1, "level 3 of the coarse mesh's family is the same file")
    man = json.loads(read(stem + "_manifest.json", "r"))["meshes"]
    check(rep1["mesh"].get("relaxed_at_quads") == man[0]["quads"],
          "relaxed_at_quads %s = level 1's quads %d" % (rep1["mesh"].get("relaxed_at_quads"),
                                                         man[0]["quads"]))
    check(man[2]["quads"] == rep1["mesh"]["quads"] == 16 * man[0]["quads"], "quads x16 in 2 levels")
    A = json.loads(run("info", STEP, "--json").stdout)["faces"][0]["area"]
    floor = 1e-13 * A
    errs = [abs(m["area"] - A) for m in man]
    for k, m in enumerate(man):
        check(m["inverted"] == 0 and m["min_scaled_jacobian"] > 0.0,
              "level %d: every quad proven valid (min scaled Jacobian %.3g)"
              % (k + 1, m["min_scaled_jacobian"]))
    for k in range(1, len(errs)):
        ok = errs[k] <= errs[k - 1] / 16 if errs[k - 1] > 100 * floor else errs[k] <= 100 * floor
        check(ok, "area error %.3g -> %.3g (level %d -> %d)" % (errs[k - 1], errs[k], k, k + 1))


def part4(d, msh_small_default):
    msh0, rep0 = fine(d, "zero", "--relax-max-quads", "0")
    check(msh0 == msh_small_default[0], "below the threshold: the same bytes as without it")
    check("relaxed_at_quads" not in msh_small_default[1]["mesh"], "no relaxed_at_quads below it")


def part5(d):
    runs = []
    for n in (1, 2, 3):
        msh, rep = os.path.join(d, "s%d.msh" % n), os.path.join(d, "s%d.json" % n)
        run("mesh", STEP, "-q", "--order", "4", "--size", "0.008", "--relax-max-quads", "5000",
            "--threads", str(n), "-o", msh, "--report", rep)
        runs.append((read(msh), report(rep)))
    m = runs[0][1]["mesh"]
    # 4 sides a quad, sorted in 3 runs of at least 4096 on 3 threads; 3 ranges of 4096
    # vertices (more vertices than quads on a face with a hole: V = F + B/2 by Euler's
    # formula, B the boundary edges); 2 chunks of 4 MB at least
    check(4 * m.get("relaxed_at_quads", 0) >= 3 * 4096 and m["quads"] >= 3 * 4096
          and len(runs[0][0]) > 2 * (4 << 20),
          "%d quads relaxed at %s, %d MB of MSH" % (m["quads"], m.get("relaxed_at_quads"),
                                                   len(runs[0][0]) >> 20))
    for n in (2, 3):
        check(runs[n - 1][0] == runs[0][0], "%d threads, sorted runs: MSH byte-identical" % n)
        check(runs[n - 1][1] == runs[0][1], "%d threads, sorted runs: report identical" % n)


def part6(d):
    out = os.path.join(d, "bad.msh")
    for args, env in ((["--threads", "-1"], None), (["--threads", "x"], None), ([], {"SEMQUAD_THREADS": "x"}),
                      (["--relax-max-quads", "-1"], None)):
        p = run("mesh", STEP, "-q", "-o", out, *args, status=2, env=env)
        lines = [ln for ln in p.stderr.splitlines() if ln.strip()]
        check(len(lines) == 1 and not os.path.exists(out),
              "%s %s: exit 2, one line (%s), no file" % (" ".join(args), env or "", lines[:1]))


def main():
    with tempfile.TemporaryDirectory() as d:
        msh1, rep1 = part1(d)
        part23(d, msh1, rep1)
        part4(d, fine(d, "default"))
        part5(d)
        part6(d)
    if failures:
        sys.exit("%d failed" % len(failures))


main()
