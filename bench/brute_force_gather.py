"""The reflected light at a run's points gathered by brute force, run by hand, not in CI: a check of
luxgrid's final gather where obstacles hide part of what a point sees (docs/indirect.md,
"Checked against Radiance").

A point's reflected light is the light every surface it sees sends it: the sum over small
elements y of every reflecting face (rooms' floors, ceilings and walls, obstacles' faces) of
(rho / pi) E(y) cos_p cos_y / r^2 dA, seen or hidden by an exact test of the segment against every
face of the scene (bench/brute_force_direct.py). E(y), the illuminance on the faces, is luxgrid's
own: a run of the same project at the same quality with a grid of SPACING on every face (room
faces by `room_surfaces`, obstacle faces by `points` at the centres of SPACING cells), made here.
So what is checked is the gather (its patches, cells and visibility), not the surfaces' light.
Elements closer to the point than 0.3 m are cut into 16 x 16 parts (64 x 64 within 0.1 m, 256 x
256 within 0.03 m), E constant over each element; beyond, one sample each.

  python3 bench/brute_force_gather.py PROJECT RUN --surface NAME [--spacing 0.05] [--every K]
      [--fields FIELD_RUN] [--within X,Y,Z,R ...]

RUN: a luxgrid output folder of PROJECT (results.json). The points of surface NAME are gathered
(every K-th of those brighter than 1 % of its maximum, within one of the --within balls where
given), and their reflected light compared with RUN's E_indirect as the promise measures it
(|difference| / E). FIELD_RUN (default RUN/brute_force_fields): a folder for the field run's
project and its output (`run/`, reused when there); LUXGRID (default build/luxgrid) makes it.
numpy is needed."""
import json
import math
import os
import subprocess
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from brute_force_direct import faces_of, hidden, in_polygon, run_parser  # noqa: E402
from radiance_rooms import LUXGRID, ccw  # noqa: E402

NEAR = ((0.3, 16), (0.1, 64), (0.03, 256))  # (distance m, parts per side) of the near elements


def obstacle_cells(room, spacing):
    """(centre, normal, (side along u, side along v) of tangents(normal), reflectance) of SPACING
    cells on each obstacle face of `room`."""
    out = []
    for ob in room.get("obstacles", []):
        f = ccw(ob["footprint"])
        z0, z1 = ob["z0"], ob["z1"]
        nz = max(1, math.ceil((z1 - z0) / spacing - 1e-9))
        for i in range(len(f)):  # sides, normals outward (the footprint counter-clockwise)
            a, b = np.array(f[i], float), np.array(f[(i + 1) % len(f)], float)
            length = float(np.linalg.norm(b - a))
            nu = max(1, math.ceil(length / spacing - 1e-9))
            t = (b - a) / length
            n = [t[1], -t[0], 0.0]
            for iu in range(nu):
                for iz in range(nz):
                    p = a + t * length * (iu + 0.5) / nu
                    out.append(([p[0], p[1], z0 + (z1 - z0) * (iz + 0.5) / nz], n,
                                (length / nu, (z1 - z0) / nz), ob["reflectance"]))
        # top and bottom: the cells of a grid over the footprint's box whose centres lie in it (a
        # turned footprint's border cells counted whole or not at all)
        xs = [x for x, _ in f]
        ys = [y for _, y in f]
        nx = max(1, math.ceil((max(xs) - min(xs)) / spacing - 1e-9))
        ny = max(1, math.ceil((max(ys) - min(ys)) / spacing - 1e-9))
        dx, dy = (max(xs) - min(xs)) / nx, (max(ys) - min(ys)) / ny
        gx, gy = np.meshgrid(min(xs) + dx * (np.arange(nx) + 0.5),
                             min(ys) + dy * (np.arange(ny) + 0.5), indexing="ij")
        centres = np.stack([gx.ravel(), gy.ravel()], 1)
        centres = centres[in_polygon(centres, np.array(f, float))]
        for z, nzv in ((z1, 1.0), (z0, -1.0)):
            if room["floor_z"] + 1e-9 < z < room["floor_z"] + room["height"] - 1e-9:
                for c in centres:
                    out.append(([c[0], c[1], z], [0.0, 0.0, nzv], (dx, dy), ob["reflectance"]))
    return out


