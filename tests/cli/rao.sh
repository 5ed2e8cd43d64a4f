#!/usr/bin/env bash
# hullopt rao end to end: rao.csv with the contract header, and one-line errors with a non-zero exit for bad
# input (zero or negative speed, empty or negative frequency list, unknown key, sectional force form). With
# solver.adaptive_grid: off rao.csv holds exactly the given frequencies; on (the default) the grid is refined
# around the peaks: more rows, increasing in omega, no under-sampled peak.
set -u
bin="$1"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*"; exit 1; }

base() {  # $1: speed block, $2: frequencies block
  cat <<YAML
hull: { offsets_csv: $PWD/data/delft372/delft372_offsets.csv, draught_m: 0.15, length_m: 3.0, hulls: 2, spacing_m: 0.70 }
mass: { mass_kg: 87.07, lcg_m_from_ap: 1.41, kyy_m: 0.782 }
speed: $1
water: { rho_kg_m3: 1000 }
solver: { kernel: impulsive, sections: 20, panels: 8, Cs: 0.024, frequencies: $2 }
YAML
}

base "{ Fn: 0.75 }" "{ lambda_over_L: [1.0, 1.5, 2.0] }" > "$tmp/refined.yaml"
"$bin" rao "$tmp/refined.yaml" --out "$tmp/refined" 2> "$tmp/refined.err" || fail "adaptive grid run refused"
rows=$(grep -v '^#' "$tmp/refined/rao.csv" | tail -n +2 | wc -l)
[ "$rows" -gt 3 ] || fail "adaptive grid: rao.csv has $rows rows, want more than the 3 given"
grep -v '^#' "$tmp/refined/rao.csv" | tail -n +2 | awk -F, 'NR > 1 && $2 <= w { exit 1 } { w = $2 }' ||
  fail "adaptive grid: rao.csv not increasing in omega"
grep -q "under-sampled" "$tmp/refined.err" && fail "adaptive grid leaves an under-sampled peak: $(cat "$tmp/refined.err")"
sed 's/Cs: 0.024,/Cs: 0.024, adaptive_grid: off,/' "$tmp/refined.yaml" > "$tmp/ok.yaml"
"$bin" rao "$tmp/ok.yaml" --out "$tmp/ok" || fail "good config refused"
header=$(awk '!/^#/ { print; exit }' "$tmp/ok/rao.csv")
[ "$header" = "omega_e_rad_s,omega_rad_s,lambda_over_L,heave_amp,heave_phase_deg,pitch_amp,pitch_phase_deg" ] ||
  fail "rao.csv header: $header"
[ "$(grep -v '^#' "$tmp/ok/rao.csv" | wc -l)" = 4 ] || fail "rao.csv should have 3 rows"
grep -qi nan "$tmp/ok/rao.csv" && fail "NaN in rao.csv"
[ -s "$tmp/ok/rao.svg" ] || fail "no rao.svg"
[ -s "$tmp/ok/config.resolved.yaml" ] || fail "no config.resolved.yaml"

# solver.headings_deg (method strip_theory_stf): one row per (heading, frequency) with the heading, sway, roll
# and yaw columns; symmetric catamaran in head seas: no sway, roll or yaw.
sed 's/solver: { kernel: impulsive,/solver: { method: strip_theory_stf, headings_deg: [180, 120, 90],/; s/kyy_m: 0.782 }/kyy_m: 0.782, kg_m: 0.34 }/' \
  "$tmp/ok.yaml" > "$tmp/headings.yaml"
