"""Test helper: bench/stress_corpus.py, the stress corpus's generator, imported
from the path a test is given, or the test skipped (exit 77) without Debian's
python3-gmsh, which the generator writes its STEP files with."""
import os
import sys


def load_stress_corpus(gen):
    sys.path.insert(0, os.path.dirname(os.path.abspath(gen)))
    try:
        import stress_corpus  # noqa: E402 (needs Debian's python3-gmsh)
    except ImportError:
        sys.exit(77)
    return stress_corpus
