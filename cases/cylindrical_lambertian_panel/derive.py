#!/usr/bin/env python3
"""Expected values for cylindrical_lambertian_panel (see README.md). Standard library only.

A 1 x 0.5 m Lambertian panel (builtin lambertian, I0 = 1000 cd, so L = I0 / A = 2000 cd/m^2)
facing down at (2, 2, 3) in a black 20 x 20 x 3 m hall. Cylindrical and semi-cylindrical
illuminance by brute force: a composite Gauss-Legendre product rule over the opening of
  E = integral of L cos_e w / d^2 dA,
w = sin(eps) / pi (cylinder) or sin(eps) (1 + cos(alpha)) / pi (half cylinder facing f),
eps the angle of the element's direction from the vertical, alpha the angle between f and the
horizontal direction towards the element (EN 13201-2 / EN 12464-1 definitions)."""
import math, pathlib
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent.parent / "_derive"))
from gauss import gauss_legendre  # noqa: E402
from lambert import black_hall_panel_project, write_case  # noqa: E402

I0, A_X, A_Y, H = 1000.0, 1.0, 0.5, 3.0   # cd, panel sides (m), room height = panel height (m)
CX, CY = 2.0, 2.0
L = I0 / (A_X * A_Y)                      # cd/m^2: builtin lambertian I(gamma) = I0 cos(gamma)
# quality standard on an analytic profile: the area-form cubature at 3e-3 (docs/nearfield.md,
# "Cylindrical and semi-cylindrical illuminance"); measured errors are below 0.07 % (README).
REL_TOL = 3e-3


def weight(rx, ry, rz, facing):
    d = math.sqrt(rx * rx + ry * ry + rz * rz)
    sin_eps = math.hypot(rx, ry) / d
    w = sin_eps / math.pi
    if facing is not None:
        alpha = math.atan2(ry, rx) - math.atan2(facing[1], facing[0])
        w *= 1.0 + math.cos(alpha)
    return w


def brute_force(p, facing, cells, order=8):
    """Composite Gauss-Legendre: cells x cells squares (scaled to the panel), order^2 nodes each."""
    xs, ws = gauss_legendre(order)
    t, wt = [0.5 * (1 + x) for x in xs], [0.5 * w for w in ws]  # on [0, 1]
    hx, hy = A_X / cells, A_Y / cells
    total = 0.0
    for i in range(cells):
        for a, wa in zip(t, wt):
            x = CX - A_X / 2 + (i + a) * hx
            for j in range(cells):
                for b, wb in zip(t, wt):
                    y = CY - A_Y / 2 + (j + b) * hy
                    rx, ry, rz = x - p[0], y - p[1], H - p[2]
                    d2 = rx * rx + ry * ry + rz * rz
                    cos_e = rz / math.sqrt(d2)
                    total += wa * wb * hx * hy * L * cos_e * weight(rx, ry, rz, facing) / d2
    return total


def far_field(p, facing):
    rx, ry, rz = CX - p[0], CY - p[1], H - p[2]
    d2 = rx * rx + ry * ry + rz * rz
    return I0 * (rz / math.sqrt(d2)) * weight(rx, ry, rz, facing) / d2


points = [(2.0, 2.0, 2.5), (2.3, 2.1, 2.9), (2.8, 2.0, 2.95), (3.5, 3.5, 1.0), (2.0, 2.0, 0.0)]
surfaces_def = [("cylindrical probes", "cylindrical", None),
                ("semi-cylindrical facing -x", "semi-cylindrical", (-1.0, 0.0)),
                ("semi-cylindrical facing +x", "semi-cylindrical", (1.0, 0.0))]
surfaces, cases, table = [], [], []
for name, quantity, facing in surfaces_def:
    s = {"name": name, "points": [{"at": list(p), "normal": [0, 0, 1]} for p in points], "quantity": quantity}
    if facing:
        s["facing"] = list(facing)
    surfaces.append(s)
    for k, p in enumerate(points):
        fine, coarse = brute_force(p, facing, 48), brute_force(p, facing, 24)
        ff = far_field(p, facing)
        table.append((name, p, fine, coarse, ff))
        cases.append({"surface": name, "point": k, "quantity": "E", "expected": fine, "rel_tol": REL_TOL,
                      "source": f"brute force (README): Gauss-Legendre 48 x 48 cells x 8 x 8 nodes over the panel at "
                                f"{p}, {abs(fine - coarse) / fine:.1e} from 24 x 24; far-field point model {ff:.3f} lx"})
here = pathlib.Path(__file__).parent
project = black_hall_panel_project("cylindrical and semi-cylindrical illuminance near a Lambertian panel",
                                   I0, (CX, CY, H), A_X, A_Y, [])
project["surfaces"] = surfaces
write_case(here, project, cases)
for name, p, fine, coarse, ff in table:
    print(f"| {name} | ({p[0]:g}, {p[1]:g}, {p[2]:g}) | {fine:.4f} | {abs(fine - coarse) / fine:.1e} | {ff:.4f} | "
          f"{100 * (ff / fine - 1):+.1f} % |")
