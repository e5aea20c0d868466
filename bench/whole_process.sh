#!/usr/bin/env bash
# The whole-process benchmark (run by hand, not in CI): each project calculated once by the
# built binary under /usr/bin/time, one Markdown row per project with wall, CPU (user + sys) and
# peak memory of the process, the phase times of its timing.json and the time outside every
# phase (start-up, loading the libraries, writing results.json and timing.json, exit).
#
#   bash bench/whole_process.sh [BINARY]          (default: build/luxgrid)
#   LUXGRID_BENCH_ARGS="--threads 1" bash bench/whole_process.sh
#
# The large projects (50-room floor, the two halls, 10^6-point grid, far1000, panel40k) are
# generated into a temporary folder by bench/make_projects.py and removed afterwards, with every output.
# docs/performance.md keeps the table and the machine it was measured on.
set -euo pipefail
cd "$(dirname "$0")/.."
bin=$(realpath "${1:-build/luxgrid}")
work=$(mktemp -d "${TMPDIR:-/tmp}/luxgrid-bench.XXXXXX")
trap 'rm -rf "$work"' EXIT
python3 bench/make_projects.py "$work"
cases=("office:examples/office/project.json" "open plan:examples/openplan/project.json"
       "50-room floor:$work/floor50/project.json" "100 x 50 m hall:$work/hall/project.json"
       "200 x 100 m hall:$work/hall200/project.json" "10^6-point grid:$work/grid1m/project.json"
       "far field 1000 x 10^4:$work/far1000/project.json"
       "near-field panel 40 000:$work/panel40k/project.json")
echo "machine: $(nproc) CPUs, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ *//'), load average $(cut -d' ' -f1-3 /proc/loadavg)"
echo "binary: $bin ${LUXGRID_BENCH_ARGS:-}"
echo
echo "| project | points | wall s | CPU s | peak MiB | load s | direct s | indirect s | report s | outside phases s |"
echo "|---|---|---|---|---|---|---|---|---|---|"
n=0
for c in "${cases[@]}"; do
  name=${c%%:*} project=${c#*:}
  n=$((n + 1))
  out="$work/out$n"
  # shellcheck disable=SC2086
  /usr/bin/time -f '%e %U %S %M' -o "$work/time$n" "$bin" calc "$project" -o "$out" ${LUXGRID_BENCH_ARGS:-} >/dev/null
  python3 - "$name" "$work/time$n" "$out" <<'PY'
import json, pathlib, sys
name, time_file, out = sys.argv[1], pathlib.Path(sys.argv[2]), pathlib.Path(sys.argv[3])
wall, user, sys_s, rss_kib = time_file.read_text().split()[-4:]
phases = json.loads((out / "timing.json").read_text())["timing_s"]
points = sum(sum(1 for _ in open(f)) - 1 for f in out.glob("*.csv"))
cpu = float(user) + float(sys_s)
get = lambda k: phases.get(k, 0.0)
outside = float(wall) - sum(phases.values())
print(f"| {name} | {points} | {float(wall):.2f} | {cpu:.2f} | {int(rss_kib) / 1024:.0f} | {get('load'):.2f} | "
      f"{get('direct'):.2f} | {get('indirect'):.2f} | {get('report'):.2f} | {outside:.2f} |")
PY
  rm -rf "$out"
done
