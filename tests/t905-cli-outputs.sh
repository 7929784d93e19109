#!/bin/sh
# Outputs by default and only where they belong (issue 21): mesh without -o
# writes <input stem>.msh in the current directory and says so (or the
# format --format names; nothing with --no-output); an output naming a
# FIFO, a directory or a device is refused with exit 2 before any work,
# and the thing it names is left as it was.
# usage: t905-cli-outputs.sh SEMQUAD EXAMPLES_DIR
set -u
sq=$(cd "$(dirname "$1")" && pwd)/$(basename "$1") # absolute: the test changes directory
ex=$(cd "$2" && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fails=0
fail() { echo "$*"; fails=$((fails + 1)); }

mkdir "$tmp/run" && cd "$tmp/run" || exit 1
"$sq" mesh "$ex/half_disc.step" --size 0.3 >"$tmp/out" 2>"$tmp/err" || fail "mesh without -o: $(cat "$tmp/err")"
[ -s half_disc.msh ] && head -2 half_disc.msh | grep -q '^4.1 0 8' || fail "mesh without -o wrote no half_disc.msh: $(ls)"
grep -qx "semquad: note: no -o given: wrote half_disc.msh" "$tmp/err" || fail "mesh without -o does not say where it wrote: $(cat "$tmp/err")"
"$sq" mesh "$ex/half_disc.step" --size 0.3 -o "$tmp/ref.msh" -q && cmp -s half_disc.msh "$tmp/ref.msh" || fail "the default output differs from -o's"
rm -f half_disc.msh
"$sq" mesh "$ex/half_disc.step" --size 0.3 --format xml -q 2>"$tmp/err" && [ -s half_disc.xml ] && [ ! -s "$tmp/err" ] ||
    fail "--format xml -q: $(ls) $(cat "$tmp/err")"
grep -q '<NEKTAR>' half_disc.xml || fail "half_disc.xml is not Nektar++ XML"
"$sq" mesh "$ex/half_disc.step" --size 0.3 --format vtu -o "$tmp/vtu.dat" -q && grep -q 'VTKFile' "$tmp/vtu.dat" || fail "--format vtu -o vtu.dat"
rm -f half_disc.xml
"$sq" mesh "$ex/half_disc.step" --size 0.3 --no-output --report "$tmp/r.json" >"$tmp/out" 2>"$tmp/err" || fail "--no-output: $(cat "$tmp/err")"
[ -z "$(ls)" ] || fail "--no-output wrote $(ls)"
grep -q '"quads"' "$tmp/r.json" && grep -q "quads, order 4" "$tmp/out" || fail "--no-output: no report or summary"

# expect WHAT ARGS...: exit 2 in one stderr line naming the path, before any
# work (no stage line), no file written
expect() {
    what=$1; shift
    "$sq" "$@" >"$tmp/out" 2>"$tmp/err"
    got=$?
    [ "$got" -eq 2 ] || fail "$what: exit $got, expected 2: $(cat "$tmp/err")"
    [ "$(wc -l <"$tmp/err")" -eq 1 ] || fail "$what: stderr is not one line: $(cat "$tmp/err")"
    grep -q "outputs are written to regular files" "$tmp/err" || fail "$what: $(cat "$tmp/err")"
    [ -z "$(ls "$tmp/run")" ] || fail "$what: wrote $(ls "$tmp/run")"
}
mkfifo "$tmp/f.msh" "$tmp/f.json"
mkdir "$tmp/d.msh" "$tmp/d.svg"
expect "mesh -o FIFO" mesh "$ex/half_disc.step" -o "$tmp/f.msh"
grep -q "f.msh is a FIFO" "$tmp/err" || fail "the FIFO is not named as one: $(cat "$tmp/err")"
expect "mesh -o DIR" mesh "$ex/half_disc.step" -o "$tmp/d.msh"
grep -q "d.msh is a directory" "$tmp/err" || fail "the directory is not named as one: $(cat "$tmp/err")"
expect "mesh --report FIFO" mesh "$ex/half_disc.step" --report "$tmp/f.json" --no-output
expect "triangulate --svg DIR" triangulate "$ex/half_disc.step" --svg "$tmp/d.svg"
expect "field --report FIFO" field "$ex/half_disc.step" --report "$tmp/f.json"
expect "layout -o DIR" layout "$ex/half_disc.step" -o "$tmp/d.msh"
expect "converge --csv FIFO" converge "$ex/square.step" --csv "$tmp/f.json" --orders 1-2
expect "mesh -o /dev/null" mesh "$ex/half_disc.step" -o /dev/null
mkdir half_disc.msh
"$sq" mesh "$ex/half_disc.step" >"$tmp/out" 2>"$tmp/err"
[ $? -eq 2 ] && grep -q "half_disc.msh is a directory" "$tmp/err" || fail "default output onto a directory: $(cat "$tmp/err")"
rmdir half_disc.msh
[ -p "$tmp/f.msh" ] && [ -p "$tmp/f.json" ] || fail "a FIFO was replaced"
[ -d "$tmp/d.msh" ] && [ -d "$tmp/d.svg" ] || fail "a directory was replaced"

[ "$fails" -eq 0 ]
