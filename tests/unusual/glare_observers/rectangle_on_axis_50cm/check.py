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
    # rectangle on its axis
    expected = 4 * math.asin(0.3 * 0.15 / math.sqrt((0.3**2 + 0.5**2) * (0.15**2 + 0.5**2)))
    got = terms.get("panel")
    if got is None:
        failures.append("no term for panel")
    elif abs(got - expected) > 1e-09 * expected:
        failures.append(f"panel: omega {got} sr, expected {expected} sr (tol rel 1e-09)")
    return failures
