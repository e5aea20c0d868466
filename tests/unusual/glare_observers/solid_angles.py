"""Shared by the glare_observers cases' check.py (run_corpus.py puts this class folder on the
module path): each luminaire's term in the eyes' views has the solid angle a closed form worked
out in the case gives; every solid angle is at most 2 pi sr and every UGR finite."""
import math


def rectangle_from_corner(a, b, d):
    """Solid angle (sr) of an a x b rectangle seen from distance d above one corner."""
    return math.asin(a * b / math.sqrt((a**2 + d**2) * (b**2 + d**2)))


def rectangle_on_axis(half_a, half_b, d):
    """Solid angle (sr) of a 2 half_a x 2 half_b rectangle seen from distance d on its axis: four
    rectangles seen from their corner."""
    return 4 * rectangle_from_corner(half_a, half_b, d)


def check_solid_angles(results, expected):
    """Failures of the surface "eyes" against `expected`: {luminaire: (omega_sr, tol_rel)}."""
    failures = []
    eyes = next(s for s in results["surfaces"] if s["name"] == "eyes")
    terms = {}
    for o in eyes["observers"]:
        for v in o["views"]:
            if v.get("UGR") is not None and not math.isfinite(v["UGR"]):
                failures.append(f"UGR {v['UGR']}")
            for t in v["terms"]:
                terms[t["luminaire"]] = t["omega"]
                if not t["omega"] <= 2 * math.pi:
                    failures.append(f"{t['luminaire']}: omega {t['omega']} sr > 2 pi")
    for name, (omega, tol_rel) in expected.items():
        got = terms.get(name)
        if got is None:
            failures.append(f"no term for {name}")
        elif abs(got - omega) > tol_rel * omega:
            failures.append(f"{name}: omega {got} sr, expected {omega} sr (tol rel {tol_rel})")
    return failures
