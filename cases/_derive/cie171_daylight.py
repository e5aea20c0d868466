"""Writes the CIE 171:2006 daylight cases 5.9-5.12 (project.json and expected.json of each
folder) with reference values derived from geometry by daylight.py, independent of luxgrid's
code. Run: python3 cases/_derive/cie171_daylight.py (about two minutes).

Each case's project holds the case's two rooms side by side (10 m apart in x; nothing outside
the rooms is modelled, so they do not see each other), black inside, ground reflectance 0.3,
the sun 60 degrees up due south; expected.json checks the daylight factor DF at a few of CIE
171's points under all 15 CIE general skies, the traditional overcast sky and the uniform sky
(the validation runner runs the project once per sky: expected.json's "sky")."""
import json
import math
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import daylight as dl  # noqa: E402
import lambert  # noqa: E402

CASES = os.path.dirname(HERE)
RHO_G = 0.3
T_N = 0.88
WALL = {"A": 2.75, "C": 1.75, "F": 0.25}           # (2, 4, z), normal -y
FLOOR = {"G": 3.75, "I": 2.75, "K": 1.75, "N": 0.25}  # (2, y, 0), normal +z
CEILING = {"G'": 3.75, "K'": 1.75, "N'": 0.25}     # (2, y, 3), normal -z


def rect_opening(kind, size):
    """(origin, U, V, su, sv) of the opening in a room at the origin."""
    if kind == "roof":
        a, b = size
        return ((2 - a / 2, 2 - b / 2, 3.0), (1, 0, 0), (0, 1, 0), a, b)
    a, b = size  # facade in the south wall y = 0: 2 x 1 at x 1..3, z 1..2, or 4 x 3
    return ((2 - a / 2, 0.0, 1.0 if a == 2 else 0.0), (1, 0, 0), (0, 0, 1), a, b)


def polygon(op, dx):
    o, U, V, su, sv = op
    pts = [(0, 0), (su, 0), (su, sv), (0, sv)]
    return [[o[0] + s * U[0] + t * V[0] + dx, o[1] + s * U[1] + t * V[1],
             o[2] + s * U[2] + t * V[2]] for s, t in pts]


def points(kind):
    out = [("wall", k, (2.0, 4.0, z), (0.0, -1.0, 0.0)) for k, z in WALL.items()]
    out += [("floor", k, (2.0, y, 0.0), (0.0, 0.0, 1.0)) for k, y in FLOOR.items()]
    if kind == "facade":
        out += [("ceiling", k, (2.0, y, 3.0), (0.0, 0.0, -1.0)) for k, y in CEILING.items()]
    return out


def closed_form(op, p, n):
    """The unglazed uniform sky's SC and the unglazed ERC by Lambert's contour integral
    (cases/_derive/lambert.py): the opening clipped at the point's horizontal plane."""
    poly = [tuple(c) for c in polygon(op, 0.0)]
    above = lambert.clip_by_horizon(poly, p, (0, 0, 1))
    below = lambert.clip_by_horizon(poly, p, (0, 0, -1))
    sc = 100.0 * lambert.lambert_E(above, 1.0, p, n) / math.pi if len(above) >= 3 else 0.0
    erc = 100.0 * RHO_G * lambert.lambert_E(below, 1.0, p, n) / math.pi if len(below) >= 3 else 0.0
    return sc, erc


def write_case(folder, title, kind, sizes, glazed, integrals):
    rooms, openings, surfaces, cases = [], [], [], []
    for r, size in enumerate(sizes):
        dx = 10.0 * r
        name = "%gx%g" % size
        rooms.append({"name": name, "outline": [[dx, 0], [dx + 4, 0], [dx + 4, 4], [dx, 4]],
                      "height": 3, "reflectance": {"floor": 0, "walls": 0, "ceiling": 0}})
        op = rect_opening(kind, size)
        opening = {"name": name + " opening", "room": name, "polygon": polygon(op, dx)}
        if glazed:
            opening["glazing"] = {"transmittance": T_N}
        openings.append(opening)
        pts = points(kind)
        surfaces.append({"name": name, "points": [
            {"at": [p[0] + dx, p[1], p[2]], "normal": list(n)} for _, _, p, n in pts]})
        for i, (face, label, p, n) in enumerate(pts):
            closed = closed_form(op, p, n)
            for sky in dl.SKIES:
                sc, erc = dl.components(op, p, n, sky, integrals[sky], RHO_G,
                                        T_N if glazed else None)
                if not glazed:
                    # The quadrature meets the closed forms (a check of daylight.py itself).
                    assert abs(erc - closed[1]) <= 1e-6 * max(1.0, closed[1]), (erc, closed)
                    if sky == "uniform":
                        assert abs(sc - closed[0]) <= 1e-6 * max(1.0, closed[0]), (sc, closed)
                        sc, erc = closed
                df = sc + erc
                how = ("closed form (Lambert)" if sky == "uniform" and not glazed
                       else "quadrature to 1e-7")
                cases.append({"surface": name, "point": i, "quantity": "DF",
                              "sky": int(sky) if sky.isdigit() else sky, "expected": df,
                              "rel_tol": 0.01, "abs_tol": 1e-3,
                              "source": "%s %s point %s (%s): SC %.6g + ERC %.6g, %s" % (
                                  title, name, label, face, sc, erc, how)})
    project = {"format": "luxgrid-project/1", "name": title,
               "settings": {"quality": "standard", "scene": "daylight"},
               "rooms": rooms, "openings": openings,
               "daylight": {"sky": {"type": "cie-overcast"},
                            "sun": {"altitude_deg": 60, "azimuth_deg": 180},
                            "diffuse_horizontal_lx": 10000, "ground": {"reflectance": RHO_G}},
               "surfaces": surfaces}
    os.makedirs(os.path.join(CASES, folder), exist_ok=True)
    with open(os.path.join(CASES, folder, "project.json"), "w") as f:
        json.dump(project, f, indent=1)
        f.write("\n")
    with open(os.path.join(CASES, folder, "expected.json"), "w") as f:
        json.dump({"notes": "written by cases/_derive/cie171_daylight.py", "cases": cases}, f,
                  indent=1)
        f.write("\n")


def main():
    integrals = {sky: dl.sky_integral(sky, 1e-8) for sky in dl.SKIES}
    for sky in dl.SKIES:
        print("E_h / L_z for sky %s: %.10f" % (sky, integrals[sky]))
    write_case("cie171_5_9_roof_opening", "CIE 171:2006 case 5.9: roof opening", "roof",
               [(1.0, 1.0), (4.0, 4.0)], False, integrals)
    write_case("cie171_5_10_glazed_roof_opening", "CIE 171:2006 case 5.10: glazed roof opening",
               "roof", [(1.0, 1.0), (4.0, 4.0)], True, integrals)
    write_case("cie171_5_11_facade_opening", "CIE 171:2006 case 5.11: facade opening", "facade",
               [(2.0, 1.0), (4.0, 3.0)], False, integrals)
    write_case("cie171_5_12_glazed_facade_opening",
               "CIE 171:2006 case 5.12: glazed facade opening", "facade", [(2.0, 1.0), (4.0, 3.0)],
               True, integrals)


if __name__ == "__main__":
    main()
