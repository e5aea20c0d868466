"""Reduces a `reference` run's results.json to what `luxgrid diff` compares (tests/rooms/README.md):
the format, the version that wrote it, and per surface its name, points, active flags and E, to 7
significant digits (5e-8 relative, far below any promise) and points to 1e-7 m.

  python3 tests/rooms/reduce_reference.py RUN/results.json tests/rooms/<room>/reference.json"""
import json
import sys


def main():
    src, dst = sys.argv[1:3]
    r = json.load(open(src))
    out = {"format": r["format"], "luxgrid_version": r.get("luxgrid_version"),
           "quality": r.get("quality"), "surfaces": []}
    for s in r["surfaces"]:
        out["surfaces"].append({
            "name": s["name"],
            "points": [[round(v, 7) for v in p] for p in s["points"]],
            "active": s.get("active", [True] * len(s["E"])),
            "E": [float(f"{v:.7g}") for v in s["E"]]})
    with open(dst, "w") as f:
        json.dump(out, f, separators=(",", ":"))
        f.write("\n")


if __name__ == "__main__":
    main()
