"""The examples under examples/python that run quickly, and the installed package."""
import glob
import json
import os
import shutil
import subprocess
import sys

from conftest import SOURCE_DIR, run_cli

EXAMPLES = os.path.join(SOURCE_DIR, "examples")


def test_photometry_survey_holds_the_cli_tables(tmp_path):
    # A folder with the example photometry in two sub-folders and a file luxgrid cannot read.
    files = sorted(glob.glob(os.path.join(EXAMPLES, "*", "photometry", "*")))[:2]
    for k, f in enumerate(files):
        (tmp_path / f"lum{k}").mkdir()
        shutil.copy(f, tmp_path / f"lum{k}")
    (tmp_path / "bad.ies").write_text("not a photometric file\n")
    out = tmp_path / "survey.csv"
    subprocess.run([sys.executable, os.path.join(EXAMPLES, "python", "photometry_survey.py"),
                    tmp_path, "-o", out], check=True, capture_output=True)
    import pandas
    frame = pandas.read_csv(out, float_precision="round_trip")
    # The unreadable file is listed with its error; the others' rows follow the CLI.
    assert frame[frame.file == "bad.ies"].error.str.contains("bad.ies").all()
    names = [os.path.join(f"lum{k}", os.path.basename(f)) for k, f in enumerate(files)]
    assert sorted(frame.file.unique()) == sorted(names + ["bad.ies"])
    for f, name in zip(files, names):
        table = json.loads(run_cli("info", f, "--json", "--ugr").stdout)["ugr_table"]
        rows = frame[frame.file == name]
        assert len(rows) == len(table["rooms"]) * len(table["reflectances"])
        for room in table["rooms"]:
            for k, (c, w, fl) in enumerate(table["reflectances"]):
                r = rows[(rows.X_H == room["x_H"]) & (rows.Y_H == room["y_H"]) &
                         (rows.ceiling == c) & (rows.walls == w) & (rows.floor == fl)]
                assert len(r) == 1
                for side in ("crosswise", "endwise"):
                    expected = room[side][k]
                    got = r[f"UGR_{side}"].iloc[0]
                    assert (got == expected) or (expected is None and got != got)


def test_cmake_install_puts_the_package_into_site_packages(tmp_path):
    build = os.environ.get("LUXGRID_BUILD_DIR", os.path.join(SOURCE_DIR, "build"))
    subprocess.run(["cmake", "--install", build], check=True, capture_output=True,
                   env=dict(os.environ, DESTDIR=str(tmp_path)))
    modules = glob.glob(str(tmp_path / "**" / "luxgrid" / "_luxgrid*.so"), recursive=True)
    assert len(modules) == 1
    package = os.path.dirname(modules[0])
    assert os.path.isfile(os.path.join(package, "__init__.py"))
    assert os.path.isfile(os.path.join(package, "sweep.py"))
    # The site-packages folder of the interpreter the module was built for, under DESTDIR.
    site = os.path.dirname(package)
    assert site[len(str(tmp_path)):] in sys.path
    p = subprocess.run([sys.executable, "-c", "import luxgrid; print(luxgrid.__file__)"],
                       env=dict(os.environ, PYTHONPATH=site), capture_output=True, text=True,
                       check=True)
    assert p.stdout.strip() == os.path.join(package, "__init__.py")
