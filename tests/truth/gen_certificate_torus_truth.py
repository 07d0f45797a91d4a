#!/usr/bin/env python3
"""Truth for tests/test_certificate_torus.c (issue 23): a torus touching a
sphere along a circle, the torus as a rational biquadratic NURBS net.

The torus has tube radius r about the circle of radius R in the plane z = 0;
the sphere is centred at (0, 0, c) on the axis. The tube's centre circle
point Q = (R, 0, 0) (in the plane through the axis) is at distance
D = sqrt(R^2 + c^2) from the sphere's centre. A sphere of radius D + r
(side +1, the torus inside it) or D - r (side -1, the sphere inside the
torus's hole side) touches the tube's circle at the point of the line
through the centre and Q at distance r from Q: Q + side r (Q - centre)/D.
Revolved about the axis, that is the tangential circle, of radius
R + side r R / D and height -side r c / D. (The tube's circle and the
sphere's meridian circle are tangent there, and nowhere else meet, by the
triangle inequality.)

Printed: R r c side, the circle's length and its height (17 digits,
mpmath at 40).

usage: gen_certificate_torus_truth.py > certificate_torus.txt
"""
import mpmath as mp

mp.mp.dps = 40
CASES = [("2", "0.5", "0", 1), ("2", "0.5", "0", -1), ("3", "1", "1", 1),
         ("3", "1", "-2", -1), ("2.5", "0.75", "0.5", 1), ("1.5", "0.25", "-1", -1)]

print("# R r c side length height")
for Rs, rs, cs, side in CASES:
    R, r, c = mp.mpf(Rs), mp.mpf(rs), mp.mpf(cs)
    D = mp.sqrt(R * R + c * c)
    print(Rs, rs, cs, side, mp.nstr(2 * mp.pi * (R + side * r * R / D), 17),
          mp.nstr(-side * r * c / D, 17))
