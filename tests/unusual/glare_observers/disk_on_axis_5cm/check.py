"""The solid angle of each luminaire's term against a closed form (solid_angles.py)."""
import math

from solid_angles import check_solid_angles


def check(results, out_dir, case_dir):
    return check_solid_angles(results, {
        # disk on its axis
        "downlight": (2 * math.pi * (1 - 0.05 / math.sqrt(0.05**2 + 0.1**2)), 0.0002),
    })
