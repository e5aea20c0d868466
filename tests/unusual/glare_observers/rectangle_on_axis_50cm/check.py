"""The solid angle of each luminaire's term against a closed form (solid_angles.py)."""
from solid_angles import check_solid_angles, rectangle_on_axis


def check(results, out_dir, case_dir):
    return check_solid_angles(results, {
        # rectangle on its axis
        "panel": (rectangle_on_axis(0.3, 0.15, 0.5), 1e-09),
    })
