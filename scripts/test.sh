#!/usr/bin/env bash
# Sets up, builds and runs every test (unit, verification, validation, examples).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
bash scripts/build.sh
(cd build && ctest --output-on-failure -j "$(nproc)")
# The unit and verification tests under ASan/UBSan (scripts/sanitize.sh --gate; `scripts/sanitize.sh --all`,
# the whole suite, was run clean by hand, see docs/developer-guide.md), in the clang tree ./build-san.
bash scripts/sanitize.sh --gate
# The fuzzing gate (docs/developer-guide.md): each libFuzzer harness over its seed corpus and 1000 mutations
# from a fixed seed (the same inputs on every machine; at most 60 s each), built in the same tree.
FUZZ_SEED=1 FUZZ_RUNS=1000 bash scripts/fuzz.sh 60
