#!/usr/bin/env bash
# Timed CLI runs (the benchmarks that time a whole command rather than a function): runs a hullopt command
# REPEAT times into fresh output folders and prints every wall time and the median, with the core count.
# Usage: bash bench/time_cli.sh [REPEAT] -- hullopt-args...   (the binary: $HULLOPT, default build/app/hullopt)
# Examples:
#   bash bench/time_cli.sh 5 -- evaluate configs/davis-holloway-2003.yaml     # the 14-hull study
#   bash bench/time_cli.sh 3 -- calibrate examples/calibrate_delft372.yaml   # one Cs calibration
set -euo pipefail
repeat=${1:-5}
shift
[ "${1:-}" = "--" ] && shift
hullopt=${HULLOPT:-build/app/hullopt}
[ -x "$hullopt" ] || { echo "time_cli: no binary at $hullopt (build first, or set HULLOPT)" >&2; exit 1; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
times=()
for i in $(seq 1 "$repeat"); do
  start=$(date +%s.%N)
  "$hullopt" "$@" --out "$work/run$i" > "$work/log$i" 2>&1 || { cat "$work/log$i" >&2; exit 1; }
  end=$(date +%s.%N)
  times+=("$(echo "$end - $start" | bc -l)")
done
median=$(printf '%s\n' "${times[@]}" | sort -g | awk '{a[NR]=$1} END {print (NR % 2) ? a[(NR+1)/2] : (a[NR/2] + a[NR/2+1]) / 2}')
printf 'hullopt %s: %d runs on %d cores (OMP_NUM_THREADS=%s), wall [s]: %s; median %.2f s\n' "$*" "$repeat" \
  "$(nproc --all)" "${OMP_NUM_THREADS:-unset}" "$(printf '%.2f ' "${times[@]}")" "$median"
