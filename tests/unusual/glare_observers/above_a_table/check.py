"""The solid angle of each luminaire's term against a closed form (solid_angles.py)."""
import math

from solid_angles import check_solid_angles


def check(results, out_dir, case_dir):
    return check_solid_angles(results, {
        # A_p / d^2
        "panel": (0.18 * (1.7 / math.sqrt(5.39)) / 5.39, 1e-12),
    })
