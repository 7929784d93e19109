#!/usr/bin/python3
"""The corner-grading budget (issue 14): stress-corpus face 60 (seed 1, a star
of 462 sharp corners, written by bench/stress_corpus.py) had its guiding
field's triangulation graded at every corner, 25 278 triangles at P = 8 against
1 518 ungraded, and took 5.9 GB and 17 s of CPU.  The graded triangulation now
has at most max(4000, 2 × the ungraded one's) triangles (GRADING_BUDGET_MIN and
GRADING_BUDGET_RATIO of src/field/field_analysis.c, docs/field.md): the bound
is exact, a count of triangles, the same on every machine.  That the grading
is still there (more triangles than ungraded) is checked too: the budget
coarsens the innermost rings, it does not drop them unless it must.  The peak
memory (the sparse system and its factor, about 230 KB per triangle at P = 8
with DG) is checked against 2 GB, about twice what the budget allows (4000 ×
230 KB = 0.9 GB), skipped in a sanitized build.
usage: t404-grading-budget.py SEMQUAD STRESS_CORPUS_PY"""
import json
import os
import resource
import subprocess
import sys
import tempfile

sq, gen = sys.argv[1:3]
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from stress_gen import load_stress_corpus  # noqa: E402 (the tests' own helper)

stress_corpus = load_stress_corpus(gen)

BUDGET_MIN, BUDGET_RATIO = 4000, 2
PEAK_KB = 2 * 1024 * 1024


def triangles(path, report, *extra):
    subprocess.run([sq, "field", path, "-q", "--report", report] + list(extra), check=True,
                   stdout=subprocess.DEVNULL, timeout=300)
    with open(report) as fh:
        return json.load(fh)["field"]["triangles"]


def main():
    with tempfile.TemporaryDirectory() as tmp:
        e = stress_corpus.generate(tmp, 1, [60])[0]
        path = os.path.join(tmp, e["file"])
        graded = triangles(path, os.path.join(tmp, "g.json"))
        peak = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss
        plain = triangles(path, os.path.join(tmp, "u.json"), "--no-grading")
    budget = max(BUDGET_MIN, BUDGET_RATIO * plain)
    fails = 0
    if not plain < graded <= budget:
        print("%s: %d graded triangles, expected in (%d, %d] (%d ungraded)"
              % (e["file"], graded, plain, budget, plain))
        fails += 1
    if not os.environ.get("ASAN_OPTIONS") and peak > PEAK_KB:
        print("%s: peak memory %d KB, expected <= %d KB (%d triangles)"
              % (e["file"], peak, PEAK_KB, graded))
        fails += 1
    return 1 if fails else 0


if __name__ == "__main__":
    sys.exit(main())
