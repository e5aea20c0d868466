"""luxgrid against Radiance on CIE 171's facade opening (cases 5.11 / 5.12: a 2 x 1 m opening in
the south wall of a black 4 x 4 x 3 m room), run by hand, not in CI.

Radiance is no Debian package: build it from its public source (github.com/LBNL-ETA/Radiance,
branch master, `cmake -DBUILD_HEADLESS=ON`, targets oconv rtrace gensky) and point RADIANCE_BIN at
its bin folder and RADIANCE_LIB at a folder holding its .cal files (src/gen/*.cal,
src/rt/rayinit.cal). It is a measuring tool only.

The points: the floor and the north wall on a grid of STEP metres. The reference at each point is
cases/_derive/daylight.py's adaptive quadrature (1e-7 relative, independent of luxgrid's code),
cached in the work folder. Radiance: gensky -c (traditional overcast) or -u (uniform) normalised
to E_h = 10 000 lx (179 lm/W), ground reflectance 0.3 through gensky's ground glow (CIE 171's
uniform ground), black plastic walls, clear glass of normal transmittance 0.88 converted to its
transmissivity by the formula of Radiance's reference manual; rtrace -I -ab 1 -aa 0 (no
irradiance caching) -as 0, one process, at each -ad given. Errors: the worst and the mean of
|value - reference| / reference over the points brighter than 1 % of the largest (the promise's
rule); CPU: user + system of the child process.

  RADIANCE_BIN=... RADIANCE_LIB=... python3 bench/radiance_daylight.py SKY glazed|unglazed STEP AD...
  e.g. python3 bench/radiance_daylight.py cie-overcast unglazed 0.2 4096 16384 65536"""
import json
import math
import os
import resource
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "cases", "_derive"))
import daylight as D  # noqa: E402

RAD = os.environ.get("RADIANCE_BIN", "")
ENV = dict(os.environ, PATH=RAD + ":" + os.environ["PATH"],
           RAYPATH=".:" + os.environ.get("RADIANCE_LIB", ""))
LUXGRID = os.environ.get("LUXGRID", os.path.join(ROOT, "build", "luxgrid"))
WORK = os.environ.get("WORK", os.path.join(tempfile.gettempdir(), "luxgrid-radiance"))
RHO_G, T_N = 0.3, 0.88
OPENING = ((1.0, 0.0, 1.0), (1, 0, 0), (0, 0, 1), 2.0, 1.0)  # x 1..3, z 1..2 at y = 0
E_H_LX, LM_PER_W = 10000.0, 179.0


def grid_points(step):
    """(x, y, z, nx, ny, nz): the floor, then the north wall (y = 4, facing -y)."""
    n = int(round(4 / step))
    pts = [((i + 0.5) * step, (j + 0.5) * step, 0.0, 0.0, 0.0, 1.0)
           for j in range(n) for i in range(n)]
    pts += [((i + 0.5) * step, 4.0, (k + 0.5) * step, 0.0, -1.0, 0.0)
            for k in range(int(round(3 / step))) for i in range(n)]
    return pts


def reference(pts, sky, glazed):
    path = os.path.join(WORK, f"ref_{sky}_{'glazed' if glazed else 'unglazed'}_{len(pts)}.json")
    if os.path.exists(path):
        return json.load(open(path))
    I = D.sky_integral(sky)
    out = []
    for p in pts:
        sc, erc = D.components(OPENING, p[:3], p[3:], sky, I, RHO_G, T_N if glazed else None, 1e-7)
        out.append(sc + erc)
    json.dump(out, open(path, "w"))
    return out


def radiance_scene(sky, glazed):
    flag = {"cie-overcast": "-c", "uniform": "-u"}[sky]
    text = subprocess.run([os.path.join(RAD, "gensky"), "-ang", "60", "0", flag, "-B",
                           str(E_H_LX / LM_PER_W), "-g", str(RHO_G)],
                          capture_output=True, text=True, env=ENV, check=True).stdout
    text += ("skyfunc glow sky_glow 0 0 4 1 1 1 0\nsky_glow source sky 0 0 4 0 0 1 180\n"
             "skyfunc glow ground_glow 0 0 4 1 1 1 0\nground_glow source ground 0 0 4 0 0 -1 180\n"
             "void plastic black 0 0 5 0 0 0 0 0\n")

    def poly(name, corners, material="black"):
        return (f"{material} polygon {name} 0 0 {3 * len(corners)} " +
                " ".join(f"{c[0]} {c[1]} {c[2]}" for c in corners) + "\n")
    text += poly("floor", [(0, 0, 0), (0, 4, 0), (4, 4, 0), (4, 0, 0)])
    text += poly("ceiling", [(0, 0, 3), (4, 0, 3), (4, 4, 3), (0, 4, 3)])
    text += poly("west", [(0, 0, 0), (0, 0, 3), (0, 4, 3), (0, 4, 0)])
    text += poly("east", [(4, 0, 0), (4, 4, 0), (4, 4, 3), (4, 0, 3)])
    text += poly("north", [(0, 4, 0), (0, 4, 3), (4, 4, 3), (4, 4, 0)])
    # The south wall around the opening, as four rectangles (x0, x1, z0, z1).
    for k, (x0, x1, z0, z1) in enumerate([(0, 1, 0, 3), (3, 4, 0, 3), (1, 3, 0, 1), (1, 3, 2, 3)]):
        text += poly(f"south{k}", [(x0, 0, z0), (x1, 0, z0), (x1, 0, z1), (x0, 0, z1)])
    if glazed:
        tn = (math.sqrt(0.8402528435 + 0.0072522239 * T_N * T_N) - 0.9166530661) / 0.0036261119 / T_N
        text += f"void glass pane 0 0 3 {tn} {tn} {tn}\n"
        text += poly("window", [(1, 0, 1), (3, 0, 1), (3, 0, 2), (1, 0, 2)], "pane")
    with open(os.path.join(WORK, "scene.rad"), "w") as f:
        f.write(text)
    with open(os.path.join(WORK, "scene.oct"), "w") as f:
        subprocess.run([os.path.join(RAD, "oconv"), os.path.join(WORK, "scene.rad")], stdout=f,
                       env=ENV, check=True)


