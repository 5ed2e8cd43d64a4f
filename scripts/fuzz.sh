#!/usr/bin/env bash
# Builds the libFuzzer harnesses (clang, ASan + UBSan) in ./build-san (scripts/san_tree.sh, the tree the
# sanitized tests share) and runs each for SECONDS (default 10) on a scratch copy of its seed corpus in
# tests/fuzz/corpus/<name>/. Exits 1 on a crash, leak, sanitizer report or timeout; the reproducer is left in
# build-san/findings/. Usage: scripts/fuzz.sh [SECONDS] [NAME...]
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-10}"
shift || true
names=("$@")
[ ${#names[@]} -eq 0 ] && names=(config offsets_csv stl tank_rao_csv rao_csv)
targets=()
for n in "${names[@]}"; do targets+=("fuzz_$n"); done
bash scripts/san_tree.sh "${targets[@]}"
mkdir -p build-san/findings
# FUZZ_SEED and FUZZ_RUNS make a run reproducible (the CI smoke run: the same inputs on every machine);
# without them libFuzzer picks a random seed and runs for SECONDS.
extra=(-seed="${FUZZ_SEED:-0}")
[ -n "${FUZZ_RUNS:-}" ] && extra+=(-runs="$FUZZ_RUNS")
status=0
for n in "${names[@]}"; do
  work=$(mktemp -d)
  cp tests/fuzz/corpus/"$n"/* "$work"/
  start=$(date +%s)
  # -timeout: one input taking longer is a hang; -rss_limit_mb: one input exhausting memory is a bug too.
  if ! ./build-san/tests/fuzz/fuzz_"$n" "$work" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 \
       -max_len=65536 -artifact_prefix=build-san/findings/"$n"- -print_final_stats=1 "${extra[@]}" \
       > build-san/"$n".log 2>&1; then
    echo "fuzz_$n: FAILED (see build-san/$n.log and build-san/findings/)"; tail -30 build-san/"$n".log; status=1
  else
    execs=$(sed -n 's/^stat::number_of_executed_units: *//p' build-san/"$n".log)
    cov=$(grep -o 'cov: [0-9]*' build-san/"$n".log | tail -1)
    echo "fuzz_$n: ok, $((  $(date +%s) - start )) s, $execs executions, $cov"
  fi
  rm -rf "$work"
done
exit $status
