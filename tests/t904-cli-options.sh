#!/bin/sh
# The command line the GNU way (issue 21): every option of every command's
# table (read from the command itself: `semquad completion table`) is in
# that command's --help with its default; --opt=value and --opt value mean
# the same, byte for byte; -- ends the options; an unknown option exits 2
# naming the closest one; the deprecated --order of field and layout warns
# once; --progress=json prints progress events only, writing's as it goes
# (a rising count per mesh format, files unchanged by progress); the bash
# completion script offers the table's options and choices.
# usage: t904-cli-options.sh SEMQUAD EXAMPLES_DIR BASH_COMPLETION
set -u
sq=$1
ex=$2
comp=$3
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fails=0
fail() { echo "$*"; fails=$((fails + 1)); }
tab=$(printf '\t')

"$sq" completion table >"$tmp/table" || fail "semquad completion table failed"
[ "$(cut -f1 "$tmp/table" | sort -u | wc -l)" -eq 6 ] || fail "the table lists $(cut -f1 "$tmp/table" | sort -u | wc -l) commands, not 6"
for c in $(cut -f1 "$tmp/table" | sort -u); do
    "$sq" "$c" --help >"$tmp/help" 2>"$tmp/err" || fail "$c --help: exit $?"
    [ -s "$tmp/err" ] && fail "$c --help wrote to stderr: $(cat "$tmp/err")"
    "$sq" "$c" -h | cmp -s - "$tmp/help" || fail "$c -h differs from $c --help"
    "$sq" help "$c" | cmp -s - "$tmp/help" || fail "semquad help $c differs from $c --help"
    grep -q "^usage: semquad $c " "$tmp/help" || fail "$c --help: no usage line"
    grep -A1 '^example:' "$tmp/help" | grep -q "^  semquad $c " || fail "$c --help: no example"
    grep "^$c$tab" "$tmp/table" | while IFS="$tab" read -r _ name short value def unit alias; do
        grep -qE -- "(^|[ ,])$name( |\$)" "$tmp/help" || echo "$c --help lacks $name"
        [ "$short" = - ] || grep -qE -- "^  $short, $name( |\$)" "$tmp/help" || echo "$c --help lacks $short, $name"
        [ "$alias" = - ] || continue
        # the option's entry, up to the next option, on one line: its help,
        # then its default (and unit)
        line=$(awk -v n="$name" '/^  (-[a-z], |    )--/ {on = ($0 ~ "^  (-[a-z], |    )" n "( |$)")} /^$/ {on = 0} on' "$tmp/help" | tr -s ' \n' '  ')
        case $line in *"(default: $def"*) ;; *) echo "$c $name: default '$def' not in: $line" ;; esac
        [ "$unit" = - ] || case $line in *"unit: $unit)"*) ;; *) echo "$c $name: unit '$unit' not in: $line" ;; esac
    done >"$tmp/missing"
    [ -s "$tmp/missing" ] && { cat "$tmp/missing"; fails=$((fails + 1)); }
done
grep -q "^mesh${tab}--field-order$tab" "$tmp/table" && grep -q "^field${tab}--field-order$tab" "$tmp/table" &&
    grep -q "^layout${tab}--field-order$tab" "$tmp/table" || fail "--field-order is not in mesh, field and layout"

# --size=0.1 and --size 0.1: the same mesh, byte for byte (through standard output)
"$sq" mesh "$ex/half_disc.step" --size=0.1 -q -o - >"$tmp/eq.msh" 2>"$tmp/err" || fail "--size=0.1: $(cat "$tmp/err")"
"$sq" mesh "$ex/half_disc.step" --size 0.1 -q -o - >"$tmp/sp.msh" 2>"$tmp/err" || fail "--size 0.1: $(cat "$tmp/err")"
[ -s "$tmp/eq.msh" ] && cmp -s "$tmp/eq.msh" "$tmp/sp.msh" || fail "--size=0.1 and --size 0.1 differ"
head -2 "$tmp/eq.msh" | grep -q '^4.1 0 8' || fail "-o - is not MSH 4.1"
# ... and the same bytes written to a file, options after --
"$sq" mesh -q --size=0.1 --output="$tmp/f.msh" -- "$ex/half_disc.step" || fail "mesh ... -- FILE failed"
cmp -s "$tmp/eq.msh" "$tmp/f.msh" || fail "-o - and -o FILE differ"
# the summary goes to stderr when the mesh goes to stdout
"$sq" mesh "$ex/half_disc.step" --size 0.3 -o - >"$tmp/o.msh" 2>"$tmp/err"
grep -q "quads, order 4" "$tmp/err" && ! grep -q "quads, order" "$tmp/o.msh" || fail "-o -: the summary is not on stderr alone"

