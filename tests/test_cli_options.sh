#!/usr/bin/env bash
# The command line's one option parser (src/cli/options.c): --opt=value is
# --opt value, - reads the problem from standard input, -- ends the
# options, -h and --help print a help written from the option table; and
# every range the help states is the range the parser accepts: each bound
# accepted, each value just beyond refused with a message naming the
# option, exit status 1 and nothing on standard output.
# usage: test_cli_options.sh BUILD_DIR SOURCE_DIR
set -u
bin="$1/intercurve"
src="$2"
ex="$src/examples"
pass=0
fail=0
check() { # description, condition status
    if [ "$2" -eq 0 ]; then pass=$((pass + 1)); else fail=$((fail + 1)); echo "FAIL: $1"; fi
}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
out="$tmp/out"
errf="$tmp/err"

# the same output both ways (and exit 0)
same() { # description, then two commands separated by ---
    local what="$1"
    shift
    local a=() b=()
    while [ "$1" != --- ]; do a+=("$1"); shift; done
    shift
    b=("$@")
    "$bin" "${a[@]}" >"$tmp/a" 2>"$errf" && "$bin" "${b[@]}" >"$tmp/b" 2>>"$errf" </dev/null
    st=$?
    check "$what: exit 0 ($(head -c 300 "$errf"))" $st
    [ -s "$tmp/a" ] && cmp -s "$tmp/a" "$tmp/b"
    check "$what: the same output" $?
}

# --opt=value is --opt value
same "point --at=... --order=3 --format=text" \
    point "$ex/viviani.json" --at 1.5,0.8660254037844386,1 --order 3 --format text --- \
    point "$ex/viviani.json" --at=1.5,0.8660254037844386,1 --order=3 --format=text
same "eval --surface=sphere --at=pi/5,0.4" \
    eval "$ex/viviani.json" --surface sphere --at pi/5,0.4 --order 2 --- \
    eval "$ex/viviani.json" --surface=sphere --at=pi/5,0.4 --order=2
same "trace --format=csv --depth=5 --tol=1e-9" \
    trace "$ex/viviani-implicit.json" --format csv --depth 5 --tol 1e-9 --- \
    trace "$ex/viviani-implicit.json" --format=csv --depth=5 --tol=1e-9
# an option's value may begin with '-'
same "eval --at -0.3,0.4 is --at=-0.3,0.4" \
    eval "$ex/viviani.json" --at -0.3,0.4 --- eval "$ex/viviani.json" --at=-0.3,0.4

# - is standard input; -- ends the options
"$bin" trace "$ex/viviani-implicit.json" >"$tmp/file.json" 2>"$errf"
"$bin" trace - <"$ex/viviani-implicit.json" >"$tmp/stdin.json" 2>>"$errf"
st=$?
check "trace - < FILE: exit 0 ($(head -c 300 "$errf"))" $st
cmp -s "$tmp/file.json" "$tmp/stdin.json"
check "trace - < FILE: the document of trace FILE" $?
"$bin" point - --at 2,0,0 <"$ex/viviani.json" >"$out" 2>"$errf"
st=$?
check "point - < FILE exits 0 ($(head -c 300 "$errf"))" $st
grep -q '"type":.*"branch-point"' "$out"
check "point - < FILE: Viviani's branch point" $?
"$bin" eval - --at 1,2,3 <"$src/tests/data/one-surface.json" >"$out" 2>"$errf"
st=$?
check "eval - < a file of one surface exits 0 ($(head -c 300 "$errf"))" $st
"$bin" plot - -o "$tmp/stdin.svg" --size 400x300 --mesh 8 <"$ex/viviani-implicit.json" 2>"$errf"
st=$?
check "plot - < FILE -o SVG exits 0 ($(head -c 300 "$errf"))" $st
grep -q '<svg' "$tmp/stdin.svg"
check "plot - < FILE: an SVG" $?
"$bin" eval - --at 1,2,3 <"$src/tests/data/bad-formula.json" >"$out" 2>"$errf"
[ $? -eq 1 ] && grep -qF '<stdin>: surfaces[0].f: column 7' "$errf"
st=$?
check "an error in standard input names <stdin>, the path and the column: $(head -c 300 "$errf")" $st
"$bin" trace -- "$ex/viviani-implicit.json" >"$tmp/dashdash.json" 2>"$errf"
cmp -s "$tmp/file.json" "$tmp/dashdash.json"
check "trace -- FILE: the document of trace FILE" $?

