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
echo "test_verify: $fails failed"
[ "$fails" -eq 0 ]
