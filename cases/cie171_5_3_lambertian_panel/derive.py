#!/usr/bin/env python3
"""Expected values for CIE 171:2006 test case 5.3 (see README.md). Standard library only.

A 1 x 1 m Lambertian panel of luminance 1000 cd/m^2 in the centre of the ceiling of a black
4 x 4 x 3 m room. Exact values by Lambert's contour integral; the far-field point value is
written next to each check (in `source`) to show where the point model fails."""
import json, math, pathlib

import sys
sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent.parent / "_derive"))
from lambert import *  # noqa: E402,F403  (shared exact Lambert polygon integral and cross-checks)

L, a, H = 1000.0, 1.0, 3.0            # cd/m^2, panel side (m), room height (m)
I0 = L * a * a                        # builtin lambertian: I(gamma) = I0 cos(gamma), L = I0 / A
panel = rectangle(2.0, 2.0, H, a, a)  # emits downward (default orientation)
REL_TOL = 0.01                        # quality standard: within 1 % of the reference (docs/accuracy.md)

def far_field(p, n):
    d = _sub(p, (2.0, 2.0, H))
    d2 = _dot(d, d)
    cos_g = max(0.0, -d[2] / math.sqrt(d2))                 # angle from the nadir
    cos_t = max(0.0, -_dot(d, n) / math.sqrt(d2))            # incidence on the receiver
    return I0 * cos_g * cos_t / d2

floor = [(0.0, 0.0), (0.5, 0.0), (1.0, 0.0), (1.5, 0.0), (2.0, 0.0),
         (0.5, 0.5), (1.0, 1.0), (1.5, 1.5), (2.0, 2.0), (1.0, 2.0)]
wall_z = [0.5, 1.0, 1.5, 2.0, 2.5, 2.75, 2.9, 2.95]
surfaces, cases, table = [], [], []
for name, pts in (("floor quadrant", [((2 + dx, 2 + dy, 0.0), (0, 0, 1)) for dx, dy in floor]),
                  ("wall x0 centre line", [((0.0, 2.0, z), (1, 0, 0)) for z in wall_z])):
    surfaces.append({"name": name, "points": [{"at": list(p), "normal": list(n)} for p, n in pts]})
    for k, (p, n) in enumerate(pts):
        E, ff = lambert_E(panel, L, p, n), far_field(p, n)
        err = ff / E - 1.0
        table.append((name, p, E, ff, err))
        cases.append({"surface": name, "point": k, "quantity": "E", "expected": E,
                      "rel_tol": REL_TOL,
                      "source": f"CIE 171:2006 5.3: Lambert contour integral at {p}; "
                                f"far-field point model {ff:.4f} lx ({100 * err:+.2f} %)"})
here = pathlib.Path(__file__).parent
project = {
    "format": "luxgrid-project/1", "name": "CIE 171:2006 case 5.3: Lambertian area source",
    "settings": {"quality": "standard", "indirect": "off"},
    "photometry": {"panel": {"builtin": "lambertian", "intensity_cd": I0}},
    "rooms": [{"name": "black room", "outline": [[0, 0], [4, 0], [4, 4], [0, 4]], "height": H,
               "reflectance": {"floor": 0, "walls": 0, "ceiling": 0}}],
    "luminaires": [{"photometry": "panel", "position": [2.0, 2.0, H],
                    "emitter": {"shape": "rectangle", "size": [a, a]}}],
    "surfaces": surfaces,
}
(here / "project.json").write_text(json.dumps(project, indent=1) + "\n")
(here / "expected.json").write_text(json.dumps({"cases": cases}, indent=1) + "\n")
for name, p, E, ff, err in table:
    print(f"| {name} | ({p[0]:g}, {p[1]:g}, {p[2]:g}) | {E:.4f} | {ff:.4f} | {100 * err:+.2f} % |")
