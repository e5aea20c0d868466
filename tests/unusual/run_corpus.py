#!/usr/bin/env python3
"""Runs the corpus of legal but unusual projects (tests/unusual/, format in README.md there).

    run_corpus.py LUXGRID CORPUS_DIR CLASS [CLASS ...]

Each case is a folder CLASS/CASE holding project.json and check.json (and, optionally, check.py,
more project files and photometry). The case folder is copied into a temporary folder of its own,
with the corpus's shared photometry/ merged into its photometry/ folder; `luxgrid calc` runs there, and what check.json states is checked, together with
what holds for every case:
  - the process ends by itself (no signal, within max_seconds) with the expected exit code;
  - a refusal (exit code other than 0) prints one message naming a file of the case;
  - results.json, when written, holds no NaN, no infinity and no null (docs/reliability.md);
  - no file of the case is changed, created or removed outside the output folder.
Every failure of every case is reported; the exit status is non-zero if any case failed.
"""
import hashlib
import importlib.util
import json
import math
import os
import re
import shutil
import subprocess
import sys
import tempfile

CHECK_KEYS = {"what", "source", "args", "exit", "stderr_contains", "stderr_not_contains",
              "warnings_contain", "warnings_not_contain", "no_warnings", "values", "equivalent",
              "max_seconds", "mirror", "flux_balance", "setup", "absolute_project"}


def snapshot(folder, skip):
    """Hash of every file under folder except those under skip."""
    state = {}
    for root, dirs, files in os.walk(folder):
        if os.path.abspath(root).startswith(skip):
            continue
        for name in files:
            path = os.path.join(root, name)
            if os.path.abspath(path).startswith(skip + os.sep):
                continue
            if not os.path.isfile(path):  # a FIFO made by "setup": opening it would block
                state[os.path.relpath(path, folder)] = "not a regular file"
                continue
            with open(path, "rb") as f:
                state[os.path.relpath(path, folder)] = hashlib.sha256(f.read()).hexdigest()
    return state


# Where results.json may hold null (docs/reliability.md): a view's UGR where it has none (no
# luminaire in its field, or outside CIE 117's range), and the surface's UGR_max when no view
# has one.
MAY_BE_NULL = ("/UGR", "/UGR_max")


def bad_number(where, value):
    if value is None and not where.endswith(MAY_BE_NULL):
        return f"null at {where}"
    if isinstance(value, float) and not math.isfinite(value):
        return f"{value} at {where}"
    if isinstance(value, dict):
        for k, v in value.items():
            found = bad_number(f"{where}/{k}", v)
            if found:
                return found
    elif isinstance(value, list):
        for i, v in enumerate(value):
            found = bad_number(f"{where}/{i}", v)
            if found:
                return found
    return None


def reject_constant(name):
    raise ValueError(f"results.json holds {name}")


def run_calc(luxgrid, case_dir, project, out, args, seconds):
    command = [luxgrid, "--threads", "1", "calc", project, "-o", out] + list(args)
    try:
        done = subprocess.run(command, cwd=case_dir, capture_output=True, text=True,
                              errors="replace", timeout=seconds)
    except subprocess.TimeoutExpired:
        return None, "", f"did not finish within {seconds} s: {' '.join(command)}"
    return done.returncode, done.stderr, None


def load_results(out):
    path = os.path.join(out, "results.json")
    if not os.path.exists(path):
        return None, "no results.json written"
    try:
        with open(path) as f:
            return json.load(f, parse_constant=reject_constant), None
    except ValueError as e:
        return None, f"results.json: {e}"


def surface(results, name):
    for s in results.get("surfaces", []):
        if s.get("name") == name:
            return s
    raise KeyError(f"no surface named {name!r} in results.json")


def within(actual, expected, spec):
    tol_rel = spec.get("tol_rel", 0.0)
    tol_abs = spec.get("tol_abs", 0.0)
    return abs(actual - expected) <= tol_abs + tol_rel * abs(expected)


def warnings_text(results):
    return [json.dumps(w) if not isinstance(w, str) else w for w in results.get("warnings", [])]


