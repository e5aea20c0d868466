#!/usr/bin/env python3
"""The office example swept over mounting height and luminaire spacing on Dask, and the trade-off
of power density against uniformity plotted (docs/python.md, "Examples").

    python3 office_sweep.py [-o office_sweep.png] [--csv office_sweep.csv] [--workers N]

Each variant sets the ceiling height (the panels are recessed, so it is their mounting height)
and a square spacing s: as many rows and columns of panels as fit the 6 x 4 m room at that
spacing, centred. More panels raise the power density (W/m^2, from the panels' stated power);
wider spacing and lower mounting lower the uniformity U0 on the workplane. The plot shows each
variant's power density against U0, the marker's colour its height, its label the spacing, and
a filled marker where the workplane meets the office's illuminance requirements (EN 12464-1
office writing: Em >= 500 lx and U0 >= 0.6; the sweep's table has every other check too).
"""
import argparse
import os

import matplotlib

matplotlib.use("Agg")  # files only, no display
import matplotlib.pyplot as plt  # noqa: E402

import luxgrid  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
OFFICE = os.path.join(HERE, "..", "office", "project.json")
ROOM_M = (6.0, 4.0)
HEIGHTS_M = (2.6, 2.8, 3.0, 3.2)
SPACINGS_M = (1.4, 1.7, 2.0, 2.5, 3.0)


def variants():
    for height in HEIGHTS_M:
        for s in SPACINGS_M:
            count = [max(1, round(side / s)) for side in ROOM_M]
            origin = [(side - (n - 1) * s) / 2 for side, n in zip(ROOM_M, count)]
            yield {"/rooms/0/height": height,
                   "/luminaires/0/array/origin": [origin[0], origin[1], height],
                   "/luminaires/0/array/count": count,
                   "/luminaires/0/array/spacing": [s, s]}


def plot(frame, path):
    fig, ax = plt.subplots(figsize=(8, 5.5), dpi=120)
    colours = plt.cm.viridis([k / (len(HEIGHTS_M) - 1) for k in range(len(HEIGHTS_M))])
    for height, colour in zip(HEIGHTS_M, colours):
        part = frame[frame["/rooms/0/height"] == height]
        met = (part["workplane.Em.met"] & part["workplane.U0.met"]).astype(bool)
        ax.plot(part["office.W_per_m2"], part["workplane.U0"], "-", color=colour, alpha=0.4)
        ax.scatter(part["office.W_per_m2"][met], part["workplane.U0"][met], color=colour, s=60,
                   label=f"height {height:.1f} m")
        ax.scatter(part["office.W_per_m2"][~met], part["workplane.U0"][~met], s=60,
                   facecolors="none", edgecolors=colour)
        for _, row in part.iterrows():
            ax.annotate(f"{row['/luminaires/0/array/spacing'][0]:g} m",
                        (row["office.W_per_m2"], row["workplane.U0"]), fontsize=7,
                        xytext=(4, 3), textcoords="offset points")
    ax.axhline(0.6, color="grey", linestyle="--", linewidth=0.8)
    ax.text(ax.get_xlim()[1], 0.6, "U0 0.6 (EN 12464-1)", ha="right", va="bottom", fontsize=8,
            color="grey")
    ax.set_xlabel("power density (W/m²)")
    ax.set_ylabel("uniformity U0 on the workplane")
    ax.set_title("Office 6 x 4 m: mounting height x spacing\n"
                 "(filled: the workplane meets Em >= 500 lx and U0 >= 0.6; label: spacing)",
                 fontsize=10)
    ax.legend(fontsize=8)
    ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(path)


if __name__ == "__main__":  # Dask starts its worker processes by importing this file again
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("-o", "--output", default="office_sweep.png")
    parser.add_argument("--csv", default="office_sweep.csv")
    parser.add_argument("--workers", type=int, default=None)
    args = parser.parse_args()
    frame = luxgrid.sweep(OFFICE, list(variants()), workers=args.workers)
    frame.to_csv(args.csv, index=False)
    failed = frame[frame["error"].notna()]
    for _, row in failed.iterrows():
        print("failed:", row["error"])
    plot(frame[frame["error"].isna()], args.output)
    print(f"{len(frame)} variants ({len(failed)} failed): {args.csv}, {args.output}")
