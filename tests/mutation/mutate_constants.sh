#!/usr/bin/env bash
# The constants' mutation study (issue 10, item 4; docs/testing.md, "Constants
# pinned"): every tracer constant of the register (src/trace/core/trace_constants.h)
# and of the tangential locator (LOCATE_* in src/local/locate_tangential.c,
# PLACE_* in src/local/tangential_place.c) is built once multiplied by 10 and
# once divided by 10, and the trace tests are run against each build. A
# constant is pinned when each of its two mutants makes some test fail.
#
#   tests/mutation/mutate_constants.sh [SCRATCH]
#
# SCRATCH (default build-mutation/ in the tree) receives a copy of the tree's
# files (git's tracked and untracked, not ignored), a Debug build of that copy,
# one log per mutation (SCRATCH/logs/) and the table (SCRATCH/results.md).
# The tree itself is never written: each mutation is applied with sed to the
# scratch copy of its file and the copy restored from the original afterwards.
#
# Environment:
#   ONLY=REGEX     run only the mutations whose constant name matches REGEX
#   TESTS="a b"    the ctest names to run (default below; `constants` is added
#                  when tests/test_constants.c exists)
#   TIMEOUT=S      ctest's per-test limit in seconds (default 900): a test that
#                  runs past it counts as caught, marked (timeout)
#
# Values: reals are multiplied and divided by 10 exactly. Counts are
# multiplied by 10 and divided by 10 rounded to the nearest whole number, at
# least 1 (a count of 0 would skip a loop altogether: no iteration, or dz
# never computed). Levels (IC_TRACE_MAX_REFINE_LEVELS, IC_TRACE_EXPLAIN_LEVELS)
# are halvings of a cell, so tenfold is about 3.3 levels: they are moved by 4
# levels up and down (a factor 16 in cell size; not below 0).
# The run takes about a minute of build and tests per mutation in a Debug
# build (one CPU; contact_place alone 25 s), about 100 minutes for all 76
# (IC_TRACE_MAX_CELLS x10 makes contact_place run 290 s; IC_TRACE_STEP_ADVANCE
# x10, where no step is accepted, makes trace run past 2 minutes:
# TIMEOUT=120 counts it caught sooner).
set -euo pipefail

TREE=$(cd "$(dirname "$0")/../.." && pwd)
SCRATCH=${1:-$TREE/build-mutation}
mkdir -p "$SCRATCH"
SCRATCH=$(cd "$SCRATCH" && pwd)
TIMEOUT=${TIMEOUT:-900}
ONLY=${ONLY:-.}
DEFAULT_TESTS="trust torture contact_place trace trace_robust trace_examples loops"
[ -f "$TREE/tests/test_constants.c" ] && DEFAULT_TESTS="$DEFAULT_TESTS constants"
TESTS=${TESTS:-$DEFAULT_TESTS}

H=src/trace/core/trace_constants.h
LT=src/local/locate_tangential.c
TP=src/local/tangential_place.c
# file  constant  value x10  value /10
MUTATIONS="
$H IC_TRACE_MAX_CELLS 20000000L 200000L
$H IC_TRACE_MAX_REFINE_LEVELS 20 12
$H IC_TRACE_EXPLAIN_LEVELS 7 0
$H IC_TRACE_MAX_REGIONS 640 6
$H IC_TRACE_COINCIDENT_TOL 1e-9 1e-11
$H IC_TRACE_COINCIDENT_REACH (10.0/64) (1.0/640)
$H IC_TRACE_ON_CURVE 1e-7 1e-9
$H IC_TRACE_POINT_TOL 1e-6 1e-8
$H IC_TRACE_PLACE_REL 1e-7 1e-9
$H IC_TRACE_PLACE_ULPS 160 2
$H IC_TRACE_SINGULAR_CLEARANCE 1.5e-3 1.5e-5
$H IC_TRACE_SAME_EXACT 1e-9 1e-11
$H IC_TRACE_SAME_APPROX 1e-3 1e-5
$H IC_TRACE_END_REACH 1e-3 1e-5
$H IC_TRACE_DEGENERATE_REACH 5e-2 5e-4
$H IC_TRACE_INDEX_CELL (10.0/128) (1.0/1280)
$H IC_TRACE_POLE_GAP_CHORDS 500.0 5.0
$H IC_TRACE_DEFERRED_CHORDS 20.0 0.2
$H IC_TRACE_STEP_HALVINGS 600 6
$H IC_TRACE_TANGENTIAL_MIN_STEP 1e-9 1e-11
$H IC_TRACE_STEP_ADVANCE 5.0 0.05
$H IC_TRACE_CORRECTION_TOLS 1e4 1e2
$H IC_TRACE_CORRECTION_OF_STEP 1e-2 1e-4
$H IC_TRACE_APPROX_TANGENTIAL_ANGLE 1e-2 1e-4
$LT LOCATE_ACCEPT 1e-11 1e-13
$LT LOCATE_PLAIN_ITERATIONS 400 4
$LT LOCATE_MAX_ITERATIONS 1000 10
$LT LOCATE_FLOOR 1e-299 1e-301
$LT LOCATE_MAX_MULTIPLICITY 160 2
$LT LOCATE_SLOW_RATIO 1.0 0.01
$LT LOCATE_DIFF_REL 1e-6 1e-8
$LT LOCATE_DIFF_OF_STEP 1e-2 1e-4
$LT LOCATE_DAMPING 1e-13 1e-15
$LT LOCATE_DIFF_RETRIES 40 1
$LT LOCATE_STALL 30 1
$TP PLACE_FIRST_RUNG 1e-14 1e-16
$TP PLACE_RUNGS 120 1
$TP PLACE_GROWTH 30.0 0.3
"

