#!/usr/bin/env bash
# The intercurve command: every example evaluates; bad input exits 1 with a
# message naming file, JSON path and column; help texts exist.
# usage: test_cli.sh BUILD_DIR SOURCE_DIR
set -u
bin="$1/intercurve"
src="$2"
pass=0
fail=0
check() { # description, condition status
    if [ "$2" -eq 0 ]; then pass=$((pass + 1)); else fail=$((fail + 1)); echo "FAIL: $1"; fi
}
out=$(mktemp)
errf=$(mktemp)
trap 'rm -f "$out" "$errf"' EXIT

for f in "$src"/examples/*.json; do
    for name in $(grep -o '"name": *"[^"]*"' "$f" | sed 's/.*: *"//; s/"$//'); do
        "$bin" eval "$f" --surface "$name" --at 0.3,0.4 >"$out" 2>"$errf"
        rc=$?
        if grep -q "needs three coordinates" "$errf"; then
            "$bin" eval "$f" --surface "$name" --at 0.3,0.4,0.5 >"$out" 2>"$errf"
            rc=$?
        fi
        check "eval $f --surface $name (rc $rc: $(cat "$errf"))" "$rc"
        grep -q '"principal_curvatures"' "$out"
        check "eval $f --surface $name prints principal_curvatures" $?
    done
done

# Viviani's sphere (radius 2) has principal curvatures -1/2 (the JSON
# numbers read back exactly, so the geometry's rounding, a few ulps, shows)
"$bin" eval "$src/examples/viviani.json" --surface sphere --at pi/5,0.4 >"$out"
grep '"principal_curvatures"' "$out" | tr -d '[],' |
    awk '{ exit !(NF == 3 && ($2 + 0.5)^2 < 1e-30 && ($3 + 0.5)^2 < 1e-30) }'
check "sphere of radius 2: principal curvatures -0.5, -0.5 within 1e-15" $?

expect_error() { # file-or-args, expected exit, expected message parts...
    local rc_want="$1"; shift
    local args="$1"; shift
    # shellcheck disable=SC2086
    "$bin" $args >"$out" 2>"$errf"
    local rc=$?
    check "'$args' exits $rc_want (got $rc)" $([ "$rc" -eq "$rc_want" ]; echo $?)
    for part in "$@"; do
        grep -qF -- "$part" "$errf"
        st=$?
        check "'$args' message contains '$part': $(head -c 300 "$errf")" $st
    done
}
d="$src/tests/data"
expect_error 1 "eval $d/bad-formula.json --at 1,2,3" "bad-formula.json" "surfaces[0].f" "column 7" "unknown identifier 'foo'" "^"
expect_error 1 "eval $d/bad-paren.json --at 1,2" "surfaces[0].xyz[2]" "never closed"
# one surface alone: a surface to evaluate (eval), no intersection (point)
"$bin" eval "$d/one-surface.json" --at 1,2,3 >"$out" 2>"$errf"
st=$?
check "eval a file of one surface exits 0 ($(cat "$errf"))" $st
grep -q '"value":.*3,' "$out"
check "eval a file of one surface: f = z is 3 at (1, 2, 3)" $?
expect_error 1 "point $d/one-surface.json --at 1,2,3" "surfaces" "exactly two surfaces"
expect_error 1 "eval $d/bad-radius.json --at 1,2,3" "surfaces[0]" "radius must be positive"
expect_error 1 "eval $d/unknown-key.json --at 1,2,3" "(root)" "unknown key \"boxx\""
# placed primitives: a bad axis or ref_direction named by its JSON path
expect_error 1 "trace $d/bad-axis-zero.json" "bad-axis-zero.json" "surfaces[1].axis" "the axis is zero"
expect_error 1 "trace $d/bad-ref-parallel.json" "surfaces[1].ref_direction" "parallel to the axis" "1e-06 radians"
expect_error 1 "eval $d/bad-plane-axis.json --at 1,2,3" "surfaces[1].axis" "a plane takes no axis"
expect_error 1 "eval $d/bad-axis-size.json --at 1,2,3" "surfaces[0].axis" "expected an array of 3 numbers"
expect_error 1 "eval $d/bad-json.json --at 1,2,3" "invalid JSON near line 2"
expect_error 1 "eval $d/bad-domain.json --at 1,2" "surfaces[0].domain[1][1]" "exponent has no digits"
expect_error 1 "eval $d/bad-type.json --at 1,2,3" "surfaces[0].type" "expected \"parametric\""
expect_error 1 "eval $d/bad-constant.json --at 1,2,3" "constants.sin" "reserved"
expect_error 1 "eval $d/self-implicit.json --at 1,2,3" "self-intersection needs a parametric surface"
expect_error 1 "eval $d/missing.json --at 1,2" "cannot open"
expect_error 1 "eval $src/examples/viviani.json --surface torus --at 1,2" "no surface named 'torus'" "'cylinder'"
expect_error 1 "eval $src/examples/viviani.json --at 1" "needs two parameters"
expect_error 1 "eval $src/examples/viviani.json --at 1,foo" "--at, value 2" "unknown identifier 'foo'"
expect_error 1 "eval $src/examples/viviani.json --at 1,2 --order 99" "--order expects a whole number from 0 to 24"
expect_error 1 "eval $src/examples/viviani.json" "needs PROBLEM.json and --at"
expect_error 1 "frobnicate" "unknown command"
expect_error 2 "eval $src/examples/viviani-implicit.json --surface sphere --at 0,0,1e300" "surfaces[1] (\"sphere\")" "column 14" "overflows"

# intercurve point
"$bin" point "$src/examples/viviani.json" --at 1.5,0.8660254037844386,1 --order 3 >"$out" 2>"$errf"
st=$?
check "point on Viviani exits 0 ($(cat "$errf"))" $st
grep -q '"type":.*"transversal"' "$out"
check "point: type transversal" $?
grep -q '"kappa":.*0.58154313668469' "$out"
check "point: Viviani curvature sqrt(14.5)/3.5^1.5" $?
grep -q '"derivatives":' "$out" && grep -q '"kappa_g":' "$out" && grep -q '"parameter_derivatives":' "$out"
check "point: derivatives, Darboux quantities and parameter derivatives" $?
"$bin" point "$src/examples/viviani.json" --at 1.5,0.8660254037844386,1 --order 3 --method closed-form >"$out" 2>"$errf"
check "point --method closed-form exits 0" $?
grep -q '"method":.*"closed-form"' "$out"
check "point: closed-form named in the output" $?
# without --order the closed forms give what they have: order 3 (was an
# error about order 4, which the user never asked for)
"$bin" point "$src/examples/viviani.json" --at 1.5,0.8660254037844386,1 --method closed-form >"$out" 2>"$errf"
st=$?
grep -q '"order":[[:space:]]*3' "$out"
found=$?
check "point --method closed-form without --order: order 3, exit 0 (exit $st; $(head -c 200 "$errf"))" $((st || found))
# an empty -o names no file: said so (was "Is a directory")
"$bin" trace "$src/examples/viviani.json" -o '' >"$out" 2>"$errf"
st=$?
grep -q "without a name" "$errf"
found=$?
check "trace -o '': refused, saying the file has no name (exit $st)" $((!st || found))
"$bin" point "$src/examples/enneper-self.json" --params 'sqrt(2),3,sqrt(2),-3' --order 3 --format text >"$out" 2>"$errf"
st=$?
check "point: Enneper self-intersection by parameters ($(cat "$errf"))" $st
grep -q 'tau          0$' "$out"
check "point: the Enneper double curve is planar (tau 0)" $?
"$bin" point "$src/examples/paraboloid-cubic.json" --at 'sqrt(11/2),sqrt(5/2),-2' --format text >"$out" 2>"$errf"
grep -q 'tau          -0.51528286240' "$out"
check "point: Abdel-All et al. (2012) Ex 5.4 torsion -27395 sqrt(55)/394282" $?
"$bin" point "$src/examples/viviani.json" --at 2,0,0 --order 3 >"$out" 2>"$errf"
st=$?
check "point at Viviani's branch point exits 0 ($(cat "$errf"))" $st
grep -q '"type":.*"branch-point"' "$out" && grep -q '"discriminant":.*0.0625' "$out"
check "point: branch point with Delta = 1/16" $?
[ "$(grep -c '"kappa_prime"' "$out")" -eq 2 ]
check "point: two branches at the branch point" $?
"$bin" point "$src/examples/sphere-plane-contact.json" --at 0,1,0 >"$out" 2>"$errf"
grep -q '"type":.*"isolated-contact"' "$out" && grep -q '"branches":.*\[\]' "$out"
check "point: isolated contact, no branch" $?
"$bin" point "$src/examples/cusp.json" --at 0,0,0 >"$out" 2>"$errf"
grep -q '"type":.*"cusp"' "$out" && grep -q '"regular":.*false' "$out"
check "point: cusp with one-sided half-branches" $?
expect_error 2 "point $src/examples/viviani.json --at 1.5,0.8660254037844386,1.2" "0.107 away from surface B" "tolerance 1e-06"
expect_error 1 "point $src/examples/ellipsoids.json --params 1,2" "both surfaces are implicit"
expect_error 1 "point $src/examples/viviani.json --at 1.5,0.8660254037844386,1 --method closed-form --order 4" "up to order 3"
expect_error 1 "point $src/examples/viviani.json --at 1,2,3 --method guess" "--method expects"
expect_error 1 "point $src/examples/viviani.json --at 1,2" "--at needs three coordinates"
expect_error 1 "point $src/examples/viviani.json --at 1,2,3 --params 1,2,3,4" "one of --at or --params"
expect_error 1 "point $src/examples/viviani.json --at 1,2,3 --order 17" "--order expects a whole number from 1 to 16"
"$bin" point "$src/examples/viviani.json" --at 2,0,0 --method closed-form --order 3 >"$out" 2>"$errf"
grep -q '"paper_coefficients"' "$out" &&
    grep '"tau":' "$out" | tr -d ',' | awk '{ n++; d = ($2 < 0 ? -$2 : $2) - 0.375; bad += d * d > 1e-24 }
        END { exit !(n == 2 && !bad) }'
st=$?
check "point: Hassan and Badr (2016) section 4 at the branch point, tau 3/8 ($(cat "$errf"))" $st
"$bin" point "$src/examples/viviani.json" --at 2,0,0 --method perturbation >"$out" 2>"$errf"
grep -q '"error_estimate"' "$out"
st=$?
check "point: perturbation reports an error estimate ($(cat "$errf"))" $st
expect_error 1 "point $src/examples/viviani.json --at 1.5,0.8660254037844386,1 --method height-difference" "for tangential points"
"$bin" point --help | grep -q "examples:"
check "point --help has examples" $?

# intercurve trace
"$bin" trace "$src/examples/viviani-implicit.json" >"$out" 2>"$errf"
st=$?
check "trace Viviani exits 0 ($(cat "$errf"))" $st
[ "$(grep -c '"closed":' "$out")" -eq 1 ] && grep -q '"closed":.*true' "$out" && grep -q '"type":.*"branch-point"' "$out"
check "trace Viviani: one closed figure-eight and the branch point" $?
grep -q '"exclusion_proven":.*true' "$out" && grep -q '"uncovered_cells":.*0' "$out"
check "trace Viviani: the report says what was proven" $?
# coaxial primitives in closed form; --no-exact searches (docs/tracing.md, "Exact paths")
coaxial='{"surfaces": [{"type": "sphere", "radius": 1},
  {"type": "plane", "center": [0, 0, 0.5], "normal": [0, 0, 1]}], "box": [[-2, 2], [-2, 2], [-2, 2]]}'
echo "$coaxial" | "$bin" trace - >"$out" 2>"$errf"
check "trace sphere and plane exits 0 ($(cat "$errf"))" $?
grep -q '"method":.*"closed form: coaxial surfaces of revolution"' "$out" &&
    grep -q '"shape":.*"circle"' "$out" && grep -q '"cells":.*0,' "$out"
check "trace sphere and plane: a circle in closed form, no cells searched" $?
echo "$coaxial" | "$bin" trace - --no-exact >"$out" 2>"$errf"
check "trace sphere and plane --no-exact exits 0 ($(cat "$errf"))" $?
grep -q '"method":.*"search"' "$out" && grep -q '"shape":.*"circle"' "$out" &&
    ! grep -q '"cells":.*0,' "$out"
check "trace sphere and plane --no-exact: the circle by the search" $?
tmpout="$(mktemp -d)/v.json"
"$bin" trace "$src/examples/ellipsoids.json" -o "$tmpout" >"$out" 2>"$errf"
check "trace -o FILE exits 0" $?
[ -s "$tmpout" ] && [ ! -e "$tmpout.tmp" ] && grep -q '"shape":.*"planar"' "$tmpout"
check "trace -o FILE: written through a rename, planar arcs of Ex 5.1" $?
expect_error 1 "trace $src/examples/viviani-implicit.json --format xls" "--format xls is not one of json, csv, vtk, obj"
for fmt in csv vtk obj step iges; do
    "$bin" trace "$src/examples/ellipsoids.json" --format $fmt -o "$tmpout.$fmt" >"$out" 2>"$errf"
    check "trace --format $fmt -o FILE exits 0" $?
    [ -s "$tmpout.$fmt" ] && [ ! -e "$tmpout.$fmt.tmp" ]
    check "trace --format $fmt: the file is there, no temporary left" $?
done
[ "$(grep -c ',branch-point$' "$tmpout.csv")" -ge 2 ] && head -1 "$tmpout.csv" | grep -q '^curve,s,x,y,z,u,v,p,q,'
check "trace --format csv: the columns of docs/output-formats.md, the branch points classified" $?
grep -q '^LINES 2 ' "$tmpout.vtk" && grep -q '^VECTORS b double' "$tmpout.vtk"
check "trace --format vtk: two polylines with the frame as point data" $?
[ "$(grep -c '^l ' "$tmpout.obj")" -eq 2 ]
check "trace --format obj: two polylines" $?
[ "$(grep -c '^#[0-9]*=B_SPLINE_CURVE_WITH_KNOTS(' "$tmpout.step")" -eq 2 ] &&
    head -1 "$tmpout.step" | grep -qx 'ISO-10303-21;'
check "trace --format step: two B-spline curves in a Part 21 file" $?
[ "$(grep -c '^     126 .*D      [13]$' "$tmpout.iges")" -eq 2 ] &&
    [ "$(awk 'length($0) != 80' "$tmpout.iges" | wc -l)" -eq 0 ]
check "trace --format iges: two entities 126, 80 columns a line" $?
for fmt in step iges; do
    "$bin" surfaces "$tmpout.$fmt" >"$out" 2>"$errf"
    grep -q "length unit mm (0.001 m), 0 surfaces" "$out"
    check "trace --format $fmt: intercurve's own reader finds millimetres (and no surface)" $?
done
"$bin" trace "$src/examples/ellipsoids.json" --format step --fit-tol 1e-6 >"$out" 2>"$errf"
! cmp -s <(grep -v FILE_NAME "$out") <(grep -v FILE_NAME "$tmpout.step") &&
    grep -q "LENGTH_MEASURE(.*E-0[56])" "$out"
check "trace --format step --fit-tol 1e-6: fitted with that tolerance" $?
expect_error 2 "trace $src/examples/ellipsoids.json -o /nonexistent-dir/x.json" "cannot write /nonexistent-dir/x.json"
"$bin" trace "$src/examples/enneper-self.json" >"$out" 2>"$errf"
[ "$(grep -c '"closed":' "$out")" -eq 2 ] && [ "$(grep -c '"shape":.*"planar"' "$out")" -eq 2 ]
check "trace a self-intersection: Enneper's two planar double curves" $?
expect_error 1 "trace $src/tests/data/bad-formula.json" "surfaces[0].f"
"$bin" trace --help | grep -q "example:"
check "trace --help has an example" $?

# a degenerate point: printed with nulls and the reason
"$bin" eval "$src/examples/viviani.json" --surface sphere --at 0.3,pi/2 >"$out" 2>"$errf"
check "sphere pole exits 0" $?
grep -q '"degenerate":.*degenerate point' "$out"
check "sphere pole says degenerate" $?
grep -q '"normal":.*null' "$out"
check "sphere pole: normal is null" $?

# pictures: formats, options, errors; the "no intersection" message is text
# in the PDF (pdftotext reads it back)
pdir=$(mktemp -d)
trap 'rm -f "$out" "$errf"; rm -rf "$pdir"' EXIT
"$bin" plot "$src/examples/viviani-implicit.json" -o "$pdir/v.svg" --view 60,10 --frames 3 --size 640x400 --mesh 12 --no-chart 2>"$errf"
st=$?
check "plot to SVG with every option (rc $st: $(cat "$errf"))" $st
[ "$(grep -c 'stroke-width:2.25;' "$pdir/v.svg")" -eq 9 ]
check "plot --frames 3: nine frame arrows" $?
[ ! -e "$pdir/v.svg.tmp.svg" ]
check "plot leaves no temporary file" $?
"$bin" trace "$src/examples/viviani-implicit.json" --format text >"$out"
grep -q "branch-point" "$out" && grep -q "15.28079115611" "$out"
check "trace --format text: the figure-eight's length and its branch point" $?
"$bin" plot "$src/tests/data/apart.json" -o "$pdir/apart.pdf" 2>"$errf"
st=$?
check "plot two spheres apart (rc $st: $(cat "$errf"))" $st
if command -v pdftotext >/dev/null 2>&1; then
    pdftotext "$pdir/apart.pdf" - | grep -q "no intersection"
    check "the figure of two spheres apart says 'no intersection'" $?
fi
expect_error 1 "plot $src/examples/viviani-implicit.json" "needs PROBLEM.json and -o FIGURE"
expect_error 1 "plot $src/examples/viviani-implicit.json -o $pdir/v.gif" "use .svg, .png, .pdf or .html"
expect_error 1 "plot $src/examples/viviani-implicit.json -o $pdir/v.png --view 30" "--view expects"
expect_error 1 "plot $src/examples/viviani-implicit.json -o $pdir/v.png --size 10x10" "--size expects"
expect_error 1 "plot $src/examples/viviani-implicit.json -o $pdir/v.png --frames 1000" "--frames"
expect_error 2 "plot $src/examples/viviani-implicit.json -o $pdir/no/such/v.png" "cannot write"
expect_error 1 "plot $src/tests/data/bad-formula.json -o $pdir/b.png" "surfaces[0].f"
"$bin" plot --help | grep -q "example:"
check "plot --help has an example" $?
# only intercurve-plot draws: the command itself starts without cairo
! readelf -d "$bin" | grep -q "libcairo"
check "the command names no cairo (plot runs intercurve-plot)" $?
lonely=$(mktemp -d)
cp "$bin" "$lonely/intercurve"
"$lonely/intercurve" plot "$src/examples/viviani-implicit.json" -o "$lonely/v.png" >"$out" 2>"$errf"
st=$?
check "plot without intercurve-plot beside the command exits 2 (got $st)" $([ "$st" -eq 2 ]; echo $?)
grep -q "cannot run intercurve-plot" "$errf"
check "plot without intercurve-plot says so: $(head -c 300 "$errf")" $?
rm -rf "$lonely"

"$bin" --help | grep -q "eval"
check "--help lists eval" $?
"$bin" eval --help | grep -q "example:"
check "eval --help has an example" $?

# intercurve surfaces: every surface of a CAD file, text and JSON; bad files exit 1
c="$src/tests/data/cad"
"$bin" surfaces "$c/small.step" >"$out" 2>"$errf"
check "surfaces small.step exits 0 ($(cat "$errf"))" $?
grep -q 'length unit inch (0.0254 m), 11 surfaces (9 readable)' "$out" &&
    grep -q '^#10  CYLINDRICAL_SURFACE  "it'"'"'s a cylinder"  cylinder  u \[0, 6.283185307\] periodic  v unbounded' "$out" &&
    grep -q '^#33  OFFSET_SURFACE  ""  not read: #33 (OFFSET_SURFACE): this surface type is not supported' "$out"
check "surfaces small.step lists the cylinder #10 and says why #33 is not read" $?
"$bin" surfaces "$c/primitives.igs" --format json >"$out" 2>"$errf"
check "surfaces primitives.igs --format json exits 0 ($(cat "$errf"))" $?
[ "$(grep -c '"entity":' "$out")" -eq 10 ] && grep -q '"unit":	"mm"' "$out" &&
    grep -q '"format":	"IGES"' "$out"
check "surfaces --format json: ten entities, IGES, unit mm" $?
expect_error 1 "surfaces $c/missing.step" "missing.step" "cannot read"
expect_error 1 "surfaces $src/examples/viviani.json" "viviani.json" "neither a STEP file"
expect_error 1 "surfaces $c/small.step --format xml" "--format"
# a STEP file's rational sphere traced against a plane through its centre: one
# circle of length 15 pi (radius 7.5), to the 12 digits the file holds
"$bin" trace "$c/problem-sphere-plane.json" --format text >"$out" 2>"$errf"
check "trace problem-sphere-plane.json exits 0 ($(cat "$errf"))" $?
grep -E '^ +1 +yes +transversal ' "$out" | awk -v pi=3.14159265358979324 \
    '{ n++; d = $4 - 15 * pi; if (d < 0) d = -d; ok = $5 > 0 && d < 1e-9 } END { exit !(n == 1 && ok) }'
check "problem-sphere-plane.json: one closed circle of length 15 pi within 1e-9" $?
# the same sphere from the IGES file OpenCASCADE wrote (entity 128, DE 5):
# IGES holds about 10 digits (the control points off the sphere by 1.9e-10
# relative, test_cad), so the length is good to about 1e-8 (measured 9e-10)
"$bin" trace "$c/problem-sphere-plane-iges.json" --format text >"$out" 2>"$errf"
check "trace problem-sphere-plane-iges.json exits 0 ($(cat "$errf"))" $?
grep -E '^ +1 +yes +transversal ' "$out" | awk -v pi=3.14159265358979324 \
    '{ n++; d = $4 - 15 * pi; if (d < 0) d = -d; ok = $5 > 0 && d < 1e-8 } END { exit !(n == 1 && ok) }'
check "problem-sphere-plane-iges.json: one closed circle of length 15 pi within 1e-8" $?
expect_error 1 "eval $c/problem-bad-entity.json --at 0,0" "problem-bad-entity.json" "surfaces[0].entity" "bspline.step" "#58" "not a surface"

echo "test_cli: $pass passed, $fail failed"
# a failure, or no check run at all, fails the test
[ "$fail" -eq 0 ] && [ "$pass" -gt 0 ]
