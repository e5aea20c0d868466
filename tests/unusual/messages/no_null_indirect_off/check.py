"""With reflected light off, the plan's estimates leave out the parts not estimated instead of
writing null (docs/project-format.md, "The plan"); run_corpus.py already refuses any null."""


def check(results, out_dir, case_dir):
    failures = []
    plan = results["plan"]
    if "indirect_run" in plan:
        failures.append("plan.indirect_run present although reflected light did not run")
    for e in plan["estimates"]:
        for key in ("patch_size", "bounces"):
            if key in e:
                failures.append(f"estimates[{e['surface']}].{key} = {e[key]} without reflected light")
        if e.get("total") != e.get("direct"):
            failures.append(f"estimates[{e['surface']}]: total {e.get('total')} is not the direct part")
    return failures
