#!/usr/bin/env bash
# The STEP and IGES curves of intercurve trace, read by OpenCASCADE
# (tests/cad/read_curves.cpp; docs/testing.md, "STEP and IGES curves read by
# OpenCASCADE"): Viviani's curve and the two loops of two cylinders, each
# written in both formats, read, and every edge checked against the two
# surfaces within the fit tolerance the trace reports. Run by hand: CI has
# no OpenCASCADE. Needs Debian's libocct-data-exchange-dev; without it, it
# says so and exits 0.
# usage: tests/cad/read_curves.sh BUILD_DIR
set -eu -o pipefail
here=$(cd "$(dirname "$0")" && pwd)
src="$here/../.."
bin="${1:?usage: read_curves.sh BUILD_DIR}/intercurve"
inc=/usr/include/opencascade
if [ ! -f "$inc/STEPControl_Reader.hxx" ] || [ ! -f "$inc/IGESControl_Reader.hxx" ]; then
    echo "read_curves: OpenCASCADE is not installed (apt-get install" \
        "libocct-data-exchange-dev); nothing checked"
    exit 0
fi
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
g++ -std=c++17 -O1 -Wall -Wno-deprecated-declarations -I"$inc" "$here/read_curves.cpp" \
    -o "$tmp/read_curves" -lTKSTEP -lTKSTEPBase -lTKIGES -lTKXSBase -lTKTopAlgo -lTKBRep \
    -lTKGeomAlgo -lTKGeomBase -lTKG3d -lTKG2d -lTKMath -lTKernel
status=0
for case in viviani:viviani-implicit cylinders:cylinders; do
    name="${case%%:*}" example="$src/examples/${case#*:}.json"
    "$bin" trace "$example" >"$tmp/$name.json"
    # the curves' count and the fit tolerance (a length) from the trace's report
    read -r curves tol < <(python3 -c 'import json, sys
d = json.load(open(sys.argv[1]))
print(len(d["curves"]), d["report"]["fit_tolerance"])' "$tmp/$name.json")
    for format in step iges; do
        "$bin" trace "$example" --format $format -o "$tmp/$name.$format"
        "$tmp/read_curves" "$name" "$curves" "$tol" "$tmp/$name.$format" | grep -v '^\s*$' ||
            status=1
    done
done
[ $status -eq 0 ] && echo "read_curves: every edge within the fit tolerance of both surfaces"
exit $status
