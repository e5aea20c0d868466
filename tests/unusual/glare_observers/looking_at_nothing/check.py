"""Every view of the eye has no term and no UGR (CIE 117's sum is empty)."""


def check(results, out_dir, case_dir):
    failures = []
    eyes = next(s for s in results["surfaces"] if s["name"] == "eyes")
    views = [v for o in eyes["observers"] for v in o["views"]]
    if len(views) != 4:
        failures.append(f"{len(views)} views, expected 4")
    for v in views:
        if v["terms"]:
            failures.append(f"a view has terms: {v['terms']}")
        if v.get("UGR") is not None:
            failures.append(f"a view has UGR {v['UGR']}")
    return failures