"$bin" rao "$tmp/headings.yaml" --out "$tmp/headings" || fail "headings run refused"
# The rao.csv of headings [180, 120, 90] in folder $1: its columns, 3 x 3 rows, no sway, roll or yaw on the
# symmetric catamaran in head seas, roll in beam seas.
check_headings() {
  local header
  header=$(awk '!/^#/ { print; exit }' "$1/rao.csv")
  [ "$header" = "wave_direction_deg,omega_e_rad_s,omega_rad_s,lambda_over_L,heave_amp,heave_phase_deg,pitch_amp,pitch_phase_deg,sway_amp,sway_phase_deg,roll_amp,roll_phase_deg,yaw_amp,yaw_phase_deg" ] ||
    fail "$1: headings rao.csv header: $header"
  [ "$(grep -v '^#' "$1/rao.csv" | tail -n +2 | wc -l)" = 9 ] || fail "$1: headings rao.csv should have 3 x 3 rows"
  grep -v '^#' "$1/rao.csv" | tail -n +2 | awk -F, '$1 == 180 && ($9 > 1e-9 || $11 > 1e-9 || $13 > 1e-9) { exit 1 }' ||
    fail "$1: head seas on a symmetric catamaran show sway, roll or yaw"
  grep -v '^#' "$1/rao.csv" | tail -n +2 | awk -F, '$1 == 90 && $11 < 0.1 { exit 1 }' || fail "$1: beam seas without roll"
}
check_headings "$tmp/headings"
grep -q "^# the oblique-sea strip theory (STF, Cs = .* in heave and pitch) at 3 headings" "$tmp/headings/rao.csv" ||
  fail "strip_theory_stf headings rao.csv does not name the method and its Cs"
grep -q "roll damping: the demihulls' Cs heave damping" "$tmp/headings/rao.csv" ||
  fail "headings rao.csv does not say which roll damping the catamaran has"
grep -q "^# warning: roll damping: Ikeda's monohull formulae do not cover a demihull pair" "$tmp/headings/rao.csv" ||
  fail "headings rao.csv does not flag Ikeda's range for the catamaran"

# solver.headings_deg with the time-domain strip method (the default; transient Green function kernel): the same
# rao.csv columns; at 180 deg heave and pitch are those of the head-sea run without the key (the same strips,
# the kernel on full sections instead of mirror-halved: round-off, 1e-8 relative against the CSV's 10
# significant digits), no sway, roll or yaw on the symmetric catamaran, roll in beam seas.
sed 's/solver: { kernel: impulsive,/solver: { /' "$tmp/ok.yaml" > "$tmp/td_head.yaml"
"$bin" rao "$tmp/td_head.yaml" --out "$tmp/td_head" --no-plots --quiet || fail "time-domain head-sea run refused"
sed 's/solver: { /solver: { headings_deg: [180, 120, 90], /; s/kyy_m: 0.782 }/kyy_m: 0.782, kg_m: 0.34 }/' \
  "$tmp/td_head.yaml" > "$tmp/td_headings.yaml"
"$bin" rao "$tmp/td_headings.yaml" --out "$tmp/td_headings" --no-plots --quiet || fail "time-domain headings run refused"
check_headings "$tmp/td_headings"
grep -q "^# the time-domain strip method (periodic steady state, Cs = .* in heave and pitch) at 3 headings" "$tmp/td_headings/rao.csv" ||
  fail "time-domain headings rao.csv does not name the method"
paste -d, <(grep -v '^#' "$tmp/td_head/rao.csv" | tail -n +2) \
  <(grep -v '^#' "$tmp/td_headings/rao.csv" | tail -n +2 | awk -F, '$1 == 180') |
  awk -F, 'function rel(a, b) { d = a - b; if (d < 0) d = -d; return d / (b < 0 ? -b : b) }
           rel($12, $4) > 1e-8 || rel($14, $6) > 1e-8 { print; exit 1 }' ||
  fail "time-domain headings at 180 deg differ from the head-sea run"
# evaluate reads a headings rao.csv whose rows are all at 180 deg as head seas, and refuses one with other
# headings at the first such row.
grep -v '^#' "$tmp/td_headings/rao.csv" | awk -F, 'NR == 1 || $1 == 180' > "$tmp/rao_180.csv"
printf 'rao_csv: rao_180.csv\nhull_extent: { cg_to_transom_m: 1.41, cg_to_bow_m: 1.59 }\nseas: [ { Hs_m: 0.1, Tz_s: 2.5 } ]\n' \
  > "$tmp/ev_180.yaml"
(cd "$tmp" && "$bin" evaluate ev_180.yaml --out ev_180 --quiet --no-plots) || fail "evaluate refused a 180 deg headings rao.csv"
sed 's#rao_180.csv#td_headings/rao.csv#' "$tmp/ev_180.yaml" > "$tmp/ev_all.yaml"
(cd "$tmp" && ! "$bin" evaluate ev_all.yaml --out ev_all --quiet 2> ev_all.err) || fail "evaluate read a rao.csv over headings"
grep -q "wave_direction_deg = 120: a RAO file is read for head seas (180 deg) only" "$tmp/ev_all.err" ||
  fail "evaluate's refusal of a rao.csv over headings: $(cat "$tmp/ev_all.err")"

