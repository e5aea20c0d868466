#!/usr/bin/env python3
"""Expected values for the five-times-rule case (see README.md). Standard library only.

A uniform (Lambertian) 0.6 x 0.6 m square emitting downward; receivers on its axis, facing it, at
0.25 to 10 times its side. Expected = exact Lambert value (Howell's parallel-rectangle formula
agrees to 1e-12); the far-field point value I0 / d^2 and its error are printed for the README."""
import json, math, pathlib

import sys
sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent.parent / "_derive"))
from lambert import *  # noqa: E402,F403  (shared exact Lambert polygon integral and cross-checks)

a, I0 = 0.6, 1000.0                 # side (m), I0 (cd): L = I0 / a^2
L = I0 / (a * a)
C = (4.0, 4.0, 7.0)                 # emitter centre, emitting downward
square = rectangle(C[0], C[1], C[2], a, a)
REL_TOL = 0.01                      # auto mode (near field inside 4 D, blend to 6 D, far beyond)
multiples = [0.25, 0.5, 1, 1.5, 2, 3, 4, 5, 6, 7, 8, 9, 10]
points, cases, table = [], [], []
for k, m in enumerate(multiples):
    d = m * a
    p = (C[0], C[1], C[2] - d)
    E = lambert_E(square, L, p, (0, 0, 1))
    check = math.pi * L * parallel_factor(-a / 2, a / 2, -a / 2, a / 2, d)
    assert abs(check - E) <= 1e-12 * E
    ff = I0 / (d * d)
    table.append((m, d, E, ff, ff / E - 1))
    points.append({"at": list(p), "normal": [0, 0, 1]})
    cases.append({"surface": "axis", "point": k, "quantity": "E", "expected": E, "rel_tol": REL_TOL,
                  "source": f"{m} x side ({d:g} m): exact Lambert; far field I0/d^2 = {ff:.4f} lx "
                            f"({100 * (ff / E - 1):+.3f} %)"})
here = pathlib.Path(__file__).parent
project = {
    "format": "luxgrid-project/1", "name": "Five-times rule: uniform square, receivers on its axis",
    "settings": {"quality": "standard", "near_field": "auto", "indirect": "off"},
    "photometry": {"square": {"builtin": "lambertian", "intensity_cd": I0}},
    "rooms": [{"name": "black shaft", "outline": [[0, 0], [8, 0], [8, 8], [0, 8]], "height": 7.5,
               "reflectance": {"floor": 0, "walls": 0, "ceiling": 0}}],
    "luminaires": [{"photometry": "square", "position": list(C),
                    "emitter": {"shape": "rectangle", "size": [a, a]}}],
    "surfaces": [{"name": "axis", "points": points}],
}
write_case(here, project, cases)
for m, d, E, ff, err in table:
    print(f"| {m:g} | {d:.3f} | {d / (a * math.sqrt(2)):.2f} | {E:.4f} | {ff:.4f} | {100 * err:+.3f} % |")
