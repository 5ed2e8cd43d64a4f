#!/usr/bin/env bash
# Builds hullopt with AddressSanitizer + UBSan in ./build-san (scripts/san_tree.sh: clang, the tree the fuzz
# harnesses share) and runs the test suite there; any sanitizer report fails the test that triggered it. By
# default the four slowest tests (minutes each even without the sanitizers: the method comparison, the
# twin-release and MPI-campaign checks and the Delft 372 validation; all of them run unsanitized in the
# normal suite) are left out so CI stays within its time; `scripts/sanitize.sh --all` runs everything.
set -euo pipefail
cd "$(dirname "$0")/.."
exclude='^(cli_evaluate_methods|verification_td_twin_release|cli_campaign_parallel_msi|validation_delft372_rao)$'
labels='.'
[ "${1:-}" = "--all" ] && exclude='^$'
# --gate (CI): the unit and verification labels only, so that CI stays near its time budget; the command-line
# paths are sanitized by the fuzz harnesses and by `--all`, which was run clean by hand. The slowest
# verification files run there as their `__subset` tests (tests/CMakeLists.txt) in place of the whole file.
if [ "${1:-}" = "--gate" ]; then
  labels='^(unit|verification)$'
  bash scripts/san_tree.sh --configure
  subsets="$(cd build-san && ctest -N | sed -n 's/^ *Test *#[0-9]*: \(.*\)__subset$/\1/p' | paste -sd '|')"
  [ -n "$subsets" ] && exclude="${exclude%)\$}|${subsets})\$"
  # Only what the selected tests run: their test executables, and the hullopt binary for the CLI checks.
  targets=()
  while read -r name; do
    case "$name" in
      cli_*) targets+=(hullopt) ;;
      unit_module_layers) ;;
      *) targets+=("${name%__subset}") ;;
    esac
  done < <(cd build-san && ctest -N -L "$labels" -E "$exclude" | sed -n 's/^ *Test *#[0-9]*: //p')
  bash scripts/san_tree.sh $(printf '%s\n' "${targets[@]}" | sort -u)
else
  bash scripts/san_tree.sh
fi
export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1:strict_string_checks=1"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
# OpenMP's and OpenMPI's own allocations are reported as leaks at exit: not ours.
export LSAN_OPTIONS="suppressions=$PWD/tests/fuzz/lsan.supp:print_suppressions=0"
cd build-san && ctest --output-on-failure -j "$(nproc)" -L "$labels" -E "$exclude"
