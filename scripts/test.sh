#!/usr/bin/env bash
# Sets up, builds and runs every test (unit, verification, validation, examples).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
bash scripts/build.sh
(cd build && ctest --output-on-failure -j "$(nproc)")
# The fuzzing gate (docs/developer-guide.md): each libFuzzer harness for 10 s. The suite under ASan/UBSan
# (scripts/sanitize.sh) joins this gate once it has had a complete clean run.
bash scripts/fuzz.sh 10
