#!/usr/bin/env bash
# Installs what luxgrid takes from the npm registry, at the exact versions of
# scripts/npm/package-lock.json, into .tools/npm (not committed): three.js, which the build embeds
# into report.html's 3D view, and the Khronos glTF validator, which a test runs on scene.glb
# (docs/report.md). Quiet and offline when the installed lock file is the committed one already.
# Without node and npm it says so and installs nothing: luxgrid then builds without the 3D view
# (its reports say so) and the validator's test fails in CI.
set -euo pipefail
cd "$(dirname "$0")/.."
dest=.tools/npm
if cmp -s scripts/npm/package-lock.json "$dest/package-lock.json" &&
   [ -f "$dest/node_modules/three/build/three.module.min.js" ] &&
   [ -f "$dest/node_modules/gltf-validator/index.js" ]; then
  exit 0
fi
if ! command -v npm >/dev/null 2>&1; then
  echo "install-npm-tools.sh: npm not found; three.js and the glTF validator not installed" >&2
  exit 0
fi
mkdir -p "$dest"
cp scripts/npm/package.json scripts/npm/package-lock.json "$dest/"
echo "installing from npm: three, gltf-validator (scripts/npm/package-lock.json)" >&2
npm ci --prefix "$dest" --no-audit --no-fund --loglevel=error >/dev/null
