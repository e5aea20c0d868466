"""Reduces a `reference` run's results.json to what `luxgrid diff` compares (tests/rooms/README.md):
the format, the version that wrote it, and per surface its name, points, active flags and E, to 7
significant digits (5e-8 relative, far below any promise) and points to 1e-7 m.

With a finer reflected light (the CSV `bench/hall_reference` writes for the same project at
`reference` and a smaller patch size, PATCH_SIZE_M), each active point's E is the run's E_direct
plus that CSV's E_indirect instead of the run's own: the reference's reflected light refined once
more, a yardstick finer than the quality it measures.

  python3 tests/rooms/reduce_reference.py RUN/results.json tests/rooms/<room>/reference.json \\
      [FINER.csv PATCH_SIZE_M]"""
import csv
import json
import sys


def finer_indirect(path):
    """(surface, point index) -> maintained E_indirect in lx, from hall_reference's CSV."""
    with open(path) as f:
        return {(row["surface"], int(row["i"])): float(row["E_indirect_maintained_lx"])
                for row in csv.DictReader(f)}


def main():
    if len(sys.argv) not in (3, 5):
        sys.exit(__doc__)
    src, dst = sys.argv[1:3]
    finer = finer_indirect(sys.argv[3]) if len(sys.argv) == 5 else None
    r = json.load(open(src))
    out = {"format": r["format"], "luxgrid_version": r.get("luxgrid_version"),
           "quality": r.get("quality"), "surfaces": []}
    if finer is not None:
        out["reflected_light_patch_size_m"] = float(sys.argv[4])
    for s in r["surfaces"]:
        active = s.get("active", [True] * len(s["E"]))
        E = list(s["E"])
        if finer is not None:
            for i, on in enumerate(active):
                if on:
                    E[i] = s["E_direct"][i] + finer[(s["name"], i)]
        out["surfaces"].append({
            "name": s["name"],
            "points": [[round(v, 7) for v in p] for p in s["points"]],
            "active": active,
            "E": [float(f"{v:.7g}") for v in E]})
    with open(dst, "w") as f:
        json.dump(out, f, separators=(",", ":"))
        f.write("\n")


if __name__ == "__main__":
    main()