# expect STATUS WORDS ARGS...: exit status, one stderr line holding WORDS
expect() {
    want=$1; words=$2; shift 2
    "$sq" "$@" >"$tmp/out" 2>"$tmp/err"
    got=$?
    [ "$got" -eq "$want" ] || fail "$*: exit $got, expected $want: $(cat "$tmp/err")"
    [ "$(wc -l <"$tmp/err")" -eq 1 ] || fail "$*: stderr is not one line: $(cat "$tmp/err")"
    grep -qF -- "$words" "$tmp/err" || fail "$*: stderr lacks '$words': $(cat "$tmp/err")"
}
expect 2 "unknown option --ordr (did you mean --order?)" mesh "$ex/half_disc.step" --ordr 3
expect 2 "unknown option --feild-order (did you mean --field-order?)" field "$ex/half_disc.step" --feild-order=3
expect 2 "unknown option --bogus (try: semquad mesh --help)" mesh "$ex/half_disc.step" --bogus
expect 2 "unknown option -x" triangulate "$ex/half_disc.step" -x
expect 2 "option --bl- is ambiguous (--bl-first, --bl-ratio, ...)" mesh "$ex/half_disc.step" --bl- 2
expect 2 "option --size needs a value" mesh "$ex/half_disc.step" --size
expect 2 "option --no-output takes no value" mesh "$ex/half_disc.step" --no-output=1
expect 2 "--size expects a number" mesh "$ex/half_disc.step" --size=abc
expect 2 "one input file expected" mesh "$ex/half_disc.step" "$ex/square.step"
expect 2 "--format expects msh, xml or vtu" mesh "$ex/half_disc.step" --format stl
expect 2 "-o and --no-output" mesh "$ex/half_disc.step" -o "$tmp/x.msh" --no-output
expect 2 "only one output can go to standard output" mesh "$ex/half_disc.step" -o - --report -
expect 2 "help: unknown command" help frobnicate
expect 2 "mesh --svg: cannot go to standard output" mesh "$ex/half_disc.step" --svg -
expect 2 "layout --output: cannot go to standard output" layout "$ex/half_disc.step" -o -
# the deprecated spelling: one warning line, the same result as the new one
for c in field layout; do
    "$sq" $c "$ex/square.step" --field-order 3 --report "$tmp/new.json" >"$tmp/new" 2>"$tmp/err" || fail "$c --field-order 3: $(cat "$tmp/err")"
    "$sq" $c "$ex/square.step" --order 3 --report "$tmp/old.json" >"$tmp/old" 2>"$tmp/err" || fail "$c --order 3: $(cat "$tmp/err")"
    [ "$(grep -c deprecated "$tmp/err")" -eq 1 ] &&
        grep -q "warning: $c: --order is deprecated, use --field-order" "$tmp/err" || fail "$c --order: no single deprecation line: $(cat "$tmp/err")"
    grep -q '"order": 3' "$tmp/old.json" || fail "$c --order 3: the report's field order is not 3"
    cmp -s "$tmp/new" "$tmp/old" || fail "$c: --order 3 and --field-order 3 print different summaries"
    "$sq" $c "$ex/square.step" --order 3 -q >/dev/null 2>"$tmp/err"
    [ -s "$tmp/err" ] && fail "$c --order -q wrote to stderr: $(cat "$tmp/err")"
