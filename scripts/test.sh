#!/usr/bin/env bash
# Sets up, builds and runs every test (unit, verification, validation, examples).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
bash scripts/build.sh
(cd build && ctest --output-on-failure -j "$(nproc)")
# The fuzzing gate (docs/developer-guide.md): each libFuzzer harness over its seed corpus and 1000 mutations
# from a fixed seed (the same inputs on every machine; at most 60 s each). The suite under ASan/UBSan
# The suite under ASan/UBSan (scripts/sanitize.sh: all but the four slowest tests, which run unsanitized above;
# `scripts/sanitize.sh --all` ran clean in full, see docs/developer-guide.md).
FUZZ_SEED=1 FUZZ_RUNS=1000 bash scripts/fuzz.sh 60
bash scripts/sanitize.sh
