#!/usr/bin/env bash
# intercurve verify (issue 23, docs/tracing.md "The certificate"): a saved
# trace is proven again without the tracer; the same document with a curve
# dropped or doubled is not (exit 2, the reason named); a document that is
# not a trace is bad input (exit 1, the JSON path named).
# usage: test_verify.sh BUILD_DIR SOURCE_DIR
set -u
bin="$1/intercurve"
src="$2"
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
fails=0
check() { # message, condition status
    if [ "$2" -ne 0 ]; then
        echo "FAIL: $1"
        fails=$((fails + 1))
    fi
}
problem="$src/examples/cylinders.json"
"$bin" trace "$problem" -o "$tmp/t.json"
check "trace" $?
out="$("$bin" verify "$problem" --trace "$tmp/t.json")"
check "verify of the true trace exits 0 ($out)" $?
[[ "$out" == proven:* ]]
check "verify says proven ($out)" $?
edit() { # python expression on d, output file
    /usr/bin/python3 -c "import json, sys
d = json.load(open(sys.argv[1]))
$1
json.dump(d, open(sys.argv[2], 'w'))" "$tmp/t.json" "$2"
}
edit "d['curves'] = d['curves'][:1]" "$tmp/dropped.json"
out="$("$bin" verify "$problem" --trace "$tmp/dropped.json")"
[ $? -eq 2 ] && [[ "$out" == *"not traced"* ]]
check "a curve dropped: exit 2, not traced ($out)" $?
edit "d['curves'].append(d['curves'][0])" "$tmp/doubled.json"
out="$("$bin" verify "$problem" --trace "$tmp/doubled.json")"
[ $? -eq 2 ] && [[ "$out" == *"more than once"* ]]
check "a curve doubled: exit 2, traced more than once ($out)" $?
echo '{"curves": [{"points": [{"xyz": [1, 2]}]}]}' >"$tmp/bad.json"
err="$("$bin" verify "$problem" --trace "$tmp/bad.json" 2>&1)"
[ $? -eq 1 ] && [[ "$err" == *"curves[0].points[0]"* ]]
check "a bad document: exit 1, its JSON path ($err)" $?
# singular points: the branch points of two equal cylinders are in the
# document's points; without them the cells there cannot be proven
branch="$src/examples/cylinders-equal.json"
"$bin" trace "$branch" -o "$tmp/b.json"
out="$("$bin" verify "$branch" --trace "$tmp/b.json")"
[ $? -eq 0 ] && [[ "$out" == proven:* ]] && [[ "$out" != *" 0 singular"* ]]
check "verify of the branch points' trace: proven, with singular cells ($out)" $?
cp "$tmp/b.json" "$tmp/t.json"
edit "d['points'] = []" "$tmp/nopoints.json"
out="$("$bin" verify "$branch" --trace "$tmp/nopoints.json")"
[ $? -eq 2 ] && [[ "$out" == *"nor by a singular point or tangential curve found"* ]]
check "the branch points dropped: exit 2, the cell named ($out)" $?
edit "d['points'][0]['xyz'] = [0, 0]" "$tmp/badpoint.json"
err="$("$bin" verify "$branch" --trace "$tmp/badpoint.json" 2>&1)"
[ $? -eq 1 ] && [[ "$err" == *"points[0].xyz"* ]]
check "a bad point: exit 1, its JSON path ($err)" $?
# a tangential curve: its tube is placed from the document's curve of type
# "tangential"; the same curve called transversal is walked and refused
line="$src/tests/torture/tangent-cylinder-plane-box.json"
"$bin" trace "$line" -o "$tmp/l.json"
out="$("$bin" verify "$line" --trace "$tmp/l.json")"
[ $? -eq 0 ] && [[ "$out" == proven:* ]] && [[ "$out" != *" 0 tangential"* ]]
check "verify of a tangential line: proven, with tangential cells ($out)" $?
cp "$tmp/l.json" "$tmp/t.json"
edit "d['curves'][0]['type'] = 'transversal'" "$tmp/untangential.json"
out="$("$bin" verify "$line" --trace "$tmp/untangential.json")"
[ $? -eq 2 ]
check "the tangential line called transversal: exit 2 ($out)" $?
"$bin" verify "$problem" >/dev/null 2>&1
[ $? -eq 1 ]
check "no --trace: exit 1" $?
# certificate files (docs/output-formats.md, "The certificate file"): the
# cover written by trace --certificate and replayed by verify --certificate
# proves the same trace; each leaf is proven again, so a file changed where
# it matters is refused (exit 2, the node named) and a file that is not a
# tree over this problem's region is bad input (exit 1, the JSON path)
roundtrip() { # problem, stem
    "$bin" trace "$1" -o "$tmp/$2.json" --certificate "$tmp/$2.cert.json"
    check "trace --certificate of $2" $?
    out="$("$bin" verify "$1" --trace "$tmp/$2.json" --certificate "$tmp/$2.cert.json")"
    [ $? -eq 0 ] && [[ "$out" == proven:* ]]
    check "the certificate of $2 replayed: proven ($out)" $?
    grown="$("$bin" verify "$1" --trace "$tmp/$2.json")"
    [ "${out%%, boxes*}" == "${grown%%, boxes*}" ]
    check "the replay of $2 has the grown cover's cells ($out | $grown)" $?
}
roundtrip "$problem" cyl
roundtrip "$branch" branch
roundtrip "$line" line
roundtrip "$src/examples/torus-sphere.json" torus
cedit() { # python expression on d (the certificate), output file
    /usr/bin/python3 -c "import json, sys
d = json.load(open(sys.argv[1]))
def first(kind):
    return next(i for i, n in enumerate(d['cells']) if n[0] == kind)
$1
json.dump(d, open(sys.argv[2], 'w'))" "$tmp/cyl.cert.json" "$2"
}
refused() { # file, message, expected text
    out="$("$bin" verify "$problem" --trace "$tmp/cyl.json" --certificate "$1")"
    [ $? -eq 2 ] && [[ "$out" == "not proven"*"$3"* ]]
    check "$2: exit 2, '$3' ($out)" $?
}
bad() { # file, message, expected text
    err="$("$bin" verify "$problem" --trace "$tmp/cyl.json" --certificate "$1" 2>&1)"
    [ $? -eq 1 ] && [[ "$err" == *"$3"* ]]
    check "$2: exit 1, '$3' ($err)" $?
}
# the true cover does not make a trace with a curve dropped proven
out="$("$bin" verify "$problem" --trace "$tmp/dropped.json" --certificate "$tmp/cyl.cert.json")"
[ $? -eq 2 ] && [[ "$out" == *"not traced"* ]]
check "a curve dropped, the true certificate: exit 2, not traced ($out)" $?
cedit "i = first('regular'); d['cells'][i] = ['empty']" "$tmp/kind.json"
refused "$tmp/kind.json" "a regular leaf called empty" "the file says empty, the check finds regular"
cedit "i = first('empty'); d['cells'][i] = ['singular']" "$tmp/sing.json"
refused "$tmp/sing.json" "an empty leaf called singular" "the file says singular, the check finds empty"
cedit "i = first('regular'); d['cells'][i][2].pop()" "$tmp/dropx.json"
refused "$tmp/dropx.json" "a crossing dropped" "crossings, the check finds"
cedit "i = first('regular'); d['cells'][i][2][0][3][0] += 1e-6" "$tmp/movex.json"
refused "$tmp/movex.json" "a crossing moved by 1e-6" "is not the root the check isolates"
cedit "i = first('regular'); d['cells'][i] = ['undecided']" "$tmp/undecided.json"
refused "$tmp/undecided.json" "an undecided leaf" "left undecided"
cedit "i = first('split'); n = d['cells'][i]; d['cells'][i] = ['split', n[1], 7.0]" "$tmp/splitout.json"
bad "$tmp/splitout.json" "a split outside its cell" "cells[0]: split at 7"
cedit "d['cells'] = d['cells'][:-1]" "$tmp/short.json"
bad "$tmp/short.json" "a tree cut short" "the tree ends early"
cedit "d['cells'].append(['empty'])" "$tmp/long.json"
bad "$tmp/long.json" "a node after the tree" "after the end of the tree"
cedit "d['region']['hi'][0] = 2" "$tmp/region.json"
bad "$tmp/region.json" "another region" "region: coordinate 0"
cedit "d['cells'][0] = ['split', 3, 0.1]" "$tmp/axis.json"
bad "$tmp/axis.json" "a split axis out of range" "cells[0]: a node of kind split is"
cedit "d['cells'][0] = ['cube']" "$tmp/kindname.json"
bad "$tmp/kindname.json" "an unknown kind" "cells[0]: not [kind"
cp "$tmp/cyl.cert.json" "$tmp/trailing.json" && echo '{"checked": false}' >>"$tmp/trailing.json"
bad "$tmp/trailing.json" "a second document after the file's" "not one JSON document"
"$bin" trace "$problem" -o "$tmp/same.json" --certificate "$tmp/same.json" 2>/dev/null
[ $? -eq 1 ] && [ ! -e "$tmp/same.json" ]
check "-o and --certificate the same file: exit 1, nothing written" $?
cedit "d['format'] = 'other'" "$tmp/format.json"
bad "$tmp/format.json" "not a certificate" "format: not"
refused "$tmp/branch.cert.json" "a certificate of another problem on the same region" \
    "is not the root the check isolates"
