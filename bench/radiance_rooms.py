"""A luxgrid run against Radiance in rooms that are not boxes (examples/lshape, tests/rooms/*), run
by hand, not in CI: an independent calculation of the same scene (docs/indirect.md, "Checked
against Radiance").

Radiance is no Debian package: build it from its public source (github.com/LBNL-ETA/Radiance,
`cmake -DBUILD_HEADLESS=ON`, targets oconv rtrace ies2rad xform) and point RADIANCE_BIN at its bin
folder and RADIANCE_LIB at a folder holding its .cal files (source.cal among them). It is a
measuring tool only.

The scene is read from the luxgrid run's results.json (its `report_input`: rooms with outline,
height and reflectances, obstacles as prisms, every luminaire's position, frame and opening, the
luminaire types' files), the points and normals from its surfaces, so the two calculations see
the same geometry by construction:
- rooms and obstacles: grey `plastic` polygons of the given reflectance (Lambertian, as luxgrid);
- luminaires: each type's intensity table as luxgrid reads it (`luxgrid info FILE --json --at
  C,gamma` at the file's own C and gamma angles, so symmetry and scaling are luxgrid's and the
  bilinear table between them the file's), written as an IES LM-63-2002 file with the opening of
  `report_input` (length along C0 = +x, width, height) and converted by Radiance's ies2rad
  (the opening as ies2rad makes it: a rectangle facing down, one facing up where the file emits
  upwards, sides where it has a height). The light material is made an `illum` without an
  alternate material, so the opening emits but is invisible to the reflected light's rays (luxgrid
  models no luminaire body: the ceiling behind a recessed luminaire reflects);
- direct light: rtrace -ab 0 with every opening cut into 8 x 8 sources, each subdivided to 0.2 % of
  its distance (-ds 0.002 -dj 0 -dt 0 -dc 1: deterministic, partial shadows by the samples; at
  -ds 0.01 a 4 cm source 2.5 m away is sampled at 2 x 2 points, and a shadow edge across the
  opening costs 1 to 2 % of the light beside examples/lshape's cabinet, docs/indirect.md);
- reflected light: rtrace -ab AB -aa 0 (no irradiance caching) -ad AD at -ds 0.05, less its own
  -ab 0 run, averaged over RUNS runs (-u+ uncorrelated sampling, each run its own random seed);
  its noise at a point is the standard error of that mean over the runs (stated per table).

Shadowed points: a point is shadowed when the segment from it to the centre or a corner of some
luminaire's opening in front of it is blocked (by an obstacle or the room's own walls), traced by
rtrace -oL in the same scene.

  RADIANCE_BIN=... RADIANCE_LIB=... python3 bench/radiance_rooms.py PROJECT RUN [--ab 12]
      [--ad 8192] [--runs 4] [--procs 1] [--work DIR]
  RUN: a luxgrid output folder of PROJECT (results.json, made with `luxgrid calc PROJECT -o RUN
  --quality reference`); LUXGRID (default build/luxgrid) reads the photometric files.

Prints per surface the promise's measure (docs/accuracy.md: |luxgrid - Radiance| / Radiance at the
points brighter than 1 % of the surface's maximum) over all points and over the shadowed ones,
with the worst point and Radiance's noise there, and the same for direct light alone."""
import argparse
import json
import math
import os
import re
import resource
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
RAD = os.environ.get("RADIANCE_BIN", "")
ENV = dict(os.environ, PATH=RAD + ":" + os.environ["PATH"])
LUXGRID = os.environ.get("LUXGRID", os.path.join(ROOT, "build", "luxgrid"))
LM_PER_W = 179.0  # Radiance's luminous efficacy of its white (ies2rad's unit)
SPLIT = 8  # the direct light's openings cut into SPLIT x SPLIT sources (split_rectangles)
LIFT_M = 1e-4  # a point is lifted off its face along its normal, so no ray starts inside it


def run(args, cwd, **kw):
    return subprocess.run(args, cwd=cwd, env=ENV, check=True, capture_output=True, text=True, **kw)


def cpu_of(fn):
    t0 = resource.getrusage(resource.RUSAGE_CHILDREN)
    out = fn()
    t1 = resource.getrusage(resource.RUSAGE_CHILDREN)
    return out, (t1.ru_utime - t0.ru_utime) + (t1.ru_stime - t0.ru_stime)


