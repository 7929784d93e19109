#!/bin/sh
# The public API as a user gets it (issue 15): `meson install` into a
# temporary prefix, examples/api/mesh_face.c compiled with nothing but
# `pkg-config --cflags --libs semquad` and <semquad.h>, half_disc meshed at
# order 4: the same quads and area as the command's report.  The library
# exports only sq_ symbols; the command and the example need no other
# library of semquad.
# args: BUILD_DIR SEMQUAD EXAMPLES PREFIX LIBDIR CC SANITIZE
set -u
build=$1 semquad=$2 examples=$3 prefix=$4 libdir=$5 cc=$6 sanitize=$7
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "$*"; exit 1; }

meson install -C "$build" --destdir "$tmp/root" --no-rebuild --quiet >/dev/null ||
    fail "meson install into $tmp/root failed"
root=$tmp/root
case $libdir in /*) lib=$root$libdir ;; *) lib=$root$prefix/$libdir ;; esac
for f in "$lib/libsemquad.so" "$lib/libsemquad.a" "$lib/pkgconfig/semquad.pc" \
         "$root$prefix/include/semquad.h" "$root$prefix/bin/semquad"; do
    [ -e "$f" ] || fail "not installed: $f"
done

# Only the public API leaves the library.
others=$(nm -D --defined-only "$lib/libsemquad.so" | awk '{print $3}' | grep -v '^sq_')
[ -z "$others" ] || fail "libsemquad.so exports non-sq_ symbols: $(echo $others | head -c 300)"
# Every exported symbol is declared in the header.
for s in $(nm -D --defined-only "$lib/libsemquad.so" | awk '{print $3}'); do
    grep -q "\\b$s(" "$root$prefix/include/semquad.h" || fail "$s exported, not in semquad.h"
done
# The installed command links libsemquad and no static copy of its stages.
readelf -d "$root$prefix/bin/semquad" | grep -q 'NEEDED.*libsemquad\.so' ||
    fail "the installed semquad does not link libsemquad.so"

export PKG_CONFIG_SYSROOT_DIR="$root" PKG_CONFIG_PATH="$lib/pkgconfig"
flags=$(pkg-config --cflags --libs semquad) || fail "pkg-config --cflags --libs semquad failed"
san=
[ "$sanitize" = none ] || san="-fsanitize=$sanitize"
# shellcheck disable=SC2086
$cc -std=c11 -Wall -Werror $san "$examples/api/mesh_face.c" $flags -o "$tmp/mesh_face" ||
    fail "examples/api/mesh_face.c does not compile against the installed library"

LD_LIBRARY_PATH="$lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}" \
    "$tmp/mesh_face" "$examples/half_disc.step" 4 "$tmp/api.msh" >"$tmp/out" 2>"$tmp/err" ||
    fail "mesh_face failed: $(cat "$tmp/err")"
"$semquad" mesh "$examples/half_disc.step" --order 4 -q -o "$tmp/cli.msh" \
    --report "$tmp/cli.json" || fail "semquad mesh failed"
cmp -s "$tmp/api.msh" "$tmp/cli.msh" || fail "the example's MSH differs from the command's"

# Same library, same input: the same quads, and the area to the report's
# printed digits (%.17g there, %.15g here: a relative 1e-14 covers the
# rounding of the two printings).
/usr/bin/python3 - "$tmp/out" "$tmp/cli.json" <<'PY' || exit 1
import json, sys
out = dict(l.split(None, 1) for l in open(sys.argv[1]).read().splitlines())
rep = json.load(open(sys.argv[2]))
quads, area = int(out["quads"]), float(out["area"])
want_q, want_a = rep["mesh"]["quads"], rep["mesh"]["area"]
if quads != want_q:
    sys.exit(f"quads {quads}, the command's {want_q}")
if abs(area - want_a) > 1e-14 * abs(want_a):
    sys.exit(f"area {area!r}, the command's {want_a!r} (tolerance 1e-14 relative)")
if int(out["order"]) != 4 or float(out["min_scaled_jacobian"]) <= 0:
    sys.exit(f"order {out['order']}, min scaled Jacobian {out['min_scaled_jacobian']}")
PY

# A bad file: the example exits with the input status, one line.
LD_LIBRARY_PATH="$lib" "$tmp/mesh_face" "$tmp/none.step" >/dev/null 2>"$tmp/err"
st=$?
[ $st -eq 3 ] || fail "missing file: exit $st, expected 3"
[ "$(wc -l <"$tmp/err")" -eq 1 ] || fail "missing file: stderr not one line: $(cat "$tmp/err")"
exit 0