def field_run(project_file, results, spacing, out_dir):
    """Runs (once) PROJECT with a SPACING grid on every face; returns its results and the
    obstacle cells' areas and reflectances, in the order of its `obstacle faces` points."""
    ri = results["report_input"]
    cells = [c for room in ri["rooms"] for c in obstacle_cells(room, spacing)]
    project = json.load(open(project_file))
    base = os.path.dirname(os.path.abspath(project_file))
    project["photometry"] = {k: os.path.join(base, v) for k, v in project["photometry"].items()}
    project.setdefault("settings", {})["allow_files_outside_project"] = True
    project["settings"]["quality"] = results["quality"]
    project["surfaces"] = [{"name": f"faces {k}", "room_surfaces": {"room": room["name"]},
                            "spacing": spacing} for k, room in enumerate(ri["rooms"])]
    if cells:
        project["surfaces"].append({"name": "obstacle faces", "points": [
            {"at": c[0], "normal": c[1]} for c in cells]})
    done = os.path.join(out_dir, "run", "results.json")
    if not os.path.exists(done):
        os.makedirs(out_dir, exist_ok=True)
        path = os.path.join(out_dir, "fields.json")
        json.dump(project, open(path, "w"))
        subprocess.run([LUXGRID, "calc", path, "-o", os.path.join(out_dir, "run"),
                        "--no-report"], check=True, stdout=subprocess.DEVNULL)
    return json.load(open(done)), cells


def elements(fields, cells, ri):
    """(positions, normals, weights rho E dA / pi, sides along tangents()) of every element of
    every reflecting face."""
    rho_of = {}
    for k, room in enumerate(ri["rooms"]):
        for part in ("floor", "ceiling"):
            rho_of[f"faces {k} {part}"] = room["reflectance"][part]
        rho_of[f"faces {k} wall"] = room["reflectance"]["walls"]
    Y, N, W, sides = [], [], [], []
    for s in fields["surfaces"]:
        P = np.array(s["points"], float)
        E = np.array(s["E"], float) / fields.get("maintenance_factor", 1.0)
        nn = np.array(s["normals"], float)
        act = np.array(s.get("active") or [True] * len(P), bool)
        if s["name"] == "obstacle faces":
            rho = np.array([c[3] for c in cells])
            side = np.array([c[2] for c in cells])
        else:
            key = s["name"] if not s["name"].split()[-2] == "wall" else " ".join(
                s["name"].split()[:-1])
            rho = np.full(len(P), rho_of[key])
            side = np.repeat(np.array([s["spacing"]], float), len(P), 0)
        Y.append(P[act])
        N.append(nn[act])
        W.append((rho * E * side[:, 0] * side[:, 1] / math.pi)[act])
        sides.append(side[act])
    return np.concatenate(Y), np.concatenate(N), np.concatenate(W), np.concatenate(sides)


def tangents(n):
    if abs(n[2]) > 0.9:
        return np.array([1.0, 0.0, 0.0]), np.array([0.0, 1.0, 0.0])
    u = np.array([-n[1], n[0], 0.0])
    u /= np.linalg.norm(u)
    return u, np.array([0.0, 0.0, 1.0])


def kernel_sum(p, n, Y, N, W, faces):
    d = Y - p[None, :]
    r2 = np.einsum("ij,ij->i", d, d)
    r = np.sqrt(r2)
    cp = (d @ n) / r
    cy = -np.einsum("ij,ij->i", d, N) / r
    ok = (cp > 0) & (cy > 0)
    idx = np.nonzero(ok)[0]
    seen = ~hidden(p, Y[idx], faces)
    return float(np.sum((W * cp * cy / r2)[idx][seen]))


