#!/usr/bin/env python3
"""Writes the whole-process benchmark's large projects into a folder (not kept in the repository:
they are generated in seconds). Usage: make_projects.py OUT_DIR

  floor50/project.json  50 rooms of 6 x 5 x 3 m on a 10 x 5 raster, 4 panels and a workplane each
  hall/project.json     a 100 x 50 x 6 m hall, 560 panels (28 x 20), workplane at 0.5 m spacing
  grid1m/project.json   a 100 x 100 m room, 25 panels, one 1000 x 1000 point workplane (10^6),
                        draft quality, no reflected light: the cost of the outputs themselves
  hall200/project.json  a 200 x 100 x 6 m hall, 2240 panels (56 x 40), workplane at 0.5 m spacing
  far1000/project.json  a 100 x 50 m hall, 1000 panels (40 x 25), one 200 x 50 point plane (10^4),
                        draft quality, no reflected light: 10^7 far-field pairs, the kernel's cost
  panel40k/project.json a 4 x 4 x 3 m black room (reflectances 0), one 0.6 x 0.6 m panel from an
                        IES table (tests/data/photometry/ies/indoor_full360_lm02.ies, 37 x 9,
                        its opening given as the panel's), a 200 x 200 point workplane (0.02 m):
                        every point in the near field, the cost of the table rung
Except panel40k, the photometric file is the open plan's (examples/openplan/photometry), copied
beside each.
"""
import json
import pathlib
import shutil
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent
LDT = ROOT / "examples" / "openplan" / "photometry" / "zumtobel_mirel_isym4.ldt"
PANEL_IES = ROOT / "tests" / "data" / "photometry" / "ies" / "indoor_full360_lm02.ies"


def room(name, x0, y0, w, d, h):
    return {"name": name, "outline": [[x0, y0], [x0 + w, y0], [x0 + w, y0 + d], [x0, y0 + d]],
            "floor_z": 0.0, "height": h, "reflectance": {"floor": 0.2, "walls": 0.5, "ceiling": 0.7}}


def panels(name, origin, count, spacing):
    return {"name": name, "photometry": "mirel", "array": {"origin": origin, "count": count, "spacing": spacing}}


def write(out, sub, title, settings, rooms, luminaires, surfaces, photometry=("mirel", LDT)):
    folder = out / sub
    (folder / "photometry").mkdir(parents=True, exist_ok=True)
    key, path = photometry
    shutil.copy(path, folder / "photometry" / path.name)
    project = {"format": "luxgrid-project/1", "name": title, "settings": settings,
               "photometry": {key: "photometry/" + path.name},
               "rooms": rooms, "luminaires": luminaires, "surfaces": surfaces}
    (folder / "project.json").write_text(json.dumps(project, indent=1) + "\n")


def main():
    out = pathlib.Path(sys.argv[1])
    standard = {"quality": "standard", "near_field": "auto", "indirect": "auto", "bounces": "auto",
                "maintenance_factor": 0.8}

    # 50 rooms, 0.2 m walls between them.
    rooms, lums, surfaces = [], [], []
    for k in range(50):
        x0, y0 = (k % 10) * 6.2, (k // 10) * 5.2
        name = f"room {k + 1:02d}"
        rooms.append(room(name, x0, y0, 6.0, 5.0, 3.0))
        lums.append(panels(f"panels {k + 1:02d}", [x0 + 1.5, y0 + 1.25, 3.0], [2, 2], [3.0, 2.5]))
        surfaces.append({"name": f"workplane {k + 1:02d}",
                         "workplane": {"room": name, "height": 0.75, "border": 0.5}, "spacing": 0.25})
    write(out, "floor50", "Benchmark floor: 50 rooms of 6 x 5 m", standard, rooms, lums, surfaces)

    write(out, "hall", "Benchmark hall 100 x 50 x 6 m, 560 panels", standard,
          [room("hall", 0, 0, 100.0, 50.0, 6.0)],
          [panels("panels", [100 / 56, 50 / 40, 6.0], [28, 20], [100 / 28, 50 / 20])],
          [{"name": "workplane", "workplane": {"room": "hall", "height": 0.75, "border": 0.5}, "spacing": 0.5}])

    write(out, "hall200", "Benchmark hall 200 x 100 x 6 m, 2240 panels", standard,
          [room("hall", 0, 0, 200.0, 100.0, 6.0)],
          [panels("panels", [100 / 56, 50 / 40, 6.0], [56, 40], [100 / 28, 50 / 20])],
          [{"name": "workplane", "workplane": {"room": "hall", "height": 0.75, "border": 0.5}, "spacing": 0.5}])

    draft = dict(standard, quality="draft", indirect="off")
    write(out, "grid1m", "Benchmark grid: 10^6 points", draft,
          [room("area", 0, 0, 100.0, 100.0, 4.0)],
          [panels("panels", [10.0, 10.0, 4.0], [5, 5], [20.0, 20.0])],
          [{"name": "grid", "plane": {"origin": [0, 0, 0.75], "u": [1, 0, 0], "v": [0, 1, 0],
                                      "size": [100, 100]}, "spacing": 0.1}])

    write(out, "far1000", "Benchmark far field: 1000 panels x 10^4 points", draft,
          [room("hall", 0, 0, 100.0, 50.0, 6.0)],
          [panels("panels", [1.25, 1.0, 6.0], [40, 25], [2.5, 2.0])],
          [{"name": "grid", "plane": {"origin": [0, 12.5, 0.75], "u": [1, 0, 0], "v": [0, 1, 0],
                                      "size": [100, 25]}, "spacing": 0.5}])

    black = {"floor": 0.0, "walls": 0.0, "ceiling": 0.0}
    write(out, "panel40k", "Benchmark near field: one 0.6 m panel over 40 000 points",
          dict(standard, indirect="auto"),
          [dict(room("room", 0, 0, 4.0, 4.0, 3.0), reflectance=black)],
          [{"name": "panel", "photometry": "panel", "position": [2.0, 2.0, 3.0],
            "emitter": {"shape": "rectangle", "size": [0.6, 0.6]}}],
          [{"name": "workplane", "workplane": {"room": "room", "height": 0.75, "border": 0.0},
            "spacing": 0.02}],
          photometry=("panel", PANEL_IES))


if __name__ == "__main__":
    main()
