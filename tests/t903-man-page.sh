#!/bin/sh
# The man page and `semquad help` cannot drift apart: every command the
# help text lists appears in the man page's SYNOPSIS, every option of a
# command's help entry in that command's section (.SS COMMAND up to the
# next section), every option of the help's closing paragraphs (healing)
# somewhere in the page, every exit status in EXIT STATUS; and groff
# formats the page without a warning.
# usage: t903-man-page.sh SEMQUAD MANPAGE
set -u
sq=$1
page=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fails=0

"$sq" help >"$tmp/help" || { echo "semquad help failed"; exit 1; }
# The page as plain text lines: \- is a minus, font changes and the
# \(aq-style escapes dropped, so options read as typed.
sed -e 's/\\-/-/g' -e 's/\\f[BIRP]//g' -e 's/\\([a-z][a-z]//g' "$page" >"$tmp/page"

# Options in a piece of help text: long options anywhere, and short ones
# where they stand as an option ("[-o", "[-q"), not in prose ("-lap u").
options() {
    grep -oE -- '--[a-z][a-z0-9-]*|\[-[a-z]([] ]|$)' | sed -e 's/^\[//' -e 's/[] ]$//' | sort -u
}

# has FILE OPTION: OPTION as a whole word of FILE (--bl is not --bl-first)
has() {
    grep -qE -- "(^|[^-a-z0-9])$2([^-a-z0-9]|\$)" "$1"
}

# The commands: two-space-indented entries between "commands:" and the
# blank line after them; each entry runs until the next one.
awk '/^commands:/ {on = 1; next} on && /^$/ {exit} on' "$tmp/help" >"$tmp/commands"
cmds=$(grep -oE '^  [a-z-]+' "$tmp/commands" | sed 's/^  //')
[ -n "$cmds" ] || { echo "no commands found in semquad help"; exit 1; }
for c in $cmds; do
    if ! grep -qE -- "^\.B semquad $c( |\$)" "$tmp/page"; then
        echo "command '$c' of semquad help is missing from the man page's SYNOPSIS"
        fails=$((fails + 1))
    fi
    case $c in -*) continue ;; esac # --version: an option itself, no section
    awk -v c="$c" '$0 ~ "^  [a-z-]" {on = ($1 == c)} on' "$tmp/commands" | options >"$tmp/opts"
    [ -s "$tmp/opts" ] || continue
    awk -v c="$c" '/^\.S[SH] / {on = ($1 == ".SS" && $2 == c); next} on' "$tmp/page" >"$tmp/section"
    if [ ! -s "$tmp/section" ]; then
        echo "man page has no section '.SS $c' for its options"
        fails=$((fails + 1))
        continue
    fi
    while read -r o; do
        if ! has "$tmp/section" "$o"; then
            echo "option $o of '$c' (semquad help) is missing from the man page's section $c"
            fails=$((fails + 1))
        fi
    done <"$tmp/opts"
done

# Options after the command list (shared by the commands).
awk '/^commands:/ {on = 1} on && /^$/ {after = 1} after' "$tmp/help" | options >"$tmp/opts"
while read -r o; do
    if ! has "$tmp/page" "$o"; then
        echo "option $o of semquad help is missing from the man page"
        fails=$((fails + 1))
    fi
done <"$tmp/opts"

# Exit statuses: "N word" pairs of the help's "exit status:" paragraph,
# each a ".B N" entry of EXIT STATUS.
codes=$(awk '/^exit status:/ {on = 1} on' "$tmp/help" | grep -oE '(^|[ :,])[0-9] [a-z]' | grep -oE '[0-9]')
[ -n "$codes" ] || { echo "no exit statuses found in semquad help"; exit 1; }
awk '/^\.SH / {on = ($0 ~ /^\.SH EXIT STATUS/); next} on' "$tmp/page" >"$tmp/exit"
for n in $codes; do
    if ! grep -qx "\.B $n" "$tmp/exit"; then
        echo "exit status $n of semquad help is missing from the man page's EXIT STATUS"
        fails=$((fails + 1))
    fi
done

# groff's warnings (all of them: -ww), where groff is installed.
if command -v groff >/dev/null 2>&1; then
    groff -man -Tutf8 -ww -z "$page" 2>"$tmp/groff"
    if [ -s "$tmp/groff" ]; then
        echo "groff warns on the man page:"; cat "$tmp/groff"
        fails=$((fails + 1))
    fi
fi

[ "$fails" -eq 0 ] || { echo "$fails problems"; exit 1; }
exit 0
