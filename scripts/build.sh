#!/usr/bin/env bash
# Configures and builds luxgrid (Release) into ./build: every target, or only the targets named
# (`bash scripts/build.sh luxgrid`). Uses ccache when it is installed (it only speeds up rebuilds;
# nothing depends on it).
set -euo pipefail
cd "$(dirname "$0")/.."
launcher=()
if command -v ccache >/dev/null 2>&1; then launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache); fi
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release "${launcher[@]}" >/dev/null
if [ "$#" -gt 0 ]; then
  cmake --build build -j"$(nproc)" --target "$@"
else
  cmake --build build -j"$(nproc)"
fi
