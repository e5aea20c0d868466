#!/usr/bin/env python3
"""Expected values of the UGR case (README.md): CIE 117's formula by hand for two Lambertian
panels, and the background luminance from a three-surface flux transfer (CIE 190's model) seen
from the eye through exact point-to-rectangle form factors. Python standard library only; writes
project.json and expected.json."""
import json, math

# --- the scene ---------------------------------------------------------------------------------
X, Y, HR = 6.0, 4.0, 2.8                      # room, m
RHO = {"floor": 0.2, "walls": 0.5, "ceiling": 0.7}
I0 = 2000.0                                   # cd, Lambertian: I = I0 cos(gamma)
A_SIDE = 0.6                                  # m, square opening
PANELS = [(3.0, 2.0, 2.8), (4.5, 3.0, 2.8)]
EYE = (1.0, 2.0, 1.2)
VIEW = (1.0, 0.0, 0.0)

def sub(a, b): return tuple(x - y for x, y in zip(a, b))
def dot(a, b): return sum(x * y for x, y in zip(a, b))
def cross(a, b): return (a[1]*b[2]-a[2]*b[1], a[2]*b[0]-a[0]*b[2], a[0]*b[1]-a[1]*b[0])
def norm(a): return math.sqrt(dot(a, a))

# --- CIE 117 terms --------------------------------------------------------------------------------
def levin_p(h, t):
    """Guth position index, Levin's (1975) closed form; h = H/R, t = T/R."""
    sigma = math.degrees(math.atan(math.hypot(h, t)))
    tau = 0.0 if h == 0 and t == 0 else math.degrees(math.atan2(t, h))
    a = (35.2 - 0.31889 * tau - 1.22 * math.exp(-2 * tau / 9)) * 1e-3
    b = (21 + 0.26667 * tau - 0.002963 * tau * tau) * 1e-5
    return math.exp(sigma * (a + b * sigma))

up = (0.0, 0.0, 1.0)
right = cross(VIEW, up)
area = A_SIDE * A_SIDE
terms = []
for c in PANELS:
    d = sub(c, EYE)
    R, H, T = dot(d, VIEW), dot(d, up), dot(d, right)
    dist = norm(d)
    cos_g = H / dist                       # the panel faces down: cos(gamma) = H / d
    L = I0 * cos_g / (area * cos_g)        # = I0 / A
    omega = area * cos_g / dist**2
    p = levin_p(H / R, abs(T) / R)
    terms.append(dict(R=R, T=T, H=H, d=dist, L=L, omega=omega, p=p, value=L * L * omega / p**2))
S = sum(t["value"] for t in terms)

# --- background luminance ---------------------------------------------------------------------------
def ff_parallel(a, b, c):
    x, y = a / c, b / c
    x1, y1 = math.sqrt(1 + x*x), math.sqrt(1 + y*y)
    s = (0.5 * math.log((1 + x*x) * (1 + y*y) / (1 + x*x + y*y)) + x * y1 * math.atan(x / y1)
         + y * x1 * math.atan(y / x1) - x * math.atan(x) - y * math.atan(y))
    return 2 * s / (math.pi * x * y)

def point_rect_down(px, py, h):
    """Fraction of a downward Lambertian point source's flux landing on the floor rectangle
    [0, X] x [0, Y] a height h below it: sum of corner-rectangle form factors (Howell B-3)."""
    def corner(a, b):  # rectangle a x b with a corner below the source
        a, b = a / h, b / h
        return (a / math.sqrt(1 + a*a) * math.atan(b / math.sqrt(1 + a*a))
                + b / math.sqrt(1 + b*b) * math.atan(a / math.sqrt(1 + b*b))) / (2 * math.pi)
    return sum(corner(ax, by) for ax in (px, X - px) for by in (py, Y - py))

flux_down = math.pi * I0                  # a Lambertian emitter's whole flux
direct = {"floor": 0.0, "walls": 0.0, "ceiling": 0.0}
for (px, py, pz) in PANELS:
    f = point_rect_down(px, py, pz)
    direct["floor"] += f * flux_down
    direct["walls"] += (1 - f) * flux_down