# ---- photometry ------------------------------------------------------------------------------

def ldt_angles(path):
    """The C and gamma angle lists of a EULUMDAT file (lines 27 + 6 n onwards, n lamp sets)."""
    lines = open(path, encoding="latin-1").read().splitlines()
    mc, ng = int(lines[3]), int(lines[5])
    n_sets = abs(int(lines[25]))
    first = 26 + 6 * n_sets + 10
    vals = [float(v.replace(",", ".")) for v in lines[first:first + mc + ng]]
    return vals[:mc], vals[mc:]


def luxgrid_table(path):
    """(C angles from 0 to 360, gamma angles, cd at each (C, gamma) C-major) of a EULUMDAT file as
    luxgrid reads it: `luxgrid info --json --at` at the file's own angles, so symmetry and scaling
    are luxgrid's."""
    c_list, g_list = ldt_angles(path)
    cs = sorted(set([c % 360.0 for c in c_list] + [0.0]))
    cs.append(360.0)
    at = []
    for c in cs:
        for g in g_list:
            at += ["--at", f"{c % 360.0:g},{g:g}"]
    info = json.loads(subprocess.run([LUXGRID, "info", path, "--json"] + at, check=True,
                                     capture_output=True, text=True).stdout)
    return cs, g_list, info["intensity_cd"]


def ies_for_type(path, opening, out_path):
    """An absolute-photometry IES LM-63-2002 file of `path` as luxgrid reads it, with `opening`."""
    cs, g_list, cd = luxgrid_table(path)
    shape = opening.get("shape", "point")
    if shape == "rectangle":
        w, l, h = opening["width"], opening["length"], opening.get("height", 0.0)
    elif shape == "disk":  # LM-63: a negative width is a circle's diameter
        w, l, h = -opening["width"], 0.0, opening.get("height", 0.0)
    else:
        w = l = h = 0.0
    with open(out_path, "w") as f:
        f.write("IESNA:LM-63-2002\n[TEST] luxgrid bench/radiance_rooms.py\n"
                f"[LUMINAIRE] {os.path.basename(path)}\nTILT=NONE\n")
        f.write(f"1 -1 1 {len(g_list)} {len(cs)} 1 2 {w:.6f} {l:.6f} {h:.6f}\n1 1 0\n")
        f.write(" ".join(f"{g:g}" for g in g_list) + "\n")
        f.write(" ".join(f"{c:g}" for c in cs) + "\n")
        k = 0
        for _ in cs:
            f.write(" ".join(f"{v:.6g}" for v in cd[k:k + len(g_list)]) + "\n")
            k += len(g_list)


def radiance_type(key, ies_path, work):
    """ies2rad's scene for one type, its light made an invisible illum (see the module text)."""
    run([os.path.join(RAD, "ies2rad"), "-dm", "-c", "1", "1", "1", "-o", key, ies_path], work)
    text = open(os.path.join(work, key + ".rad")).read()
    text = text.replace(f" light '{key}_light'", f" illum '{key}_light'")
    # A flat opening's brightdata carries one real argument, the multiplier 1 / area, which
    # rtrace's source_corr (src/rt/func.c, this build) applies only when there are more than one
    # (a box's four): it would be lost, the light a factor of the area too dark. It goes into the
    # illum's colour instead, the brightdata's argument made 1 so that either reading agrees.
    m = re.search(r"\n0\n1 (\S+)\n", text)
    if m:
        mult = float(m.group(1))
        text = text[:m.start()] + "\n0\n1 1\n" + text[m.end():]
        text = text.replace("\n3 1 1 1\n", f"\n3 {mult:.9g} {mult:.9g} {mult:.9g}\n", 1)
    return text