def mirror_failures(results, spec):
    """Each point of spec["surface"] against the point of spec["image"] at its mirror position in
    the plane spec["axis"] = spec["at"] (matched within 1e-9 m): the fields agree within the
    tolerances."""
    failures = []
    axis = "xyz".index(spec["axis"])
    mine, image = surface(results, spec["surface"]), surface(results, spec["image"])

    def key(p):
        return tuple(round(c, 9) for c in p)

    index = {key(p): i for i, p in enumerate(image["points"])}
    for i, p in enumerate(mine["points"]):
        q = list(p)
        q[axis] = 2.0 * spec["at"] - q[axis]
        j = index.get(key(q))
        if j is None:
            failures.append(f"mirror: {spec['surface']} point {i} {p} has no image in "
                            f"{spec['image']}")
            continue
        for field in spec.get("fields", ["E"]):
            a, b = mine[field][i], image[field][j]
            if not within(a, b, spec):
                failures.append(f"mirror: {spec['surface']}.{field}[{i}] = {a}, "
                                f"{spec['image']}.{field}[{j}] = {b}")
    return failures


def flux_balance_failures(results, spec):
    """The plan's first bounce: the direct flux landing on the rooms' faces equals the flux the
    luminaires send into the rooms (closed rooms lose none), and with "whole": true that equals
    the luminaires' whole flux (every opening inside the rooms)."""
    run = results.get("plan", {}).get("indirect_run")
    if not run:
        return ["flux_balance: results.json has no plan.indirect_run"]
    failures = []
    received, emitted, whole = (run["received_flux_lm"], run["emitted_flux_lm"],
                                run["luminaire_flux_lm"])
    if not within(received, emitted, spec):
        failures.append(f"flux_balance: {received} lm land on the faces of {emitted} lm emitted "
                        f"into the rooms")
    if spec.get("whole") and not within(emitted, whole, spec):
        failures.append(f"flux_balance: {emitted} lm emitted into the rooms of {whole} lm from "
                        f"the luminaires")
    return failures


