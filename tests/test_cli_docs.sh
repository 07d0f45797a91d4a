#!/usr/bin/env bash
# The ranges and defaults the commands' --help states (written from the
# option tables, src/cli/) are the ones the documentation states:
# - docs/cli.md has one table row per option of each command, with the
#   help's range and default, and no row for an option the command lacks;
# - wherever else the documents (docs/*.md, README.md) write a range next to
#   options, in a paragraph, it is a range of one of those options.
# A range is written a..b (whole numbers) or (a, b] (numbers).
# usage: test_cli_docs.sh BUILD_DIR SOURCE_DIR
set -u
bin="$1/intercurve"
src="$2"
pass=0
fail=0
check() { # description, condition status
    if [ "$2" -eq 0 ]; then pass=$((pass + 1)); else fail=$((fail + 1)); echo "FAIL: $1"; fi
}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# From each help: "cmd|option|range|default" (range and default may be
# empty); the range without its value's name ("K in ", "one of ").
for cmd in eval point trace plot surfaces verify; do
    "$bin" $cmd --help >"$tmp/help.$cmd"
    check "$cmd --help exits 0" $?
    opt="" meta="" range="" default=""
    flush() {
        [ -n "$opt" ] && echo "$cmd|$opt|$range|$default" >>"$tmp/help.table"
        opt="" meta="" range="" default=""
    }
    while IFS= read -r line; do
        if [[ $line =~ ^\ \ (-[-a-z]+)(\ ([^ ]+))?\ \  ]]; then
            flush
            [ "${BASH_REMATCH[1]}" = -h ] && continue
            opt="${BASH_REMATCH[1]}" meta="${BASH_REMATCH[3]}"
            continue
        fi
        [[ $line =~ ^\ {4} ]] || { flush; continue; }
        [ -n "$opt" ] || continue
        line="${line#"${line%%[! ]*}"}" # leading blanks
        if [[ $line =~ ^default\ (.*)$ ]]; then
            default="${BASH_REMATCH[1]}"
            continue
        fi
        if [[ $line =~ ^(.*)\;\ default\ (.*)$ ]]; then
            line="${BASH_REMATCH[1]}" default="${BASH_REMATCH[2]}"
        fi
        if [[ $line == "$meta in "* ]]; then
            range="${line#"$meta in "}"
        elif [[ $line == "one of "* ]]; then
            range="${line#one of }"
        elif [[ $line == "W in "* || $line == "$meta > "* ]]; then
            range="$line"
        fi
    done <"$tmp/help.$cmd"
    flush
done
[ "$(grep -c . "$tmp/help.table")" -ge 20 ]
check "the options of the five commands read from their help ($(wc -l <"$tmp/help.table"))" $?

# docs/cli.md: "cmd|option|range|default" from the table under
# "### intercurve CMD" (the option's name is the first word in backquotes).
sed 's/\\|/¦/g' "$src/docs/cli.md" | awk -F'|' '
    /^### intercurve / { cmd = $0; sub(/^### intercurve /, "", cmd); next }
    /^## / { cmd = "" }
    cmd != "" && /^\| `-/ {
        name = $2; sub(/^ *`/, "", name); sub(/[ `].*$/, "", name)
        range = $4; default = $5
        gsub(/^ +| +$/, "", range); gsub(/^ +| +$/, "", default); gsub(/¦/, "|", range)
        print cmd "|" name "|" range "|" default
    }' >"$tmp/docs.table"

while IFS='|' read -r cmd opt range default; do
    row=$(grep -F "$cmd|$opt|" "$tmp/docs.table" | head -1)
    check "docs/cli.md has a row for $cmd $opt" $([ -n "$row" ]; echo $?)
    [ -n "$row" ] || continue
    IFS='|' read -r _ _ drange ddefault <<<"$row"
    [ "$drange" = "$range" ]
    check "$cmd $opt: docs/cli.md's range '$drange' is the help's '$range'" $?
    if [ -n "$default" ]; then
        [ "$ddefault" = "$default" ]
        check "$cmd $opt: docs/cli.md's default '$ddefault' is the help's '$default'" $?
    fi
done <"$tmp/help.table"
while IFS='|' read -r cmd opt _; do
    grep -qF "$cmd|$opt|" "$tmp/help.table"
    check "docs/cli.md's $cmd $opt is an option of $cmd --help" $?
done <"$tmp/docs.table"

# Every other page: in a paragraph that names options, each range is one
# of theirs. "option|token" pairs from the help (a size has two ranges).
while IFS='|' read -r _ opt range _; do
    echo "$range" | grep -oE '[0-9]+\.\.[0-9]+|\([^,]+, [^]]+\]' | sed "s/^/$opt|/"
done <"$tmp/help.table" | sort -u >"$tmp/tokens"
for page in "$src"/docs/*.md "$src/README.md"; do
    awk -v tokens="$tmp/tokens" -v page="${page#"$src"/}" '
        BEGIN {
            while ((getline l < tokens) > 0) { split(l, f, "|"); ok[f[1] "|" f[2]] = 1 }
            RS = "" # then one record per paragraph
        }
        {
            n = 0; rest = $0
            while (match(rest, /--[a-z][a-z-]*/)) {
                opts[++n] = substr(rest, RSTART, RLENGTH); rest = substr(rest, RSTART + RLENGTH)
            }
            if (n == 0) next
            rest = $0
            while (match(rest, /[0-9]+\.\.[0-9]+|\([0-9.e+-]+, [0-9.e+-]+\]/)) {
                t = substr(rest, RSTART, RLENGTH); rest = substr(rest, RSTART + RLENGTH)
                found = 0
                for (i = 1; i <= n; i++) found = found || ((opts[i] "|" t) in ok)
                text = substr($0, 1, 100); gsub(/[|\n]/, " ", text)
                print (found ? "ok" : "FAIL") "|" page "|" t "|" text
            }
        }' "$page"
done >"$tmp/paragraphs"
while IFS='|' read -r verdict page token text; do
    check "$page: the range $token is one of the options' in: $text" \
        $([ "$verdict" = ok ]; echo $?)
done <"$tmp/paragraphs"
# The pages that state these ranges state each of them, as the help has it.
while read -r page cmd opt; do
    tokens=$(grep -F "$cmd|$opt|" "$tmp/help.table" | cut -d'|' -f3 |
        grep -oE '[0-9]+\.\.[0-9]+|\([^,]+, [^]]+\]')
    [ -n "$tokens" ]
    check "$cmd $opt has a range in its help" $?
    for t in $(echo "$tokens" | tr ' ' '#'); do
        t=$(echo "$t" | tr '#' ' ')
        grep -qF "ok|$page|$t|" "$tmp/paragraphs"
        check "$page states $cmd $opt's range $t" $?
    done
done <<'LIST'
docs/conventions.md eval --order
docs/conventions.md point --order
README.md point --order
docs/plots.md plot --size
docs/plots.md plot --frames
docs/plots.md plot --mesh
docs/tracing.md trace --tol
docs/tracing.md trace --depth
docs/tracing.md trace --time-limit
LIST

echo "test_cli_docs: $pass passed, $fail failed"
[ "$fail" -eq 0 ]
