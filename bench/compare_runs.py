#!/ usr / bin / env python3
"""Measured error of one luxgrid run against another, per surface, as the promise counts it.

    python3 bench/compare_runs.py RUN_DIR REFERENCE_DIR

Both directories are `luxgrid calc -o` outputs of the same project (one CSV per surface). For
each surface: the largest |E - E_ref| / max(E_ref, 1 % of the surface's largest E_ref) over its
active points (docs/accuracy.md: the promise covers points brighter than 1 % of their surface's
maximum; dimmer ones count by their absolute error), the same for the reflected part alone
(relative to the same E_ref), and the run's own estimates from its results.json (plan.estimates:
the total and the patch-size part), with the ratio estimate / measured. Prints one line per
surface and the worst line. Standard library only (CI has no numpy).
"""
import csv
import json
import os
import sys

FLOOR = 0.01


def read_surface(path):
    rows = []
    with open(path, newline="") as f:
        for row in csv.DictReader(f):
            if row["active"] != "true":
                rows.append(None)
                continue
            rows.append((float(row["E_maintained_lx"]), float(row["E_indirect_maintained_lx"])))
    return rows


def surfaces_of(run_dir):
    results = json.load(open(os.path.join(run_dir, "results.json")))
    return results


def measured(run, ref):
    e_max = max(r[0] for r in ref if r is not None)
    floor = FLOOR * e_max
    worst = worst_ind = 0.0
    for a, b in zip(run, ref):
        if a is None or b is None:
            continue
        d = max(b[0], floor)
        if d <= 0.0:
            continue
        worst = max(worst, abs(a[0] - b[0]) / d)
        worst_ind = max(worst_ind, abs(a[1] - b[1]) / d)
    return worst, worst_ind


def file_name(surface):
    return "".join(c if c.isalnum() or c in "-_" else "_" for c in surface) + ".csv"


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    run_dir, ref_dir = sys.argv[1:]
    results = surfaces_of(run_dir)
    estimates = {e["surface"]: e for e in results.get("plan", {}).get("estimates", [])}
    print(f"{'surface':20s} {'measured':>9s} {'refl.':>7s} {'est.':>7s} {'patch':>7s} {'ratio':>6s}")
    worst = None
    for s in results["surfaces"]:
        name = s["name"]
        f = file_name(name)
        a = read_surface(os.path.join(run_dir, f))
        b = read_surface(os.path.join(ref_dir, f))
        m, m_ind = measured(a, b)
        e = estimates.get(name, {})
        parts = [e.get(k, 0.0) for k in ("direct", "patch_size", "bounces")]
        total = e.get("total", sum(p for p in parts if p and p > 0.0))
        patch = e.get("patch_size", float("nan"))
        ratio = total / m if m > 0 else float("inf")
        print(f"{name:20s} {100 * m:8.3f}% {100 * m_ind:6.3f}% {100 * total:6.3f}% "
              f"{100 * patch:6.3f}% {ratio:6.2f}")
        if worst is None or m > worst[1]:
            worst = (name, m)
    print(f"worst: {worst[0]} {100 * worst[1]:.3f}%")


if __name__ == "__main__":
    main()