def cpu_of(run):
    t0 = resource.getrusage(resource.RUSAGE_CHILDREN)
    out = run()
    t1 = resource.getrusage(resource.RUSAGE_CHILDREN)
    return out, (t1.ru_utime - t0.ru_utime) + (t1.ru_stime - t0.ru_stime)


def radiance(pts, ad):
    # Points on a surface are lifted 0.1 mm off it, so no ray starts inside its own face.
    inp = "".join(f"{p[0]} {p[1] - 1e-4 * (p[1] == 4.0)} {p[2] + 1e-4 * (p[2] == 0.0)} "
                  f"{p[3]} {p[4]} {p[5]}\n" for p in pts)
    r, cpu = cpu_of(lambda: subprocess.run(
        [os.path.join(RAD, "rtrace"), "-h", "-I+", "-ab", "1", "-ad", str(ad), "-as", "0", "-aa",
         "0", "-lw", "1e-9", "-n", "1", os.path.join(WORK, "scene.oct")],
        input=inp, capture_output=True, text=True, env=ENV, check=True))
    vals = []
    for line in r.stdout.split("\n"):
        if line.strip():
            rgb = [float(x) for x in line.split()]
            irradiance = 0.265 * rgb[0] + 0.670 * rgb[1] + 0.065 * rgb[2]
            vals.append(100.0 * LM_PER_W * irradiance / E_H_LX)
    return vals, cpu


def luxgrid(pts, sky, glazed, quality):
    case = "cie171_5_12_glazed_facade_opening" if glazed else "cie171_5_11_facade_opening"
    p = json.load(open(os.path.join(ROOT, "cases", case, "project.json")))
    p["rooms"] = [r for r in p["rooms"] if r["name"] == "2x1"]
    p["openings"] = [o for o in p["openings"] if o["room"] == "2x1"]
    p["daylight"]["sky"] = {"type": sky}
    p["settings"]["quality"] = quality
    p["surfaces"] = [{"name": "points", "points": [{"at": list(q[:3]), "normal": list(q[3:])}
                                                   for q in pts]}]
    project = os.path.join(WORK, "project.json")
    json.dump(p, open(project, "w"))
    _, cpu = cpu_of(lambda: subprocess.run(
        [LUXGRID, "--threads", "1", "calc", project, "-o", os.path.join(WORK, "out"),
         "--no-report"], stdout=subprocess.DEVNULL, check=True))
    return json.load(open(os.path.join(WORK, "out", "results.json")))["surfaces"][0]["DF"], cpu


def errors(vals, ref):
    top = max(ref)
    rel = [abs(v - r) / r for v, r in zip(vals, ref) if r > 0.01 * top]
    return max(rel), sum(rel) / len(rel)


def main():
    sky, glazed, step = sys.argv[1], sys.argv[2] == "glazed", float(sys.argv[3])
    os.makedirs(WORK, exist_ok=True)
    pts = grid_points(step)
    ref = reference(pts, sky, glazed)
    print(f"{len(pts)} points (floor and north wall at {step} m), sky {sky}, "
          f"{'glazed' if glazed else 'unglazed'}")
    print("| run | worst error % | mean error % | CPU s | ms per point |\n|---|---|---|---|---|")
    rows = [(f"luxgrid {q}", lambda q=q: luxgrid(pts, sky, glazed, q))
            for q in ("draft", "standard", "high")]
    rows += [(f"rtrace -ab 1 -ad {ad}", lambda ad=ad: radiance(pts, ad)) for ad in sys.argv[4:]]
    if sys.argv[4:]:
        radiance_scene(sky, glazed)
    for name, run in rows:
        vals, cpu = run()
        worst, mean = errors(vals, ref)
        print(f"| {name} | {100 * worst:.3f} | {100 * mean:.3f} | {cpu:.2f} | "
              f"{1e3 * cpu / len(pts):.3f} |", flush=True)


if __name__ == "__main__":
    main()
