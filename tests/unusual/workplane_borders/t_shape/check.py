"""Active workplane points by the walls' distance rule (active_points.py)."""
from active_points import check_active


def check(results, out_dir, case_dir):
    return check_active(results, case_dir)