# --help and -h: exit 0, the usage first, an example, even among bad arguments
for cmd in eval point trace plot; do
    "$bin" $cmd --help >"$out" 2>"$errf"
    check "$cmd --help exits 0" $?
    head -1 "$out" | grep -q "^usage: intercurve $cmd PROBLEM.json" && grep -q '^options:$' "$out" &&
        grep -q '^  -h, --help ' "$out" && grep -q 'example' "$out" && [ ! -s "$errf" ]
    check "$cmd --help: usage, options, -h, an example, nothing on stderr" $?
    "$bin" $cmd --bogus -h >"$tmp/h" 2>"$errf"
    [ $? -eq 0 ] && cmp -s "$out" "$tmp/h"
    check "$cmd --bogus -h: the help, exit 0" $?
done

# A refusal: exit 1, nothing on stdout, the message names `want` and
# points to the help.
refused() { # description, want, command args...
    local what="$1" want="$2"
    shift 2
    "$bin" "$@" >"$out" 2>"$errf"
    local rc=$?
    [ $rc -eq 1 ] && [ ! -s "$out" ] && grep -qF -- "$want" "$errf" &&
        ! grep -q "cannot open" "$errf"
    st=$?
    check "$what: exit 1 (got $rc), nothing on stdout, names '$want': $(head -c 300 "$errf")" $st
}
refused "an unknown option" "unknown option '--bogus'" trace "$ex/viviani.json" --bogus
refused "an unknown option with a value" "unknown option '--bogus'" trace "$ex/viviani.json" --bogus=1
refused "a missing value" "--depth needs a value D" trace "$ex/viviani.json" --depth
refused "a flag with a value" "--no-chart takes no value" plot "$ex/viviani.json" -o x.png --no-chart=1
refused "a count with a tail" "--threads expects a whole number from 0 to 256, got '0x'" \
    trace "$ex/viviani.json" --threads 0x
refused "a negative count" "--threads expects a whole number from 0 to 256, got '-2'" \
    plot "$ex/viviani.json" -o x.png --threads -2
refused "two problem files" "unexpected argument 'other.json'" trace "$ex/viviani.json" other.json
refused "no problem file" "needs PROBLEM.json" trace
refused "a missing required option" "needs PROBLEM.json and -o FIGURE (missing: -o)" plot "$ex/viviani.json"
refused "both of --at and --params" "give only one of --at or --params" \
    point "$ex/viviani.json" --at 1,2,3 --params 1,2
grep -qF "try 'intercurve point --help'" "$errf"
check "a refusal points to the command's help" $?