bad "$tmp/torus.cert.json" "a certificate of another region" "region: coordinate 0"
roundtrip "$src/examples/viviani.json" viviani
bad "$tmp/viviani.cert.json" "a certificate of another pairing" "pairing"
echo '{"format": "intercurve-certificate", "version": 1, "checked": false, "reason": "no"}' \
    >"$tmp/unchecked.json"
refused "$tmp/unchecked.json" "a file of a check that did not run" "holds no cover"
"$bin" verify "$problem" --trace "$tmp/cyl.json" --certificate "$tmp/missing.json" >/dev/null 2>&1
[ $? -eq 1 ]
check "a missing certificate file: exit 1" $?
# attacks a review found (issue 23): a file may choose any tree, so what it
# leaves unexamined must not depend on how coarse its cells are.
# 1. No curve, a made-up higher-order contact at the centre of small-loop's
#    loop (its box wider than the loop) and a tree of 13 nodes with one
#    singular cell holding the whole loop: the claimed point is refuted,
#    the cell halved piece by piece down to where each is proven smooth
loop="$src/examples/small-loop.json"
echo '{"curves": [], "points": [{"xyz": [0.3, 0.2, 0.105], "type": "higher-order-contact",
  "branches": 0, "approximate": false}], "report": {"cells": 0}}' >"$tmp/hoc.trace.json"
