#!/usr/bin/env bash
# Convergence of one hull's strip results with the panel count: runs `hullopt coefficients` on a hull config
# at a fixed number of sections and several panel counts and prints A33, A53, B33 and B55 at one wave
# frequency, so that the order of convergence can be read off (first order: the differences between
# successive doublings halve; second order: they fall by four).
# Usage: scripts/panel_convergence.sh HULL_CONFIG OMEGA_RAD_S [SECTIONS] [PANELS...]
#   e.g. scripts/panel_convergence.sh configs/davis-holloway-2003/hull05_S64.yaml 0.7 40 14 28 56 84
# The config must not have a solver block (one is appended). Binary: $HULLOPT (default build/app/hullopt).
# $PANEL_SPACING (optional) is appended as solver.panel_spacing, e.g. PANEL_SPACING='{ end_spacing: 0.08 }'.
set -euo pipefail
[ $# -ge 2 ] || { sed -n 2,9p "$0"; exit 2; }
cfg=$(realpath "$1"); omega=$2; sections=${3:-40}; shift $(( $# >= 3 ? 3 : 2 ))
panels=("$@"); [ ${#panels[@]} -gt 0 ] || panels=(14 28 56)
bin=$(realpath "${HULLOPT:-build/app/hullopt}")
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
printf '| panels | A33 [kg] | A53 [kg m] | B33 [kg/s] | B55 [kg m2/s] |\n|---|---|---|---|---|\n'
for p in "${panels[@]}"; do
  d="$work/p$p"; mkdir -p "$d"
  cp "$cfg" "$d/h.yaml"
  printf 'solver: { sections: %s, panels: %s, frequencies: { omega_rad_s: [%s] }%s }\n' \
    "$sections" "$p" "$omega" "${PANEL_SPACING:+, panel_spacing: $PANEL_SPACING}" >> "$d/h.yaml"
  "$bin" coefficients "$d/h.yaml" --out "$d/out" > "$d/log" 2>&1 || { cat "$d/log" >&2; exit 1; }
  grep -v '^#' "$d/out/coefficients.csv" | awk -F, -v p="$p" '
    NR == 1 { for (i = 1; i <= NF; i++) c[$i] = i; next }
    { printf "| %s | %.6g | %.6g | %.6g | %.6g |\n", p, $c["A33_kg"], $c["A53_kg_m"], $c["B33_kg_per_s"], $c["B55_kg_m2_per_s"] }'
done
