#!/usr/bin/env bash
# --quiet (every command: nothing on stdout) and --no-plots (rao, design, evaluate, optimize, explore: the
# numbers only, no .svg and no report.html, and the same numbers as with the figures).
set -u
bin="$1"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*"; exit 1; }

for cmd in hull section rao coefficients design evaluate optimize explore calibrate resistance; do
  "$bin" "$cmd" --help | grep -q -- "--quiet" || fail "$cmd has no --quiet"
done
for cmd in rao design evaluate optimize explore; do
  "$bin" "$cmd" --help | grep -q -- "--no-plots" || fail "$cmd has no --no-plots"
done

cat > "$tmp/rao.yaml" <<YAML
hull: { offsets_csv: $PWD/data/delft372/delft372_offsets.csv, draught_m: 0.15, length_m: 3.0, hulls: 2, spacing_m: 0.70 }
mass: { mass_kg: 87.07, lcg_m_from_ap: 1.41, kyy_m: 0.782 }
speed: { Fn: 0.75 }
water: { rho_kg_m3: 1000 }
solver: { kernel: impulsive, sections: 20, panels: 8, Cs: 0.024, frequencies: { lambda_over_L: [1.0, 1.5, 2.0] } }
YAML
"$bin" rao "$tmp/rao.yaml" --out "$tmp/plots" > "$tmp/plots.out" || fail "rao refused"
[ -s "$tmp/plots.out" ] || fail "rao printed no result line"
[ -s "$tmp/plots/rao.svg" ] || fail "rao wrote no rao.svg"
"$bin" rao "$tmp/rao.yaml" --out "$tmp/bare" --no-plots --quiet > "$tmp/bare.out" || fail "rao --no-plots --quiet refused"
[ -s "$tmp/bare.out" ] && fail "rao --quiet printed: $(cat "$tmp/bare.out")"
[ -e "$tmp/bare/rao.svg" ] && fail "rao --no-plots wrote rao.svg"
cmp -s "$tmp/plots/rao.csv" "$tmp/bare/rao.csv" || fail "rao.csv differs with --no-plots"

"$bin" hull examples/hull_catamaran.yaml --out "$tmp/hull" --quiet > "$tmp/hull.out" || fail "hull --quiet refused"
[ -s "$tmp/hull.out" ] && fail "hull --quiet printed: $(cat "$tmp/hull.out")"
[ -s "$tmp/hull/hydrostatics.json" ] || fail "hull --quiet wrote no hydrostatics.json"

sed -e 's/samples: [0-9]*/samples: 16/' examples/explore_analytic_demo.yaml > "$tmp/explore.yaml"
"$bin" explore "$tmp/explore.yaml" --out "$tmp/explore" --threads 1 --quiet --no-plots > "$tmp/explore.out" ||
  fail "explore --no-plots refused"
[ -s "$tmp/explore.out" ] && fail "explore --quiet printed: $(cat "$tmp/explore.out")"
[ -s "$tmp/explore/samples.csv" ] || fail "explore wrote no samples.csv"
[ -s "$tmp/explore/summary.json" ] || fail "explore wrote no summary.json"
ls "$tmp/explore" | grep -qE '\.svg$|report\.html' && fail "explore --no-plots wrote figures: $(ls "$tmp/explore")"
echo "PASS"
