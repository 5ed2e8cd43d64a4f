#!/usr/bin/env bash
# Builds hullopt with AddressSanitizer + UBSan (HULLOPT_SANITIZE=ON, gcc) in ./build-asan and runs the test
# suite there; any sanitizer report fails the test that triggered it. By default the four slowest tests
# (minutes each even without the sanitizers: the method comparison, the twin-release and MPI-campaign
# checks and the Delft 372 validation; all of them run unsanitized in the normal suite) are left out so CI
# stays within its time; `scripts/sanitize.sh --all` runs everything.
set -euo pipefail
cd "$(dirname "$0")/.."
cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=Release -DHULLOPT_SANITIZE=ON -DHULLOPT_BENCHMARKS=OFF \
  > build-asan-configure.log
cmake --build build-asan -j "$(nproc)" > build-asan.log
export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1:strict_string_checks=1"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
# OpenMPI's own allocations are reported as leaks at exit: not ours.
export LSAN_OPTIONS="suppressions=$PWD/tests/fuzz/lsan.supp:print_suppressions=0"
exclude='^(cli_evaluate_methods|verification_td_twin_release|cli_campaign_parallel_msi|validation_delft372_rao)$'
labels='.'
[ "${1:-}" = "--all" ] && exclude='^$'
# --gate (CI): the unit and verification labels only, so that CI stays near its time budget; the command-line
# paths are sanitized by the fuzz harnesses and by `--all`, which was run clean by hand.
[ "${1:-}" = "--gate" ] && labels='^(unit|verification)$'
cd build-asan && ctest --output-on-failure -j "$(nproc)" -L "$labels" -E "$exclude"
