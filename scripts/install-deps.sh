#!/usr/bin/env bash
# Installs luxgrid's build and test dependencies from Debian packages, only those missing.
# Run as root on Debian 12 (bookworm). Quiet when everything is there already.
set -euo pipefail
packages=(cmake make g++ pkg-config
          libcgal-dev libembree-dev libglm-dev libdeflate-dev libpng-dev libfreetype-dev nlohmann-json3-dev libtbb-dev libcli11-dev nettle-dev
          libgtest-dev libbenchmark-dev fonts-dejavu-core python3 chromium poppler-utils clang-format
          # The Python package (python/, docs/python.md) and its tests.
          python3-dev pybind11-dev python3-numpy python3-pandas python3-distributed python3-pytest
          ${LUXGRID_EXTRA_PACKAGES:-})
# The plots of examples/python/office_sweep.py. Not in CI (CI=true), which runs no example that
# plots: matplotlib brings SciPy, SymPy and some 35 more packages, 43 MB of the 58 MB of
# packages the Python set downloads.
if [ "${CI:-}" != true ]; then packages+=(python3-matplotlib); fi
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "installing: ${missing[*]}" >&2
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -qq
  apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi
# three.js and the glTF validator, from the npm registry (report.html's 3D view, scene.glb's test).
bash "$(dirname "$0")/install-npm-tools.sh"
