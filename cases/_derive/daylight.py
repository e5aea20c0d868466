"""Reference values for the CIE 171 daylight cases (5.9-5.12), independent of luxgrid's code.
Standard library only.

The sky and externally reflected components at a point p (receiver normal n), in percent of the
unobstructed sky's horizontal illuminance E_h, through a rectangular opening:

  SC  = 100 / I * integral over the opening's part above p's horizontal plane of
        l(w) T(w) cos(theta_p) cos(theta_o) / r^2 dA
  ERC = 100 * rho_g / pi * the same over the part below, with l = 1,

where l = L / L_z is the sky's relative luminance, I = integral of l cos Z over the hemisphere
(E_h / L_z), T the glazing's transmittance (1 unglazed). The area integrals are taken by adaptive
product Gauss-Legendre cubature on the opening's rectangle (split at the point's horizon and at
the sun's ray, where the integrand has a kink), I by the same on (cos^2 Z, azimuth) split at the
sun. Tolerances: 1e-7 relative per integral, so the values are converged well beyond 1e-5
(derive.py checks this by halving the tolerance).

Sources: ISO 15469 / CIE S 011 (the general sky), Moon and Spencer (the traditional overcast
sky), Radiance's glass material (the glazing, refractive index 1.52), CIE 171:2006 (the ground:
a uniform plane of luminance rho_g E_h / pi below the horizon)."""
import heapq
import math

from gauss import gauss_legendre

# ISO 15469 Table 3: a, b, c, d, e of the 15 general skies.
CIE_SKIES = {
    1: (4.0, -0.70, 0, -1.0, 0.00), 2: (4.0, -0.70, 2, -1.5, 0.15),
    3: (1.1, -0.80, 0, -1.0, 0.00), 4: (1.1, -0.80, 2, -1.5, 0.15),
    5: (0.0, -1.00, 0, -1.0, 0.00), 6: (0.0, -1.00, 2, -1.5, 0.15),
    7: (0.0, -1.00, 5, -2.5, 0.30), 8: (0.0, -1.00, 10, -3.0, 0.45),
    9: (-1.0, -0.55, 2, -1.5, 0.15), 10: (-1.0, -0.55, 5, -2.5, 0.30),
    11: (-1.0, -0.55, 10, -3.0, 0.45), 12: (-1.0, -0.32, 10, -3.0, 0.45),
    13: (-1.0, -0.32, 16, -3.0, 0.30), 14: (-1.0, -0.15, 16, -3.0, 0.30),
    15: (-1.0, -0.15, 24, -2.8, 0.15),
}
SKIES = [str(k) for k in range(1, 16)] + ["cie-overcast", "uniform"]

# The sun of CIE 171's daylight cases: 60 degrees up, due south (+y north, z up).
SUN = (0.0, -math.cos(math.radians(60.0)), math.sin(math.radians(60.0)))


def relative_luminance(sky, w):
    """L / L_z for the unit direction w (z up); 0 below the horizon."""
    cz = w[2]
    if cz <= 0.0:
        return 0.0
    if sky == "uniform":
        return 1.0
    if sky == "cie-overcast":
        return (1.0 + 2.0 * cz) / 3.0
    a, b, c, d, e = CIE_SKIES[int(sky)]
    def phi(cos_z):
        return 1.0 + a * math.exp(b / cos_z) if cos_z > 0.0 else 1.0
    def f(chi):
        return 1.0 + c * (math.exp(d * chi) - math.exp(d * math.pi / 2)) + e * math.cos(chi) ** 2
    dot = max(-1.0, min(1.0, w[0] * SUN[0] + w[1] * SUN[1] + w[2] * SUN[2]))
    chi = math.acos(dot)
    zs = math.acos(SUN[2])
    return f(chi) * phi(cz) / (f(zs) * phi(1.0))


