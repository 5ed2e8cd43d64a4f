#!/usr/bin/env bash
# The default campaign (configs/optimize-catamaran.yaml) with the fixed 60-frequency grid
# (solver.adaptive_grid: off) and with the adaptive grid (the default), paired: `explore` over the same N Sobol
# samples, then `optimize` (LN_COBYLA to convergence) in each mode. Prints evaluations per second (wall, and
# user+system CPU per evaluation), how many evaluations carry an under-sampled-peak or grid-cap warning, and
# the optimum's objective. Runs one after the other (no other heavy job should run meanwhile).
# Usage: bash bench/adaptive_grid_pair.sh [N=100] [THREADS=2]   (binary: $HULLOPT, default build/app/hullopt)
set -euo pipefail
n=${1:-100}
threads=${2:-2}
hullopt=${HULLOPT:-build/app/hullopt}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
sed -e "s/samples: [0-9]*/samples: $n/" configs/optimize-catamaran.yaml > "$work/on.yaml"
sed -e 's/^solver:$/solver:\n  adaptive_grid: off/' "$work/on.yaml" > "$work/off.yaml"
grep -q "adaptive_grid: off" "$work/off.yaml" || { echo "setup: solver block not found" >&2; exit 1; }
echo "default campaign, $(getconf _NPROCESSORS_ONLN) cores, --threads $threads, load average $(cut -d' ' -f1-3 /proc/loadavg)"
for command in explore optimize; do
  for mode in off on; do
    out="$work/$command-$mode"
    log=$([ "$command" = explore ] && echo samples.csv || echo history.csv)
    start=$(date +%s.%N)
    /usr/bin/time -f "%U %S" -o "$work/time" "$hullopt" "$command" "$work/$mode.yaml" --out "$out" \
      --threads "$threads" --quiet > "$work/log" 2>&1 || { cat "$work/log" >&2; exit 1; }
    end=$(date +%s.%N)
    rows=$(($(grep -vc '^#' "$out/$log") - 1))
    warned=$(grep -v '^#' "$out/$log" | grep -c -E "under-sampled|adaptive frequency grid" || true)
    best=$(python3 -c "
import json
s = json.load(open('$out/summary.json'))
b = s.get('best', {})
x = b.get('variables', b.get('x', ''))
print(s.get('best_objective', ''), x if x != '' else '')" 2>/dev/null || true)
    read -r user sys < "$work/time"
    printf '%-8s grid %-3s %4d evaluations in %6.1f s wall: %5.2f evaluations/s, %6.1f ms CPU each; %3d with a grid warning; best objective %s\n' \
      "$command" "$mode" "$rows" "$(echo "$end - $start" | bc -l)" "$(echo "$rows / ($end - $start)" | bc -l)" \
      "$(echo "1000 * ($user + $sys) / $rows" | bc -l)" "$warned" "$best"
  done
done
