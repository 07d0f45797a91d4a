#!/usr/bin/env bash
# Installs the build into a temporary prefix (cmake --install) and builds and
# runs tests/install/consumer.c, which loads examples/viviani.json, through
#  (a) pkg-config, shared library;
#  (b) pkg-config --static, static library (a copy of the prefix without the
#      shared one, so the linker can only take libintercurve.a);
#  (c) a CMake project with find_package(intercurve CONFIG): intercurve::intercurve
#      and intercurve::intercurve_static; and the version file refuses an older
#      API generation;
#  (d) given PYTHON: the installed Python package imported from the prefix,
#      loading the installed library, tracing Viviani's curve;
#  and the installed command: it names no cairo, and its plot runs the
#  installed intercurve-plot (libexec) to draw a picture.
# usage: test_install.sh BUILD_DIR SOURCE_DIR C_COMPILER [EXTRA_CFLAGS [PYTHON]]
set -u
build="$1"
src="$2"
cc="$3"
# sanitizer builds: the consumers need the same runtime
read -r -a extra <<<"${4:-}"
python="${5:-}"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
pass=0
fail=0
check() { # description, status
    if [ "$2" -eq 0 ]; then pass=$((pass + 1)); else fail=$((fail + 1)); echo "FAIL: $1"; fi
}
finish() {
    echo "install: $pass passed, $fail failed"
    # a failure, or no check run at all, fails the test
    [ "$fail" -eq 0 ] && [ "$pass" -gt 0 ]
    exit $?
}
needed() { # the shared libraries an executable names
    readelf -d "$1" | sed -n 's/.*(NEEDED).*\[\(.*\)\]/\1/p'
}
links_shared() { # executable: it exists and names the shared intercurve
    [ -f "$1" ] && needed "$1" | grep -qx "$soname"
}
links_static() { # executable: it exists and names no shared intercurve
    [ -f "$1" ] && ! needed "$1" | grep -q libintercurve
}
consumer="$src/tests/install/consumer.c"
problem="$src/examples/viviani.json"

prefix="$work/prefix"
cmake --install "$build" --prefix "$prefix" >"$work/install.log" 2>&1
rc=$?
check "cmake --install: $(tail -3 "$work/install.log")" $rc
pc=$(find "$prefix" -name intercurve.pc)
test -n "$pc"
check "intercurve.pc installed" $?
[ -n "$pc" ] || finish
"$prefix/bin/intercurve" --help >/dev/null
check "the installed command runs" $?
! needed "$prefix/bin/intercurve" | grep -q cairo
check "the installed command does not load cairo" $?
"$prefix/bin/intercurve" plot "$problem" -o "$work/viviani.svg" --size 300x200 &&
    grep -q "<svg" "$work/viviani.svg"
check "the installed command draws (through libexec/intercurve/intercurve-plot)" $?

# (a) pkg-config, shared
export PKG_CONFIG_PATH
PKG_CONFIG_PATH=$(dirname "$pc")
libdir=$(pkg-config --variable=libdir intercurve)
version=$(pkg-config --modversion intercurve)
soname=$(readelf -d "$libdir/libintercurve.so" | sed -n 's/.*(SONAME).*\[\(.*\)\]/\1/p')
[[ "$soname" == libintercurve.so.[0-9]* ]]
check "the shared library has a SONAME ($soname)" $?
# shellcheck disable=SC2046 # pkg-config's words are separate arguments
"$cc" "${extra[@]}" -o "$work/shared" "$consumer" $(pkg-config --cflags --libs intercurve) -lm \
    2>"$work/err"
rc=$?
check "pkg-config --libs: build ($(cat "$work/err"))" $rc
links_shared "$work/shared"
check "pkg-config --libs: linked to $soname" $?
LD_LIBRARY_PATH="$libdir" "$work/shared" "$problem" "$work/a.svg"
check "pkg-config --libs: run" $?
test -s "$work/a.svg"
check "pkg-config --libs: picture written" $?

