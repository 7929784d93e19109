#!/bin/sh
# Healing never changes a face that needs no fix (issue 23): every planar
# example meshes to the same bytes with and without --no-heal.
# usage: t338-heal-examples.sh SEMQUAD EXAMPLES_DIR
set -u
sq=$1 examples=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fails=0 n=0
for f in "$examples"/*.step; do
    b=$(basename "$f" .step)
    "$sq" mesh "$f" -q -o "$tmp/$b.msh" 2>/dev/null || continue # not planar (sphere)
    "$sq" mesh "$f" -q --no-heal -o "$tmp/$b.noheal.msh" ||
        { echo "$b: --no-heal fails where healing meshes"; fails=$((fails + 1)); continue; }
    cmp -s "$tmp/$b.msh" "$tmp/$b.noheal.msh" ||
        { echo "$b: the mesh differs with --no-heal"; fails=$((fails + 1)); }
    n=$((n + 1))
done
[ "$n" -ge 12 ] || { echo "only $n examples meshed"; fails=$((fails + 1)); }
[ "$fails" -eq 0 ]