COPY=$SCRATCH/tree
BUILD=$SCRATCH/build
LOGS=$SCRATCH/logs
mkdir -p "$COPY" "$LOGS"

# the tree's files, as git sees them (new files included), into the copy
(cd "$TREE" && git ls-files -z --cached --others --exclude-standard |
     tar --null -T - -cf -) | tar -xmf - -C "$COPY"  # -m: new times, rebuilt

targets=""
for t in $TESTS; do targets="$targets test_$t"; done
regex="^($(echo "$TESTS" | tr ' ' '|'))\$"

# Builds the copy and runs the tests; prints the failing ones (or "none",
# "BUILD FAILED"). The log goes to $1.
build_and_test() {
    local log=$1
    if ! cmake --build "$BUILD" -j1 --target $targets >"$log" 2>&1; then
        echo "BUILD FAILED"
        return
    fi
    (cd "$BUILD" && ctest -j1 --timeout "$TIMEOUT" --output-on-failure -R "$regex" >>"$log" 2>&1) || true
    local failed
    failed=$(sed -nE 's/^ *[0-9]+\/[0-9]+ Test +#[0-9]+: ([a-z_]+) .*\*\*\*Timeout.*/\1 (timeout)/p;
                      s/^ *[0-9]+\/[0-9]+ Test +#[0-9]+: ([a-z_]+) .*\*\*\*(Failed|Exception).*/\1/p' "$log" |
             paste -sd, - | sed 's/,/, /g')
    echo "${failed:-none}"
}

cmake -S "$COPY" -B "$BUILD" -DCMAKE_BUILD_TYPE=Debug >/dev/null
base=$(build_and_test "$LOGS/baseline.log")
if [ "$base" != none ]; then
    echo "the unmutated tree fails ($base): see $LOGS/baseline.log" >&2
    exit 1
fi

# restores the file being mutated, whatever happens
current=""
restore() { [ -n "$current" ] && cp "$current.orig" "$current" && rm -f "$current.orig"; current=""; }
trap restore EXIT
trap "exit 1" INT TERM

results=$SCRATCH/results.md
{
    echo "| constant | value | x10 | caught by | /10 | caught by |"
    echo "|---|---|---|---|---|---|"
} >"$results"
while read -r file name up down; do
    [ -n "$file" ] || continue
    [[ $name =~ $ONLY ]] || continue
    target=$COPY/$file
    if [ "$(grep -c "^#define $name " "$target")" != 1 ]; then
        echo "$name: not defined exactly once in $file" >&2
        exit 1
    fi
    value=$(sed -nE "s/^#define $name (.*)$/\1/p" "$target")
    row="| \`$name\` | $value"
    for mutant in "$up" "$down"; do
        cp "$target" "$target.orig"
        current=$target
        sed -i -E "s|^#define $name .*$|#define $name $mutant|" "$target"
        tag=$([ "$mutant" = "$up" ] && echo x10 || echo div10)
        caught=$(build_and_test "$LOGS/$name-$tag.log")
        restore
        echo "$name = $mutant: $caught" >&2
        row="$row | $mutant | $caught"
    done
    echo "$row |" >>"$results"
done <<<"$MUTATIONS"
# the copy restored: its build matches the tree again
cmake --build "$BUILD" -j1 --target $targets >/dev/null
cat "$results"
