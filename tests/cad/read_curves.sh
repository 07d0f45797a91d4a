#!/usr/bin/env bash
# The STEP and IGES curves of intercurve trace, read by OpenCASCADE
# (tests/cad/read_curves.cpp; docs/testing.md, "STEP and IGES curves read by
# OpenCASCADE"): Viviani's curve and the two loops of two cylinders, each
# written in both formats, read, and every edge checked against the two
# surfaces within the fit tolerance the trace reports, and every closed curve
# closed. ctest runs it with the reader it builds where Debian's
# libocct-data-exchange-dev is installed (CI has no OpenCASCADE); by hand,
# without READER, it compiles the reader itself, or says OpenCASCADE is
# missing and exits 0.
# usage: tests/cad/read_curves.sh BUILD_DIR [READER]
set -eu -o pipefail
here=$(cd "$(dirname "$0")" && pwd)
src="$here/../.."
bin="${1:?usage: read_curves.sh BUILD_DIR}/intercurve"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
reader="${2:-}"
if [ -z "$reader" ]; then
    inc=/usr/include/opencascade
    if [ ! -f "$inc/STEPControl_Reader.hxx" ] || [ ! -f "$inc/IGESControl_Reader.hxx" ]; then
        echo "read_curves: OpenCASCADE is not installed (apt-get install" \
            "libocct-data-exchange-dev); nothing checked"
        exit 0
    fi
    reader="$tmp/read_curves"
    g++ -std=c++17 -O1 -Wall -Wno-deprecated-declarations -I"$inc" "$here/read_curves.cpp" \
        -o "$reader" -lTKSTEP -lTKSTEPBase -lTKIGES -lTKXSBase -lTKTopAlgo -lTKBRep \
        -lTKGeomAlgo -lTKGeomBase -lTKG3d -lTKG2d -lTKMath -lTKernel
fi
status=0
for case in viviani:viviani-implicit cylinders:cylinders; do
    name="${case%%:*}" example="$src/examples/${case#*:}.json"
    "$bin" trace "$example" >"$tmp/$name.json"
    # the curves' count, the closed ones' and the fit tolerance (a length) from the trace's report
    read -r curves closed tol < <(python3 -c 'import json, sys
d = json.load(open(sys.argv[1]))
print(len(d["curves"]), sum(c["closed"] for c in d["curves"]), d["report"]["fit_tolerance"])' \
        "$tmp/$name.json")
    for format in step iges; do
        "$bin" trace "$example" --format $format -o "$tmp/$name.$format"
        "$reader" "$name" "$curves" "$closed" "$tol" "$tmp/$name.$format" | grep -v '^\s*$' ||
            status=1
    done
done
[ $status -eq 0 ] && echo "read_curves: every edge within the fit tolerance of both surfaces"
exit $status
