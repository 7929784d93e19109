#!/bin/sh
# Install exactly the Debian 12 packages semquad needs to build, test and draw.
# python3-gmsh (with /usr/bin/python3) is Gmsh's own reader on our MSH
# output: t604, and tests/msh_quad_stats.py (t603, t611, t616).  gmsh (the
# executable, same 4.8.4 library) is what bench/compare_gmsh.py times
# against.  python3-numpy is what tests/cascade_aerofoil.py interpolates its
# B-splines with at build time and what the semquad Python package
# (python/) returns its arrays in, python3-meshio what Mesh.to_meshio
# converts to; t960 runs the package.  python3-scipy's k-d tree is how
# tests/msh_quad_stats.py and t645/t646 match nodes (not pulled in by the
# others: a fresh Debian 12 has none).  parallel (GNU parallel) runs batches
# on one machine: scripts/mesh_parallel.sh, t906 (docs/scale-out.md).
# zlib1g-dev compresses the compressed Nektar++ XML (--binary with xml).
# `--bench` adds what only benchmarks use, not the build or the tests:
# python3-dolfinx (DOLFINx 0.5.2 with PETSc, MPI and FFCx, about 170
# packages), the Navier-Stokes solver of bench/dfg_cylinder.py.
# Idempotent: quiet when everything is present; runs apt-get update only when
# something is missing.
set -eu
BENCH_PKGS="python3-dolfinx"
PKGS="meson ninja-build pkg-config gcc g++ \
libocct-foundation-dev libocct-modeling-data-dev libocct-modeling-algorithms-dev \
libocct-data-exchange-dev \
libcgal-dev libgmp-dev libmpfr-dev \
libgsl-dev liblapacke-dev zlib1g-dev libopenblas-dev libopenblas-serial-dev libsuitesparse-dev \
librsvg2-bin \
python3-gmsh gmsh python3-numpy python3-scipy python3-meshio python3-vtk9 parallel"
case "${1:-}" in
    "") ;;
    --bench) PKGS="$PKGS $BENCH_PKGS" ;;
    *) echo "usage: bootstrap.sh [--bench]" >&2; exit 2 ;;
esac
missing=""
for p in $PKGS; do
    if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
        missing="$missing $p"
    fi
done
[ -z "$missing" ] && exit 0
if [ "$(id -u)" -ne 0 ]; then
    echo "bootstrap: missing packages:$missing (run as root to install)" >&2
    exit 1
fi
echo "bootstrap: installing$missing" >&2
export DEBIAN_FRONTEND=noninteractive
apt-get update -qq >/dev/null
# shellcheck disable=SC2086
apt-get install -y -qq --no-install-recommends $missing >/dev/null
