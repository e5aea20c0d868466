"""luxgrid.calc against the CLI: the same values to the bit, the same results.json, the same
outputs and messages."""
import json
import os

import numpy as np
import pytest

import luxgrid
from conftest import OFFICE, office_copy, run_cli


def bits(a):
    """The bit patterns of a float64 array: equal bits, not merely equal values (-0.0, NaN)."""
    return np.ascontiguousarray(a, dtype=np.float64).view(np.uint64)


@pytest.fixture(scope="module")
def office_cli(tmp_path_factory):
    out = tmp_path_factory.mktemp("cli") / "office.out"
    run_cli("calc", OFFICE, "-o", out, "--arrays", "npy")
    with open(out / "results.json") as f:
        text = f.read()
    return out, text, json.loads(text)


@pytest.fixture(scope="module")
def office():
    return luxgrid.calc(OFFICE)


def test_arrays_equal_the_cli_bit_for_bit(office, office_cli):
    out, _, doc = office_cli
    assert list(office.surfaces) == [s["name"] for s in doc["surfaces"]]
    for s in doc["surfaces"]:
        r = office.surfaces[s["name"]]
        for key in ("E", "E_direct", "E_indirect", "points", "normals"):
            a = getattr(r, key)
            assert a.dtype == np.float64 and not a.flags.writeable
            np.testing.assert_array_equal(bits(a), bits(np.array(s[key], dtype=np.float64)),
                                          err_msg=f"{s['name']}.{key}")
        assert r.active.dtype == np.bool_
        np.testing.assert_array_equal(r.active, np.array(s["active"], dtype=bool))
        assert r.stats == s["stats"]
        # The CLI's .npy (written by its own writer): x, y, z, E per point.
        npy = np.load(out / (s["name"].replace(" ", "_") + ".npy"))
        np.testing.assert_array_equal(bits(npy[:, :3]), bits(r.points))
        np.testing.assert_array_equal(bits(npy[:, 3]), bits(r.E))


def test_to_json_is_the_cli_results_json(office, office_cli):
    # The same writer: the very bytes, the plan's timings excepted (none are in results.json).
    _, text, doc = office_cli
    assert office.to_json() == text
    assert office.to_dict() == doc
    assert office.requirements_met == doc["requirements_met"]
    assert [dict(r, surface=None) for r in office.requirements] == \
        [dict(r, surface=None) for s in doc["surfaces"] for r in s.get("requirements", [])]
    assert office.plan == doc["plan"]
    assert office.warnings == doc["warnings"] == []


def test_arrays_outlive_the_results(office):
    # The arrays view the calculation's memory and keep it alive (no copy was made).
    e = luxgrid.calc(OFFICE, quality="draft").surfaces["workplane"].E
    import gc
    gc.collect()
    assert e.base is not None and np.all(e > 0)


def test_a_dict_calculates_as_the_file(office, tmp_path, monkeypatch):
    with open(OFFICE) as f:
        document = json.load(f)
    base = os.path.dirname(OFFICE)
    for r in (luxgrid.calc(document, base_dir=base), luxgrid.calc(luxgrid.load(OFFICE))):
        for name, s in office.surfaces.items():
            np.testing.assert_array_equal(bits(r.surfaces[name].E), bits(s.E))
    # Relative photometry paths are resolved against base_dir, by default the working folder.
    monkeypatch.chdir(tmp_path)
    with pytest.raises(luxgrid.InputError) as e:
        luxgrid.calc(document)
    assert e.value.file == "<dict>" and e.value.pointer == "/photometry/mirel"
    assert "photometry file not found: photometry/zumtobel_mirel_isym4.ldt" in str(e.value)


def test_write_outputs_writes_what_the_cli_writes(office, office_cli, tmp_path):
    out, text, _ = office_cli
    assert luxgrid.write_outputs(office, tmp_path / "out") == []
    for name in sorted(os.listdir(out)):
        if name.endswith((".csv", ".png", ".json")) and name != "timing.json":
            assert (tmp_path / "out" / name).read_bytes() == (out / name).read_bytes(), name
    # The CLI's rule: a folder holding a user's file is not replaced, and the file stays.
    mine = tmp_path / "mine"
    mine.mkdir()
    (mine / "notes.txt").write_text("keep me")
    with pytest.raises(luxgrid.InputError):
        luxgrid.write_outputs(office, mine)
    assert (mine / "notes.txt").read_text() == "keep me" and os.listdir(mine) == ["notes.txt"]


def place_and_message(tmp_path, document_text):
    path = tmp_path / "bad.json"
    path.write_text(document_text)
    cli = run_cli("calc", path, "-o", tmp_path / "out", check=False)
    assert cli.returncode == 2
    with pytest.raises(luxgrid.InputError) as e:
        luxgrid.calc(str(path))
    # The CLI's message, to the character.
    assert "luxgrid: error: " + str(e.value) + "\n" == cli.stderr
    return e.value


def test_input_errors_carry_their_place(tmp_path):
    with open(OFFICE) as f:
        lines = f.read().split("\n")
    row = next(k for k, line in enumerate(lines) if '"height": 2.8' in line)
    lines[row] = lines[row].replace('"height": 2.8', '"height": -2.8')
    office_copy(tmp_path)
    e = place_and_message(tmp_path, "\n".join(lines))
    # A value's place: the project named by its file's name (as the CLI does), line, pointer.
    assert (e.file, e.line, e.pointer) == ("bad.json", row + 1, "/rooms/0/height")
    assert str(e).startswith(f"bad.json:{row + 1}:")
    assert e.message in str(e)
    # A syntax error: the line and column, no pointer.
    e = place_and_message(tmp_path, '{\n  "format": "luxgrid-project/1",\n  "name": \n}\n')
    assert (e.line, e.column, e.pointer) == (4, 1, None)


def test_photometry_errors_name_the_file_and_line(tmp_path):
    office_copy(tmp_path)
    ldt = tmp_path / "photometry" / "zumtobel_mirel_isym4.ldt"
    lines = ldt.read_text(errors="replace").split("\n")
    lines[2] = "x"  # line 3: the type indicator, a number
    ldt.write_text("\n".join(lines))
    with pytest.raises(luxgrid.InputError) as e:
        luxgrid.info(ldt)
    assert (e.value.file, e.value.line) == (str(ldt), 3)
    cli = run_cli("info", ldt, check=False)
    assert cli.stderr == "luxgrid: error: " + str(e.value) + "\n"


def test_info_is_the_cli_json():
    ldt = os.path.join(os.path.dirname(OFFICE), "photometry", "zumtobel_mirel_isym4.ldt")
    cli = json.loads(run_cli("info", ldt, "--json", "--ugr", "--at", "0,30").stdout)
    assert luxgrid.info(ldt, at=[(0, 30)], ugr=True) == cli


def test_errors_are_python_exceptions():
    assert issubclass(luxgrid.InputError, ValueError)
    assert issubclass(luxgrid.CalculationError, RuntimeError)
    with pytest.raises(luxgrid.InputError, match="quality: expected draft"):
        luxgrid.calc(OFFICE, quality="fast")
    with pytest.raises(luxgrid.InputError, match="threads: expected"):
        luxgrid.set_threads(0)
