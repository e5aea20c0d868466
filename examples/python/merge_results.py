#!/usr/bin/env python3
"""Merge the results.json of many `luxgrid calc` runs into one CSV table, one row per run.

    python3 merge_results.py OUT.csv RESULTS [RESULTS ...]

Each RESULTS is a results.json or an output folder holding one (a folder of folders is searched
too: every results.json below it). The columns are those of luxgrid.sweep (docs/python.md):
"run" (the output folder), "project", "quality", "<surface>.<statistic>" (Emin, Eavg, Emax, U0,
Ud; UGR_max of observers surfaces), "<surface>.<quantity>.achieved" and ".met" per requirement,
and "requirements_met". Only the standard library: it runs wherever Python 3 does (a cluster's
login node, without NumPy or pandas). The CLI-only path of docs/python.md, "Beyond one machine"
uses it after a Slurm job array.
"""
import csv
import json
import os
import sys


def results_files(paths):
    for path in paths:
        if os.path.isdir(path):
            for folder, dirs, files in os.walk(path):
                dirs.sort()
                if "results.json" in files:
                    yield os.path.join(folder, "results.json")
        else:
            yield path


def row_of(path):
    with open(path) as f:
        doc = json.load(f)
    row = {"run": os.path.dirname(path) or ".", "project": doc["project"],
           "quality": doc["quality"]}
    for s in doc["surfaces"]:
        for stat, value in s["stats"].items():
            row[f"{s['name']}.{stat}"] = value
        if s.get("UGR_max") is not None:
            row[f"{s['name']}.UGR_max"] = s["UGR_max"]
    for s in doc["surfaces"]:
        for r in s.get("requirements", []):
            key = f"{s['name']}.{r['quantity']}"
            if f"{key}.met" in row:  # the same quantity again under another role
                key += f"[{r['role']}]"
            row[f"{key}.achieved"] = r["achieved"] if r["calculated"] else None
            row[f"{key}.met"] = r["met"]
    row["requirements_met"] = doc.get("requirements_met")
    return row


def merge(out_csv, paths):
    rows = [row_of(p) for p in results_files(paths)]
    columns = []
    for row in rows:
        columns += [c for c in row if c not in columns]
    with open(out_csv, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=columns)
        writer.writeheader()
        for row in rows:
            writer.writerow(row)  # a float as its shortest text that reads back the same
    return len(rows)


if __name__ == "__main__":
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    print(f"{merge(sys.argv[1], sys.argv[2:])} runs merged into {sys.argv[1]}")
