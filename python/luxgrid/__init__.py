"""luxgrid from Python: calculate lighting projects and sweep their parameters (docs/python.md).

A thin layer over the C++ library that the `luxgrid` command runs: the compiled module
`_luxgrid` beside this file loads, calculates and writes outputs exactly as `luxgrid calc` does;
this package adds the Python-side conveniences (projects as dicts, JSON pointers, the Dask
sweep). Importing it imports neither NumPy nor pandas nor Dask; they are loaded when used.
"""
import os

from . import _luxgrid
from ._luxgrid import CalculationError, InputError, Results, Surface, __version__  # noqa: F401
from .project import Project, load  # noqa: F401
from .sweep import sweep  # noqa: F401

__all__ = ["calc", "load", "info", "write_outputs", "sweep", "set_threads", "threads", "Project",
           "Results", "Surface", "InputError", "CalculationError", "__version__"]


def calc(project, quality=None, scene=None, base_dir=None):
    """Calculate a project and return its Results.

    project: a path (str or os.PathLike) to a project file, loaded as `luxgrid calc` loads it;
    a dict (the project document); or a Project from load(). quality: "draft", "standard",
    "high" or "reference" overrides settings.quality; scene: "normal" or "emergency" overrides
    settings.scene. base_dir: where a dict's relative photometry paths are resolved (default:
    the current working directory; docs/python.md, "Projects as dicts"); for a path or a Project
    it is the project file's folder and base_dir must be None.

    The GIL is released while it calculates; set_threads() caps its threads. Bad input raises
    InputError, a calculation that cannot complete CalculationError.
    """
    if isinstance(project, (str, os.PathLike)):
        if base_dir is not None:
            raise TypeError("base_dir applies to a project given as a dict, not to a file")
        return _luxgrid.calc_file(os.fspath(project), quality, scene)
    text, label, folder = Project.of(project, base_dir).source()
    return _luxgrid.calc_text(text, label, folder, quality, scene)


def info(photometry_file, at=(), interpolation="bilinear", ugr=False):
    """What `luxgrid info FILE --json` prints, as a dict: at: (C, gamma) pairs in degrees,
    interpolation: "bilinear" or "bicubic", ugr: add the CIE 190 UGR table ("ugr_table")."""
    return _luxgrid.info(os.fspath(photometry_file), [tuple(a) for a in at], interpolation, ugr)


def write_outputs(results, folder, report=True, arrays_npy=False, part_plots=False):
    """Write every output of `results` into `folder` as `luxgrid calc -o folder` does
    (results.json, CSV and PNG per surface, report.html, timing.json; <surface>.npy with
    arrays_npy; the part plots with part_plots), by the same rules: the folder appears whole or
    not at all, and only over an empty or missing folder or one luxgrid wrote before
    (docs/reliability.md, "Output folders"). Returns the outputs' warnings."""
    warnings, _kept = _luxgrid.write_outputs(results, os.fspath(folder), report, arrays_npy,
                                             part_plots)
    return warnings


def set_threads(n):
    """Cap every calculation of this process at n threads (None: every core), as the CLI's
    --threads does. LUXGRID_THREADS sets it at import."""
    _luxgrid.set_threads(n)


def threads():
    """The thread cap set by set_threads() or LUXGRID_THREADS; None: every core."""
    return _luxgrid.threads()

