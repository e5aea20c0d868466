"""The solid angle of each luminaire's term against a closed form (solid_angles.py)."""
import math

from solid_angles import check_solid_angles, rectangle_on_axis


def check(results, out_dir, case_dir):
    return check_solid_angles(results, {
        # near: on its axis
        "near": (rectangle_on_axis(0.3, 0.15, 0.1), 1e-09),
        # far: CIE 117's A_p / d^2
        "far": (0.18 * (0.1 / math.sqrt(2.26)) / 2.26, 1e-12),
    })