def split_rectangles(text, k):
    """Each four-cornered emitting polygon of ies2rad's text cut into k x k polygons of the same
    material: rtrace samples a source at the centres of pieces about -ds times its distance
    across, at most MAXSPART (64, src/rt/source.h) of them, too few for a penumbra cast by an
    obstacle's edge close by; k x k sources of up to 64 samples each are not. The luminance per
    area is the opening's, so the pieces sum to the same light."""
    pat = re.compile(r"('[^']*_light') polygon '([^']*)'\n0\n0\n12\n((?:\s*\S+){12})\n?")

    def cut(m):
        v = [float(x) for x in m.group(3).split()]
        c = [v[0:3], v[3:6], v[6:9], v[9:12]]

        def at(u, w):  # bilinear in the quadrilateral c0 c1 c2 c3
            return [(1 - u) * (1 - w) * c[0][i] + u * (1 - w) * c[1][i] + u * w * c[2][i] +
                    (1 - u) * w * c[3][i] for i in range(3)]
        out = ""
        for i in range(k):
            for j in range(k):
                q = [at(i / k, j / k), at((i + 1) / k, j / k), at((i + 1) / k, (j + 1) / k),
                     at(i / k, (j + 1) / k)]
                out += (f"{m.group(1)} polygon '{m.group(2)}{i}_{j}'\n0\n0\n12\n" +
                        "\n".join("\t%.9g\t%.9g\t%.9g" % tuple(x) for x in q) + "\n")
        return out
    return pat.sub(cut, text)


def euler_xyz(frame):
    """Angles (degrees) about x, then y, then z that turn the world axes into frame's axes."""
    r = [[frame[col][row] for col in range(3)] for row in range(3)]  # columns are the axes
    b = math.asin(max(-1.0, min(1.0, -r[2][0])))
    a = math.atan2(r[2][1], r[2][2])
    c = math.atan2(r[1][0], r[0][0])
    return [math.degrees(v) for v in (a, b, c)]


# ---- geometry --------------------------------------------------------------------------------

def poly(mat, name, corners):
    return (f"{mat} polygon {name} 0 0 {3 * len(corners)} " +
            " ".join(f"{c[0]:.9g} {c[1]:.9g} {c[2]:.9g}" for c in corners) + "\n")


def ccw(outline):
    area = sum(outline[i][0] * outline[(i + 1) % len(outline)][1] -
               outline[(i + 1) % len(outline)][0] * outline[i][1] for i in range(len(outline)))
    return outline if area > 0 else outline[::-1]


def room_text(room, k):
    rho = room["reflectance"]
    z0 = room["floor_z"]
    z1 = z0 + room["height"]
    out = ""
    for part in ("floor", "walls", "ceiling"):
        out += f"void plastic r{k}_{part} 0 0 5 {rho[part]} {rho[part]} {rho[part]} 0 0\n"
    o = ccw(room["outline"])
    out += poly(f"r{k}_floor", f"r{k}_floor", [(x, y, z0) for x, y in o])
    out += poly(f"r{k}_ceiling", f"r{k}_ceiling", [(x, y, z1) for x, y in o[::-1]])
    for i in range(len(o)):  # inward normals
        (xa, ya), (xb, yb) = o[i], o[(i + 1) % len(o)]
        out += poly(f"r{k}_walls", f"r{k}_wall{i}",
                    [(xa, ya, z0), (xa, ya, z1), (xb, yb, z1), (xb, yb, z0)])
    for j, ob in enumerate(room.get("obstacles", [])):
        name = f"r{k}_ob{j}"
        rho_o = ob["reflectance"]
        out += f"void plastic {name}_mat 0 0 5 {rho_o} {rho_o} {rho_o} 0 0\n"
        f = ccw(ob["footprint"])
        if ob["z1"] < z1 - 1e-9:
            out += poly(f"{name}_mat", f"{name}_top", [(x, y, ob["z1"]) for x, y in f])
        if ob["z0"] > z0 + 1e-9:
            out += poly(f"{name}_mat", f"{name}_bottom", [(x, y, ob["z0"]) for x, y in f[::-1]])
        for i in range(len(f)):  # outward normals
            (xa, ya), (xb, yb) = f[i], f[(i + 1) % len(f)]
            out += poly(f"{name}_mat", f"{name}_side{i}",
                        [(xa, ya, ob["z0"]), (xb, yb, ob["z0"]), (xb, yb, ob["z1"]),
                         (xa, ya, ob["z1"])])
    return out


