#!/usr/bin/env bash
# What users read cites the papers by author and year (docs/references.md) and
# points only to files in the repository: no private file numbers ("seed 001",
# "seed002-cusp"), no "../shared/..." paths, no DESIGN.md. Checked: the files
# under src/, include/, docs/ and examples/, README.md, and the help text of
# every command. Exempt: the "Former names" section of docs/references.md,
# which explains the old numbers to users of earlier versions.
# usage: test_citations.sh BUILD_DIR SOURCE_DIR
set -u
bin="$1/intercurve"
src="$2"
FORBIDDEN='seeds?[ _-]?0|\.\./shared|DESIGN\.md'
EXEMPT_FILE=docs/references.md
EXEMPT_SECTION='## Former names'
pass=0
fail=0
check() { # description, condition status
    if [ "$2" -eq 0 ]; then pass=$((pass + 1)); else fail=$((fail + 1)); echo "FAIL: $1"; fi
}

# The files in scope, relative to the source directory: the tracked ones
# where the source is a git work tree, else every file there.
files_in_scope() {
    if git -C "$src" rev-parse --is-inside-work-tree >/dev/null 2>&1; then
        git -C "$src" ls-files -- src include docs examples README.md
    else
        (cd "$src" && find src include docs examples README.md -type f)
    fi
}

# A file's text without the exempt section (from its heading to the next one).
text_of() { # relative path
    if [ "$1" = "$EXEMPT_FILE" ]; then
        awk -v h="$EXEMPT_SECTION" '/^## / { skip = ($0 == h) } !skip' "$src/$1"
    else
        cat "$src/$1"
    fi
}

nfiles=0
while IFS= read -r f; do
    [ -f "$src/$f" ] || continue
    grep -Iq . "$src/$f" || continue # binary (the gallery's pictures) or empty
    nfiles=$((nfiles + 1))
    hits=$(text_of "$f" | grep -n -i -E "$FORBIDDEN")
    [ -z "$hits" ]
    check "$f mentions a file number or a file outside the repository:
$hits" $?
done < <(files_in_scope)
# the scope is not empty by mistake (a wrong directory passes vacuously)
[ "$nfiles" -ge 50 ] && text_of "$EXEMPT_FILE" | grep -q 'Hassan and Badr (2016)'
check "found $nfiles text files in $src, docs/references.md among them" $?

# the exemption is in use: the old numbers are explained there
grep -q -i -E "$FORBIDDEN" "$src/$EXEMPT_FILE" && grep -q -x "$EXEMPT_SECTION" "$src/$EXEMPT_FILE"
check "docs/references.md explains the former names under \"$EXEMPT_SECTION\"" $?

for cmd in "" eval point trace plot; do
    out=$("$bin" $cmd --help 2>&1)
    rc=$?
    [ $rc -eq 0 ] && [ -n "$out" ]
    check "intercurve $cmd --help prints its help (exit $rc)" $?
    hits=$(printf '%s\n' "$out" | grep -n -i -E "$FORBIDDEN")
    [ -z "$hits" ]
    check "intercurve $cmd --help mentions a file number or an outside file:
$hits" $?
done

echo "test_citations: $pass passed, $fail failed"
# a failure, or no check run at all, fails the test
[ "$fail" -eq 0 ] && [ "$pass" -gt 0 ]