echo '{"format": "intercurve-certificate", "version": 1, "checked": true, "accepted": true,
  "reason": "", "pairing": "implicit/implicit", "dimension": 3,
  "region": {"lo": [-1, -1, -1], "hi": [1, 1, 1], "periodic": [0, 0, 0]},
  "cells": [["split", 0, 0.288], ["empty"], ["split", 0, 0.312], ["split", 1, 0.188],
  ["empty"], ["split", 1, 0.212], ["split", 2, 0.093], ["empty"], ["split", 2, 0.117],
  ["singular"], ["empty"], ["empty"], ["empty"]]}' >"$tmp/hoc.cert.json"
out="$("$bin" verify "$loop" --trace "$tmp/hoc.trace.json" --certificate "$tmp/hoc.cert.json")"
[ $? -eq 2 ] && [[ "$out" == *"singular point 0 (of the result's) near (0.3, 0.2, 0.105) is none"* ]]
check "a made-up contact in a cell fitted to its box: exit 2, refuted ($out)" $?
#    the same point called a surface's own singular point is refuted too
sed 's/higher-order-contact/surface-singular/' "$tmp/hoc.trace.json" >"$tmp/ss.trace.json"
out="$("$bin" verify "$loop" --trace "$tmp/ss.trace.json" --certificate "$tmp/hoc.cert.json")"
[ $? -eq 2 ]
check "a made-up surface singular point: exit 2 ($out)" $?
# 2. A transversal curve called tangential (its tube's cells unexamined),
#    and a tangential circle added in empty space: the tube's points are not
#    where the surfaces touch (grown or replayed)
cp "$tmp/cyl.json" "$tmp/t.json"
edit "d['curves'][0]['type'] = 'tangential'" "$tmp/calledtangential.json"
out="$("$bin" verify "$problem" --trace "$tmp/calledtangential.json")"
[ $? -eq 2 ] && [[ "$out" == *"curve 0 is called tangential but its point 0 is not a point where the surfaces touch"* ]]
check "a transversal curve called tangential: exit 2 ($out)" $?
edit "import math
d['curves'].append(dict(d['curves'][0], type='tangential', closed=True, points=[dict(d['curves'][0]['points'][0], xyz=[0.2 * math.cos(t / 8), 0.2 * math.sin(t / 8), 1.2], params=[None, None]) for t in range(50)]))" "$tmp/faketube.json"
out="$("$bin" verify "$problem" --trace "$tmp/faketube.json")"
[ $? -eq 2 ] && [[ "$out" == *"is called tangential"* ]]
check "a tangential circle in empty space: exit 2 ($out)" $?
# 3. A point of a curve moved off the curve within one cell (a spike): not
#    on the intersection
edit "c = d['curves'][0]['points']; c[len(c) // 2] = dict(c[len(c) // 2], xyz=[x * 1.01 for x in c[len(c) // 2]['xyz']])" "$tmp/spike.json"
out="$("$bin" verify "$problem" --trace "$tmp/spike.json")"
[ $? -eq 2 ] && [[ "$out" == *"of curve 0 is not on the intersection"* ]]
check "a point moved off its curve by 1 %: exit 2 ($out)" $?
# a trace the checker does not run on still writes a file, saying why
"$bin" trace "$problem" --time-limit 1e-9 -o "$tmp/short.trace.json" \
    --certificate "$tmp/none.cert.json" 2>"$tmp/none.err"
grep -q '"checked":[[:space:]]*false' "$tmp/none.cert.json" && grep -q "holds no cover" "$tmp/none.err"
check "an unchecked trace's certificate says so ($(cat "$tmp/none.err"))" $?
echo "test_verify: $fails failed"
[ "$fails" -eq 0 ]
