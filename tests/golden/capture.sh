#!/usr/bin/env bash
# Writes every output document of the command on the bundled cases into OUTDIR,
# one file per case and format, with the STEP and IGES files' time stamps set to
# a fixed text of the same length (they are the writing time, the only part of
# an output that is not a function of the input). The cases: every bundled
# example, every torture case and every NURBS and CAD problem; the formats:
# trace's json (with and without the exact paths), text, csv, vtk, obj, step and
# iges, point's json at the first point of each traced curve, and the examples'
# SVG pictures. tests/test_golden.sh compares their hashes with
# tests/golden/outputs.sha256, made by this script from the tree of issue 22's
# start (commit 309689a), so that a change of layout shows itself as a change of
# no output at all; made again when issue 23's certificate changed the trace
# documents (json and text only: the report's tracer_complete and certificate,
# complete as the checker's verdict), and again for the certificate's `restarts`
# and its region size from samples (the covers' counts of cells), and for the
# cover's split by lengths in space (overflow-exp proven, cut-open-torus
# refused at another cell: their json and text), and for the boxes of cusps,
# tacnodes and higher-order contacts 400 times wider (the certificate's counts
# of cells of the cusp, tacnode and contact-x4y4 cases: json and text), and for
# issue 23's glued edges and the checker's diagonal test beside the diagonal
# (enneper-self and whitney-umbrella: the covers' counts), the reason of a
# cover out of cells naming its cell (eggcrate-k100, overflow-pow1025), and the
# fit check's distance to a sheet from three starts (viviani's fit 9 knots
# fewer in every format, sphere-cylinder-branch and the NURBS viviani's
# fit_error).
#   capture.sh BUILD_DIR SOURCE_DIR OUTDIR [examples] [K/N]
# With "examples", only the bundled examples (the sanitized build's run: the
# whole set takes 20 minutes under AddressSanitizer in a Debug build). With
# K/N, only the K-th of every N cases (1 <= K <= N), so that the tests can run
# the set in N parts side by side; the keys of the cases written (the names of
# their documents up to the first dot after the key) go to OUTDIR/.keys.
set -uo pipefail
build="$1" src="$2" out="$3"
shift 3
only="" shard_k=1 shard_n=1
for arg in "$@"; do
    case "$arg" in
    examples) only=examples ;;
    */*) shard_k="${arg%/*}" shard_n="${arg#*/}" ;;
    *) echo "capture.sh: unknown argument '$arg' (examples or K/N)" >&2; exit 2 ;;
    esac
done
if ! [[ "$shard_k" =~ ^[0-9]+$ && "$shard_n" =~ ^[0-9]+$ ]] || ((shard_k < 1 || shard_k > shard_n)); then
    echo "capture.sh: the part '$shard_k/$shard_n' is not K/N with 1 <= K <= N" >&2
    exit 2
fi
ic="$build/intercurve"
mkdir -p "$out"
cd "$src" || exit 2

all_cases() {
    if [ "$only" = examples ]; then
        ls examples/*.json
    else
        ls examples/*.json tests/torture/*.json tests/data/nurbs/problem-*.json \
            tests/data/cad/problem-*.json
    fi
}
# this part's cases: the K-th of every N
cases() { all_cases | awk -v k="$shard_k" -v n="$shard_n" 'NR % n == k % n'; }


# fixed-length time stamps: STEP's FILE_NAME and IGES's global section
unstamp() {
    sed -E -e "s/'[0-9]{4}-[0-9]{2}-[0-9]{2}T[0-9]{2}:[0-9]{2}:[0-9]{2}'/'0000-00-00T00:00:00'/" \
        -e 's/15H[0-9]{8}\.[0-9]{6}/15H00000000.000000/g'
}

# the first point of each curve of a trace document, as --at X,Y,Z
first_points() {
    python3 -c '
import json, sys
doc = json.load(open(sys.argv[1]))
for c in doc.get("curves", []):
    pts = c.get("points") or []
    if pts:
        print(",".join(repr(x) for x in pts[0]["xyz"]))
' "$1" 2>/dev/null | head -n "$POINTS_PER_CASE"
}

run() { # name, command...: the output and the exit status, both recorded
    local name="$1"
    shift
    "$@" >"$out/$name" 2>"$out/$name.err"
    echo "exit $?" >>"$out/$name.err"
}

# the first curves' points only: a case of thousands of curves would take minutes
POINTS_PER_CASE=3
# cases of a gigabyte in every format or 20 s a run: the json only
HEAVY="tests/torture/eggcrate-k100.json"
# cases of 1.5 to 9 s a run (the certificate's tubes along a tangential
# curve): the json, without the exact paths, and the text only; the other
# formats are written by the same code for every other case
MEDIUM="examples/torus-sphere.json examples/torus-plane-tangential.json
    tests/torture/tangent-sphere-cylinder-box.json tests/torture/tangent-sphere-cylinder-domain.json
    tests/torture/tangent-cylinder-plane-box.json tests/data/nurbs/problem-torus-sphere-tangential.json"

: >"$out/.keys"
for f in $(cases); do
    key="$(echo "${f%.json}" | tr '/' '_')"
    echo "$key" >>"$out/.keys"
    if [[ " $HEAVY " == *" $f "* ]]; then
        "$ic" trace "$f" 2>"$out/$key.trace.json.err" | sha256sum >"$out/$key.trace.json.sha256"
        continue
    fi
    run "$key.trace.json" "$ic" trace "$f"
    run "$key.noexact.json" "$ic" trace "$f" --no-exact
    if [[ " $(echo $MEDIUM) " == *" $f "* ]]; then
        run "$key.trace.text" "$ic" trace "$f" --format text
        continue
    fi
    for fmt in text csv vtk obj; do
        run "$key.trace.$fmt" "$ic" trace "$f" --format "$fmt"
    done
    for fmt in step iges; do
        run "$key.trace.$fmt.raw" "$ic" trace "$f" --format "$fmt"
        unstamp <"$out/$key.trace.$fmt.raw" >"$out/$key.trace.$fmt"
        rm -f "$out/$key.trace.$fmt.raw"
        mv "$out/$key.trace.$fmt.raw.err" "$out/$key.trace.$fmt.err"
    done
    i=0
    for at in $(first_points "$out/$key.trace.json"); do
        run "$key.point$i.json" "$ic" point "$f" --at "$at"
        i=$((i + 1))
    done
done
for f in $(cases | grep '^examples/'); do
    key="$(echo "${f%.json}" | tr '/' '_')"
    "$ic" plot "$f" -o "$out/$key.plot.svg" >/dev/null 2>"$out/$key.plot.err"
    echo "exit $?" >>"$out/$key.plot.err"
done
exit 0
