"""Active workplane points by the walls' distance rule (active_points.py), and
the case's own point."""
from active_points import check_active


def check(results, out_dir, case_dir):
    return check_active(
        results, case_dir, must_be_active=[
            (3.6, 3.6, "0.566 m from the reflex corner (4, 4) and farther from every wall")])
