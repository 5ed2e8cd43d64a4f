#!/usr/bin/env bash
# Kernel build time of this build against the code before the speed work (commit 1f50dd8), measured in turns
# in one session so that both figures see the same machine load: builds bench_rao at that commit in a
# temporary worktree (a few minutes), then runs BM_KernelBuild/THREADS of the two binaries ROUNDS times each,
# alternating, each run the median of 15 repetitions; prints the median of the run medians of each, and the
# median of the paired ratios. With a third argument, a bench_rao binary built elsewhere (e.g. of main before
# a change) is the baseline instead, and nothing is built (it reads its data from the source tree it was built
# in).
# Usage: bash bench/kernel_speedup.sh [ROUNDS=20] [THREADS=1] [BASELINE_BENCH_RAO]   (this build: build/bench/bench_rao)
set -euo pipefail
rounds=${1:-20}
threads=${2:-1}
root=$(cd "$(dirname "$0")/.." && pwd)
now="$root/build/bench/bench_rao"
[ -x "$now" ] || { echo "kernel_speedup: build first (bash scripts/build.sh)" >&2; exit 1; }
base=$(mktemp -d)
if [ -n "${3:-}" ]; then
  trap 'rm -rf "$base"' EXIT
  before="$(cd "$(dirname "$3")" && pwd)/$(basename "$3")"
  label="baseline $3"
else
  trap 'git -C "$root" worktree remove --force "$base" > /dev/null 2>&1 || rm -rf "$base"' EXIT
  git -C "$root" worktree add -q --detach "$base" 1f50dd8
  cmake -S "$base" -B "$base/build" -DCMAKE_BUILD_TYPE=Release > "$base/configure.log"
  cmake --build "$base/build" --target bench_rao -j "$(nproc)" > "$base/build.log"
  before="$base/build/bench/bench_rao"
  label="before (1f50dd8)"
fi
median_of() { sort -n | awk '{a[NR] = $1} END {print (NR % 2 ? a[(NR + 1) / 2] : (a[NR / 2] + a[NR / 2 + 1]) / 2)}'; }
one() {  # binary -> median ms of 15 repetitions (run from the old worktree, whose data paths it reads)
  (cd "$base" && "$1" --benchmark_filter="BM_KernelBuild/$threads\$|BM_KernelBuild/$threads/" \
    --benchmark_repetitions=15 --benchmark_report_aggregates_only=true 2>/dev/null | awk '/_median/ {print $2}')
}
: > "$base/runs"
for ((i = 0; i < rounds; ++i)); do echo "$(one "$before") $(one "$now")" >> "$base/runs"; done
echo "BM_KernelBuild/$threads, $rounds alternating runs on $(nproc) cores (load average $(cut -d' ' -f1-3 /proc/loadavg) at the end), medians in ms:"
echo "  $label: $(awk '{print $1}' "$base/runs" | median_of)"
echo "  this build: $(awk '{print $2}' "$base/runs" | median_of)"
echo "  speed-up (median of paired ratios): $(awk '{print $1 / $2}' "$base/runs" | median_of)"
