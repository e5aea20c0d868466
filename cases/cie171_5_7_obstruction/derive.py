#!/usr/bin/env python3
"""Exact reference values for cie171_5_7_obstruction (derivation in README.md). Stdlib only.

A uniformly bright (Lambertian) wall S2, 4 m wide x 3 m high, luminance L = 1000/pi cd/m^2
(exitance M = pi L = 1000 lm/m^2), lights the black floor and the black opposite wall S1 of a
4 x 4 x 3 m room over a black full-width obstruction 1 m high and 0.2 m deep in the middle.
E at a receiver point P = M * F(P -> visible part of S2), F the differential-area-to-polygon
configuration factor. Because the obstruction spans the full width of the room (and of S2), the
part of S2 that P sees is the rectangle 0 <= x <= 4, z_min(P) <= z <= 3 (see README), so F is
Lambert's exact contour formula for a rectangle. A second, independent estimator (Gauss-Legendre
quadrature of cos cos' / (pi r^2) over the same rectangle) must agree to 1e-9.
"""
import json, math, pathlib
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent.parent / "_derive"))
from gauss import gauss_legendre  # noqa: E402  (shared with the other brute-force cases)

W, D, H = 4.0, 4.0, 3.0          # room: x in [0, W], y in [0, D], z in [0, H]; S2 is the wall y = D
OB_Y0, OB_Y1, OB_H = 1.9, 2.1, 1.0  # obstruction: full width, y in [1.9, 2.1], z in [0, 1]
L = 1000.0 / math.pi              # cd/m^2, so M = pi L = 1000 lm/m^2 and E = 1000 F
M = math.pi * L
I0 = L * W * H                    # lambertian intensity of the 4 x 3 m emitter, cd (I0 = L A)


def sub(a, b): return [a[i] - b[i] for i in range(3)]
def dot(a, b): return sum(a[i] * b[i] for i in range(3))
def cross(a, b): return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
def norm(a): return math.sqrt(dot(a, a))


def z_min(p):
    """Lowest visible height on S2 from p = (x, y, z). In the (y, z) plane the obstruction is the
    rectangle [OB_Y0, OB_Y1] x [0, OB_H] standing on the floor; a ray from p (y_p < OB_Y0) to
    (D, z_e) clears it iff it is at or above OB_H at both top edges, i.e.
    z_e >= z_p + (OB_H - z_p) (D - y_p) / (y_e - y_p) for y_e in {OB_Y0, OB_Y1}."""
    _, yp, zp = p
    if yp >= OB_Y1:
        return 0.0  # in front of the obstruction: all of S2 is in view
    zm = max(zp + (OB_H - zp) * (D - yp) / (ye - yp) for ye in (OB_Y0, OB_Y1))
    return min(max(zm, 0.0), H)


def lambert_polygon(p, n, poly):
    """Configuration factor from a differential area at p with unit normal n to a polygon, all of
    it in front of p: F = 1/(2 pi) sum_i theta_i n . (R_i x R_i+1)/|R_i x R_i+1| (Lambert 1760;
    e.g. Ashdown, 'Near-field photometry', or Siegel & Howell). theta_i by atan2 (robust)."""
    total = 0.0
    for i in range(len(poly)):
        a, b = sub(poly[i], p), sub(poly[(i + 1) % len(poly)], p)
        c = cross(a, b)
        cn = norm(c)
        if cn == 0.0:
            continue
        theta = math.atan2(cn, dot(a, b))
        total += theta * dot(n, c) / cn
    return abs(total) / (2.0 * math.pi)


GL_X, GL_W = gauss_legendre(24)


def quadrature(p, n, z0, panels=16):
    """Second estimator: F = integral over x in [0, W], z in [z0, H] of cos_r cos_e / (pi r^2),
    composite 24-point Gauss-Legendre with `panels` panels per side."""
    if z0 >= H:
        return 0.0
    total = 0.0
    ne = [0.0, -1.0, 0.0]  # S2 faces -y, into the room
    for i in range(panels):
        xa, xb = W * i / panels, W * (i + 1) / panels
        for j in range(panels):
            za, zb = z0 + (H - z0) * j / panels, z0 + (H - z0) * (j + 1) / panels
            for gx, wx in zip(GL_X, GL_W):
                x = 0.5 * (xa + xb) + 0.5 * (xb - xa) * gx
                for gz, wz in zip(GL_X, GL_W):
                    z = 0.5 * (za + zb) + 0.5 * (zb - za) * gz
                    r = sub([x, D, z], p)
                    r2 = dot(r, r)
                    cr = dot(n, r) / math.sqrt(r2)
                    ce = -dot(ne, r) / math.sqrt(r2)
                    if cr > 0 and ce > 0:
                        total += wx * wz * 0.25 * (xb - xa) * (zb - za) * cr * ce / (math.pi * r2)
    return total


