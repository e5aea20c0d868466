"""Shared set-up of the Python package's tests (ctest `python_package`, docs/python.md).

The package under test is the one built in build/python (PYTHONPATH); the CLI it is compared
with is the built `luxgrid` (LUXGRID_BINARY); the examples come from LUXGRID_SOURCE_DIR. Every
test writes under its own temporary folder (pytest's tmp_path).
"""
import json
import os
import shutil
import subprocess

import pytest

SOURCE_DIR = os.path.abspath(os.environ.get("LUXGRID_SOURCE_DIR",
                                            os.path.join(os.path.dirname(__file__), "..", "..")))
CLI = os.path.abspath(os.environ.get("LUXGRID_BINARY", os.path.join(SOURCE_DIR, "build", "luxgrid")))
OFFICE = os.path.join(SOURCE_DIR, "examples", "office", "project.json")


def run_cli(*args, check=True):
    """Runs the CLI on one thread; returns the finished process."""
    p = subprocess.run([CLI, "--threads", "1", *map(str, args)], capture_output=True, text=True)
    if check and p.returncode != 0:
        raise AssertionError(f"luxgrid {' '.join(map(str, args))}: {p.stderr}")
    return p


def office_copy(folder, document=None):
    """The office example (or `document`) as project.json in `folder`, its photometry beside."""
    shutil.copytree(os.path.join(os.path.dirname(OFFICE), "photometry"),
                    os.path.join(folder, "photometry"), dirs_exist_ok=True)
    if document is None:
        with open(OFFICE) as f:
            document = json.load(f)
    path = os.path.join(folder, "project.json")
    with open(path, "w") as f:
        json.dump(document, f, indent=1)
    return path


@pytest.fixture(scope="session")
def dask_client():
    """A LocalCluster of 2 worker processes, one thread each, shared by the sweep tests."""
    distributed = pytest.importorskip("distributed")
    import logging
    cluster = distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                       dashboard_address=None, silence_logs=logging.ERROR)
    client = distributed.Client(cluster)
    yield client
    client.close()
    cluster.close()
