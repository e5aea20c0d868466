"""Active workplane points by the walls' distance rule (active_points.py), and
the case's own point."""
from active_points import check_active


def check(results, out_dir, case_dir):
    return check_active(
        results, case_dir, must_be_active=[
            (3.0, 2.0, "the point under the luminaire at (3, 2), 1 m from the spike's tip")])
