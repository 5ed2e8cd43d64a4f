#!/usr/bin/env bash
# Convergence of the 14-hull study (configs/davis-holloway-2003.yaml) with the strip resolution: every hull at
# 20 x 8, 40 x 14 and 80 x 28 (sections x panels per body), heave and pitch RAO peaks, MSI in 3 m / 7.5 s
# seas and the largest strip condition estimate. Uses `hullopt evaluate` with `resolution_check` (factor 2)
# at 20 x 8 (giving 40 x 14) and at 40 x 14 (giving 80 x 28); prints a markdown table.
# Usage: scripts/study_convergence.sh [HULLOPT_BINARY] [WORK_DIR]
# Environment: SOLVER_EXTRA, further solver keys for every hull (e.g. SOLVER_EXTRA="body_potential: green_identity").
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
bin="$(realpath "${1:-$root/build/app/hullopt}")"
work="${2:-$(mktemp -d)}"
mkdir -p "$work"
study="$root/configs/davis-holloway-2003.yaml"
for res in "20 8" "40 14"; do
  set -- $res
  dir="$work/base_${1}x${2}"
  mkdir -p "$dir/hulls"
  for cfg in "$root"/configs/davis-holloway-2003/hull*.yaml; do
    out="$dir/hulls/$(basename "$cfg")"
    cp "$cfg" "$out"
    printf 'solver: { sections: %s, panels: %s%s }\n' "$1" "$2" "${SOLVER_EXTRA:+, $SOLVER_EXTRA}" >> "$out"
  done
  sed -e "s#\(config: *\)\(configs/\)\?davis-holloway-2003/#\1$dir/hulls/#" "$study" > "$dir/study.yaml"
  printf 'resolution_check: { enabled: true, factor: 2 }\n' >> "$dir/study.yaml"
  "$bin" evaluate "$dir/study.yaml" --out "$dir/out" > "$dir/stdout.txt" 2> "$dir/stderr.txt"
done
/usr/bin/python3 - "$work" <<'PY'
import json, sys
work = sys.argv[1]
a = json.load(open(f"{work}/base_20x8/out/summary.json"))
b = json.load(open(f"{work}/base_40x14/out/summary.json"))
def i3(d):
    return [i for i, s in enumerate(d["seas"]) if abs(s["Hs_m"] - 3.0) < 1e-9][0]
print("| design | heave peak 20x8 / 40x14 / 80x28 [m/m] | change 40x14 -> 80x28 | pitch peak 20x8 / 40x14 / 80x28 [-] | change | MSI 3 m 20x8 / 40x14 / 80x28 [%] | max MSI change 40x14 -> 80x28 over the seas [points] | converged |")
print("|---|---|---|---|---|---|---|---|")
for da, db in zip(a["designs"], b["designs"]):
    ra, rb = da["resolution_check"], db["resolution_check"]
    print(f"| {db['name']} | {ra['heave_peak']:.3f} / {rb['heave_peak']:.3f} / {rb['heave_peak_fine']:.3f} | "
          f"{100*rb['heave_peak_change']:+.1f}% | {ra['pitch_peak']:.3f} / {rb['pitch_peak']:.3f} / "
          f"{rb['pitch_peak_fine']:.3f} | {100*rb['pitch_peak_change']:+.1f}% | {ra['mean_msi_pct'][i3(da)]:.1f} / {rb['mean_msi_pct'][i3(db)]:.1f} / {rb['fine_mean_msi_pct'][i3(db)]:.1f} | "
          f"{rb['max_msi_change_pct']:.2f} | {'yes' if rb['converged'] else '**no**'} |")
PY
