#!/usr/bin/env bash
# The shared library exports exactly the documented API: every dynamic symbol
# it defines is a function declared in the public headers (so carries the ic_
# prefix), and every declared function is exported (none lacks IC_API); and
# every global name of the static library beside it (libintercurve.a, whose
# internal functions a program linking it also sees) carries the ic_ prefix.
# usage: test_symbols.sh LIBRARY.so C_COMPILER SOURCE_DIR
set -u
lib="$1"
cc="$2"
src="$3"
for tool in nm "$cc"; do
    command -v "$tool" >/dev/null || { echo "FAIL: $tool not found"; exit 1; }
done
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# Exported: defined dynamic symbols, less the linker's absolute markers (type
# A: _end, __bss_start on some linkers), which name no code or data.
nm -D --defined-only "$lib" | awk '$2 != "A" { print $3 }' | sort -u >"$work/exported"
# Declared: the function names of the preprocessed headers (comments and
# macros are gone there; a declaration is the only "ic_name(", once the
# return types of function pointer types, "ic_status (*", are dropped).
"$cc" -E -P -I"$src/include" "$src/include/intercurve.h" |
    sed 's/\bic_[a-z0-9_]*[[:space:]]*([[:space:]]*\*//g' |
    grep -o '\bic_[a-z0-9_]*[[:space:]]*(' | tr -d ' \t(' | sort -u >"$work/declared"

fail=0
n_exp=$(wc -l <"$work/exported")
n_dec=$(wc -l <"$work/declared")
if [ "$n_dec" -lt 100 ]; then
    echo "FAIL: only $n_dec functions found in the public headers: the parse is broken"
    fail=1
fi
unprefixed=$(grep -v '^ic_' "$work/exported")
if [ -n "$unprefixed" ]; then
    echo "FAIL: exported without the ic_ prefix:"
    echo "$unprefixed" | sed 's/^/  /'
    fail=1
fi
undeclared=$(comm -23 "$work/exported" "$work/declared" | grep '^ic_')
if [ -n "$undeclared" ]; then
    echo "FAIL: exported but not declared in include/ (internal functions must stay hidden):"
    echo "$undeclared" | sed 's/^/  /'
    fail=1
fi
missing=$(comm -13 "$work/exported" "$work/declared")
if [ -n "$missing" ]; then
    echo "FAIL: declared in include/ but not exported (IC_API missing?):"
    echo "$missing" | sed 's/^/  /'
    fail=1
fi
static="$(dirname "$lib")/libintercurve.a"
if [ ! -f "$static" ]; then
    echo "FAIL: no static library at $static"
    fail=1
else
    # names beginning with two underscores are the compiler's and the
    # sanitizers' (reserved to the implementation: __odr_asan.*)
    loose=$(nm -g --defined-only "$static" 2>/dev/null | awk 'NF == 3 { print $3 }' |
        grep -v '^ic_' | grep -v '^__' | sort -u)
    if [ -n "$loose" ]; then
        echo "FAIL: global names of the static library without the ic_ prefix:"
        echo "$loose" | sed 's/^/  /'
        fail=1
    fi
fi
echo "symbols: $n_exp exported, $n_dec declared"
exit $fail
