#!/bin/sh
# semquad field --singularities: exit 5 with the explanation for a pattern
# breaking Gauss-Bonnet or with a bad line, exit 0 with VTU (H, theta), SVG
# and a JSON report of kind H-theta otherwise; the holonomy warning names
# the loop; semquad layout with a pattern giving an obtuse vertex one quad
# (a boundary valence-2 point) repairs it by the valence-2 split; mesh sizes
# follow e^H; semquad mesh on the disc splits its degenerate centre (a note
# on stderr).  usage: t420-cli-htheta.sh SEMQUAD EXAMPLES_DIR
set -u
sq=$1
ex=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fails=0
fail() { echo "$1"; fails=$((fails + 1)); }

"$sq" field "$ex/square.step" --singularities "$ex/square_bad.txt" --report "$tmp/o.json" \
    >/dev/null 2>"$tmp/err"
[ $? -eq 5 ] || fail "square_bad: exit status not 5"
grep -q "4.712389 (3 x pi/2) but 2 pi chi = 6.283185" "$tmp/err" || fail "square_bad: $(cat "$tmp/err")"
grep -q "add one valence-3 point or remove one valence-5 point" "$tmp/err" || fail "square_bad: no fix"
[ -e "$tmp/o.json" ] && fail "square_bad: left a report"

printf '0.5 0.5 3\n0.5 0.5 x\n' >"$tmp/bad.txt"
"$sq" field "$ex/square.step" --singularities "$tmp/bad.txt" >/dev/null 2>"$tmp/err"
[ $? -eq 5 ] || fail "bad line: exit status not 5"
grep -q "bad.txt:2:" "$tmp/err" || fail "bad line: $(cat "$tmp/err")"

printf '0.5 0.5 3\n2 2 3\n' >"$tmp/out.txt"
"$sq" field "$ex/square.step" --singularities "$tmp/out.txt" >/dev/null 2>"$tmp/err"
[ $? -eq 5 ] || fail "outside: exit status not 5"
grep -q "line 2: point (2, 2) lies outside" "$tmp/err" || fail "outside: $(cat "$tmp/err")"

"$sq" field "$ex/square.step" --singularities "$tmp/missing.txt" >/dev/null 2>&1
[ $? -eq 3 ] || fail "missing pattern file: exit status not 3"

"$sq" field "$ex/square.step" --singularities "$ex/square_v8.txt" --vtu "$tmp/o.vtu" \
    --svg "$tmp/o.svg" --report "$tmp/o.json" >/dev/null 2>"$tmp/err"
[ $? -eq 0 ] || fail "square_v8: exit status not 0: $(cat "$tmp/err")"
grep -q '"kind": *"H-theta"' "$tmp/o.json" || fail "square_v8: report kind"
grep -q '"origin": *"imposed"' "$tmp/o.json" || fail "square_v8: origin"
grep -q '"theta_jumps"' "$tmp/o.json" || fail "square_v8: no theta_jumps"
grep -q 'Name="H"' "$tmp/o.vtu" || fail "square_v8: VTU without H"
grep -q 'Name="theta"' "$tmp/o.vtu" || fail "square_v8: VTU without theta"
grep -q '<svg' "$tmp/o.svg" || fail "square_v8: no SVG"

"$sq" field "$ex/square_hole.step" --singularities "$ex/square_hole_twisted.txt" >/dev/null \
    2>"$tmp/err"
[ $? -eq 0 ] || fail "twisted: exit status not 0"
grep -q "misaligned by -19.1[0-9]* deg with boundary loop 1" "$tmp/err" || fail "twisted: $(cat "$tmp/err")"

"$sq" field "$ex/triangle.step" --singularities natural --report "$tmp/t.json" >/dev/null 2>&1
[ $? -eq 0 ] || fail "triangle natural: exit status not 0"
grep -q '"origin": *"critical-point"' "$tmp/t.json" || fail "triangle natural: origin"
# naca0012's natural pattern: the H field's curvature data near the sharp
# trailing edge balances its point sources only to quadrature accuracy
# (5e-6 relative), which the pure-Neumann check must accept
"$sq" field "$ex/naca0012.step" --singularities natural -q >/dev/null 2>"$tmp/err"
[ $? -eq 0 ] || fail "naca0012 natural: exit status not 0: $(cat "$tmp/err")"
"$sq" layout "$ex/obtuse_quad.step" --singularities "$ex/obtuse_quad_v2.txt" \
    --report "$tmp/q.json" --svg "$tmp/q.svg" >/dev/null 2>"$tmp/err"
[ $? -eq 0 ] || fail "obtuse_quad valence-2: exit status not 0: $(cat "$tmp/err")"
grep -q '"valence2_split": *1,' "$tmp/q.json" || fail "obtuse_quad valence-2: not split once"
grep -q '"quad_patches": *3,' "$tmp/q.json" || fail "obtuse_quad valence-2: not 3 quad patches"
grep -q '"origin": *"valence2-split"' "$tmp/q.json" || fail "obtuse_quad valence-2: node origin"
grep -q 'valence-2 point' "$tmp/q.svg" || fail "obtuse_quad valence-2: not marked in the SVG"
# the mesh command's own H/θ settings (order 8, grading 1e-2) keep the
# pattern aligned with the boundary (at order 6: 0.016 deg, over 0.01)
"$sq" mesh "$ex/obtuse_quad.step" --singularities "$ex/obtuse_quad_v2.txt" --size 0.1 -q \
    -o "$tmp/q.msh" --report "$tmp/qm.json" 2>"$tmp/err"
[ $? -eq 0 ] || fail "obtuse_quad valence-2 mesh: exit status not 0: $(cat "$tmp/err")"
grep -q '"irregular_interior_vertices": *1,' "$tmp/qm.json" ||
    fail "obtuse_quad valence-2 mesh: not 1 interior irregular vertex"
# mesh sizes from e^H (Jezdimirović 2021 eq. 21): on the triangle the three
# kite patches take 4 x 4 quads each, about area / size^2 = 43.3 quads — with
# a uniform size their short spokes would be refined to match the 0.5-long
# boundary sides (5 x 5 each, 75 quads, the guiding-field mesh)
"$sq" mesh "$ex/triangle.step" --singularities natural --size 0.1 -q -o "$tmp/t.msh" \
    --report "$tmp/tm.json" 2>"$tmp/err"
[ $? -eq 0 ] || fail "triangle natural mesh: exit status not 0: $(cat "$tmp/err")"
grep -q '"quads": *48,' "$tmp/tm.json" || fail "triangle natural mesh: not 48 quads (e^H sizes)"
"$sq" mesh "$ex/triangle.step" --size 0.1 -q -o "$tmp/t.msh" --report "$tmp/tg.json" 2>/dev/null
grep -q '"quads": *75,' "$tmp/tg.json" || fail "triangle guiding mesh: not 75 quads"

# a degenerate critical point (the disc's index-4 centre) is split into four
# valence-3 points, said on stderr, and meshed on their H/theta field
"$sq" mesh "$ex/disc.step" --no-output --report "$tmp/d.json" >/dev/null 2>"$tmp/err"
[ $? -eq 0 ] || fail "disc mesh: exit status not 0: $(cat "$tmp/err")"
grep -q "1 degenerate singular point .* split into 4 elementary points" "$tmp/err" ||
    fail "disc mesh: no note on the split: $(cat "$tmp/err")"
grep -q '"irregular_interior_vertices": *4' "$tmp/d.json" || fail "disc mesh: irregular vertices"
grep -q '"inverted": *0' "$tmp/d.json" || fail "disc mesh: inverted quads"
exit $((fails != 0))
