#!/usr/bin/env bash
# Sets up, builds and runs the main job: the default optimisation campaign (configs/optimize-catamaran.yaml,
# a 1000 t catamaran at 40 kn minimising mean MSI in head seas) into out/main/. Re-running continues a
# campaign that was interrupted; a finished one is replayed from out/main/history.csv without recomputing.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
bash scripts/build.sh
./build/app/hullopt optimize configs/optimize-catamaran.yaml --out out/main
