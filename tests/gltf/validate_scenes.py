#!/usr/bin/env python3
"""validate_scenes.py LUXGRID SOURCE_DIR VALIDATOR_DIR: scene.glb of every example under
examples/ and of tests/data/daylight_office (windows and a roof light: faces with holes, panes,
outlines) (`luxgrid calc --quality draft --no-report`: the values change, the structure does not)
and the scene of `luxgrid view PROJECT -o X.glb` (no values) through the Khronos glTF validator
(tests/gltf/validate.cjs). Fails on any error or warning. Without node or the validator (bash
scripts/install-npm-tools.sh installs it) it fails in CI and is skipped (exit 77) elsewhere."""
import os
import pathlib
import shutil
import subprocess
import sys
import tempfile

luxgrid, source, validator = sys.argv[1], pathlib.Path(sys.argv[2]), pathlib.Path(sys.argv[3])
if not shutil.which("node") or not (validator / "index.js").is_file():
    print(f"node or the glTF validator ({validator}) missing: bash scripts/install-npm-tools.sh")
    sys.exit(1 if os.environ.get("CI") == "true" else 77)

files = []
with tempfile.TemporaryDirectory(prefix="luxgrid-gltf-") as tmp:
    tmp = pathlib.Path(tmp)
    projects = sorted((source / "examples").glob("*/project.json"))
    projects.append(source / "tests/data/daylight_office/project.json")
    for project in projects:
        name = project.parent.name
        out = tmp / name
        subprocess.run([luxgrid, "--threads", "2", "calc", str(project), "-o", str(out),
                        "--quality", "draft", "--no-report"], check=True, stdout=subprocess.DEVNULL)
        files.append(out / "scene.glb")
        view = tmp / f"{name}.view.glb"
        subprocess.run([luxgrid, "view", str(project), "-o", str(view)], check=True,
                       stdout=subprocess.DEVNULL)
        files.append(view)
    if len(files) < 8:
        sys.exit(f"expected the three examples and the daylit office, found {len(files) // 2}")
    result = subprocess.run(["node", str(source / "tests/gltf/validate.cjs"), str(validator)]
                            + [str(f) for f in files])
    sys.exit(result.returncode)
