"""Direct light at chosen points of a luxgrid run by brute force, run by hand, not in CI: the
yardstick for points in a penumbra, where two programs' quadratures of a partly hidden opening
disagree (docs/indirect.md, "Checked against Radiance").

Each luminaire's opening (a rectangle, length along its frame's x, width along y; or a disk, the
cells of its square whose centres lie in it) is cut into N x N equal cells, each emitting I(w) /
(the cells' count) from its centre [Luksch2020, Eq. 1: the opening as
uniform emitters], I the file's table as luxgrid reads it (`luxgrid info FILE --json --at C,gamma`
at the file's own angles, bilinear between them, as bench/radiance_rooms.py writes it for
Radiance); each cell is seen or hidden by an exact test of the segment from the point to its
centre against every face of the scene (the rooms' floor, ceiling and walls, every obstacle's
faces) from the run's `report_input`. So only the quadrature of the opening is approximate, and
it converges as N grows (a shadow edge across the opening is placed to within 1 / N of it): the
script prints the value at each N asked.

  python3 bench/brute_force_direct.py PROJECT RUN --at SURFACE:INDEX [--at ...]
      [--nodes 128,256,512]

RUN: a luxgrid output folder of PROJECT (its results.json); LUXGRID (default build/luxgrid) reads
the photometric files (EULUMDAT). numpy is needed. Prints per point its position, luxgrid's
E_direct (lx, initial), the brute-force value at each N and luxgrid's difference to the finest."""
import argparse
import json
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from radiance_rooms import ccw, luxgrid_table  # noqa: E402

EPS_T = 1e-9  # a segment's ends (on the opening's and the point's own face) are not crossings


def table_of(path):
    """(C angles with 360, gamma angles, cd[C][gamma]) of a EULUMDAT file as luxgrid reads it."""
    cs, g_list, cd = luxgrid_table(path)
    return np.array(cs), np.array(g_list, float), np.array(cd, float).reshape(len(cs), len(g_list))


def intensity(table, c_deg, g_deg):
    """Bilinear in the table's (C, gamma) cells."""
    cs, gs, cd = table
    c = np.mod(c_deg, 360.0)
    i = np.clip(np.searchsorted(cs, c, side="right") - 1, 0, len(cs) - 2)
    j = np.clip(np.searchsorted(gs, g_deg, side="right") - 1, 0, len(gs) - 2)
    fc = (c - cs[i]) / (cs[i + 1] - cs[i])
    fg = (g_deg - gs[j]) / (gs[j + 1] - gs[j])
    a = cd[i, j] * (1 - fg) + cd[i, j + 1] * fg
    b = cd[i + 1, j] * (1 - fg) + cd[i + 1, j + 1] * fg
    return a * (1 - fc) + b * fc


def faces_of(report_input):
    """Every face of the scene as (origin, u, v, normal, outline in (u, v)): planar polygons."""
    faces = []

    def add(corners):
        p = [np.array(c, float) for c in corners]
        n = np.cross(p[1] - p[0], p[2] - p[0])
        n /= np.linalg.norm(n)
        u = (p[1] - p[0]) / np.linalg.norm(p[1] - p[0])
        v = np.cross(n, u)
        faces.append((p[0], u, v, n, np.array([[(q - p[0]) @ u, (q - p[0]) @ v] for q in p])))

    for room in report_input["rooms"]:
        z0, z1 = room["floor_z"], room["floor_z"] + room["height"]
        o = ccw(room["outline"])
        add([(x, y, z0) for x, y in o])
        add([(x, y, z1) for x, y in o])
        for i in range(len(o)):
            (xa, ya), (xb, yb) = o[i], o[(i + 1) % len(o)]
            add([(xa, ya, z0), (xb, yb, z0), (xb, yb, z1), (xa, ya, z1)])
        for ob in room.get("obstacles", []):
            f = ccw(ob["footprint"])
            add([(x, y, ob["z0"]) for x, y in f])
            add([(x, y, ob["z1"]) for x, y in f])
            for i in range(len(f)):
                (xa, ya), (xb, yb) = f[i], f[(i + 1) % len(f)]
                add([(xa, ya, ob["z0"]), (xb, yb, ob["z0"]), (xb, yb, ob["z1"]),
                     (xa, ya, ob["z1"])])
    return faces


def in_polygon(q, poly):
    """Even-odd test of the (M, 2) points q against the polygon's (K, 2) outline."""
    inside = np.zeros(len(q), bool)
    for k in range(len(poly)):
        a, b = poly[k], poly[(k + 1) % len(poly)]
        crosses = (a[1] > q[:, 1]) != (b[1] > q[:, 1])
        with np.errstate(divide="ignore", invalid="ignore"):
            x = a[0] + (q[:, 1] - a[1]) * (b[0] - a[0]) / (b[1] - a[1])
        inside ^= crosses & (q[:, 0] < x)
    return inside


