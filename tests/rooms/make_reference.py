"""Makes a room's stored reference (tests/rooms/README.md): a `reference` run of the project, its
reflected light solved once more at a finer patch size by bench/hall_reference, reduced by
reduce_reference.py to what `luxgrid diff` compares.

  python3 tests/rooms/make_reference.py BUILD PROJECT OUT.json [PATCH_SIZE_M]

BUILD is the build folder (its luxgrid and bench/hall_reference are run), PATCH_SIZE_M the finer
solve's patch size (default 0.1 m, half of `reference`'s 0.2 m). Works in a temporary folder: the
project is copied there with "quality": "reference" and its photometry paths made absolute (so
the copy reads the same files), and nothing beside the project is written. Prints each step's
command and the CPU and wall time it took."""
import json
import os
import resource
import subprocess
import sys
import tempfile
import time

# The finer solve's patch budget per room (at most limits.h's kMaxPatchesPerRoom) and the memory
# its clustered links may take, in MB: high enough that neither changes the solve (the rooms here
# take up to 37 000 patches and 0.9 GB at 0.1 m).
FINE_BUDGET = 100000
FINE_LINK_MB = 12000


def run(cmd):
    print(" ".join(cmd), flush=True)
    t0, c0 = time.monotonic(), resource.getrusage(resource.RUSAGE_CHILDREN)
    subprocess.run(cmd, check=True)
    c1 = resource.getrusage(resource.RUSAGE_CHILDREN)
    print(f"  {c1.ru_utime - c0.ru_utime + c1.ru_stime - c0.ru_stime:.1f} s CPU, "
          f"{time.monotonic() - t0:.1f} s wall", flush=True)


def main():
    if len(sys.argv) not in (4, 5):
        sys.exit(__doc__)
    build, project, out = sys.argv[1:4]
    size_m = sys.argv[4] if len(sys.argv) == 5 else "0.1"
    here = os.path.dirname(os.path.abspath(__file__))
    with tempfile.TemporaryDirectory(prefix="luxgrid-reference-") as tmp:
        run_dir = os.path.join(tmp, "run")
        run([os.path.join(build, "luxgrid"), "calc", project, "--quality", "reference", "-o",
             run_dir, "--no-report"])
        p = json.load(open(project))
        folder = os.path.dirname(os.path.abspath(project))
        p["settings"] = dict(p.get("settings", {}), quality="reference",
                             allow_files_outside_project=True)
        p["photometry"] = {k: os.path.join(folder, v) for k, v in p["photometry"].items()}
        copy = os.path.join(tmp, "project.json")
        json.dump(p, open(copy, "w"))
        fine = os.path.join(tmp, "fine.csv")
        run([os.path.join(build, "bench", "hall_reference"), copy, "0", str(FINE_LINK_MB), fine,
             size_m, str(FINE_BUDGET)])
        run([sys.executable, os.path.join(here, "reduce_reference.py"),
             os.path.join(run_dir, "results.json"), out, fine, size_m])


if __name__ == "__main__":
    main()
