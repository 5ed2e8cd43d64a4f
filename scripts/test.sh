#!/usr/bin/env bash
# Sets up, builds and runs every test (unit, verification, validation, examples).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
bash scripts/build.sh
(cd build && ctest --output-on-failure -j "$(nproc)")
# The fuzzing and sanitizer gate (docs/developer-guide.md): each libFuzzer harness for 10 s, then the suite
# under ASan/UBSan.
bash scripts/fuzz.sh 10
bash scripts/sanitize.sh