def glass_transmittance(tn, cos_i):
    """Radiance's clear glass (n = 1.52): Fresnel in sine/tangent form, the internal
    transmissivity solved from T_n by bisection, the pane's series in closed form."""
    n = 1.52
    cos_i = abs(cos_i)
    if cos_i <= 0.0:
        return 0.0
    def pane(ti, t_pass_normal):
        if ti == 0.0:
            r = ((n - 1) / (n + 1)) ** 2
            return (1 - r) ** 2 * t_pass_normal / (1 - r * r * t_pass_normal ** 2)
        tt = math.asin(math.sin(ti) / n)
        t = t_pass_normal ** (1.0 / math.cos(tt))
        total = 0.0
        for r in (math.sin(ti - tt) ** 2 / math.sin(ti + tt) ** 2,
                  math.tan(ti - tt) ** 2 / math.tan(ti + tt) ** 2):
            total += 0.5 * (1 - r) ** 2 * t / (1 - r * r * t * t)
        return total
    return pane(math.acos(min(1.0, cos_i)), _normal_transmissivity(tn, pane))


_TRANSMISSIVITY = {}


def _normal_transmissivity(tn, pane):
    """The one-pass transmissivity t_n with pane(0, t_n) = T_n, by bisection (once per T_n)."""
    if tn not in _TRANSMISSIVITY:
        lo, hi = 0.0, 1.0
        for _ in range(200):
            mid = 0.5 * (lo + hi)
            if pane(0.0, mid) < tn:
                lo = mid
            else:
                hi = mid
        _TRANSMISSIVITY[tn] = 0.5 * (lo + hi)
    return _TRANSMISSIVITY[tn]


_GL = gauss_legendre(5)


def _rule(f, x0, x1, y0, y1):
    hx, hy = 0.5 * (x1 - x0), 0.5 * (y1 - y0)
    cx, cy = 0.5 * (x0 + x1), 0.5 * (y0 + y1)
    s = 0.0
    for xi, wi in zip(*_GL):
        for yj, wj in zip(*_GL):
            s += wi * wj * f(cx + hx * xi, cy + hy * yj)
    return s * hx * hy


def adaptive_2d(f, x0, x1, y0, y1, rel_tol, xcuts=(), ycuts=(), max_cells=200000):
    """The integral of f over [x0, x1] x [y0, y1]: 5 x 5 Gauss-Legendre per cell, a cell's error
    the difference from its four children, the worst cell split until the errors add up to
    rel_tol times the value."""
    xs = sorted({x0, x1, *[x for x in xcuts if x0 < x < x1]})
    ys = sorted({y0, y1, *[y for y in ycuts if y0 < y < y1]})
    heap, total, error = [], 0.0, 0.0
    def cell(a, b, c, d, coarse):
        mx, my = 0.5 * (a + b), 0.5 * (c + d)
        kids = [(a, mx, c, my), (mx, b, c, my), (a, mx, my, d), (mx, b, my, d)]
        vals = [_rule(f, *k) for k in kids]
        fine = sum(vals)
        return (-abs(fine - coarse), fine, kids, vals)
    for i in range(len(xs) - 1):
        for j in range(len(ys) - 1):
            box = (xs[i], xs[i + 1], ys[j], ys[j + 1])
            item = cell(*box, _rule(f, *box))
            total += item[1]
            error += -item[0]
            heapq.heappush(heap, (item[0], len(heap) * 1e-300, item[1], item[2], item[3]))
    count = 0
    while heap and error > rel_tol * abs(total) and len(heap) < max_cells:
        neg_err, _, fine, kids, vals = heapq.heappop(heap)
        total -= fine
        error += neg_err
        for k, v in zip(kids, vals):
            item = cell(*k, v)
            total += item[1]
            error += -item[0]
            count += 1
            heapq.heappush(heap, (item[0], count, item[1], item[2], item[3]))
    return sum(h[2] for h in heap), error


