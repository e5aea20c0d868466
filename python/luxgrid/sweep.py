"""Parametric studies on Dask: many variants of one project, each calculated as a task on a
dask.distributed cluster, gathered into one pandas DataFrame (docs/python.md, "Sweeps")."""
import concurrent.futures
import functools
import json
import os
import time

from . import _luxgrid
from .project import PointerError, Project


def sweep(project, variants, client=None, quality=None, scene=None, base_dir=None, workers=None,
          threads=1):
    """Calculate every variant of `project` on Dask and return a DataFrame, one row per variant.

    project: a path, a dict (with base_dir, as for calc) or a Project. variants: dicts of JSON
    pointer to value, e.g. {"/rooms/0/height": 2.8, "/luminaires/0/array/spacing": [2, 2]}.
    Every variant is checked before anything is submitted: each pointer must exist in the project
    and the variant must load (a bad one raises InputError naming the variant and the pointer).
    client: a dask.distributed Client; None starts a LocalCluster of `workers` worker processes
    (default: one per core) with one thread each, and closes it afterwards. threads: the thread
    cap of each calculation (set_threads) in the workers.

    Columns: the pointers (the variant's value, or the project's where a variant leaves one out);
    "<surface>.<statistic>" (Emin, Eavg, Emax, U0, Ud; UGR_max of observers surfaces);
    "<surface>.<quantity>.achieved" and ".met" per requirement, and "requirements_met";
    "<room>.W_per_m2" and "<room>.W_per_m2_per_100lx"; "warnings"; "run_time_s"; "error" (None,
    or the message of a variant that failed: its other columns are then empty).
    """
    import pandas

    base = Project.of(project, base_dir)
    variants = [dict(v) for v in variants]
    texts = _checked_texts(base, variants)
    own_cluster = None
    if client is None:
        from distributed import Client, LocalCluster
        import logging
        own_cluster = LocalCluster(n_workers=workers or os.cpu_count(), threads_per_worker=1,
                                   processes=True, dashboard_address=None,
                                   silence_logs=logging.ERROR)
        client = Client(own_cluster)
    try:
        task = functools.partial(_run_variant, name=base.name, base_dir=base.base_dir,
                                 quality=quality, scene=scene, threads=threads)
        futures = client.map(task, texts, pure=False)
        rows = []
        for future in futures:
            # A worker that died (out of memory, killed) fails its variant, not the sweep.
            try:
                rows.append(future.result())
            except Exception as e:  # noqa: BLE001 (reported in the row)
                rows.append({"error": f"{type(e).__name__}: {e}"})
    finally:
        if own_cluster is not None:
            client.close()
            own_cluster.close()
    pointers = []
    for v in variants:
        pointers += [p for p in v if p not in pointers]
    table = []
    for v, row in zip(variants, rows):
        params = {p: v[p] if p in v else base.get(p) for p in pointers}
        table.append({**params, **row})
    frame = pandas.DataFrame(table)
    # The error column last (a failed variant's row has only it and the run time).
    return frame[[c for c in frame.columns if c != "error"] + ["error"]]


def _input_error(message, pointer=None, cause=None):
    error = _luxgrid.InputError(message)
    error.file = getattr(cause, "file", None)
    error.line = getattr(cause, "line", None)
    error.column = getattr(cause, "column", None)
    error.pointer = pointer if pointer is not None else getattr(cause, "pointer", None)
    error.message = message
    return error


def _checked_texts(base, variants):
    """Each variant's project text, once every variant has been checked (pointers, then loading
    in parallel: the loader releases the GIL)."""
    texts = []
    for k, v in enumerate(variants):
        try:
            texts.append(base.with_values(v).source()[0])
        except PointerError as e:
            raise _input_error(f"variant {k}: {e.args[0]}", e.pointer) from None
        except ValueError as e:  # NaN or infinity: not JSON
            raise _input_error(f"variant {k}: {e}") from None
    with concurrent.futures.ThreadPoolExecutor(max_workers=os.cpu_count() or 1) as pool:
        checks = list(pool.map(
            lambda t: _check(t, base.name, base.base_dir), texts))
    for k, error in enumerate(checks):
        if error is not None:
            raise _input_error(f"variant {k} {json.dumps(variants[k])}: {error}",
                               cause=error) from error
    return texts


def _check(text, name, base_dir):
    try:
        _luxgrid.check_text(text, name, base_dir)
        return None
    except _luxgrid.InputError as e:
        return e


def _run_variant(text, name, base_dir, quality, scene, threads):
    """One variant on a worker: its row without the parameters."""
    if threads != _luxgrid.threads():
        _luxgrid.set_threads(threads)
    t0 = time.perf_counter()
    try:
        results = _luxgrid.calc_text(text, name, base_dir, quality, scene)
    except Exception as e:  # noqa: BLE001 (the variant's error, the sweep goes on)
        message = str(e) if isinstance(e, (_luxgrid.InputError, _luxgrid.CalculationError)) \
            else f"{type(e).__name__}: {e}"
        return {"run_time_s": time.perf_counter() - t0, "error": message}
    row = summary_row(results)
    row["run_time_s"] = time.perf_counter() - t0
    row["error"] = None
    return row


def summary_row(results):
    """A calculation's statistics, requirement results and energy figures as one flat dict."""
    row = {}
    for name, surface in results.surfaces.items():
        for stat, value in surface.stats.items():
            row[f"{name}.{stat}"] = value
        if surface.UGR_max is not None:
            row[f"{name}.UGR_max"] = surface.UGR_max
    for check in results.requirements:
        key = f"{check['surface']}.{check['quantity']}"
        if f"{key}.met" in row:  # the same quantity again under another role
            key += f"[{check['role']}]"
        row[f"{key}.achieved"] = check["achieved"] if check["calculated"] else None
        row[f"{key}.met"] = check["met"]
    row["requirements_met"] = results.requirements_met
    for room in results.energy:
        row[f"{room['room']}.W_per_m2"] = room["W_per_m2"]
        row[f"{room['room']}.W_per_m2_per_100lx"] = room["W_per_m2_per_100lx"]
    row["warnings"] = "\n".join(results.warnings)
    return row