expect_error() {  # $1: name, $2: config text, $3: text the message must contain
  echo "$2" > "$tmp/$1.yaml"
  if "$bin" rao "$tmp/$1.yaml" --out "$tmp/$1" 2> "$tmp/$1.err"; then fail "$1: accepted"; fi
  grep -q "hullopt: error:" "$tmp/$1.err" || fail "$1: not a clean error: $(cat "$tmp/$1.err")"
  grep -q "$3" "$tmp/$1.err" || fail "$1: message lacks '$3': $(cat "$tmp/$1.err")"
  [ "$(wc -l < "$tmp/$1.err")" = 1 ] || fail "$1: error is not one line"
}
expect_error zero_speed "$(base "{ Fn: 0 }" "{ omega_rad_s: [2.0] }")" "speed.Fn"
expect_error negative_speed "$(base "{ m_s: -2 }" "{ omega_rad_s: [2.0] }")" "speed.m_s"
expect_error empty_list "$(base "{ Fn: 0.75 }" "{ omega_rad_s: [] }")" "omega_rad_s"
expect_error negative_freq "$(base "{ Fn: 0.75 }" "{ omega_e_rad_s: [2.0, -1.0] }")" "> 0"
expect_error unknown_key "$(base "{ Fn: 0.75 }" "{ omega_rad_s: [2.0] }")
extra_key: 1" "extra_key"
expect_error bad_force "$(base "{ Fn: 0.75 }" "{ omega_rad_s: [2.0] }" | sed 's/Cs: 0.024,/Cs: 0.024, sectional_force: lift,/')" \
  "solver.sectional_force"
expect_error impulsive_pressure "$(base "{ Fn: 0.75 }" "{ omega_rad_s: [2.0] }" | sed 's/Cs: 0.024,/Cs: 0.024, sectional_force: pressure,/')" \
  "momentum form only"
# The paper's pressure form runs with the transient kernel and says so in the header.
base "{ Fn: 0.75 }" "{ lambda_over_L: [1.5, 2.0] }" | sed 's/kernel: impulsive,/kernel: transient_green, sectional_force: pressure,/' > "$tmp/p.yaml"
"$bin" rao "$tmp/p.yaml" --out "$tmp/p" || fail "pressure form refused"
grep -q "sectional force: pressure form" "$tmp/p/rao.csv" || fail "rao.csv header does not name the pressure form"
grep -qi nan "$tmp/p/rao.csv" && fail "NaN in rao.csv (pressure form)"
# A hull whose sections stop below the draught (deck edge under water): named body and station.
printf 'x_m,y_m,z_m\n0,0,0\n0,0.5,0.1\n1,0,0\n1,0.5,0.1\n2,0,0\n2,0.5,0.1\n' > "$tmp/low.csv"
expect_error low_deck "hull: { offsets_csv: $tmp/low.csv, draught_m: 0.2 }
speed: { m_s: 2.0 }
solver: { kernel: impulsive, sections: 10, panels: 6, frequencies: { omega_rad_s: [2.0] } }" "waterline"
# Running attitude: even keel given explicitly reproduces the default (refined) rao.csv byte for byte; the Delft 372
# running trim and sinkage at Fn 0.75 (sinkage 2.57 mm up, trim 1.35 deg bow up) runs and says so in the header.
base "{ Fn: 0.75 }" "{ lambda_over_L: [1.0, 1.5, 2.0] }" |
  sed 's/spacing_m: 0.70 }/spacing_m: 0.70, attitude: { sinkage_m: 0.0, trim_deg: 0.0 } }/' > "$tmp/even.yaml"
grep -q "attitude:" "$tmp/even.yaml" || fail "test setup: attitude not inserted"
"$bin" rao "$tmp/even.yaml" --out "$tmp/even" > /dev/null || fail "even-keel attitude refused"
cmp -s "$tmp/refined/rao.csv" "$tmp/even/rao.csv" || fail "even-keel attitude changed rao.csv"
base "{ Fn: 0.75 }" "{ lambda_over_L: [1.0, 1.5, 2.0] }" |
  sed 's/spacing_m: 0.70 }/spacing_m: 0.70, attitude: { sinkage_m: -0.00257, trim_deg: 1.35 } }/' > "$tmp/run.yaml"
