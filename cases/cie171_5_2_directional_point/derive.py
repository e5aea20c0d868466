#!/usr/bin/env python3
"""Expected values for CIE 171:2006 test case 5.2 (see README.md). Standard library only."""
import json, math, pathlib

I0, h = 1000.0, 3.0       # I(gamma) = I0 cos(gamma) cd; source 3 m above the floor centre
centre = (2.0, 2.0)
# Ten points over one quadrant of the 4 x 4 m floor (x, y >= centre), from the nadir to the corner.
quadrant = [(0.0, 0.0), (0.5, 0.0), (1.0, 0.0), (1.5, 0.0), (2.0, 0.0),
            (0.5, 0.5), (1.0, 1.0), (1.5, 1.5), (2.0, 2.0), (1.0, 2.0)]
points, cases = [], []
for k, (dx, dy) in enumerate(quadrant):
    d2 = h * h + dx * dx + dy * dy
    E = I0 * h * h / d2**2      # I0 (h/d) (h/d) / d^2 = I0 h^2 / d^4
    points.append({"at": [centre[0] + dx, centre[1] + dy, 0.0], "normal": [0, 0, 1]})
    cases.append({"surface": "floor quadrant", "point": k, "quantity": "E", "expected": E,
                  "rel_tol": 1e-6,
                  "source": f"CIE 171:2006 5.2: E = I0 h^2 / d^4 at offset ({dx}, {dy}) m"})
here = pathlib.Path(__file__).parent
project = {
    "format": "luxgrid-project/1", "name": "CIE 171:2006 case 5.2: directional point source",
    "settings": {"quality": "standard", "indirect": "off"},
    "photometry": {"cos1000": {"builtin": "lambertian", "intensity_cd": I0}},
    "rooms": [{"name": "black room", "outline": [[0, 0], [4, 0], [4, 4], [0, 4]], "height": 3.0,
               "reflectance": {"floor": 0, "walls": 0, "ceiling": 0}}],
    "luminaires": [{"photometry": "cos1000", "position": [centre[0], centre[1], h]}],
    "surfaces": [{"name": "floor quadrant", "points": points}],
}
(here / "project.json").write_text(json.dumps(project, indent=1) + "\n")
(here / "expected.json").write_text(json.dumps({"cases": cases}, indent=1) + "\n")
