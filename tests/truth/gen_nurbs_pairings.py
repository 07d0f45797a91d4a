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

Run: python3 tests/truth/gen_nurbs_pairings.py  (writes the two problem files)
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
    for name, doc in (("problem-viviani-nurbs-nurbs.json", both),
                      ("problem-viviani-nurbs-formula.json", formula)):
        with open(os.path.join(DATA, name), "w") as f:
            json.dump(doc, f)
            f.write("\n")


if __name__ == "__main__":
    main()