def check_case(luxgrid, corpus, case_rel):
    failures = []
    with open(os.path.join(corpus, case_rel, "check.json")) as f:
        check = json.load(f)
    unknown = set(check) - CHECK_KEYS
    if unknown:
        return [f"check.json: unknown keys {sorted(unknown)}"]
    if "what" not in check or "source" not in check:
        return ["check.json must say what is unusual (\"what\") and where the check comes from "
                "(\"source\")"]
    seconds = check.get("max_seconds", 60)
    with tempfile.TemporaryDirectory(prefix="luxgrid-unusual-") as tmp:
        case_dir = os.path.join(tmp, "case")
        shutil.copytree(os.path.join(corpus, case_rel), case_dir,
                        ignore=shutil.ignore_patterns("__pycache__", "*.pyc"))
        # The corpus's photometry, shared by the cases, as the case's own photometry/ folder.
        shutil.copytree(os.path.join(corpus, "photometry"), os.path.join(case_dir, "photometry"),
                        dirs_exist_ok=True)
        # Paths a case needs that a folder copy cannot carry: FIFOs and folders, made here.
        for step in check.get("setup", []):
            (kind, rel), = step.items()
            target = os.path.join(case_dir, rel)
            os.makedirs(os.path.dirname(target), exist_ok=True)
            if kind == "mkfifo":
                os.mkfifo(target)
            elif kind == "mkdir":
                os.makedirs(target)
            else:
                return [f"check.json: unknown setup step {kind!r}"]
        out = os.path.join(tmp, "out")
        before = snapshot(tmp, out)
        project = (os.path.join(case_dir, "project.json") if check.get("absolute_project")
                   else "project.json")
        code, stderr, error = run_calc(luxgrid, case_dir, project, out,
                                       check.get("args", []), seconds)
        if error:
            return [error]
        if code < 0:
            return [f"killed by signal {-code}; stderr: {stderr.strip()[-400:]}"]
        expected_exit = check.get("exit", 0)
        if code != expected_exit:
            failures.append(f"exit {code}, expected {expected_exit}; stderr: {stderr.strip()[-600:]}")
        if code != 0:
            names = set()
            for root, _, files in os.walk(case_dir):
                names.update(files)
            if not any(n in stderr for n in names):
                failures.append(f"the refusal names no file of the case: {stderr.strip()[-400:]}")
        for text in check.get("stderr_contains", []):
            if text not in stderr:
                failures.append(f"stderr lacks {text!r}: {stderr.strip()[-600:]}")
        for text in check.get("stderr_not_contains", []):
            if text in stderr:
                failures.append(f"stderr holds {text!r}")
        after = snapshot(tmp, out)
        if after != before:
            changed = sorted(set(before.items()) ^ set(after.items()))
            failures.append(f"files of the case changed: {[c[0] for c in changed][:5]}")
        if code != 0:
            return failures
        results, error = load_results(out)
        if error:
            return failures + [error]
        found = bad_number("", results)
        if found:
            failures.append(f"results.json: {found}")
        warnings = warnings_text(results)
        for text in check.get("warnings_contain", []):
            if not any(text in w for w in warnings):
                failures.append(f"no warning holds {text!r}; warnings: {warnings}")
        for text in check.get("warnings_not_contain", []):
            if any(text in w for w in warnings):
                failures.append(f"a warning holds {text!r}")
        if check.get("no_warnings") and warnings:
            failures.append(f"warnings, expected none: {warnings}")
        for spec in check.get("values", []):
            try:
                s = surface(results, spec["surface"])
                if "stat" in spec:
                    actual = s["stats"][spec["stat"]]
                    label = f"{spec['surface']} {spec['stat']}"
                else:
                    actual = s[spec.get("field", "E")][spec["point"]]
                    label = f"{spec['surface']} {spec.get('field', 'E')}[{spec['point']}]"
            except (KeyError, IndexError) as e:
                failures.append(f"values: {e}")
                continue
            if not within(actual, spec["expected"], spec):
                failures.append(f"{label} = {actual}, expected {spec['expected']} "
                                f"(tol_rel {spec.get('tol_rel', 0)}, tol_abs {spec.get('tol_abs', 0)})")
        for spec in check.get("equivalent", []):
            other_out = os.path.join(tmp, "out_" + re.sub(r"\W", "_", spec["project"]))
            code2, stderr2, error2 = run_calc(luxgrid, case_dir, spec["project"], other_out,
                                              spec.get("args", check.get("args", [])), seconds)
            if error2 or code2 != 0:
                failures.append(f"equivalent project {spec['project']}: exit {code2} {error2 or ''} "
                                f"{stderr2.strip()[-400:]}")
                continue
            other, error2 = load_results(other_out)
            if error2:
                failures.append(f"equivalent project {spec['project']}: {error2}")
                continue
            for mine, theirs in spec["surfaces"].items():
                for field in spec.get("fields", ["E"]):
                    try:
                        a = surface(results, mine)[field]
                        b = surface(other, theirs)[field]
                    except KeyError as e:
                        failures.append(f"equivalent: {e}")
                        continue
                    if len(a) != len(b):
                        failures.append(f"{mine}.{field}: {len(a)} points, {spec['project']} "
                                        f"{theirs}: {len(b)}")
                        continue
                    worst = max(range(len(a)), key=lambda i: abs(a[i] - b[i]) -
                                spec.get("tol_rel", 0) * abs(b[i]), default=None)
                    if worst is not None and not within(a[worst], b[worst], spec):
                        failures.append(f"{mine}.{field}[{worst}] = {a[worst]}, {spec['project']} "
                                        f"{theirs}.{field}[{worst}] = {b[worst]}")
        for spec in check.get("mirror", []):
            try:
                failures += mirror_failures(results, spec)
            except KeyError as e:
                failures.append(f"mirror: {e}")
        if "flux_balance" in check:
            failures += flux_balance_failures(results, check["flux_balance"])
        script = os.path.join(case_dir, "check.py")
        if os.path.exists(script):
            # A class may share its checks in a module of its own folder (workplane_borders/
            # active_points.py): check.py imports it by name, from the corpus (read only: no
            # bytecode is written into it).
            class_dir = os.path.join(corpus, os.path.dirname(case_rel))
            sys.dont_write_bytecode = True
            if class_dir not in sys.path:
                sys.path.insert(0, class_dir)
            module_spec = importlib.util.spec_from_file_location("case_check", script)
            module = importlib.util.module_from_spec(module_spec)
            module_spec.loader.exec_module(module)
            failures += module.check(results, out, case_dir)
    return failures


def main():
    if len(sys.argv) < 4:
        sys.exit(__doc__)
    luxgrid = os.path.abspath(sys.argv[1])
    corpus = os.path.abspath(sys.argv[2])
    cases = []
    for cls in sys.argv[3:]:
        for case in sorted(os.listdir(os.path.join(corpus, cls))):
            if os.path.exists(os.path.join(corpus, cls, case, "check.json")):
                cases.append(os.path.join(cls, case))
    failed = 0
    for case in cases:
        try:
            failures = check_case(luxgrid, corpus, case)
        except Exception as e:  # a broken check.json or check.py is a failure of its case
            failures = [f"{type(e).__name__}: {e}"]
        if failures:
            failed += 1
            print(f"FAIL {case}")
            for f in failures:
                print(f"    {f}")
        else:
            print(f"ok   {case}")
    print(f"{len(cases) - failed} of {len(cases)} cases passed")
    sys.exit(1 if failed or not cases else 0)


if __name__ == "__main__":
    main()
