#!/usr/bin/env python3
"""Viviani's curve in the pairings gen_nurbs_quadrics.py leaves out: the
NURBS unit sphere (axis y, poles off the curve: tests/data/nurbs/
surface-unit-sphere-axis-y.json) with
  - the cylinder (x - 0.5)^2 + y^2 = 1/4, |z| <= 2, as a NURBS: the unit
    NURBS cylinder of surface-cylinder.json moved by the affine map
    (x, y, z) -> (x/2 + 1/2, y/2, z) applied to its control points (NURBS
    are affinely invariant: the map of the surface is the surface of the
    mapped points, with the same weights; halving and adding 1/2 are exact
    in binary), and
  - the same cylinder as parametric formulas (0.5 + 0.5 cos u, 0.5 sin u, v).
The curve is Viviani's, of length 4 sqrt(2) E(1/2) = 7.64039557805542403580952416434
(tests/truth/nurbs_quadrics_truth.txt, problem-viviani-axis-y.json), with its
branch point at (1, 0, 0).

It also writes the knot-line patch of gen_nurbs_knotline.py as NURBS-Python
(geomdl) writes it, geomdl-knotline.json (points flattened with v fastest,
weights alongside), and problem-geomdl-knotline.json, the knot-line problem
reading it: its truth is that of problem-knotline-plane.json.

And the unit NURBS sphere (axis z) moved up by 1 (control points' z + 1,
exact), resting on the plane z = 0 written as a bilinear NURBS patch over
[-2, 2]^2: one isolated contact at (0, 0, 0), the sphere's south pole, where
its parametrisation degenerates (problem-sphere-touch-nurbs-nurbs.json).

And the NURBS cylinder of radius 1 (surface-cylinder.json) with the sphere
primitive of radius 2 (parametric form): two unit circles at z = +-sqrt(3),
each 2 pi long (problem-cylinder-sphere-primitive.json).

Run: python3 tests/truth/gen_nurbs_pairings.py  (writes the six files)
"""
import json
import os

HERE = os.path.dirname(os.path.abspath(__file__))
DATA = os.path.join(HERE, "..", "data", "nurbs")


def load(name):
    with open(os.path.join(DATA, name)) as f:
        return json.load(f)


def moved_cylinder():
    cyl = load("surface-cylinder.json")
    cyl["name"] = "cylinder"
    cyl["control_points"] = [[[x / 2 + 0.5, y / 2, z] for x, y, z in row]
                             for row in cyl["control_points"]]
    return cyl


def main():
    sphere = load("surface-unit-sphere-axis-y.json")
    both = {"title": "Viviani from two NURBS: the unit sphere (axis y) and the cylinder "
                     "(x - 0.5)^2 + y^2 = 1/4 (tests/truth/gen_nurbs_pairings.py)",
            "surfaces": [sphere, moved_cylinder()]}
    formula = {"title": "Viviani from a NURBS sphere (axis y) and a parametric formula "
                        "cylinder (tests/truth/gen_nurbs_pairings.py)",
               "surfaces": [sphere, {"name": "cylinder", "type": "parametric",
                                     "xyz": ["0.5 + 0.5*cos(u)", "0.5*sin(u)", "v"],
                                     "domain": [[0, "2*pi"], [-2, 2]],
                                     "periodic": [True, False]}]}
    patch = load("surface-knotline.json")
    geomdl = {"shape": {"type": "surface", "count": 1, "data": [{
        "type": "spline", "rational": "weights" in patch, "dimension": 3,
        "degree_u": patch["degree"][0], "degree_v": patch["degree"][1],
        "knotvector_u": patch["knots"][0], "knotvector_v": patch["knots"][1],
        "size_u": len(patch["control_points"]), "size_v": len(patch["control_points"][0]),
        "control_points": {"points": [p for row in patch["control_points"] for p in row]},
        "delta": 0.05}]}}
    if "weights" in patch:
        geomdl["shape"]["data"][0]["control_points"]["weights"] = [
            w for row in patch["weights"] for w in row]
    knot_problem = load("problem-knotline-plane.json")
    knot_problem["title"] = "The knot-line patch read from a geomdl file, and the plane x = 0.75"
    knot_problem["surfaces"][0] = {"name": "knotline", "type": "geomdl",
                                   "file": "geomdl-knotline.json"}
    lifted = load("surface-unit-sphere.json")
    lifted["control_points"] = [[[x, y, z + 1] for x, y, z in row]
                                for row in lifted["control_points"]]
    plane = {"name": "plane", "type": "nurbs", "degree": [1, 1],
             "knots": [[0, 0, 1, 1], [0, 0, 1, 1]],
             "control_points": [[[-2, -2, 0], [-2, 2, 0]], [[2, -2, 0], [2, 2, 0]]]}
    touch = {"title": "The unit NURBS sphere resting on a NURBS plane at its south pole "
                      "(tests/truth/gen_nurbs_pairings.py)", "surfaces": [lifted, plane]}
    cylinder = load("surface-cylinder.json")
    with_primitive = {"title": "The NURBS cylinder of radius 1 and the sphere primitive of "
                               "radius 2: two unit circles (tests/truth/gen_nurbs_pairings.py)",
                      "surfaces": [cylinder, {"name": "sphere", "type": "sphere",
                                              "form": "parametric", "radius": 2}]}
    for name, doc in (("problem-viviani-nurbs-nurbs.json", both),
                      ("problem-cylinder-sphere-primitive.json", with_primitive),
                      ("problem-sphere-touch-nurbs-nurbs.json", touch),
                      ("problem-viviani-nurbs-formula.json", formula),
                      ("geomdl-knotline.json", geomdl),
                      ("problem-geomdl-knotline.json", knot_problem)):
        with open(os.path.join(DATA, name), "w") as f:
            json.dump(doc, f)
            f.write("\n")


if __name__ == "__main__":
    main()
