"""Shared by the derive.py scripts of the near-field cases: the exact illuminance of a uniform
(Lambertian) convex polygon and independent cross-checks. Standard library only."""
import math

# --- exact illuminance from a uniform (Lambertian) convex polygon: Lambert's contour integral ---
# E = L/2 * sum over edges of theta_i (n . g_i), with r_i = v_i - p, theta_i the angle between
# r_i and r_{i+1}, g_i the unit normal of the plane through p, v_i, v_{i+1}. The polygon is first
# clipped by the receiver's horizon (n . (v - p) >= 0): light from below the horizon never arrives.
def _sub(a, b): return (a[0] - b[0], a[1] - b[1], a[2] - b[2])
def _dot(a, b): return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
def _cross(a, b): return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])
def _norm(a): return math.sqrt(_dot(a, a))

def clip_by_horizon(poly, p, n):
    out = []
    for i, a in enumerate(poly):
        b = poly[(i + 1) % len(poly)]
        da, db = _dot(n, _sub(a, p)), _dot(n, _sub(b, p))
        if da >= 0: out.append(a)
        if (da >= 0) != (db >= 0):
            t = da / (da - db)
            out.append(tuple(a[k] + t * (b[k] - a[k]) for k in range(3)))
    return out

def lambert_E(poly, L, p, n):
    """Exact E (lx) at p (unit normal n) from the polygon `poly` of uniform luminance L (cd/m^2)."""
    poly = clip_by_horizon(poly, p, n)
    if len(poly) < 3: return 0.0
    s = 0.0
    for i, a in enumerate(poly):
        ra, rb = _sub(a, p), _sub(poly[(i + 1) % len(poly)], p)
        c = _cross(ra, rb)
        cn = _norm(c)
        if cn == 0.0: continue
        theta = math.atan2(cn, _dot(ra, rb))   # robust for all angles (never acos of a dot)
        s += theta * _dot(n, c) / cn
    return 0.5 * L * abs(s)

def rectangle(cx, cy, cz, a, b):
    """Corners of an a x b horizontal rectangle centred at (cx, cy, cz)."""
    return [(cx - a / 2, cy - b / 2, cz), (cx + a / 2, cy - b / 2, cz),
            (cx + a / 2, cy + b / 2, cz), (cx - a / 2, cy + b / 2, cz)]
# -------------------------------------------------------------------------------------------------
# --- independent cross-checks, so the contour integral above is compared with something else ---
def corner_factor(a, b, c):
    """Configuration factor from a differential element to a parallel a x b rectangle at distance c,
    the element facing it opposite one corner (Howell's catalogue, case B-3)."""
    X, Y = a / c, b / c
    return (X / math.sqrt(1 + X * X) * math.atan(Y / math.sqrt(1 + X * X)) +
            Y / math.sqrt(1 + Y * Y) * math.atan(X / math.sqrt(1 + Y * Y))) / (2 * math.pi)

def parallel_factor(x0, x1, y0, y1, c):
    """Element at the origin facing a parallel rectangle [x0,x1] x [y0,y1] at distance c, by
    superposition of corner rectangles (signed)."""
    def f(x, y):
        return math.copysign(1, x) * math.copysign(1, y) * corner_factor(abs(x), abs(y), c) if x and y else 0.0
    return f(x1, y1) - f(x0, y1) - f(x1, y0) + f(x0, y0)

def midpoint_E(poly_rect, L, p, n, m=400):
    """Brute-force area integral of L cos_e cos_r / d^2 over a horizontal rectangle emitting
    downward (normal -z) or upward (+z): (x0, x1, y0, y1, z, sz) with sz the emitting normal's z."""
    x0, x1, y0, y1, z, sz = poly_rect
    hx, hy, s = (x1 - x0) / m, (y1 - y0) / m, 0.0
    for i in range(m):
        for j in range(m):
            q = (x0 + (i + 0.5) * hx, y0 + (j + 0.5) * hy, z)
            d = _sub(p, q)
            d2 = _dot(d, d)
            ce, cr = sz * d[2] / math.sqrt(d2), -_dot(d, n) / math.sqrt(d2)
            if ce > 0 and cr > 0: s += ce * cr / d2
    return L * s * hx * hy
# -------------------------------------------------------------------------------------------------

# --- the case files shared by the Lambertian-rectangle cases ---
def black_hall_panel_project(name, I0, centre, a, b, points):
    """A 20 x 20 x 3 m black hall (no reflected light) with one downward Lambertian a x b panel
    of intensity I0 centred at `centre`, and the probe points as the one surface "probes"."""
    return {
        "format": "luxgrid-project/1", "name": name,
        "settings": {"quality": "standard", "indirect": "off"},
        "photometry": {"panel": {"builtin": "lambertian", "intensity_cd": I0}},
        "rooms": [{"name": "black hall", "outline": [[0, 0], [20, 0], [20, 20], [0, 20]], "height": 3.0,
                   "reflectance": {"floor": 0, "walls": 0, "ceiling": 0}}],
        "luminaires": [{"photometry": "panel", "position": list(centre),
                        "emitter": {"shape": "rectangle", "size": [a, b]}}],
        "surfaces": [{"name": "probes", "points": points}],
    }

def write_case(here, project, cases):
    """Writes project.json and expected.json of the case folder `here`."""
    import json
    (here / "project.json").write_text(json.dumps(project, indent=1) + "\n")
    (here / "expected.json").write_text(json.dumps({"cases": cases}, indent=1) + "\n")

# `from lambert import *` in the derive scripts also needs the small vector helpers.
__all__ = ["math", "_sub", "_dot", "_cross", "_norm", "clip_by_horizon", "lambert_E", "rectangle",
           "corner_factor", "parallel_factor", "midpoint_E", "black_hall_panel_project", "write_case"]
