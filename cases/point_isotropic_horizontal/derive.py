#!/usr/bin/env python3
"""Expected values for point_isotropic_horizontal (see README.md). Standard library only."""
import json, math, pathlib

I, h = 1000.0, 2.5                      # cd, m above the plane
src = (5.0, 5.0, h)
offsets = [0.0, 0.5, 1.0, 2.0, 3.0, 4.5]  # horizontal distance r, m (along +x)
points, cases = [], []
for k, r in enumerate(offsets):
    d = math.hypot(h, r)
    E = I * h / d**3                    # inverse square law x cosine of incidence (h/d)
    points.append({"at": [src[0] + r, src[1], 0.0], "normal": [0, 0, 1]})
    cases.append({"surface": "probes", "point": k, "quantity": "E", "expected": E,
                  "rel_tol": 1e-9, "source": f"E = I h / d^3, r = {r} m (README)"})
here = pathlib.Path(__file__).parent
project = {
    "format": "luxgrid-project/1", "name": "isotropic point source over a horizontal plane",
    "settings": {"quality": "draft", "indirect": "off", "near_field": "never"},
    "photometry": {"iso": {"builtin": "isotropic", "intensity_cd": I}},
    "rooms": [{"name": "black box", "outline": [[0, 0], [10, 0], [10, 10], [0, 10]], "height": 3.0,
               "reflectance": {"floor": 0, "walls": 0, "ceiling": 0}}],
    "luminaires": [{"photometry": "iso", "position": list(src)}],
    "surfaces": [{"name": "probes", "points": points}],
}
(here / "project.json").write_text(json.dumps(project, indent=1) + "\n")
(here / "expected.json").write_text(json.dumps({"cases": cases}, indent=1) + "\n")
