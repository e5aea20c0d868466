"""The solid angle of each luminaire's term against a closed form (solid_angles.py)."""
from solid_angles import check_solid_angles


def check(results, out_dir, case_dir):
    return check_solid_angles(results, {
        # A / d^2 on the axis
        "panel": (0.18 / 2.0**2, 1e-12),
    })
