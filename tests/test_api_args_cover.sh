#!/usr/bin/env bash
# tests/test_api_args.c calls every public function: each function declared
# in the public headers (found as tests/test_symbols.sh finds them) is named
# in the test's code (its comments stripped), so a function added to the API
# without its argument checks tested fails here.
# usage: test_api_args_cover.sh C_COMPILER SOURCE_DIR
set -u
cc="$1"
src="$2"
test_c="$src/tests/test_api_args.c"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

"$cc" -E -P -I"$src/include" "$src/include/intercurve.h" |
    sed 's/\bic_[a-z0-9_]*[[:space:]]*([[:space:]]*\*//g' |
    grep -o '\bic_[a-z0-9_]*[[:space:]]*(' | tr -d ' \t(' | sort -u >"$work/declared"
# comments out (perl, in every Debian: compilers differ in how they keep
# macros while dropping comments): a name in a comment is not covered
perl -0777 -pe 's{/\*.*?\*/}{}gs; s{//[^\n]*}{}g' "$test_c" |
    grep -o '\bic_[a-z0-9_]*\b' | sort -u >"$work/used"

n_dec=$(wc -l <"$work/declared")
if [ "$n_dec" -lt 100 ]; then
    echo "FAIL: only $n_dec functions found in the public headers: the parse is broken"
    exit 1
fi
if [ ! -s "$work/used" ]; then
    echo "FAIL: no ic_ name found in $test_c"
    exit 1
fi
missing=$(comm -23 "$work/declared" "$work/used")
if [ -n "$missing" ]; then
    echo "FAIL: public functions not exercised by tests/test_api_args.c:"
    echo "$missing" | sed 's/^/  /'
    exit 1
fi
echo "api_args_cover: all $n_dec public functions exercised"
