#!/usr/bin/env bash
# Installs what is missing, builds the luxgrid binary only (not the tests and benchmarks), and
# calculates the bundled example office.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
bash scripts/build.sh luxgrid
./build/luxgrid calc examples/office/project.json -o examples/office/project.out
