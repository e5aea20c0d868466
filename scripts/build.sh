#!/usr/bin/env bash
# Configures and builds luxgrid (Release) into ./build. Uses ccache when it is installed (it only
# speeds up rebuilds; nothing depends on it).
set -euo pipefail
cd "$(dirname "$0")/.."
launcher=()
if command -v ccache >/dev/null 2>&1; then launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache); fi
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release "${launcher[@]}" >/dev/null
cmake --build build -j"$(nproc)"