def build_scene(results, project_file, work):
    ri = results["report_input"]
    project = json.load(open(project_file))
    openings = {}
    for lum in ri["luminaires"]:
        openings.setdefault(lum["photometry"], lum["opening"])
    text = ""
    for t in ri["luminaire_types"]:
        key = t["key"]
        path = os.path.join(os.path.dirname(project_file), project["photometry"][key])
        ies = os.path.join(work, key + ".ies")
        ies_for_type(path, openings[key], ies)
        one = radiance_type(key, ies, work)
        open(os.path.join(work, key + "_type.rad"), "w").write(one)
        open(os.path.join(work, key + "_split.rad"), "w").write(split_rectangles(one, SPLIT))
    rooms = "".join(room_text(room, k) for k, room in enumerate(ri["rooms"]))
    # scene.oct for the reflected light and the shadow test, scene_split.oct (every opening cut
    # into SPLIT x SPLIT sources) for the direct light.
    for suffix, name in (("_type.rad", "scene"), ("_split.rad", "scene_split")):
        text = ""
        for k, lum in enumerate(ri["luminaires"]):
            a, b, c = euler_xyz(lum["rotation"])
            x, y, z = lum["position"]
            text += run([os.path.join(RAD, "xform"), "-n", f"l{k}", "-rx", f"{a:.9g}", "-ry",
                         f"{b:.9g}", "-rz", f"{c:.9g}", "-t", f"{x:.9g}", f"{y:.9g}", f"{z:.9g}",
                         lum["photometry"] + suffix], work).stdout
        open(os.path.join(work, name + ".rad"), "w").write(text + rooms)
        with open(os.path.join(work, name + ".oct"), "w") as f:
            subprocess.run([os.path.join(RAD, "oconv"), name + ".rad"], cwd=work, env=ENV,
                           stdout=f, check=True)


# ---- points, runs ----------------------------------------------------------------------------

def points_of(results):
    """[(surface, index, p, n)] of the active points."""
    out = []
    for s in results["surfaces"]:
        act = s.get("active", [True] * len(s["E"]))
        for i, (p, n) in enumerate(zip(s["points"], s["normals"])):
            if act[i]:
                out.append((s["name"], i, p, n))
    return out


def origin(p, n):
    return [p[k] + LIFT_M * n[k] for k in range(3)]


def rtrace_irradiance(pts, work, opts, octree="scene.oct"):
    inp = "".join("%.9g %.9g %.9g %.9g %.9g %.9g\n" % (*origin(p, n), *n) for _, _, p, n in pts)
    r = run([os.path.join(RAD, "rtrace"), "-h", "-I+", "-lw", "1e-6", "-lr", "-20"] + opts +
            [octree], work, input=inp)
    vals = []
    for line in r.stdout.split("\n"):
        if line.strip():
            rgb = [float(x) for x in line.split()]
            vals.append(LM_PER_W * (0.265 * rgb[0] + 0.670 * rgb[1] + 0.065 * rgb[2]))
    assert len(vals) == len(pts)
    return vals


def shadowed(pts, results, work):
    """Per point: "" when it sees the centre and the corners of every luminaire's opening in front
    of it; "obstacle" when one of them is hidden by an obstacle (its first hit along the segment,
    an obstacle's face, lies short of it by more than 1 mm); "room" when only the room's own faces
    hide one (beyond a reflex corner)."""
    rays, owner = [], []
    for k, (_, _, p, n) in enumerate(pts):
        o = origin(p, n)
        for lum in results["report_input"]["luminaires"]:
            c = lum["position"]
            op = lum["opening"]
            ex, ey = lum["rotation"][0], lum["rotation"][1]
            hl, hw = 0.5 * op.get("length", 0.0), 0.5 * op.get("width", 0.0)
            targets = [c] + [[c[i] + sx * hl * ex[i] + sy * hw * ey[i] for i in range(3)]
                             for sx in (-1, 1) for sy in (-1, 1) if hl > 0 or hw > 0]
            for t in targets:
                d = [t[i] - o[i] for i in range(3)]
                dist = math.sqrt(sum(v * v for v in d))
                if dist < 1e-6 or sum(d[i] * n[i] for i in range(3)) <= 1e-6 * dist:
                    continue  # behind the point's face or in its plane: no light either way
                rays.append((o, [v / dist for v in d], dist))
                owner.append(k)
    inp = "".join("%.9g %.9g %.9g %.9g %.9g %.9g\n" % (*o, *d) for o, d, _ in rays)
    r = run([os.path.join(RAD, "rtrace"), "-h", "-ab", "0", "-oLm", "scene.oct"], work, input=inp)
    lines = [ln.split() for ln in r.stdout.split("\n") if ln.strip()]
    assert len(lines) == len(rays)
    out = [""] * len(pts)
    for (o, d, dist), k, hit in zip(rays, owner, lines):
        if float(hit[0]) < dist - 1e-3:
            by = "obstacle" if "_ob" in hit[1] else "room"
            if out[k] != "obstacle":
                out[k] = by
    return out


