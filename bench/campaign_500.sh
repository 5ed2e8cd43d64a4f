#!/usr/bin/env bash
# 500 evaluations of the default campaign (configs/optimize-catamaran.yaml: parametric catamaran
# → 40×14 time-domain strip RAOs → MSI in two seas), timed as whole CLI runs:
#   explore, 500 Sobol samples: 1 thread, 2 threads (2 samples at a time), mpirun -n 2 (1 thread per rank);
#   optimize, GN_ISRES capped at 500 evaluations (one evaluation at a time, kernel parallel): 1 and 2 threads.
# Prints wall time and evaluations per second of each, with the core count.
# Usage: bash bench/campaign_500.sh [all|explore|explore2|optimize]   (default all; explore2: the 2-thread
#        explore run alone; binaries: $HULLOPT, default
#        build/app/hullopt; $HULLOPT_MPI, default build/app/hullopt_mpi). The runs pass --quiet --no-plots
#        when the binary has --no-plots (the figures are not what is timed), else --quiet only.
set -euo pipefail
which=${1:-all}
case "$which" in all | explore | explore2 | optimize) ;; *) echo "campaign_500: all, explore, explore2 or optimize, not '$which'" >&2; exit 1 ;; esac
hullopt=${HULLOPT:-build/app/hullopt}
hullopt_mpi=${HULLOPT_MPI:-build/app/hullopt_mpi}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
sed -e 's/samples: [0-9]*/samples: 500/' configs/optimize-catamaran.yaml > "$work/explore.yaml"
sed -e 's/algorithm: LN_COBYLA/algorithm: GN_ISRES/' -e 's/max_evaluations: [0-9]*/max_evaluations: 500/' \
  configs/optimize-catamaran.yaml > "$work/optimize.yaml"
run() {  # label, evaluations-file, command...
  local label=$1 file=$2; shift 2
  local start end rows
  start=$(date +%s.%N)
  "$@" > "$work/log" 2>&1 || { cat "$work/log" >&2; exit 1; }
  end=$(date +%s.%N)
  rows=$(($(wc -l < "$file") - 1))
  printf '%-34s %4d evaluations in %6.1f s wall: %5.2f evaluations/s\n' "$label" "$rows" \
    "$(echo "$end - $start" | bc -l)" "$(echo "$rows / ($end - $start)" | bc -l)"
}
quiet=(--quiet)
"$hullopt" explore --help 2> /dev/null | grep -q -- --no-plots && quiet=(--quiet --no-plots)
echo "default campaign, 500 evaluations, $(nproc --all) cores, ${quiet[*]}"
if [ "$which" = explore2 ]; then
  run "explore, 2 threads" "$work/e2/samples.csv" "$hullopt" explore "$work/explore.yaml" --out "$work/e2" --threads 2 "${quiet[@]}"
  exit 0
fi
if [ "$which" != optimize ]; then
run "explore, 1 thread" "$work/e1/samples.csv" "$hullopt" explore "$work/explore.yaml" --out "$work/e1" --threads 1 "${quiet[@]}"
run "explore, 2 threads" "$work/e2/samples.csv" "$hullopt" explore "$work/explore.yaml" --out "$work/e2" --threads 2 "${quiet[@]}"
if [ -x "$hullopt_mpi" ] && command -v mpirun > /dev/null; then
  run "explore, mpirun -n 2 (1 thread each)" "$work/m2/samples.csv" mpirun --allow-run-as-root --oversubscribe -n 2 \
    "$hullopt_mpi" explore "$work/explore.yaml" --out "$work/m2" --threads 1 "${quiet[@]}"
fi
fi
[ "$which" = explore ] && exit 0
run "optimize GN_ISRES, 1 thread" "$work/o1/history.csv" "$hullopt" optimize "$work/optimize.yaml" --out "$work/o1" --threads 1 "${quiet[@]}"
run "optimize GN_ISRES, 2 threads" "$work/o2/history.csv" "$hullopt" optimize "$work/optimize.yaml" --out "$work/o2" --threads 2 "${quiet[@]}"
