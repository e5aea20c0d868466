#!/usr/bin/env bash
# Installs what is missing, builds, and runs the whole test suite: the format check
# (scripts/check-format.sh), every GoogleTest suite and the validation cases (ctest), then the
# sanitized job (fuzz/run.sh: the readers' and the loader's tests under ASan + UBSan, and each
# fuzzer for a short fixed time) when clang is there.
# Every part runs even when an earlier one failed; the exit status is non-zero if any failed.
set -euo pipefail
cd "$(dirname "$0")/.."
LUXGRID_EXTRA_PACKAGES="clang ${LUXGRID_EXTRA_PACKAGES:-}" bash scripts/install-deps.sh
# A whole build: the libraries as unity builds (scripts/build.sh).
LUXGRID_UNITY_BUILD=ON bash scripts/build.sh
status=0
bash scripts/check-format.sh || status=1
# `promise`: the promise tests of the non-convex rooms not yet kept (tests/rooms/README.md), left
# out; the ones kept run here (label `rooms`). Run the others with `ctest --test-dir build -L promise`.
ctest --test-dir build --output-on-failure -j"$(nproc)" -LE promise || status=1
bash fuzz/run.sh || status=1
if [ "$status" -ne 0 ]; then echo "run-tests.sh: some tests failed (see above)" >&2; fi
exit "$status"
