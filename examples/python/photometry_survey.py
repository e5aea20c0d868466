#!/usr/bin/env python3
"""A photometry survey: the CIE 190 UGR tables of every IES and EULUMDAT file under a folder,
in one table (docs/python.md, "Examples").

    python3 photometry_survey.py [FOLDER] [-o survey.csv]

FOLDER defaults to the repository's examples/. One row per file, room size and reflectance
combination: the file, its luminaire and flux, the room (X and Y in units of the mounting height
H above the eye), the ceiling / wall / floor reflectances, and the UGR viewed crosswise and
endwise for the file's lamp flux, as `luxgrid info FILE --ugr` gives them. Files luxgrid cannot
read are listed with their error, not skipped silently.
"""
import argparse
import os

import pandas

import luxgrid

EXTENSIONS = (".ies", ".ldt")


def photometry_files(folder):
    for root, dirs, files in os.walk(folder):
        dirs[:] = sorted(d for d in dirs if not d.startswith((".", "build")))
        for f in sorted(files):
            if f.lower().endswith(EXTENSIONS):
                yield os.path.join(root, f)


def survey(folder):
    rows = []
    for path in photometry_files(folder):
        name = os.path.relpath(path, folder)
        try:
            info = luxgrid.info(path, ugr=True)
        except luxgrid.InputError as e:
            rows.append({"file": name, "error": str(e)})
            continue
        table = info["ugr_table"]
        luminaire = info["keywords"].get("LUMINAIRE") or info["keywords"].get("LUMCAT", "")
        for room in table["rooms"]:
            for k, (ceiling, walls, floor) in enumerate(table["reflectances"]):
                rows.append({"file": name, "luminaire": luminaire, "flux_lm": info["flux_lm"],
                             "X_H": room["x_H"], "Y_H": room["y_H"], "ceiling": ceiling,
                             "walls": walls, "floor": floor,
                             "UGR_crosswise": room["crosswise"][k],
                             "UGR_endwise": room["endwise"][k], "error": None})
    return pandas.DataFrame(rows)


if __name__ == "__main__":
    here = os.path.dirname(os.path.abspath(__file__))
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("folder", nargs="?", default=os.path.dirname(here))
    parser.add_argument("-o", "--output", default="survey.csv")
    args = parser.parse_args()
    frame = survey(args.folder)
    frame.to_csv(args.output, index=False)
    if "X_H" in frame:
        # The data sheets' reference value: 4H x 8H, reflectances 0.7 / 0.5 / 0.2.
        ref = frame[(frame.X_H == 4) & (frame.Y_H == 8) & (frame.ceiling == 0.7) &
                    (frame.walls == 0.5) & (frame.floor == 0.2)]
        print(ref[["file", "luminaire", "UGR_crosswise", "UGR_endwise"]].to_string(index=False))
    for _, row in frame[frame.error.notna()].iterrows():
        print("not read:", row.error)
    print(f"{len(frame)} rows written to {args.output}")
