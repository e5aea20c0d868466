"""Shared by the workplane_borders cases' check.py (run_corpus.py puts this class folder on the
module path). Which workplane points are active, worked out here from their distance to the
room's walls: a point counts when it lies inside the outline, at least the border (less 1e-9 m)
from every wall, and not strictly inside the footprint of an obstacle spanning the workplane's
height."""

import json
import math
import os


def seg_dist(p, a, b):
    ab = (b[0] - a[0], b[1] - a[1])
    l2 = ab[0] ** 2 + ab[1] ** 2
    t = 0.0 if l2 == 0 else max(0.0, min(1.0, ((p[0] - a[0]) * ab[0] + (p[1] - a[1]) * ab[1]) / l2))
    return math.hypot(p[0] - a[0] - t * ab[0], p[1] - a[1] - t * ab[1])


def inside(p, poly):  # even-odd ray casting; boundary points are never grid points here
    c = False
    for i in range(len(poly)):
        a, b = poly[i], poly[(i + 1) % len(poly)]
        if (a[1] > p[1]) != (b[1] > p[1]):
            x = a[0] + (p[1] - a[1]) * (b[0] - a[0]) / (b[1] - a[1])
            if p[0] < x:
                c = not c
    return c


def check_active(results, case_dir, must_be_active=()):
    """Failures where a workplane point's active flag differs from the walls' distance rule, plus
    each (x, y, why) of `must_be_active` whose nearest point is not active."""
    with open(os.path.join(case_dir, "project.json")) as f:
        project = json.load(f)
    failures = []
    for s in project["surfaces"]:
        if "workplane" not in s:
            continue
        wp = s["workplane"]
        room = next(r for r in project["rooms"] if r["name"] == wp["room"])
        outline, border = room["outline"], wp.get("border", 0.0)
        z = room.get("floor_z", 0.0) + wp["height"]
        cut = [o for o in room.get("obstacles", [])
               if o["box"]["min"][2] <= z <= o["box"]["max"][2]]
        got = next(g for g in results["surfaces"] if g["name"] == s["name"])
        wrong = []
        for i, (p, active) in enumerate(zip(got["points"], got["active"])):
            d = min(seg_dist(p, outline[k], outline[(k + 1) % len(outline)])
                    for k in range(len(outline)))
            expected = inside(p, outline) and d >= border - 1e-9
            for o in cut:
                lo, hi = o["box"]["min"], o["box"]["max"]
                if lo[0] < p[0] < hi[0] and lo[1] < p[1] < hi[1]:
                    expected = False
            if expected != active:
                wrong.append(f"point {i} {p[:2]}: active {active}, distance to the walls {d:.6f}")
        if wrong:
            failures.append(f"{s['name']}: {len(wrong)} points wrong: " + "; ".join(wrong[:5]))
        if not any(got["active"]):
            failures.append(f"{s['name']}: no point active")
        for x, y, why in must_be_active:
            near = min(range(len(got["points"])),
                       key=lambda i: math.hypot(got["points"][i][0] - x, got["points"][i][1] - y))
            if not got["active"][near]:
                failures.append(f"the point nearest ({x}, {y}), {why}, is not active: "
                                + str(got["points"][near]))
    return failures