def hidden(p, ends, faces):
    """True where the segment from p to each of `ends` (M, 3) crosses some face strictly inside."""
    d = ends - p[None, :]
    out = np.zeros(len(ends), bool)
    for o, u, v, n, outline in faces:
        hp = (p - o) @ n
        he = (ends - o) @ n
        with np.errstate(divide="ignore", invalid="ignore"):
            t = hp / (hp - he)
        cand = ((hp > 0) != (he > 0)) & (hp != 0) & (he != 0) & (t > EPS_T) & (t < 1 - EPS_T)
        if not cand.any():
            continue
        x = p[None, :] + t[cand, None] * d[cand]
        q = np.stack([(x - o) @ u, (x - o) @ v], 1)
        hit = np.zeros(len(ends), bool)
        hit[np.nonzero(cand)[0]] = in_polygon(q, outline)
        out |= hit
    return out


def direct_lx(p, n, luminaires, tables, faces, nodes):
    total = 0.0
    cells = (np.arange(nodes) + 0.5) / nodes - 0.5
    a, b = np.meshgrid(cells, cells)
    a, b = a.ravel(), b.ravel()
    for lum in luminaires:
        o = lum["opening"]
        shape = o.get("shape")
        if shape not in ("rectangle", "disk") or o.get("height", 0.0) > 0.0:
            raise SystemExit(f"{lum['label']}: only flat rectangles and disks are integrated here")
        frame = np.array(lum["rotation"], float)  # rows: the frame's x, y, z axes in the world
        ax, ay, az = frame[0], frame[1], frame[2]
        length = o["width"] if shape == "disk" else o["length"]  # a disk's width is its diameter
        keep = (a * a + b * b <= 0.25) if shape == "disk" else np.ones(len(a), bool)
        centres = (np.array(lum["position"], float)[None, :] +
                   (a[keep] * length)[:, None] * ax + (b[keep] * o["width"])[:, None] * ay)
        d = p[None, :] - centres  # from the cell to the point
        r = np.linalg.norm(d, axis=1)
        w = d / r[:, None]
        local = np.stack([w @ ax, w @ ay, w @ az], 1)
        gamma = np.degrees(np.arccos(np.clip(-local[:, 2], -1.0, 1.0)))
        c = np.degrees(np.arctan2(local[:, 1], local[:, 0]))
        cos_r = np.maximum(-(w @ n), 0.0)
        seen = ~hidden(p, centres, faces)
        total += float(np.sum(intensity(tables[lum["photometry"]], c, gamma) * cos_r / r**2 *
                              seen)) / len(centres)
    return total


def run_parser(doc):
    """The command line both brute-force scripts start from: PROJECT and RUN, `doc` as help."""
    ap = argparse.ArgumentParser(description=doc,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("project", help="the project file RUN was made from")
    ap.add_argument("run", help="a luxgrid output folder of PROJECT (its results.json)")
    return ap


def main():
    ap = run_parser(__doc__)
    ap.add_argument("--at", action="append", required=True,
                    help="SURFACE:INDEX, a point of RUN's surface (repeat for more)")
    ap.add_argument("--nodes", default="128,256,512",
                    help="cells per side of each opening, one run each (default 128,256,512)")
    args = ap.parse_args()
    results = json.load(open(os.path.join(args.run, "results.json")))
    ri = results["report_input"]
    project = json.load(open(args.project))
    base = os.path.dirname(os.path.abspath(args.project))
    tables = {t["key"]: table_of(os.path.join(base, project["photometry"][t["key"]]))
              for t in ri["luminaire_types"]}
    faces = faces_of(ri)
    mf = results.get("maintenance_factor", 1.0)
    surfaces = {s["name"]: s for s in results["surfaces"]}
    nodes = [int(x) for x in args.nodes.split(",")]
    for spec in args.at:
        name, index = spec.rsplit(":", 1)
        s = surfaces[name]
        i = int(index)
        p = np.array(s["points"][i], float)
        n = np.array(s["normals"][i], float)
        lux = s["E_direct"][i] / mf
        values = [direct_lx(p, n, ri["luminaires"], tables, faces, k) for k in nodes]
        cols = "  ".join(f"N={k}: {v:.4f}" for k, v in zip(nodes, values))
        print(f"{name} {i} ({p[0]:.4g}, {p[1]:.4g}, {p[2]:.4g}): luxgrid {lux:.4f} lx  {cols}  "
              f"luxgrid - finest: {100.0 * (lux - values[-1]) / values[-1]:+.3f} %")


if __name__ == "__main__":
    main()