# The ranges the help states, at and beyond their bounds. An accepted
# value gets as far as opening the (missing) problem file.
missing="$tmp/no-such-problem.json"
required() { # the options a command cannot run without
    case "$1" in
    eval) echo "--at 1,2" ;;
    point) echo "--at 1,2,3" ;;
    plot) echo "-o $tmp/x.png" ;;
    esac
}
accepted() { # cmd, option, value: both --opt value and --opt=value
    local cmd="$1" opt="$2" value="$3" form
    for form in spaced joined; do
        # shellcheck disable=SC2046
        if [ $form = spaced ]; then
            "$bin" $cmd "$missing" $(required $cmd) "$opt" "$value" >"$out" 2>"$errf"
        else
            "$bin" $cmd "$missing" $(required $cmd) "$opt=$value" >"$out" 2>"$errf"
        fi
        grep -q "cannot open" "$errf"
        st=$?
        check "$cmd $opt $value ($form) is accepted: $(head -c 300 "$errf")" $st
    done
}
beyond() { # cmd, option, value
    # shellcheck disable=SC2046
    refused "$1 $2 $3 is refused" "$2" $1 "$missing" $(required $1) "$2" "$3"
    refused "$1 $2=$3 is refused" "$2" $1 "$missing" $(required $1) "$2=$3"
}
ranges=0
for cmd in eval point trace plot; do
    "$bin" $cmd --help >"$tmp/help.$cmd"
    opt=""
    while IFS= read -r line; do
        if [[ $line =~ ^\ \ (-[-a-z]+)(\ ([^ ]+))?\ \  ]]; then
            opt="${BASH_REMATCH[1]}"
            [ -z "${BASH_REMATCH[3]}" ] && [ "$opt" != -h ] &&
                refused "$cmd $opt=1 (a flag)" "$opt takes no value" $cmd "$missing" \
                    $(required $cmd) "$opt=1"
            continue
        fi
        [[ $line =~ ^\ {4} ]] || opt=""
        [ -n "$opt" ] || continue
        if [[ $line =~ W\ in\ ([0-9]+)\.\.([0-9]+),\ H\ in\ ([0-9]+)\.\.([0-9]+) ]]; then
            wl=${BASH_REMATCH[1]} wh=${BASH_REMATCH[2]} hl=${BASH_REMATCH[3]} hh=${BASH_REMATCH[4]}
            accepted $cmd $opt "${wl}x$hl"
            accepted $cmd $opt "${wh}x$hh"
            beyond $cmd $opt "$((wl - 1))x$hl"
            beyond $cmd $opt "${wl}x$((hl - 1))"
            beyond $cmd $opt "$((wh + 1))x$hl"
            beyond $cmd $opt "${wl}x$((hh + 1))"
            ranges=$((ranges + 1))
        elif [[ $line =~ ^\ +[^\ ]+\ in\ (-?[0-9]+)\.\.([0-9]+) ]]; then
            lo=${BASH_REMATCH[1]} hi=${BASH_REMATCH[2]}
            accepted $cmd $opt $lo
            accepted $cmd $opt $hi
            beyond $cmd $opt $((lo - 1))
            beyond $cmd $opt $((hi + 1))
            beyond $cmd $opt 2.5
            ranges=$((ranges + 1))
        elif [[ $line =~ ^\ +[^\ ]+\ in\ \(([^,]+),\ ([^]]+)\] ]]; then
            lo=${BASH_REMATCH[1]} hi=${BASH_REMATCH[2]}
            accepted $cmd $opt "$hi"
            accepted $cmd $opt "$(awk -v h="$hi" 'BEGIN { printf "%.10g", h * 0.999 }')"
            beyond $cmd $opt "$lo"
            beyond $cmd $opt "$(awk -v h="$hi" 'BEGIN { printf "%.10g", h * 1.001 }')"
            ranges=$((ranges + 1))
        elif [[ $line =~ ^\ +[^\ ]+\ \>\ ([^\;]+) ]]; then
            lo=${BASH_REMATCH[1]}
            accepted $cmd $opt 1e-300
            beyond $cmd $opt "$lo"
            beyond $cmd $opt -1
            ranges=$((ranges + 1))
        elif [[ $line =~ ^\ +one\ of\ ([^\;]+) ]]; then
            IFS=', ' read -r -a choices <<<"${BASH_REMATCH[1]}"
            for c in "${choices[@]}"; do accepted $cmd $opt "$c"; done
            beyond $cmd $opt bogus
            ranges=$((ranges + 1))
        fi
    done <"$tmp/help.$cmd"
done
# eval --order; point --order, --method, --format, --point-tol; trace
# --format, --tol, --depth, --time-limit, --fit-tol, --threads; plot --frames,
# --size, --mesh, --tol, --depth, --threads
[ "$ranges" -eq 17 ]
check "17 ranges found in the help texts (found $ranges)" $?

echo "test_cli_options: $pass passed, $fail failed"
[ "$fail" -eq 0 ]