def compare(pts, lux, rad, noise, shade, label, tops=None):
    """Per surface: the promise's measure of luxgrid against Radiance, over every bright point, the
    shadowed ones and those behind an obstacle."""
    classes = [("all", lambda k: True), ("shadowed", lambda k: shade[k] != ""),
               ("behind an obstacle", lambda k: shade[k] == "obstacle")]
    print(f"\n{label}: |luxgrid - Radiance| / Radiance at the points brighter than 1 % of the "
          "surface's maximum (count, mean, max, where, Radiance's noise there)")
    print("| surface | " + " | ".join(f"{c}: n | mean % | max % | at (x, y, z) m | noise %"
                                      for c, _ in classes) + " |")
    print("|---|" + "---:|---:|---:|---|---:|" * len(classes))
    names = []
    for s, _, _, _ in pts:
        if s not in names:
            names.append(s)
    rel = {}
    for name in names + [None]:
        if name is not None:
            idx = [k for k in range(len(pts)) if pts[k][0] == name]
            top = tops[name] if tops else max(rad[k] for k in idx)
            bright = [k for k in idx if rad[k] > 0.01 * top]
            for k in bright:
                rel[k] = abs(lux[k] - rad[k]) / rad[k]
        else:
            bright = sorted(rel)
        cells = [name if name is not None else "**all surfaces**"]
        for _, keep in classes:
            ks = [k for k in bright if keep(k)]
            if not ks:
                cells += ["0", "-", "-", "-", "-"]
                continue
            w = max(ks, key=lambda k: rel[k])
            cells += [str(len(ks)), f"{100 * sum(rel[k] for k in ks) / len(ks):.3f}",
                      f"{100 * rel[w]:.3f}", "%.2f, %.2f, %.2f" % tuple(pts[w][2]),
                      f"{100 * noise[w]:.3f}"]
        print("| " + " | ".join(cells) + " |")
    ks = sorted(rel)
    print(f"signed mean of (luxgrid - Radiance) / Radiance over the bright points: "
          f"{100 * sum((lux[k] - rad[k]) / rad[k] for k in ks) / len(ks):+.3f} %")
    print(f"Radiance's noise over the bright points: mean "
          f"{100 * sum(noise[k] for k in ks) / len(ks):.3f} %, max "
          f"{100 * max(noise[k] for k in ks):.3f} %")


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("project", help="the project the run calculated (its photometric files)")
    ap.add_argument("run_dir")
    ap.add_argument("--ab", type=int, default=12)
    ap.add_argument("--ad", type=int, default=8192)
    ap.add_argument("--runs", type=int, default=4, help="reflected-light runs; 0: direct only")
    ap.add_argument("--procs", type=int, default=1, help="rtrace -n")
    ap.add_argument("--select", choices=["all", "shadowed", "obstacle"], default="all",
                    help="the points of the reflected-light runs")
    ap.add_argument("--every", type=int, default=1, help="every K-th of the selected points")
    ap.add_argument("--work", default=os.path.join(tempfile.gettempdir(), "luxgrid-radiance-rooms"))
    a = ap.parse_args()
    os.makedirs(a.work, exist_ok=True)
    ENV["RAYPATH"] = ".:" + os.environ.get("RADIANCE_LIB", "")
    results = json.load(open(os.path.join(a.run_dir, "results.json")))
    build_scene(results, os.path.abspath(a.project), a.work)
    pts = points_of(results)
    by_name = {s["name"]: s for s in results["surfaces"]}
    lux = [by_name[s]["E"][i] for s, i, _, _ in pts]
    lux_direct = [by_name[s]["E_direct"][i] for s, i, _, _ in pts]
    print(f"{a.run_dir}: {len(pts)} points, quality {results.get('quality')}, "
          f"maintenance factor {results.get('maintenance_factor')}")
    shade, cpu = cpu_of(lambda: shadowed(pts, results, a.work))
    print(f"shadowed points: {sum(1 for v in shade if v)}, of them behind an obstacle: "
          f"{sum(1 for v in shade if v == 'obstacle')} ({cpu:.1f} s CPU)")
    n = ["-n", str(a.procs)]
    fine = ["-ds", "0.002", "-dj", "0", "-dt", "0", "-dc", "1", "-dr", "0"]
    direct, cpu = cpu_of(lambda: rtrace_irradiance(pts, a.work, ["-ab", "0"] + fine + n,
                                                   "scene_split.oct"))
    print(f"direct: rtrace -ab 0 {' '.join(fine)}, every opening cut into {SPLIT} x {SPLIT} "
          f"sources: {cpu:.1f} s CPU")
    zero = [0.0] * len(pts)
    compare(pts, lux_direct, direct, zero, shade, "Direct light")
    if a.runs == 0:
        return
    # The reflected light at the chosen points only (it costs about a second of CPU per point
    # and run at -ad 4096): every point, the shadowed ones or those behind an obstacle, every K-th.
    keep = {"all": lambda k: True, "shadowed": lambda k: shade[k] != "",
            "obstacle": lambda k: shade[k] == "obstacle"}[a.select]
    sub = [k for k in range(len(pts)) if keep(k)][::a.every]
    spts = [pts[k] for k in sub]
    # Deterministic sources (-dj 0) at 5 % of their distance, so that the -ab 0 run subtracted
    # is the same direct light as the one inside each -ab run.
    coarse = ["-ds", "0.05", "-dj", "0", "-dt", "0", "-dc", "1", "-dr", "0"]
    base = rtrace_irradiance(spts, a.work, ["-ab", "0"] + coarse + n)
    # Runs are kept in the work folder and added to: --runs N makes N in all, so a later call
    # lowers the noise further, and a call on another run of the same project compares with them.
    cache = os.path.join(a.work, f"reflected_ab{a.ab}_ad{a.ad}_{a.select}_{a.every}.json")
    key = [[s, i] for s, i, _, _ in spts]
    runs = []
    if os.path.exists(cache):
        c = json.load(open(cache))
        if c["points"] == key:
            runs = c["runs"]
    while len(runs) < a.runs:
        vals, cpu = cpu_of(lambda: rtrace_irradiance(
            spts, a.work, ["-ab", str(a.ab), "-aa", "0", "-ad", str(a.ad), "-as", "0", "-u+"] +
            coarse + n))
        runs.append([v - b for v, b in zip(vals, base)])
        json.dump({"points": key, "runs": runs}, open(cache, "w"))
        print(f"reflected run {len(runs)}: rtrace -ab {a.ab} -aa 0 -ad {a.ad} -as 0 -u+ "
              f"{' '.join(coarse)}: {cpu:.1f} s CPU for {len(spts)} points", flush=True)
    m = len(runs)
    ind = [sum(col) / m for col in zip(*runs)]
    total = [direct[k] + i for k, i in zip(sub, ind)]
    if m > 1:
        se = [math.sqrt(sum((x - mu) ** 2 for x in col) / (m - 1) / m)
              for col, mu in zip(zip(*runs), ind)]
    else:
        se = [0.0] * len(spts)
    noise = [e / t if t > 0 else 0.0 for e, t in zip(se, total)]
    compare(spts, [lux[k] for k in sub], total, noise, [shade[k] for k in sub],
            f"Direct and reflected light at {len(spts)} points ({a.select}, every {a.every}; "
            f"{m} runs of -ab {a.ab} -ad {a.ad} averaged; a surface's maximum: luxgrid's)",
            {s["name"]: max(s["E"]) for s in results["surfaces"]})

if __name__ == "__main__":
    main()
