"""luxgrid.sweep on a LocalCluster of 2 worker processes: rows equal to CLI runs of the same
variants, a failing variant reported in its row, bad variants refused before anything runs."""
import csv
import json
import os
import subprocess
import sys

import pytest

import luxgrid
from conftest import OFFICE, SOURCE_DIR, office_copy, run_cli

MERGE = os.path.join(SOURCE_DIR, "examples", "python", "merge_results.py")


def office_document():
    with open(OFFICE) as f:
        document = json.load(f)
    # "scene" stated, so that a variant may switch to the emergency scene (which the office,
    # with no emergency luminaires, cannot calculate: a variant that loads but fails).
    document["settings"]["scene"] = "normal"
    document["settings"]["quality"] = "draft"
    return document


VARIANTS = [
    {"/rooms/0/height": 2.8, "/luminaires/0/array/origin": [1.0, 1.0, 2.8]},
    {"/rooms/0/height": 3.2, "/luminaires/0/array/origin": [1.0, 1.0, 3.2]},
    {"/settings/scene": "emergency"},
    {"/luminaires/0/array/spacing": [2.0, 1.8], "/rooms/0/reflectance/walls": 0.3},
]


class NoClient:
    """A client that must not be used: a sweep with a bad variant submits nothing."""

    def map(self, *args, **kwargs):
        raise AssertionError("submitted although a variant was bad")


def test_rows_equal_cli_runs_and_a_failure_stays_in_its_row(dask_client, tmp_path):
    base = office_document()
    project = luxgrid.Project(base, os.path.dirname(OFFICE))
    frame = luxgrid.sweep(project, VARIANTS, client=dask_client)
    assert len(frame) == len(VARIANTS)
    assert list(frame.columns[:5]) == ["/rooms/0/height", "/luminaires/0/array/origin",
                                       "/settings/scene", "/luminaires/0/array/spacing",
                                       "/rooms/0/reflectance/walls"]
    # A pointer a variant leaves out holds the project's value.
    assert frame.loc[0, "/settings/scene"] == "normal"
    assert frame.loc[2, "/rooms/0/height"] == 2.8
    assert frame.columns[-1] == "error"
    # The failing variant: its error, the CLI's message; the others calculated.
    assert "the emergency scene has no light" in frame.loc[2, "error"]
    assert frame["error"].isna().tolist() == [False if k == 2 else True for k in range(4)]
    for k, variant in enumerate(VARIANTS):
        document = luxgrid.Project(base).with_values(variant).document
        folder = tmp_path / f"v{k}"
        folder.mkdir()
        path = office_copy(folder, document)
        cli = run_cli("calc", path, "-o", folder / "out", check=False)
        if k == 2:
            assert cli.returncode == 2
            assert cli.stderr.startswith("luxgrid: error: project.json: ")
            assert frame.loc[k, "error"] == cli.stderr[len("luxgrid: error: "):].strip() \
                .replace("project.json", "<dict>")
            continue
        with open(folder / "out" / "results.json") as f:
            doc = json.load(f)
        row = frame.loc[k]
        for s in doc["surfaces"]:
            for stat, value in s["stats"].items():
                assert row[f"{s['name']}.{stat}"] == value, (k, s["name"], stat)
            if "UGR_max" in s:
                assert row[f"{s['name']}.UGR_max"] == s["UGR_max"]
            for r in s.get("requirements", []):
                assert row[f"{s['name']}.{r['quantity']}.met"] == r["met"]
                assert row[f"{s['name']}.{r['quantity']}.achieved"] == r["achieved"]
        assert row["requirements_met"] == doc["requirements_met"]
        assert row["run_time_s"] > 0 and row["office.W_per_m2"] > 0
    # The CLI-only path: the merge of the runs' results.json holds the sweep's values.
    subprocess.run([sys.executable, MERGE, tmp_path / "table.csv", tmp_path], check=True,
                   capture_output=True)
    with open(tmp_path / "table.csv") as f:
        merged = list(csv.DictReader(f))
    assert [m["run"] for m in merged] == [str(tmp_path / f"v{k}" / "out") for k in (0, 1, 3)]
    for m, k in zip(merged, (0, 1, 3)):
        for column, text in m.items():
            if column in ("run", "project", "quality"):
                continue
            value = frame.loc[k, column]
            assert text == (str(value) if not isinstance(value, float) else repr(value)), column


def test_bad_variants_are_refused_before_anything_runs():
    project = luxgrid.Project(office_document(), os.path.dirname(OFFICE))
    with pytest.raises(luxgrid.InputError) as e:
        luxgrid.sweep(project, [VARIANTS[0], {"/rooms/0/hieght": 3.0}], client=NoClient())
    assert e.value.pointer == "/rooms/0/hieght" and str(e.value).startswith("variant 1: ")
    with pytest.raises(luxgrid.InputError) as e:
        luxgrid.sweep(project, [{"/rooms/0/height": -1.0}, VARIANTS[0]], client=NoClient())
    assert e.value.pointer == "/rooms/0/height" and e.value.file == "<dict>"
    assert str(e.value).startswith('variant 0 {"/rooms/0/height": -1.0}: <dict> /rooms/0/height')
