#!/usr/bin/env bash
# Configures and builds hullopt in ./build (Release, warnings as errors). Extra args go to cmake configure.
# A new tree uses Ninja and lld where they are installed (scripts/setup.sh installs both): Ninja keeps both
# cores busy across the libraries' boundaries, and lld links the many test executables in a fraction of ld's
# time. An existing tree keeps its generator.
set -euo pipefail
cd "$(dirname "$0")/.."
gen=()
[ -f build/CMakeCache.txt ] || ! command -v ninja > /dev/null || gen=(-G Ninja)
linker=()
command -v ld.lld > /dev/null && linker=(-DCMAKE_EXE_LINKER_FLAGS=-fuse-ld=lld -DCMAKE_SHARED_LINKER_FLAGS=-fuse-ld=lld)
cmake -S . -B build "${gen[@]}" -DCMAKE_BUILD_TYPE=Release -DHULLOPT_WERROR=ON "${linker[@]}" "$@" > build-configure.log
cmake --build build -j "$(nproc)"
