#!/usr/bin/env python3
"""Expected values for point_lambertian_tilted (see README.md). Standard library only."""
import json, math, pathlib

I0 = 1200.0               # cd, I(gamma) = I0 cos(gamma) below the luminaire, 0 above
src = (3.0, 2.0, 2.5)
tilt_deg = 30.0           # rotation about the world y axis
t = math.radians(tilt_deg)
# Rotating the luminaire by +30 deg about +y turns its nadir (0, 0, -1) into
# (x cos + z sin, y, -x sin + z cos) = (-sin t, 0, -cos t).
axis = (-math.sin(t), 0.0, -math.cos(t))
floor_points = [(3.0, 2.0), (2.0, 2.0), (1.0, 2.0), (4.0, 2.0), (5.5, 2.0), (3.0, 3.5), (1.0, 0.5)]
points, cases = [], []
for k, (x, y) in enumerate(floor_points):
    v = (x - src[0], y - src[1], 0.0 - src[2])
    d = math.sqrt(sum(c * c for c in v))
    w = tuple(c / d for c in v)
    cos_gamma = sum(a * b for a, b in zip(w, axis))   # angle from the tilted nadir
    I = I0 * max(0.0, cos_gamma)
    E = I * (-w[2]) / d**2                              # cos θ at the floor = -w_z
    points.append({"at": [x, y, 0.0], "normal": [0, 0, 1]})
    cases.append({"surface": "floor probes", "point": k, "quantity": "E", "expected": E,
                  "rel_tol": 1e-9,
                  "source": f"E = I0 cos(gamma) cos(theta) / d^2, gamma from the tilted axis (README)"})
here = pathlib.Path(__file__).parent
project = {
    "format": "luxgrid-project/1", "name": "lambertian point source tilted 30 degrees about y",
    "settings": {"quality": "draft", "indirect": "off", "near_field": "never"},
    "photometry": {"cosine": {"builtin": "lambertian", "intensity_cd": I0}},
    "rooms": [{"name": "black box", "outline": [[0, 0], [6, 0], [6, 4], [0, 4]], "height": 3.0,
               "reflectance": {"floor": 0, "walls": 0, "ceiling": 0}}],
    "luminaires": [{"photometry": "cosine", "position": list(src), "rotation": [0, tilt_deg, 0]}],
    "surfaces": [{"name": "floor probes", "points": points}],
}
(here / "project.json").write_text(json.dumps(project, indent=1) + "\n")
(here / "expected.json").write_text(json.dumps({"cases": cases}, indent=1) + "\n")
