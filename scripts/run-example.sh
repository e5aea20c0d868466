#!/usr/bin/env bash
# Installs what is missing, builds, and calculates the bundled example office.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
bash scripts/build.sh
./build/luxgrid calc examples/office/project.json -o examples/office/project.out