done
# progress: one JSON object per event with --progress=json (even with -q);
# no bar where stderr is not a terminal
"$sq" mesh "$ex/half_disc.step" --size 0.3 -q --progress=json -o "$tmp/p.msh" 2>"$tmp/err" >/dev/null ||
    fail "--progress=json: $(cat "$tmp/err")"
grep -vqE '^\{"stage": "(trace|mesh|relax|write)", "done": [0-9]+, "total": [0-9]+\}$' "$tmp/err" &&
    fail "--progress=json: a line that is not a progress event: $(grep -vE '^\{"stage"' "$tmp/err" | head -3)"
for s in trace mesh relax write; do grep -q "\"stage\": \"$s\"" "$tmp/err" || fail "--progress=json: no $s event"; done
sed -E 's/.*"done": ([0-9]+), "total": ([0-9]+).*/\1 \2/' "$tmp/err" | awk '$1 > $2 {bad = 1} END {exit bad}' ||
    fail "--progress=json: done above total"
tail -1 "$tmp/err" | grep -qE '^\{"stage": "write", "done": ([0-9]+), "total": \1\}$' || fail "--progress=json: the last event is not the write's end"
# writing reports as it goes (issue 21): for each format, from 0 up to total
# in at most ~100 steps, done rising; the file is byte for byte the one
# written without progress
for f in msh xml vtu svg; do
    "$sq" mesh "$ex/square_hole.step" --size 0.02 -q --progress=json -o "$tmp/json.$f" 2>"$tmp/err" >/dev/null ||
        fail "square_hole --progress=json -o .$f: $(cat "$tmp/err")"
    "$sq" mesh "$ex/square_hole.step" --size 0.02 -q --progress=none -o "$tmp/none.$f" 2>/dev/null >/dev/null
    cmp -s "$tmp/json.$f" "$tmp/none.$f" || fail "square_hole .$f: --progress=json changes the file written"
    grep '"stage": "write"' "$tmp/err" | sed -E 's/.*"done": ([0-9]+), "total": ([0-9]+).*/\1 \2/' >"$tmp/write"
    awk -v f=$f 'NR == 1 && $1 != 0 {print f ": the first write event is at " $1; bad = 1}
                 NR > 1 && ($1 <= d || $2 != t) {print f ": write event " $1 " of " $2 " after " d " of " t; bad = 1}
                 {d = $1; t = $2}
                 END {if (NR < 10 || NR > 102) {print f ": " NR " write events"; bad = 1}
                      if (d != t) {print f ": writing ended at " d " of " t; bad = 1}
                      exit bad}' "$tmp/write" || fail "square_hole .$f: write events wrong"
done
"$sq" mesh "$ex/half_disc.step" --size 0.3 --no-output 2>"$tmp/err" >/dev/null
grep -q "$(printf '\r')" "$tmp/err" && fail "a progress bar on a stderr that is not a terminal"
expect 2 "--progress expects auto, json or none" mesh "$ex/half_disc.step" --progress=bar
"$sq" --version | grep -qE '^semquad [0-9]+\.[0-9]+\.[0-9]+$' || fail "--version"

# bash completion: generated from the same tables
bash -n "$comp" || fail "the bash completion script does not parse"
complete_words() { # WORD... : what completing the last word offers
    bash -c '. "$1"; shift; COMP_WORDS=("$@"); COMP_CWORD=$(($# - 1)); _semquad; echo "${COMPREPLY[*]}"' _ "$comp" "$@"
}
[ "$(complete_words semquad mesh --ord)" = "--order --orders" ] || fail "completing mesh --ord: $(complete_words semquad mesh --ord)"
[ "$(complete_words semquad mesh --road '')" = "auto layout split" ] || fail "completing mesh --road: $(complete_words semquad mesh --road '')"
[ "$(complete_words semquad fi)" = "field" ] || fail "completing fi: $(complete_words semquad fi)"
complete_words semquad field --fi | grep -q -- "--field-order" || fail "completing field --fi: $(complete_words semquad field --fi)"
if command -v zsh >/dev/null 2>&1; then
    "$sq" completion zsh >"$tmp/_semquad" && zsh -n "$tmp/_semquad" || fail "the zsh completion script does not parse"
fi

[ "$fails" -eq 0 ]