def gather(p, n, Y, N, W, sizes, faces):
    r = np.linalg.norm(Y - p[None, :], axis=1)
    far = r >= NEAR[0][0]
    total = kernel_sum(p, n, Y[far], N[far], W[far], faces)
    for i in np.nonzero(~far)[0]:
        k = [parts for (dist, parts) in NEAR if r[i] < dist][-1]
        g = ((np.arange(k) + 0.5) / k - 0.5)
        gu, gv = np.meshgrid(g, g)
        u, v = tangents(N[i])
        P2 = (Y[i][None, :] + (gu.ravel() * sizes[i][0])[:, None] * u +
              (gv.ravel() * sizes[i][1])[:, None] * v)
        total += kernel_sum(p, n, P2, np.repeat(N[i][None, :], len(P2), 0),
                            np.full(len(P2), W[i] / len(P2)), faces)
    return total


def main():
    ap = run_parser(__doc__)
    ap.add_argument("--surface", required=True, help="the surface whose points are gathered")
    ap.add_argument("--spacing", type=float, default=0.05,
                    help="the field run's grid on every face, m (default 0.05)")
    ap.add_argument("--every", type=int, default=1,
                    help="gather every K-th bright point (default 1: all)")
    ap.add_argument("--fields", default=None,
                    help="the field run's folder (default RUN/brute_force_fields; reused when "
                         "there)")
    ap.add_argument("--within", action="append", default=[], metavar="X,Y,Z,R",
                    help="only the points within R m of (X, Y, Z) (repeat for more balls)")
    args = ap.parse_args()
    balls = [[float(v) for v in b.split(",")] for b in args.within]
    if any(len(b) != 4 for b in balls):
        sys.exit("--within takes X,Y,Z,R")
    results = json.load(open(os.path.join(args.run, "results.json")))
    ri = results["report_input"]
    fields, cells = field_run(args.project, results, args.spacing,
                              args.fields or os.path.join(args.run, "brute_force_fields"))
    Y, N, W, sizes = elements(fields, cells, ri)
    faces = faces_of(ri)
    s = next(x for x in results["surfaces"] if x["name"] == args.surface)
    mf = results.get("maintenance_factor", 1.0)
    act = s.get("active") or [True] * len(s["E"])
    top = max(e for e, a in zip(s["E"], act) if a)
    chosen = [i for i in range(len(s["E"])) if act[i] and s["E"][i] > 0.01 * top
              and (not balls or any(math.dist(s["points"][i], b[:3]) <= b[3] for b in balls))]
    chosen = chosen[::args.every]
    rows = []
    for i in chosen:
        p = np.array(s["points"][i], float)
        n = np.array(s["normals"][i], float)
        brute = gather(p, n, Y, N, W, sizes, faces)
        lux = s["E_indirect"][i] / mf
        rows.append((abs(lux - brute) / (s["E"][i] / mf), lux - brute, i, s["points"][i], lux,
                     brute, s["E"][i] / mf))
    rows.sort(reverse=True)
    print(f"{args.surface}: {len(rows)} points; |luxgrid - brute force| / E: mean "
          f"{100 * sum(r[0] for r in rows) / len(rows):.3f} %, signed mean "
          f"{100 * sum(r[1] / r[6] for r in rows) / len(rows):+.3f} %")
    print("| point | index | E lx | luxgrid reflected lx | brute force lx | difference / E |")
    print("|---|---:|---:|---:|---:|---:|")
    for r in rows[:10]:
        x, y, z = r[3]
        print(f"| ({x:.4g}, {y:.4g}, {z:.4g}) | {r[2]} | {r[6]:.3f} | {r[4]:.3f} | {r[5]:.3f} | "
              f"{100 * r[1] / r[6]:+.3f} % |")


if __name__ == "__main__":
    main()
