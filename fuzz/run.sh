#!/bin/sh
# The sanitized job, with clang: the main CMake project built with -DLUXGRID_SANITIZE=ON (every
# target under AddressSanitizer + UndefinedBehaviorSanitizer, undefined behaviour aborts) in a
# build folder of its own, then
#   1. the photometric readers' and the project loader's unit tests under both;
#   2. a small scene end to end through the sanitized `luxgrid calc` (examples/office: loading,
#      direct light, the near field with its far-field bound, reflected light, glare, every
#      output): exit code 0, and results.json parses with no NaN or infinity and null only where
#      the format allows it (an observer's UGR outside the table's range);
#   3. each libFuzzer target for a fixed time on a corpus seeded from tests/data, examples/ and
#      cases/.
# Skips (exit 0, saying so) when clang++ is missing.
#   fuzz/run.sh [seconds-per-fuzzer=12] [build-dir=build-fuzz]
# Exit status: non-zero if a sanitized test or the scene failed or a fuzzer found a crash (the
# reproducer is left in the build dir).
set -eu
SECONDS_PER_TARGET="${1:-12}"
ROOT="$(cd "$(dirname "$0")/.." && pwd)"
BUILD="${2:-$ROOT/build-fuzz}"
CXX_CLANG="$(command -v clang++ || true)"
if [ -z "$CXX_CLANG" ]; then
  echo "fuzz/run.sh: clang++ not found; the sanitized tests and the fuzzers are skipped"
  exit 0
fi
LAUNCHER=""
if command -v ccache >/dev/null 2>&1; then LAUNCHER="-DCMAKE_CXX_COMPILER_LAUNCHER=ccache"; fi
cmake -S "$ROOT" -B "$BUILD" -DCMAKE_CXX_COMPILER="$CXX_CLANG" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DLUXGRID_SANITIZE=ON -DLUXGRID_BUILD_BENCH=OFF $LAUNCHER >/dev/null
cmake --build "$BUILD" -j"$(nproc)" --target luxgrid photometry_tests project_tests \
  ies_reader_fuzz eulumdat_reader_fuzz project_loader_fuzz

# Leak checking is on too (LeakSanitizer is part of ASan); UB aborts (-fno-sanitize-recover).
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=0 UBSAN_OPTIONS=print_stacktrace=1

echo "== sanitized unit tests (ASan + UBSan): photometric readers and project loader"
"$BUILD/tests/photometry_tests" --gtest_brief=1
"$BUILD/tests/project_tests" --gtest_brief=1

echo "== sanitized scene end to end (ASan + UBSan): examples/office through luxgrid calc"
scene_out="$BUILD/scene_office"
rm -rf "$scene_out"
"$BUILD/luxgrid" calc "$ROOT/examples/office/project.json" -o "$scene_out" --part-plots
python3 - "$scene_out/results.json" <<'EOF'
import json, math, sys
# Keys whose value may be null (results.json writes null for a value that does not exist);
# null anywhere else is a number the calculation did not give (results_json writes NaN as null).
may_be_null = {"UGR"}
def bad_constant(name):
    raise ValueError(f"results.json holds {name}")
def walk(value, key, where):
    if value is None and key not in may_be_null:
        sys.exit(f"results.json: null at {where}")
    if isinstance(value, float) and not math.isfinite(value):
        sys.exit(f"results.json: {value} at {where}")
    if isinstance(value, dict):
        for k, v in value.items():
            walk(v, k, f"{where}/{k}")
    elif isinstance(value, list):
        for i, v in enumerate(value):
            walk(v, key, f"{where}/{i}")
with open(sys.argv[1]) as f:
    walk(json.load(f, parse_constant=bad_constant), "", "")
print("results.json: every number finite")
EOF

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
