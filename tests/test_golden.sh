#!/usr/bin/env bash
# The layout of the code changes no output: every document the command writes on
# the bundled cases (tests/golden/capture.sh says which) has the hash it had when
# tests/golden/outputs.sha256 was made. A change that is meant to change an output
# regenerates the list (tests/golden/capture.sh, then `sha256sum *` in its
# directory) and says why in its commit.
#   test_golden.sh BUILD_DIR SOURCE_DIR [examples] [K/N]
# With "examples", the bundled examples' documents only (capture.sh says why);
# with K/N, the K-th of every N cases only (the tests run the parts side by
# side: one part would be the suite's longest test by far).
set -uo pipefail
build="$1" src="$2"
shift 2
only=""
for arg in "$@"; do [ "$arg" = examples ] && only=examples; done
# under the sanitizers, LeakSanitizer's list of the suppressions it used
# (tests/lsan.supp: cairo's fonts) would join the plot's standard error
export LSAN_OPTIONS="${LSAN_OPTIONS:+$LSAN_OPTIONS:}print_suppressions=0"
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
bash "$src/tests/golden/capture.sh" "$build" "$src" "$tmp/out" "$@" || exit 1
(cd "$tmp/out" && sha256sum -- * | LC_ALL=C sort -k2) >"$tmp/now.sha256"
# the documents of the cases this run wrote: a name is its case's key and a dot
awk 'NR == FNR { key[$0] = 1; next }
     { for (k in key) if (index($2, k ".") == 1) { print; next } }' \
    "$tmp/out/.keys" "$src/tests/golden/outputs.sha256" | LC_ALL=C sort -k2 >"$tmp/then.sha256"
if ! [ -s "$tmp/then.sha256" ]; then
    echo "golden: no document of tests/golden/outputs.sha256 belongs to the cases run"
    exit 1
fi
if ! diff -q "$tmp/then.sha256" "$tmp/now.sha256" >/dev/null; then
    echo "outputs that differ from tests/golden/outputs.sha256 (< then, > now):"
    diff "$tmp/then.sha256" "$tmp/now.sha256" | grep '^[<>]' | head -60
    n="$(diff "$tmp/then.sha256" "$tmp/now.sha256" | grep -c '^>')"
    echo "golden: $n of $(wc -l <"$tmp/then.sha256") documents differ"
    exit 1
fi
echo "golden: all $(wc -l <"$tmp/now.sha256") documents as before"
