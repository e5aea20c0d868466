#!/usr/bin/env python3
"""Expected values: a Lambertian 1.2 x 0.3 m rectangle over parallel planes (see README.md).
Standard library only. Exact E by Lambert's contour integral, checked against Howell's
rectangle formula (superposition of corner rectangles) to 1e-12."""
import json, math, pathlib

import sys
sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent.parent / "_derive"))
from lambert import *  # noqa: E402,F403  (shared exact Lambert polygon integral and cross-checks)

a, b, I0 = 1.2, 0.3, 1000.0               # m, m, cd: L = I0 / (a b) = 2777.8 cd/m^2
L = I0 / (a * b)
C = (5.0, 5.0, 2.8)                       # centre of the opening, emitting downward
panel = rectangle(C[0], C[1], C[2], a, b)
REL_TOL = 0.01                            # quality standard within 1 % (auto switch included)
named = {  # name: (x, y, z) receiver facing up
    "floor, below the centre": (5.0, 5.0, 0.0),
    "floor, below an end": (5.6, 5.0, 0.0),
    "floor, below a corner": (5.6, 5.15, 0.0),
    "floor, 1 m beside": (5.0, 6.0, 0.0),
    "floor, 2 m along and 1 m beside": (7.0, 6.0, 0.0),
    "near plane 0.2 m below, centre": (5.0, 5.0, 2.6),
    "near plane 0.2 m below, end": (5.6, 5.0, 2.6),
    "near plane 0.2 m below, 0.3 m outside the end": (5.9, 5.0, 2.6),
    "near plane 0.05 m below, corner": (5.6, 5.15, 2.75),
    "far: floor 12 m along": (17.0, 5.0, 0.0),
    "far: floor 9 m along, 6 m beside": (14.0, 11.0, 0.0),
}
points, cases, table = [], [], []
for k, (label, p) in enumerate(named.items()):
    n = (0, 0, 1)
    E = lambert_E(panel, L, p, n)
    c = C[2] - p[2]
    check = math.pi * L * parallel_factor(C[0] - a / 2 - p[0], C[0] + a / 2 - p[0],
                                           C[1] - b / 2 - p[1], C[1] + b / 2 - p[1], c)
    assert abs(check - E) <= 1e-12 * E, (label, E, check)
    d2 = sum((p[i] - C[i]) ** 2 for i in range(3))
    ff = I0 * (c * c / d2) / d2
    table.append((label, p, E, ff))
    points.append({"at": list(p), "normal": list(n)})
    cases.append({"surface": "probes", "point": k, "quantity": "E", "expected": E, "rel_tol": REL_TOL,
                  "source": f"{label}: Lambert contour integral = Howell B-3 superposition; "
                            f"far field {ff:.6g} lx ({100 * (ff / E - 1):+.2f} %)"})
here = pathlib.Path(__file__).parent
write_case(here, black_hall_panel_project("Lambertian rectangle over parallel planes", I0, C, a, b, points), cases)
for label, p, E, ff in table:
    print(f"| {label} | ({p[0]:g}, {p[1]:g}, {p[2]:g}) | {E:.6g} | {ff:.6g} | {100 * (ff / E - 1):+.2f} % |")
