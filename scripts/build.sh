#!/usr/bin/env bash
# Configures and builds hullopt in ./build (Release, warnings as errors). Extra args go to cmake configure.
set -euo pipefail
cd "$(dirname "$0")/.."
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DHULLOPT_WERROR=ON "$@" > build-configure.log
cmake --build build -j "$(nproc)"
