#!/bin/sh
# The sanitized job (fuzz/CMakeLists.txt), with clang: builds the readers and the project loader
# with AddressSanitizer + UndefinedBehaviorSanitizer, runs their unit tests under both, then each
# libFuzzer target for a fixed time on a corpus seeded from tests/data, examples/ and cases/.
# Skips (exit 0, saying so) when clang++ is missing.
#   fuzz/run.sh [seconds-per-fuzzer=20] [build-dir=build-fuzz]
# Exit status: non-zero if a sanitized test failed or a fuzzer found a crash (the reproducer is
# left in the build dir).
set -eu
SECONDS_PER_TARGET="${1:-20}"
ROOT="$(cd "$(dirname "$0")/.." && pwd)"
BUILD="${2:-$ROOT/build-fuzz}"
CXX_CLANG="$(command -v clang++ || true)"
if [ -z "$CXX_CLANG" ]; then
  echo "fuzz/run.sh: clang++ not found; the sanitized tests and the fuzzers are skipped"
  exit 0
fi
LAUNCHER=""
if command -v ccache >/dev/null 2>&1; then LAUNCHER="-DCMAKE_CXX_COMPILER_LAUNCHER=ccache"; fi
cmake -S "$ROOT/fuzz" -B "$BUILD" -DCMAKE_CXX_COMPILER="$CXX_CLANG" -DCMAKE_BUILD_TYPE=RelWithDebInfo $LAUNCHER >/dev/null
cmake --build "$BUILD" -j"$(nproc)"

echo "== sanitized unit tests (ASan + UBSan): photometric readers and project loader"
# Leak checking is on too (LeakSanitizer is part of ASan); UB aborts (-fno-sanitize-recover).
ASAN_OPTIONS=detect_leaks=1:abort_on_error=0 UBSAN_OPTIONS=print_stacktrace=1 \
  "$BUILD/sanitized_tests" --gtest_brief=1

for target in ies_reader_fuzz eulumdat_reader_fuzz project_loader_fuzz; do
  corpus="$BUILD/corpus_$target"
  mkdir -p "$corpus"
  case "$target" in
    ies_*) cp "$ROOT"/tests/data/photometry/ies/*.ies "$ROOT"/tests/data/bad/*.ies "$corpus"/ 2>/dev/null || true ;;
    eulumdat_*) cp "$ROOT"/tests/data/photometry/ldt/*.ldt "$ROOT"/tests/data/bad/*.ldt "$corpus"/ 2>/dev/null || true ;;
    project_*)
      # Real projects and the hostile ones; each copy named after its folder so none overwrites another.
      for p in "$ROOT"/examples/*/project.json "$ROOT"/cases/*/project.json; do
        cp "$p" "$corpus/$(basename "$(dirname "$p")").json"
      done
      cp "$ROOT"/tests/data/bad/projects/*.json "$corpus"/ ;;
  esac
  # The 1.3 MB interlab file slows every iteration down; inputs are capped at 64 kB. A project
  # the loader accepts may build grids up to its limits (8 million points: about 1 GB and tens of
  # seconds under ASan on a loaded machine), so the loader gets a longer timeout and more memory;
  # a hang or a leak beyond them is still a failure.
  timeout=10
  rss=2048
  case "$target" in project_*) timeout=120; rss=4096 ;; esac
  echo "== $target: ${SECONDS_PER_TARGET} s"
  (cd "$BUILD" && "./$target" -max_total_time="$SECONDS_PER_TARGET" -max_len=65536 -rss_limit_mb="$rss" \
      -timeout="$timeout" -print_final_stats=1 "$corpus")
done
