#!/usr/bin/env bash
# Installs what is missing, builds, and runs the whole test suite: every GoogleTest suite and the
# validation cases (ctest), then the fuzzers for a short fixed time when clang is there.
set -euo pipefail
cd "$(dirname "$0")/.."
LUXGRID_EXTRA_PACKAGES="clang ${LUXGRID_EXTRA_PACKAGES:-}" bash scripts/install-deps.sh
bash scripts/build.sh
ctest --test-dir build --output-on-failure -j"$(nproc)"
if [ -x fuzz/run.sh ] || [ -f fuzz/run.sh ]; then bash fuzz/run.sh; fi