# Receiver points. Floor (normal +z) along the centre line x = 2 and one off it; opposite wall
# y = 0 (normal +y) along x = 2. Boundaries: the floor umbra starts where the ray over the
# obstruction's back top edge just reaches the top of S2: OB_H (D - y)/(OB_Y0 - y) = H ->
# y = (H OB_Y0 - OB_H D)/(H - OB_H) = 0.85 m. On the opposite wall all of S2 is in view from the
# height where the ray over the front top edge meets S2's bottom edge:
# z_p + (OB_H - z_p) D / OB_Y1 = 0 -> z_p = OB_H D / (D - OB_Y1) = 2.105263 m.
Y_UMBRA = (H * OB_Y0 - OB_H * D) / (H - OB_H)
Z_FULL_VIEW = OB_H * D / (D - OB_Y1)
FLOOR = [(2.0, 0.25), (2.0, 0.5), (2.0, Y_UMBRA), (2.0, 1.5), (2.0, 3.0), (1.0, 0.5), (0.5, 0.25)]
WALL = [(2.0, 0.5), (2.0, 1.0), (2.0, 1.5), (2.0, 2.0), (2.0, Z_FULL_VIEW), (2.0, 2.5), (0.5, 1.5)]

# Tolerances. Interior points: 1 % (the `standard` quality's near-field target) or 0.5 lx. Points
# on a shadow boundary: the value there is 0 (umbra edge) or the derivative jumps (full-view
# edge), so a method that samples visibility can land on either side: absolute 2 lx, which is
# what a 1 mm shift of the point changes at the umbra edge times ~10 (see README).
REL, ABS, ABS_BOUNDARY = 0.01, 0.5, 2.0

cases, floor_points, wall_points, table = [], [], [], []
for k, (x, y) in enumerate(FLOOR):
    p, n = [x, y, 0.0], [0.0, 0.0, 1.0]
    z0 = z_min(p)
    rect = [[0.0, D, z0], [W, D, z0], [W, D, H], [0.0, D, H]]
    F = lambert_polygon(p, n, rect) if z0 < H else 0.0
    Fq = quadrature(p, n, z0)
    assert abs(F - Fq) < 1e-9, (p, F, Fq)
    boundary = abs(y - Y_UMBRA) < 1e-12
    floor_points.append({"at": p, "normal": n})
    c = {"surface": "floor", "point": k, "quantity": "E", "expected": M * F,
         "rel_tol": REL, "abs_tol": ABS_BOUNDARY if boundary else ABS,
         "source": f"E = M F, F = Lambert contour integral over S2 above z = {z0:.6f} m "
                   f"(quadrature agrees to {abs(F - Fq):.1e}); floor ({x}, {y:.6g})"
                   + (" on the umbra boundary" if boundary else "")}
    cases.append(c)
    table.append(("floor", x, y, z0, F, M * F))
for k, (x, z) in enumerate(WALL):
    p, n = [x, 0.0, z], [0.0, 1.0, 0.0]
    z0 = z_min(p)
    rect = [[0.0, D, z0], [W, D, z0], [W, D, H], [0.0, D, H]]
    F = lambert_polygon(p, n, rect) if z0 < H else 0.0
    Fq = quadrature(p, n, z0)
    assert abs(F - Fq) < 1e-9, (p, F, Fq)
    boundary = abs(z - Z_FULL_VIEW) < 1e-12
    wall_points.append({"at": p, "normal": n})
    cases.append({"surface": "opposite wall", "point": k, "quantity": "E", "expected": M * F,
                  "rel_tol": REL, "abs_tol": ABS_BOUNDARY if boundary else ABS,
                  "source": f"E = M F, F = Lambert contour integral over S2 above z = {z0:.6f} m "
                            f"(quadrature agrees to {abs(F - Fq):.1e}); wall ({x}, {z:.6g})"
                            + (" on the full-view boundary" if boundary else "")})
    table.append(("wall", x, z, z0, F, M * F))

here = pathlib.Path(__file__).parent
project = {
    "format": "luxgrid-project/1",
    "name": "CIE 171:2006 case 5.7: diffuse emitter wall over an internal obstruction",
    "settings": {"quality": "reference", "indirect": "off", "near_field": "always"},
    "photometry": {"bright wall": {"builtin": "lambertian", "intensity_cd": I0}},
    "rooms": [{"name": "black room", "outline": [[0, 0], [W, 0], [W, D], [0, D]], "height": H,
               "reflectance": {"floor": 0, "walls": 0, "ceiling": 0},
               "obstacles": [{"name": "obstruction", "box": {"min": [0, OB_Y0, 0], "max": [W, OB_Y1, OB_H]},
                              "reflectance": 0}]}],
    # The emitter is S2 itself: a 4 x 3 m lambertian rectangle centred on the wall y = D, turned
    # by rx = -90 degrees so that its nadir (local -z) points along -y into the room; its local x
    # (4 m) stays along world x and its local y (3 m) becomes world -z.
    "luminaires": [{"name": "S2", "photometry": "bright wall", "position": [W / 2, D, H / 2],
                    "rotation": [-90, 0, 0], "emitter": {"shape": "rectangle", "size": [W, H]}}],
    "surfaces": [{"name": "floor", "points": floor_points},
                 {"name": "opposite wall", "points": wall_points}],
}
(here / "project.json").write_text(json.dumps(project, indent=1) + "\n")
(here / "expected.json").write_text(json.dumps({"cases": cases}, indent=1) + "\n")
if __name__ == "__main__":
    print(f"{'surface':8} {'x':>5} {'y|z':>9} {'z_min':>9} {'F':>12} {'E (lx)':>10}")
    for s, x, c, z0, F, E in table:
        print(f"{s:8} {x:5.2f} {c:9.6f} {z0:9.6f} {F:12.9f} {E:10.4f}")
