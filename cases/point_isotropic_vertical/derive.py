#!/usr/bin/env python3
"""Expected values for point_isotropic_vertical (see README.md). Standard library only."""
import json, math, pathlib

I = 800.0                 # cd
src = (2.0, 3.0, 2.0)
wall_x = 5.0              # vertical plane x = 5, facing the source (normal -x)
a = wall_x - src[0]       # perpendicular distance to the plane
grid = [(3.0, 2.0), (3.0, 0.5), (1.0, 2.0), (5.0, 1.0), (3.0, 2.9), (0.5, 0.2)]  # (y, z) on the wall
points, cases = [], []
for k, (y, z) in enumerate(grid):
    d = math.sqrt(a**2 + (y - src[1])**2 + (z - src[2])**2)
    E = I * a / d**3      # cos θ = a / d at a vertical receiver facing the source
    points.append({"at": [wall_x, y, z], "normal": [-1, 0, 0]})
    cases.append({"surface": "wall probes", "point": k, "quantity": "E", "expected": E,
                  "rel_tol": 1e-9, "source": f"E = I a / d^3 at (y, z) = ({y}, {z}) (README)"})
# a point behind the source's plane side: facing away from it gets nothing
points.append({"at": [wall_x, 3.0, 2.0], "normal": [1, 0, 0]})
cases.append({"surface": "wall probes", "point": len(grid), "quantity": "E", "expected": 0.0,
              "abs_tol": 0.0, "source": "receiver facing away from the source: cos θ < 0, E = 0"})
here = pathlib.Path(__file__).parent
project = {
    "format": "luxgrid-project/1", "name": "isotropic point source and a vertical plane",
    "settings": {"quality": "draft", "indirect": "off", "near_field": "never"},
    "photometry": {"iso": {"builtin": "isotropic", "intensity_cd": I}},
    "rooms": [{"name": "black box", "outline": [[0, 0], [5, 0], [5, 6], [0, 6]], "height": 3.0,
               "reflectance": {"floor": 0, "walls": 0, "ceiling": 0}}],
    "luminaires": [{"photometry": "iso", "position": list(src)}],
    "surfaces": [{"name": "wall probes", "points": points}],
}
(here / "project.json").write_text(json.dumps(project, indent=1) + "\n")
(here / "expected.json").write_text(json.dumps({"cases": cases}, indent=1) + "\n")
