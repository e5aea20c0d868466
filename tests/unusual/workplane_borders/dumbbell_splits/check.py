"""Active workplane points by the walls' distance rule (active_points.py), and
no point in the passage."""
from active_points import check_active


def check(results, out_dir, case_dir):
    failures = check_active(results, case_dir)
    got = next(g for g in results["surfaces"] if g["name"] == "workplane")
    if any(a and 3.3 < p[0] < 3.7 for p, a in zip(got["points"], got["active"])):
        failures.append("a point of the passage is active")
    return failures
