"""A quality's promise on one room (ctest promise_<room>_<quality>, tests/rooms/README.md): runs
`luxgrid calc PROJECT --quality Q` in a temporary folder and holds it to the room's stored
reference with `luxgrid diff --promise --tol TOL` (every point brighter than 1 % of its surface's
maximum within TOL of the reference), to the plan's own estimates: none above the promise (a
run that keeps the promise without knowing it still warns its user), and to no warning at all (a
refinement a limit stopped where the estimate needed it warns too).

  python3 check_promise.py LUXGRID PROJECT REFERENCE QUALITY TOL

Exit 0 when both hold, 1 when either fails (the diff's table and the estimates say where), 2 on a
run that did not complete. Prints the CPU time of the calculation (user + system of the child)."""
import json
import os
import resource
import subprocess
import sys
import tempfile


def main():
    luxgrid, project, reference, quality, tol = sys.argv[1:6]
    with tempfile.TemporaryDirectory(prefix="luxgrid-promise-") as tmp:
        out = os.path.join(tmp, "out")
        t0 = resource.getrusage(resource.RUSAGE_CHILDREN)
        calc = subprocess.run([luxgrid, "calc", project, "--quality", quality, "-o", out,
                               "--no-report"], capture_output=True, text=True)
        t1 = resource.getrusage(resource.RUSAGE_CHILDREN)
        cpu = (t1.ru_utime - t0.ru_utime) + (t1.ru_stime - t0.ru_stime)
        print(f"luxgrid calc {project} --quality {quality}: exit {calc.returncode}, "
              f"{cpu:.2f} s CPU")
        if calc.returncode != 0:
            print(calc.stdout + calc.stderr)
            return 2
        diff = subprocess.run([luxgrid, "diff", out, reference, "--promise", "--tol", tol],
                              capture_output=True, text=True)
        print(diff.stdout + diff.stderr, end="")
        if diff.returncode not in (0, 1):
            return 2
        results = json.load(open(os.path.join(out, "results.json")))
        plan = results["plan"]
        promise = plan.get("promise", 0.0)
        over = [e for e in plan.get("estimates", []) if promise > 0 and e["total"] > promise]
        for e in over:
            print(f"FAIL: surface '{e['surface']}': the plan's estimate {100 * e['total']:.2f} % "
                  f"exceeds {quality}'s promise of {100 * promise:g} %")
        warnings = results.get("warnings", [])
        for w in warnings:
            print(f"FAIL: the run warns: {w}")
        return 1 if diff.returncode == 1 or over or warnings else 0


if __name__ == "__main__":
    sys.exit(main())
