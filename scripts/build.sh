#!/usr/bin/env bash
# Configures and builds luxgrid (Release) into ./build: every target, or only the targets named
# (`bash scripts/build.sh luxgrid`). Uses ccache when it is installed (it only speeds up rebuilds;
# nothing depends on it). With CI=true, warnings are errors (LUXGRID_WERROR) and bench/ is skipped.
set -euo pipefail
cd "$(dirname "$0")/.."
launcher=()
if command -v ccache >/dev/null 2>&1; then launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache); fi
# In CI (CI=true, as GitHub Actions and most CI services set it) warnings are errors, and the
# Google Benchmark programs (bench/, run by hand: docs/performance.md) are not built, to keep the
# job within its time on a 2-core machine.
# LUXGRID_UNITY_BUILD=ON (as scripts/run-tests.sh sets it) compiles the libraries as unity builds:
# a whole build in about half the time, a one-file change slower (CMakeLists.txt).
options=(-DLUXGRID_UNITY_BUILD="${LUXGRID_UNITY_BUILD:-OFF}")
if [ "${CI:-}" = true ]; then options+=(-DLUXGRID_WERROR=ON -DLUXGRID_BUILD_BENCH=OFF); fi
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release "${launcher[@]}" "${options[@]}" >/dev/null
if [ "$#" -gt 0 ]; then
  cmake --build build -j"$(nproc)" --target "$@"
else
  cmake --build build -j"$(nproc)"
fi
