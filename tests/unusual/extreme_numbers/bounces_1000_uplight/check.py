"""The 1000-bounce run against its 500-bounce equivalent (check.json "equivalent"): the same mesh
(patch size, patches, refinements) and a finite, zero residual: every bounce after about 700
carries less flux than the smallest double (0.3^700 < 1e-308), so nothing is left unfollowed."""
import json
import os


def check(results, out_dir, case_dir):
    failures = []
    # run_corpus.py writes the equivalent project's results next to this case's (out_<name>).
    with open(os.path.join(os.path.dirname(out_dir), "out_equivalent_json", "results.json")) as f:
        other = json.load(f)
    mine, theirs = results["plan"]["indirect_run"], other["plan"]["indirect_run"]
    for key in ("patch_size_m", "patches", "refined_patches"):
        if mine[key] != theirs[key]:
            failures.append(f"indirect_run.{key}: {mine[key]} at 1000 bounces, {theirs[key]} at 500")
    if len(results["plan"]["refinements"]) != len(other["plan"]["refinements"]):
        failures.append("a different number of patch-size refinements than at 500 bounces")
    if mine.get("residual") != 0.0:
        failures.append(f"residual {mine.get('residual')}, expected 0 (every later bounce underflows)")
    if mine["bounces_run"] != 1000:
        failures.append(f"bounces_run {mine['bounces_run']}, expected 1000")
    return failures
