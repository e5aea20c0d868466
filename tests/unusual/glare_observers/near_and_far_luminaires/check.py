"""The solid angle of each luminaire's term, against a closed form worked out here; every solid
angle at most 2 pi sr and every UGR finite."""
import math


def check(results, out_dir, case_dir):
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
    # near: on its axis
    expected = 4 * math.asin(0.3 * 0.15 / math.sqrt((0.3**2 + 0.1**2) * (0.15**2 + 0.1**2)))
    got = terms.get("near")
    if got is None:
        failures.append("no term for near")
    elif abs(got - expected) > 1e-09 * expected:
        failures.append(f"near: omega {got} sr, expected {expected} sr (tol rel 1e-09)")
    # far: CIE 117's A_p / d^2
    expected = 0.18 * (0.1 / math.sqrt(2.26)) / 2.26
    got = terms.get("far")
    if got is None:
        failures.append("no term for far")
    elif abs(got - expected) > 1e-12 * expected:
        failures.append(f"far: omega {got} sr, expected {expected} sr (tol rel 1e-12)")
    return failures
