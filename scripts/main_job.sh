#!/usr/bin/env bash
# Sets up, builds and runs the main job on the default config.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
bash scripts/build.sh
./build/app/hullopt hull configs/davis-holloway-2003-hulls.yaml --out out/main
