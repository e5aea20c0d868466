#!/usr/bin/env python3
"""Expected values for CIE 171:2006 test case 5.6, scenario 2 (see README.md). Standard library.

A uniformly bright 4 x 4 m horizontal surface (Lambertian, luminance L = 1000/pi cd/m^2, so
E = 1000 F with F the configuration factor) lights points on a black wall standing on its edge
and on a black ceiling 3 m above it. E = pi L F exactly; F by Lambert's contour integral, checked
against Howell's rectangle formula (ceiling) and a brute-force area integral (wall)."""
import json, math, pathlib

import sys
sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent.parent / "_derive"))
from lambert import *  # noqa: E402,F403  (shared exact Lambert polygon integral and cross-checks)

S, H = 4.0, 3.0                          # bright square side, ceiling height (m)
L = 1000.0 / math.pi                     # so that E (lx) = 1000 F
I0 = L * S * S                           # builtin lambertian with a 4 x 4 emitter: L = I0 / A
bright = rectangle(S / 2, S / 2, 0.0, S, S)   # emits upward: rotation [180, 0, 0]
REL_TOL, ABS_TOL = 0.01, 0.01            # quality standard within 1 %; 0.01 lx = F of 1e-5

wall = [(2.0, z) for z in (0.05, 0.25, 0.5, 1.0, 2.0, 3.0)] + [(0.25, 0.25), (0.25, 1.5)]
ceiling = [(2.0, 2.0), (3.0, 2.0), (4.0, 2.0), (3.0, 3.0), (4.0, 4.0), (0.5, 3.5)]
surfaces, cases, table = [], [], []
for name, pts in (("wall x4", [((S, y, z), (-1, 0, 0)) for y, z in wall]),
                  ("ceiling", [((x, y, H), (0, 0, -1)) for x, y in ceiling])):
    surfaces.append({"name": name, "points": [{"at": list(p), "normal": list(n)} for p, n in pts]})
    for k, (p, n) in enumerate(pts):
        E = lambert_E(bright, L, p, n)
        F = E / (math.pi * L)
        if name == "ceiling":
            check = parallel_factor(-p[0], S - p[0], -p[1], S - p[1], H)
            assert abs(check - F) < 1e-12, (p, F, check)
        elif p[2] >= 0.25:
            check = midpoint_E((0, S, 0, S, 0.0, 1.0), L, p, n, m=300) / (math.pi * L)
            assert abs(check - F) < 2e-3 * F, (p, F, check)
        table.append((name, p, F, E))
        cases.append({"surface": name, "point": k, "quantity": "E", "expected": E,
                      "rel_tol": REL_TOL, "abs_tol": ABS_TOL,
                      "source": f"CIE 171:2006 5.6 scenario 2: F = {F:.6f} at {p} (Lambert contour "
                                f"integral), E = pi L F"})
here = pathlib.Path(__file__).parent
project = {
    "format": "luxgrid-project/1",
    "name": "CIE 171:2006 case 5.6 scenario 2: configuration factors from a bright floor square",
    "settings": {"quality": "standard", "indirect": "off"},
    "photometry": {"bright": {"builtin": "lambertian", "intensity_cd": I0}},
    "rooms": [{"name": "black room", "outline": [[0, 0], [S, 0], [S, S], [0, S]], "height": H,
               "reflectance": {"floor": 0, "walls": 0, "ceiling": 0}}],
    "luminaires": [{"photometry": "bright", "position": [S / 2, S / 2, 0.0], "rotation": [180, 0, 0],
                    "emitter": {"shape": "rectangle", "size": [S, S]}}],
    "surfaces": surfaces,
}
(here / "project.json").write_text(json.dumps(project, indent=1) + "\n")
(here / "expected.json").write_text(json.dumps({"cases": cases}, indent=1) + "\n")
for name, p, F, E in table:
    print(f"| {name} | ({p[0]:g}, {p[1]:g}, {p[2]:g}) | {F:.6f} | {E:.4f} |")
