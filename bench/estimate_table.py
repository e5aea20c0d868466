"""The plan's own estimate against the measured error, per surface, as a markdown table
(docs/accuracy.md, "How close the estimate is to the measured error").

  python3 bench/estimate_table.py LUXGRID RUN REFERENCE

RUN is the folder of a `luxgrid calc` run, REFERENCE a results.json or a stored reference
(tests/rooms/*/reference.json). The measured error is `luxgrid diff RUN/results.json REFERENCE
--promise`'s largest error per surface (points brighter than 1 % of the surface's largest E,
direct and reflected light); the estimate is the plan's total (`plan.estimates[].total`). A ratio
outside [0.5, 2] is marked "outside 2x", and an estimate below a measured error above the
promise "below, promise broken"."""
import json
import re
import subprocess
import sys


def measured_errors(luxgrid, run, reference):
    """surface name -> largest relative error, from luxgrid diff's table."""
    out = subprocess.run([luxgrid, "diff", run + "/results.json", reference, "--promise"],
                         capture_output=True, text=True).stdout
    errors = {}
    for line in out.splitlines():
        m = re.match(r"^(\S.*?)\s+\d+\s+\d+\s+([0-9.]+)%", line)
        if m:
            errors[m.group(1)] = float(m.group(2)) / 100
    return errors


def percent(x):
    return f"{100 * x:.2f} %"


def main():
    if len(sys.argv) != 4:
        sys.exit(__doc__)
    luxgrid, run, reference = sys.argv[1:4]
    plan = json.load(open(run + "/results.json"))["plan"]
    measured = measured_errors(luxgrid, run, reference)
    promise = plan.get("promise", 0.0)
    print("| surface | d1 | order | reflected light: patch size + bounces | total estimate | "
          "measured | ratio |")
    print("|---|---:|---:|---:|---:|---:|---:|")
    for e in plan["estimates"]:
        m = measured[e["surface"]]
        ratio = e["total"] / m if m > 0 else float("inf")
        mark = ""
        if e["total"] < m and m > promise:
            mark = " (below, promise broken)"
        elif not 0.5 <= ratio <= 2.0:
            mark = " (outside 2x)"
        print(f"| {e['surface']} | {percent(e['patch_difference'])} | {e['patch_order']:.2f} | "
              f"{percent(e['patch_size'] + e['bounces'])} | {percent(e['total'])} | "
              f"{percent(m)} | {ratio:.2f}{mark} |")


if __name__ == "__main__":
    main()
