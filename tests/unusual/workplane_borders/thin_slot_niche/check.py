"""Active workplane points by the walls' distance rule (active_points.py), and
the case's own point."""
from active_points import check_active


def check(results, out_dir, case_dir):
    return check_active(
        results, case_dir, must_be_active=[(3.0, 3.75, "0.25 m from the niche's mouth")])