def sky_integral(sky, rel_tol=1e-9):
    """I = E_h / L_z: over u = cos^2 Z in [0, 1] (cos Z sin Z dZ = du / 2) and azimuth."""
    if sky == "uniform":
        return math.pi
    if sky == "cie-overcast":
        return 7.0 * math.pi / 9.0
    def f(u, alpha):
        cz, sz = math.sqrt(u), math.sqrt(1.0 - u)
        return 0.5 * relative_luminance(sky, (sz * math.sin(alpha), sz * math.cos(alpha), cz))
    sun_alpha = math.atan2(SUN[0], SUN[1])
    value, _ = adaptive_2d(f, 0.0, 1.0, sun_alpha - math.pi, sun_alpha + math.pi, rel_tol,
                           xcuts=(SUN[2] ** 2,), ycuts=(sun_alpha,))
    return value


def components(opening, p, n, sky, sky_I, rho_g, tn=None, rel_tol=1e-7):
    """(SC, ERC) in percent at p (unit normal n) through the rectangle opening = (origin, U, V,
    su, sv): corners origin + s U + t V, s in [0, su], t in [0, sv], U and V orthonormal."""
    o, U, V, su, sv = opening
    N = (U[1] * V[2] - U[2] * V[1], U[2] * V[0] - U[0] * V[2], U[0] * V[1] - U[1] * V[0])
    def point(s, t):
        return tuple(o[k] + s * U[k] + t * V[k] for k in range(3))
    def integrand(s, t, ground):
        x = point(s, t)
        d = tuple(x[k] - p[k] for k in range(3))
        r2 = d[0] ** 2 + d[1] ** 2 + d[2] ** 2
        r = math.sqrt(r2)
        w = tuple(dk / r for dk in d)
        if (w[2] < 0.0) != ground or w[2] == 0.0:
            return 0.0
        cos_p = w[0] * n[0] + w[1] * n[1] + w[2] * n[2]
        if cos_p <= 0.0:
            return 0.0
        cos_o = abs(w[0] * N[0] + w[1] * N[1] + w[2] * N[2])
        t_glass = glass_transmittance(tn, cos_o) if tn is not None else 1.0
        lum = 1.0 if ground else relative_luminance(sky, w)
        return lum * t_glass * cos_p * cos_o / r2
    # Kinks: the point's horizon (the plane z = p.z) and the sun's ray, where they cross.
    scuts, tcuts = [], []
    if abs(V[2]) > 0 and U[2] == 0.0:
        tcuts.append((p[2] - o[2]) / V[2])
    denom = SUN[0] * N[0] + SUN[1] * N[1] + SUN[2] * N[2]
    if denom != 0.0:
        lam = ((o[0] - p[0]) * N[0] + (o[1] - p[1]) * N[1] + (o[2] - p[2]) * N[2]) / denom
        if lam > 0:
            hit = tuple(p[k] + lam * SUN[k] - o[k] for k in range(3))
            scuts.append(hit[0] * U[0] + hit[1] * U[1] + hit[2] * U[2])
            tcuts.append(hit[0] * V[0] + hit[1] * V[1] + hit[2] * V[2])
    # The point's foot on the opening's plane: the kernel peaks there.
    foot = tuple(p[k] - o[k] for k in range(3))
    scuts.append(foot[0] * U[0] + foot[1] * U[1] + foot[2] * U[2])
    tcuts.append(foot[0] * V[0] + foot[1] * V[1] + foot[2] * V[2])
    sky_part, _ = adaptive_2d(lambda s, t: integrand(s, t, False), 0, su, 0, sv, rel_tol,
                              scuts, tcuts)
    ground_part, _ = adaptive_2d(lambda s, t: integrand(s, t, True), 0, su, 0, sv, rel_tol,
                                 scuts, tcuts)
    return 100.0 * sky_part / sky_I, 100.0 * rho_g / math.pi * ground_part
