#!/usr/bin/python3
"""The layout repairs' work bound (issue 14): stress-corpus face 53 (seed 1, a
plate with holes, written by bench/stress_corpus.py) traces 130 separatrices of
1e5 points with 1.6e4 crossings, and its repairs, one crossing or limit cycle a
pass with every crossing found again, ran past 120 s.  They now stop at a bound
on the work (separatrix points visited, the same on every machine), so
`semquad layout` answers: exit 0, or exit 6 with one stderr line that says the
repairs stopped at their bound, no signal.  FACE_TIMEOUT is no tolerance on a
measured time: it only turns a hang into a failure (30 s of one core in all,
the default route making three layout attempts; without the bound, 400 passes
of about 1.5 s each an attempt).
usage: t518-layout-work-bound.py SEMQUAD STRESS_CORPUS_PY"""
import os
import subprocess
import sys
import tempfile

sq, gen = sys.argv[1:3]
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from stress_gen import load_stress_corpus  # noqa: E402 (the tests' own helper)

stress_corpus = load_stress_corpus(gen)

FACE_TIMEOUT = 300
if os.environ.get("ASAN_OPTIONS"):  # the sanitized build runs several times slower
    FACE_TIMEOUT *= 4


def main():
    with tempfile.TemporaryDirectory() as tmp:
        e = stress_corpus.generate(tmp, 1, [53])[0]
        path = os.path.join(tmp, e["file"])
        try:
            p = subprocess.run([sq, "layout", path, "-q"], capture_output=True, text=True,
                               timeout=FACE_TIMEOUT)
        except subprocess.TimeoutExpired:
            print("%s: no answer after %d s" % (e["file"], FACE_TIMEOUT))
            return 1
    err = [ln for ln in p.stderr.splitlines() if ln.strip()]
    if p.returncode == 0:
        return 0
    if p.returncode != 6 or len(err) != 1 or "work bound" not in err[0]:
        print("%s: exit %d, %d stderr lines, expected 0, or 6 with the work bound named: %s"
              % (e["file"], p.returncode, len(err), " | ".join(err)))
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
