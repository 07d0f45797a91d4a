#!/usr/bin/env bash
# Builds tests/cad/gen_cad_files.cpp against OpenCASCADE and writes the CAD
# test files into tests/data/cad (docs/testing.md, "CAD test files"). Needs
# Debian's libocct-data-exchange-dev and libocct-modeling-algorithms-dev;
# without them it says so and exits 0 (CI never runs it: the files it wrote
# are committed).
# usage: tests/cad/gen_cad_files.sh [OUTDIR]
set -eu
here=$(cd "$(dirname "$0")" && pwd)
out="${1:-$here/../data/cad}"
inc=/usr/include/opencascade
if [ ! -f "$inc/STEPControl_Writer.hxx" ] || [ ! -f "$inc/IGESControl_Writer.hxx" ]; then
    echo "gen_cad_files: OpenCASCADE is not installed (apt-get install" \
        "libocct-data-exchange-dev libocct-modeling-algorithms-dev); nothing written"
    exit 0
fi
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
g++ -std=c++17 -O1 -Wno-deprecated-declarations -I"$inc" "$here/gen_cad_files.cpp" -o "$tmp/gen_cad_files" \
    -lTKSTEP -lTKSTEPBase -lTKIGES -lTKXSBase -lTKTopAlgo -lTKBRep -lTKGeomAlgo \
    -lTKGeomBase -lTKG3d -lTKG2d -lTKMath -lTKernel
mkdir -p "$out"
"$tmp/gen_cad_files" "$out"
ls -l "$out"