A = {"floor": X * Y, "ceiling": X * Y, "walls": 2 * HR * (X + Y)}
F_fc = ff_parallel(X, Y, HR)
F = {("floor", "ceiling"): F_fc, ("ceiling", "floor"): F_fc, ("floor", "walls"): 1 - F_fc,
     ("ceiling", "walls"): 1 - F_fc, ("floor", "floor"): 0.0, ("ceiling", "ceiling"): 0.0}
F[("walls", "floor")] = A["floor"] * F[("floor", "walls")] / A["walls"]
F[("walls", "ceiling")] = F[("walls", "floor")]
F[("walls", "walls")] = 1 - 2 * F[("walls", "floor")]
names = ["floor", "walls", "ceiling"]
# exitant flux Phi_i = rho_i (D_i + sum_j Phi_j F_ji), by Gauss-Seidel to convergence
phi = {n: 0.0 for n in names}
for _ in range(2000):
    for n in names:
        phi[n] = RHO[n] * (direct[n] + sum(phi[m] * F[(m, n)] for m in names))
M = {n: phi[n] / A[n] for n in names}     # uniform exitances, lm/m2

def lambert_ff(x, n, poly):
    """Differential-area-to-polygon form factor (Lambert's contour integral), the polygon
    clipped to the receiver's hemisphere (Sutherland-Hodgman against the plane n.(y-x) = 0)."""
    clipped = []
    for i in range(len(poly)):
        a, b = poly[i], poly[(i + 1) % len(poly)]
        da, db = dot(n, sub(a, x)), dot(n, sub(b, x))
        if da >= 0: clipped.append(a)
        if (da >= 0) != (db >= 0):
            t = da / (da - db)
            clipped.append(tuple(a[k] + t * (b[k] - a[k]) for k in range(3)))
    if len(clipped) < 3: return 0.0
    s = 0.0
    for i in range(len(clipped)):
        r1, r2 = sub(clipped[i], x), sub(clipped[(i + 1) % len(clipped)], x)
        c = cross(r1, r2)
        cn = norm(c)
        if cn == 0: continue
        th = math.atan2(cn, dot(r1, r2))
        s += th * dot(n, c) / cn
    return abs(s) / (2 * math.pi)

surfaces = {
    "floor": [[(0, 0, 0), (X, 0, 0), (X, Y, 0), (0, Y, 0)]],
    "ceiling": [[(0, 0, HR), (X, 0, HR), (X, Y, HR), (0, Y, HR)]],
    "walls": [[(0, 0, 0), (X, 0, 0), (X, 0, HR), (0, 0, HR)], [(X, 0, 0), (X, Y, 0), (X, Y, HR), (X, 0, HR)],
              [(X, Y, 0), (0, Y, 0), (0, Y, HR), (X, Y, HR)], [(0, Y, 0), (0, 0, 0), (0, 0, HR), (0, Y, HR)]],
}
# The panels' own openings are part of the ceiling plane but emit, not reflect: leave them out of
# the ceiling's reflected exitance (they are 0.72 m2 of 24 m2; the eye sees them at 0.6 % of its
# hemisphere's projected solid angle, so the hand value ignores that).
# First reflection exactly: each surface cut into cells, the cell's direct illuminance from the
# panels (as Lambertian points, I0 cos(gamma) cos(theta) / d^2), its exitance rho E, and the eye
# gathering M cos(theta_eye) cos(theta_cell) dA / (pi d^2). Later reflections from the uniform
# model: its exitances minus its own (uniform) first reflection rho D / A.
def cells(poly, n):
    o, a, b = poly[0], sub(poly[1], poly[0]), sub(poly[3], poly[0])
    nrm = cross(a, b); nrm = tuple(c / norm(nrm) for c in nrm)
    dA = norm(cross(a, b)) / (n * n)
    for i in range(n):
        for j in range(n):
            yield tuple(o[k] + (i + 0.5) / n * a[k] + (j + 0.5) / n * b[k] for k in range(3)), nrm, dA

