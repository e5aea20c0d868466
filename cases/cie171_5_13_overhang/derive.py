"""Writes CIE 171:2006 case 5.13 (project.json, expected.json): the 2 x 1 m facade opening of case
5.11 under a horizontal overhang at the ceiling's height (z = 3), projecting 0.5, 1 or 2 m and
continuous along the facade, with reference values derived from geometry, independent of
luxgrid's code. Run: python3 cases/cie171_5_13_overhang/derive.py (about a minute of CPU).

Why the references reduce to the unobstructed case. A floor point P = (2, y0, 0) sees the
opening (y = 0, x in [1, 3], z in [1, 2]) upwards only; the ray from P through the opening's
point (x, 0, z) rises and moves south, and reaches the overhang's underside plane z = 3 at
y = y0 (1 - 3 / z). It meets the underside (y in [-d, 0]) exactly when y0 (3 / z - 1) <= d, that
is z >= z_c = 3 y0 / (y0 + d): the overhang hides the band z in [z_c, 2] of the opening, whatever
x (the boundary is the image of the overhang's front edge, a horizontal line), and the ray
reaches no other face of it first (the front face faces away from P, the ends lie beyond the
view). So, with the band clipped to the opening:
  SC  = the sky component of the rectangle x in [1, 3], z in [1, min(2, z_c)], unobstructed;
  ERC = 100 L_u / E_h x the projected solid angle of x in [1, 3], z in [max(1, z_c), 2],
where L_u is the underside's luminance. The underside faces down and sees the ground's whole
hemisphere (luxgrid's model, docs/daylight.md): E_u = rho_g E_h, L_u = rho_u rho_g E_h / pi. The
first integral is cases/_derive/daylight.py's cubature to 1e-7 (its closed form for the uniform
sky), the second Lambert's contour integral (cases/_derive/lambert.py), exact."""
import json
import math
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.path.dirname(HERE), "_derive"))
import daylight as dl  # noqa: E402
import lambert  # noqa: E402

RHO_G = 0.3
# The underside's reflectance: its luminance rho_u rho_g E_h / pi is then 0.050 E_h / pi, the
# value CIE's tables were fitted with.
RHO_U = 1.0 / 6.0
DEPTHS = [0.5, 1.0, 2.0]
FLOOR = {"A": 3.75, "B": 3.25, "C": 2.75, "D": 2.25, "E": 1.75, "F": 1.25, "G": 0.75, "H": 0.25}
SPACING = 20.0  # rooms this far apart in x: no view of one reaches another's overhang
THICKNESS = 0.2


def references(sky, integral, y0, depth):
    p, n = (2.0, y0, 0.0), (0.0, 0.0, 1.0)
    z_c = 3.0 * y0 / (y0 + depth)
    top = min(2.0, z_c)
    sc = 0.0
    if top > 1.0:
        op = ((1.0, 0.0, 1.0), (1, 0, 0), (0, 0, 1), 2.0, top - 1.0)
        if sky == "uniform":
            sc = 100.0 * lambert.lambert_E(
                [(1.0, 0.0, 1.0), (3.0, 0.0, 1.0), (3.0, 0.0, top), (1.0, 0.0, top)], 1.0, p,
                n) / math.pi
        else:
            sc, erc = dl.components(op, p, n, sky, integral, RHO_G)
            assert erc == 0.0
    bottom = max(1.0, z_c)
    erc = 0.0
    if bottom < 2.0:
        band = [(1.0, 0.0, bottom), (3.0, 0.0, bottom), (3.0, 0.0, 2.0), (1.0, 0.0, 2.0)]
        luminance_per_eh = RHO_U * RHO_G / math.pi
        erc = 100.0 * lambert.lambert_E(band, luminance_per_eh, p, n)
    return sc, erc, z_c


def main():
    integrals = {sky: dl.sky_integral(sky, 1e-8) for sky in dl.SKIES}
    rooms, openings, obstructions, surfaces, cases = [], [], [], [], []
    for r, depth in enumerate(DEPTHS):
        dx = SPACING * r
        name = "overhang %g m" % depth
        rooms.append({"name": name, "outline": [[dx, 0], [dx + 4, 0], [dx + 4, 4], [dx, 4]],
                      "height": 3, "reflectance": {"floor": 0, "walls": 0, "ceiling": 0}})
        openings.append({"name": name + " opening", "room": name,
                         "polygon": [[dx + 1, 0, 1], [dx + 3, 0, 1], [dx + 3, 0, 2],
                                     [dx + 1, 0, 2]]})
        # Continuous along the facade: every view from the points that reaches z = 3 + 0.2 does
        # so within 3.2 m of x = 2, so 8 m either side is as long as infinite.
        obstructions.append({"name": name, "box": {"min": [dx - 6, -depth, 3],
                                                   "max": [dx + 10, 0, 3 + THICKNESS]},
                             "reflectance": RHO_U})
        surfaces.append({"name": name, "points": [
            {"at": [dx + 2.0, y, 0.0], "normal": [0, 0, 1]} for y in FLOOR.values()]})
        for i, (label, y0) in enumerate(FLOOR.items()):
            for sky in dl.SKIES:
                sc, erc, z_c = references(sky, integrals[sky], y0, depth)
                how = ("closed form (Lambert)" if sky == "uniform"
                       else "SC by quadrature to 1e-7, ERC closed form (Lambert)")
                cases.append({"surface": name, "point": i, "quantity": "DF",
                              "sky": int(sky) if sky.isdigit() else sky, "expected": sc + erc,
                              "rel_tol": 0.01, "abs_tol": 1e-3,
                              "source": "CIE 171:2006 case 5.13 %s point %s: SC %.6g + ERC %.6g "
                                        "(the overhang hides z >= %.6g), %s" % (
                                            name, label, sc, erc, z_c, how)})
    project = {"format": "luxgrid-project/1", "name": "CIE 171:2006 case 5.13: overhangs",
               "settings": {"quality": "standard", "scene": "daylight"},
               "rooms": rooms, "openings": openings,
               "daylight": {"sky": {"type": "cie-overcast"},
                            "sun": {"altitude_deg": 60, "azimuth_deg": 180},
                            "diffuse_horizontal_lx": 10000, "ground": {"reflectance": RHO_G},
                            "obstructions": obstructions},
               "surfaces": surfaces}
    with open(os.path.join(HERE, "project.json"), "w") as f:
        json.dump(project, f, indent=1)
        f.write("\n")
    with open(os.path.join(HERE, "expected.json"), "w") as f:
        json.dump({"notes": "written by cases/cie171_5_13_overhang/derive.py", "cases": cases},
                  f, indent=1)
        f.write("\n")
    for c in cases:
        if c["sky"] in (16, "cie-overcast", "uniform", 1, 12):
            print(c["sky"], c["source"], "DF %.6g" % c["expected"])


if __name__ == "__main__":
    main()