# (b) pkg-config --static, from a prefix holding only the static library
cp -a "$prefix" "$work/static-prefix"
rm -f "$work/static-prefix/${libdir#"$prefix"/}"/libintercurve.so*
PKG_CONFIG_PATH="$work/static-prefix/${PKG_CONFIG_PATH#"$prefix"/}"
# shellcheck disable=SC2046
"$cc" "${extra[@]}" -o "$work/static" "$consumer" $(pkg-config --cflags --static --libs intercurve) \
    2>"$work/err"
rc=$?
check "pkg-config --static --libs: build ($(cat "$work/err"))" $rc
links_static "$work/static"
check "pkg-config --static --libs: no shared intercurve needed" $?
"$work/static" "$problem" "$work/b.svg"
check "pkg-config --static --libs: run" $?

# (c) CMake package
flags=(-DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_C_COMPILER="$cc" -DCMAKE_C_FLAGS="${extra[*]}")
cmake -S "$src/tests/install" -B "$work/cmake" "${flags[@]}" -DIC_WANT_VERSION="$version" \
    >"$work/cmake.log" 2>&1 && cmake --build "$work/cmake" >>"$work/cmake.log" 2>&1
rc=$?
check "find_package(intercurve $version CONFIG): build ($(tail -5 "$work/cmake.log"))" $rc
links_shared "$work/cmake/consumer_shared"
check "intercurve::intercurve is the shared library" $?
links_static "$work/cmake/consumer_static"
check "intercurve::intercurve_static is the static library" $?
"$work/cmake/consumer_shared" "$problem" "$work/c.svg"
check "find_package: intercurve::intercurve runs" $?
"$work/cmake/consumer_static" "$problem" "$work/d.svg"
check "find_package: intercurve::intercurve_static runs" $?
# the version file: an older API generation is refused (before 1.0 every
# minor version is one: SameMinorVersion; from 1.0 a major one)
major=${version%%.*}
minor=$(echo "$version" | cut -d. -f2)
if [ "$major" -eq 0 ]; then older="0.$((minor - 1))"; else older="$((major - 1)).0"; fi
! cmake -S "$src/tests/install" -B "$work/cmake-older" "${flags[@]}" -DIC_WANT_VERSION="$older" \
    >"$work/older.log" 2>&1
check "find_package(intercurve $older) refused by the version file" $?
grep -q "intercurveConfig.cmake, version: $version" "$work/older.log"
check "the refusal names the installed version $version" $?

# (d) the Python package, run from elsewhere than the sources, no
# INTERCURVE_LIB: it finds the library installed beside it
if [ -n "$python" ]; then
    pkg=$(find "$prefix" -path '*/intercurve/__init__.py' -printf '%h\n')
    test -n "$pkg" -a -f "$pkg/_installed.py"
    check "the Python package and its _installed.py are installed ($pkg)" $?
    (cd "$work" && env -u INTERCURVE_LIB PYTHONPATH="$(dirname "$pkg")" PYTHONDONTWRITEBYTECODE=1 \
        "$python" -c '
import math, sys
import intercurve as ic
pkg, libdir, problem = sys.argv[1:4]
assert ic.__file__.startswith(pkg), ic.__file__
assert ic.library_path().startswith(libdir + "/libintercurve.so"), ic.library_path()
r = ic.Problem.load(problem).trace(tol=1e-10)
(c,) = r.curves
# the length of Viviani s curve, the integral of sqrt(1 + cos^2(t/2)) over [0, 4 pi]
# by the midpoint rule on 20000 panels (error ~1e-9)
n = 20000
length = sum(math.sqrt(1 + math.cos((k + 0.5) * 4 * math.pi / n / 2) ** 2)
             for k in range(n)) * 4 * math.pi / n
assert c.closed and abs(c.length - length) < 1e-7, (c.length, length)
' "$pkg" "$libdir" "$problem") >"$work/python.log" 2>&1
    check "the installed Python package traces Viviani's curve ($(tail -3 "$work/python.log"))" $?
fi
finish