"$bin" rao "$tmp/run.yaml" --out "$tmp/run" > /dev/null || fail "running attitude refused"
grep -q "running attitude: sinkage -0.00257 m" "$tmp/run/rao.csv" || fail "rao.csv header lacks the attitude"
cmp -s "$tmp/ok/rao.csv" "$tmp/run/rao.csv" && fail "running attitude did not change rao.csv"
# Trim that puts the Delft 372 deck (0.05 m freeboard) under water at the transom; a rise that lifts it out.
expect_error deck_under "$(base "{ Fn: 0.75 }" "{ omega_rad_s: [2.0] }" |
  sed 's/spacing_m: 0.70 }/spacing_m: 0.70, attitude: { trim_deg: 2.5 } }/')" "hull.attitude.*deck edge"
expect_error lifted_out "$(base "{ Fn: 0.75 }" "{ omega_rad_s: [2.0] }" |
  sed 's/spacing_m: 0.70 }/spacing_m: 0.70, attitude: { sinkage_m: -0.02 } }/')" "hull.attitude.*lifted out"
expect_error big_trim "$(base "{ Fn: 0.75 }" "{ omega_rad_s: [2.0] }" |
  sed 's/spacing_m: 0.70 }/spacing_m: 0.70, attitude: { trim_deg: 7 } }/')" "hull.attitude.trim_deg"
# solver.steady_flow: off (given) leaves rao.csv byte for byte; on solves the attitude and says so in the
# header; on together with hull.attitude is refused naming the key.
sed 's/Cs: 0.024,/Cs: 0.024, steady_flow: off,/' "$tmp/ok.yaml" > "$tmp/sf_off.yaml"
"$bin" rao "$tmp/sf_off.yaml" --out "$tmp/sf_off" > /dev/null || fail "steady_flow: off refused"
cmp -s "$tmp/ok/rao.csv" "$tmp/sf_off/rao.csv" || fail "steady_flow: off changed rao.csv"
sed 's/Cs: 0.024,/Cs: 0.024, steady_flow: on,/' "$tmp/ok.yaml" > "$tmp/sf_on.yaml"
"$bin" rao "$tmp/sf_on.yaml" --out "$tmp/sf_on" > /dev/null || fail "steady_flow: on refused"
grep -q "running attitude: sinkage .* (from calm water on the strips" "$tmp/sf_on/rao.csv" ||
  fail "rao.csv header lacks the solved attitude"
expect_error steady_and_attitude "$(sed 's/spacing_m: 0.70 }/spacing_m: 0.70, attitude: { trim_deg: 1.0 } }/' "$tmp/sf_on.yaml")" \
  "solver.steady_flow.*hull.attitude"
# compare.tank_rao_csv: measured points on rao.svg, the file named relative to the config's folder (run from
# another working directory); a file without a row at the run's Fn is refused naming its speeds.
mkdir -p "$tmp/cmp/data"
cp data/delft372/delft372_tank_rao_fn075.csv "$tmp/cmp/data/tank.csv"
cp "$tmp/ok.yaml" "$tmp/cmp/rao.yaml"
printf 'compare: { tank_rao_csv: data/tank.csv, label: "tank Fn 0.75" }\n' >> "$tmp/cmp/rao.yaml"
(cd / && "$bin" rao "$tmp/cmp/rao.yaml" --out "$tmp/cmp/out" > "$tmp/cmp/log") || fail "compare: refused"
grep -q "measured points drawn: 13" "$tmp/cmp/log" || fail "compare: $(cat "$tmp/cmp/log")"
grep -q "tank Fn 0.75" "$tmp/cmp/out/rao.svg" || fail "compare: no measured series in rao.svg"
[ "$(grep -o 'fill="#ffffff" stroke="#000000"' "$tmp/cmp/out/rao.svg" | wc -l)" -ge $((8 * 13 - 8)) ] ||
  fail "compare: measured markers missing from rao.svg"
expect_error compare_other_speed "$(sed 's/Fn: 0.75/Fn: 0.5/' "$tmp/cmp/rao.yaml" |
  sed "s|data/tank.csv|$tmp/cmp/data/tank.csv|")" "compare.tank_rao_csv.*no row at the run's Fn 0.5 (rows at Fn 0.75)"
echo "rao CLI: all checks passed"
