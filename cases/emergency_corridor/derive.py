#!/usr/bin/env python3
"""Expected values for emergency_corridor (see README.md). Standard library only."""
import json, math, pathlib

h = 2.5                                  # m, the luminaires above the floor
I_iso = 500.0 * 0.1                      # cd: isotropic 500 cd at its emergency fraction 0.1
I0_lam = 40.0                            # cd: the Lambertian emergency module, straight down
iso_at, lam_at = (2.0, 1.0), (8.0, 1.0)  # plan positions of the two emergency luminaires


def E(x, y):
    """Horizontal illuminance on the floor at (x, y): both emergency luminaires, direct only."""
    r2 = (x - iso_at[0]) ** 2 + (y - iso_at[1]) ** 2
    e_iso = I_iso * h / (h * h + r2) ** 1.5          # I cos^3(theta) / h^2 = I h / d^3
    r2 = (x - lam_at[0]) ** 2 + (y - lam_at[1]) ** 2
    e_lam = I0_lam * h * h / (h * h + r2) ** 2       # I0 cos(theta) cos(theta) / d^2 = I0 h^2 / d^4
    return e_iso + e_lam


centre = [(float(x), 1.0) for x in range(11)]        # stations every 1 m, ends included
band = [(x, y) for (x, _) in centre for y in (0.5, 1.0, 1.5)]  # central band: half of 2 m
core = [(float(x), 1.0) for x in range(1, 10)]       # open area: cell centres of the 9 m x 1 m core
cases = []
for k, (x, y) in enumerate(centre):
    cases.append({"surface": "exit centre line", "point": k, "quantity": "E", "expected": E(x, y),
                  "rel_tol": 1e-9, "source": f"README: E at x = {x:g} m on the centre line"})
for surface, pts in (("exit centre line", centre), ("exit band", band), ("hall", core)):
    values = [E(x, y) for (x, y) in pts]
    for stat, v in (("Emin", min(values)), ("Emax", max(values))):
        cases.append({"surface": surface, "stat": stat, "quantity": "E", "expected": v, "rel_tol": 1e-9,
                      "source": f"README: {stat} over the {len(pts)} points of {surface}"})
here = pathlib.Path(__file__).parent
project = {
    "format": "luxgrid-project/1", "name": "emergency lighting of a corridor (EN 1838)",
    "settings": {"quality": "draft", "near_field": "never", "scene": "emergency"},
    "photometry": {"iso": {"builtin": "isotropic", "intensity_cd": 500.0},
                   "panel": {"builtin": "lambertian", "intensity_cd": 1000.0},
                   "module": {"builtin": "lambertian", "intensity_cd": I0_lam}},
    "rooms": [{"name": "corridor", "outline": [[0, 0], [10, 0], [10, 2], [0, 2]], "height": 3.0,
               "reflectance": {"floor": 0.3, "walls": 0.7, "ceiling": 0.8}}],
    "luminaires": [
        {"name": "exit light", "photometry": "iso", "position": [iso_at[0], iso_at[1], h],
         "emergency": {"fraction": 0.1}},
        {"name": "general", "photometry": "iso", "position": [5.0, 1.0, h]},
        {"name": "panel", "photometry": "panel", "position": [lam_at[0], lam_at[1], h],
         "emergency": {"photometry": "module"}},
    ],
    "surfaces": [
        {"name": "exit", "escape_route": {"path": [[0, 1], [10, 1]], "width": 2.0}, "spacing": 1.0},
        {"name": "hall", "open_area": {"room": "corridor"}, "spacing": 1.0},
    ],
}
(here / "project.json").write_text(json.dumps(project, indent=1) + "\n")
(here / "expected.json").write_text(json.dumps({"cases": cases}, indent=1) + "\n")
for name, pts in (("centre line", centre), ("band", band), ("open area", core)):
    values = [E(x, y) for (x, y) in pts]
    print(f"{name}: Emin {min(values):.4f} lx, Emax {max(values):.4f} lx, Emax/Emin {max(values) / min(values):.3f}")
for (x, y) in centre:
    print(f"x = {x:4.1f}  E = {E(x, y):.6f} lx")
