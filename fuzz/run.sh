#!/bin/sh
# Builds the photometry fuzzers with clang (skips, exit 0, when clang++ is missing) and runs each
# for a fixed time on a corpus seeded from tests/data (the real files and the hostile ones).
#   fuzz/run.sh [seconds-per-target=20] [build-dir=build-fuzz]
# Exit status: non-zero if a fuzzer found a crash (the reproducer is left in the build dir).
set -eu
SECONDS_PER_TARGET="${1:-20}"
ROOT="$(cd "$(dirname "$0")/.." && pwd)"
BUILD="${2:-$ROOT/build-fuzz}"
CXX_CLANG="$(command -v clang++ || true)"
if [ -z "$CXX_CLANG" ]; then
  echo "fuzz/run.sh: clang++ not found; fuzzers skipped"
  exit 0
fi
cmake -S "$ROOT/fuzz" -B "$BUILD" -DCMAKE_CXX_COMPILER="$CXX_CLANG" -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
cmake --build "$BUILD" -j2
for target in ies_reader_fuzz eulumdat_reader_fuzz; do
  corpus="$BUILD/corpus_$target"
  mkdir -p "$corpus"
  case "$target" in
    ies_*) cp "$ROOT"/tests/data/photometry/ies/*.ies "$ROOT"/tests/data/bad/*.ies "$corpus"/ 2>/dev/null || true ;;
    *) cp "$ROOT"/tests/data/photometry/ldt/*.ldt "$ROOT"/tests/data/bad/*.ldt "$corpus"/ 2>/dev/null || true ;;
  esac
  # The 1.3 MB interlab file slows every iteration down; inputs are capped at 64 kB.
  echo "== $target: ${SECONDS_PER_TARGET} s"
  (cd "$BUILD" && "./$target" -max_total_time="$SECONDS_PER_TARGET" -max_len=65536 -rss_limit_mb=2048 \
      -timeout=10 -print_final_stats=1 "$corpus")
done
