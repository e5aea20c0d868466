"""The solid angle of each luminaire's term against a closed form (solid_angles.py)."""
from solid_angles import check_solid_angles, rectangle_from_corner


def check(results, out_dir, case_dir):
    return check_solid_angles(results, {
        # rectangle from above a corner
        "panel": (rectangle_from_corner(0.6, 0.3, 0.05), 1e-09),
    })