INWARD = {"floor": 1, "ceiling": -1}
NCELL = 120
E_first = 0.0
for n_, polys in surfaces.items():
    for poly in polys:
        for c, nrm, dA in cells(poly, NCELL):
            # the room's faces' normals point into the room
            if n_ == "floor": nrm = (0.0, 0.0, 1.0)
            elif n_ == "ceiling": nrm = (0.0, 0.0, -1.0)
            else:
                centre = (X / 2, Y / 2, c[2])
                if dot(nrm, sub(centre, c)) < 0: nrm = tuple(-x for x in nrm)
            E = 0.0
            for pc in PANELS:
                d = sub(c, pc)
                r = norm(d)
                cos_g = -d[2] / r                  # from the panel's downward axis
                cos_t = -dot(nrm, d) / r           # at the cell
                if cos_g > 0 and cos_t > 0: E += I0 * cos_g * cos_t / r**2
            M1 = RHO[n_] * E
            d = sub(c, EYE)
            r = norm(d)
            ce, cc = dot(VIEW, d) / r, -dot(nrm, d) / r
            if ce > 0 and cc > 0: E_first += M1 * ce * cc * dA / (math.pi * r * r)
M_tail = {n: M[n] - RHO[n] * direct[n] / A[n] for n in names}
E_tail = sum(M_tail[n] * sum(lambert_ff(EYE, VIEW, poly) for poly in surfaces[n]) for n in names)
E_ind = E_first + E_tail
E_uniform = sum(M[n] * sum(lambert_ff(EYE, VIEW, poly) for poly in surfaces[n]) for n in names)
Lb = E_ind / math.pi
UGR = 8 * math.log10(0.25 * S / Lb)

# --- files --------------------------------------------------------------------------------------------
project = {
    "format": "luxgrid-project/1",
    "name": "UGR: two Lambertian panels, one observer",
    "settings": {"quality": "high", "indirect": "on"},
    "photometry": {"panel": {"builtin": "lambertian", "intensity_cd": I0}},
    "rooms": [{"name": "room", "outline": [[0, 0], [X, 0], [X, Y], [0, Y]], "height": HR,
               "reflectance": RHO}],
    "luminaires": [{"name": "panel %d" % (k + 1), "photometry": "panel", "position": list(c),
                    "emitter": {"shape": "rectangle", "size": [A_SIDE, A_SIDE]}} for k, c in enumerate(PANELS)],
    "surfaces": [{"name": "eyes", "observers": [{"at": list(EYE), "directions": [list(VIEW)]}]}],
}
cases = []
for k, t in enumerate(terms):
    for q in ("L", "omega", "p"):
        cases.append({"surface": "eyes", "point": 0, "quantity": q, "term": k, "expected": t[q], "rel_tol": 1e-9,
                      "source": "CIE 117 by hand (README): panel %d, R %.3f T %.3f H %.3f m" % (k + 1, t["R"], t["T"], t["H"])})
cases.append({"surface": "eyes", "point": 0, "quantity": "Lb", "expected": Lb, "rel_tol": 0.05,
              "source": "first reflection integrated over 120 x 120 cells per face, later ones by the three-surface flux transfer (README)"})
cases.append({"surface": "eyes", "point": 0, "quantity": "UGR", "expected": UGR, "abs_tol": 0.2,
              "source": "UGR = 8 log10(0.25 / Lb sum L^2 omega / p^2), sum by hand, Lb as above (README)"})
cases.append({"surface": "eyes", "stat": "UGR_max", "expected": UGR, "abs_tol": 0.2,
              "source": "one view: UGR_max = UGR (README)"})
with open("project.json", "w") as f: json.dump(project, f, indent=1); f.write("\n")
with open("expected.json", "w") as f: json.dump({"cases": cases}, f, indent=1); f.write("\n")
for k, t in enumerate(terms):
    print("panel %d: R %.4f T %.4f H %.4f d %.4f  L %.2f omega %.6f p %.4f  L2w/p2 %.1f" % (
        k + 1, t["R"], t["T"], t["H"], t["d"], t["L"], t["omega"], t["p"], t["value"]))
print("sum %.1f" % S)
print("direct lm", {k: round(v, 1) for k, v in direct.items()}, "M", {k: round(v, 2) for k, v in M.items()})
print("E_ind %.3f lx (first reflection %.3f, later %.3f; all-uniform model %.3f)  Lb %.3f cd/m2  UGR %.3f" % (
    E_ind, E_first, E_tail, E_uniform, Lb, UGR))
