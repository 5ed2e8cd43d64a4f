#!/usr/bin/env bash
# Configures the one sanitizer tree, ./build-san (clang-14, AddressSanitizer + UBSan, HULLOPT_SANITIZE=ON and
# HULLOPT_FUZZ=ON), and builds the given targets there (all when none are given). The libFuzzer harnesses
# (scripts/fuzz.sh) and the sanitized test suite (scripts/sanitize.sh) share it, so CI builds the library
# once for both. Release optimisation as the normal build, plus line tables for the reports' stack traces,
# and lld to link the many test executables. Usage: scripts/san_tree.sh [--configure | TARGET...]
set -euo pipefail
cd "$(dirname "$0")/.."
CXX_CLANG="$(command -v clang++-14 || command -v clang++)"
C_CLANG="$(command -v clang-14 || command -v clang)"
gen=()
[ -f build-san/CMakeCache.txt ] || ! command -v ninja > /dev/null || gen=(-G Ninja)
linker=()
command -v ld.lld > /dev/null && linker=(-DCMAKE_EXE_LINKER_FLAGS=-fuse-ld=lld)
cmake -S . -B build-san "${gen[@]}" -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER="$CXX_CLANG" \
  -DCMAKE_C_COMPILER="$C_CLANG" -DCMAKE_CXX_FLAGS=-gline-tables-only -DCMAKE_C_FLAGS=-gline-tables-only \
  "${linker[@]}" -DHULLOPT_SANITIZE=ON -DHULLOPT_FUZZ=ON -DHULLOPT_BENCHMARKS=OFF -DHULLOPT_PYTHON=OFF \
  > build-san-configure.log
[ "${1:-}" = "--configure" ] && exit 0
targets=()
[ $# -gt 0 ] && targets=(--target "$@")
cmake --build build-san -j "$(nproc)" "${targets[@]}" > build-san.log
