#!/usr/bin/env bash
# hullopt hull end to end: a good config writes its outputs; bad input of many kinds exits 1 with one line
# "hullopt: error: ..." naming the key or file line and the rule; nothing crashes (exit codes > 1 fail).
set -u
BIN="$1"
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
fail=0

good() {
  "$BIN" hull examples/hull_catamaran.yaml --out "$T/good" > "$T/good.log" 2>&1 || { echo "FAIL good config: $(cat "$T/good.log")"; fail=1; return; }
  for f in hydrostatics.json offsets.csv bodyplan.svg config.resolved.yaml VERSION; do
    [ -s "$T/good/$f" ] || { echo "FAIL good config: missing $f"; fail=1; }
  done
  for k in L_m B_m T_m volume_m3 displacement_t Cb Cp Cm Cwp Cvp LCB_pct_L LCF_pct_L Fr hulls spacing_m; do
    grep -q "\"$k\":" "$T/good/hydrostatics.json" || { echo "FAIL hydrostatics.json lacks $k"; fail=1; }
  done
  # The resolved config re-runs to the same hull.
  "$BIN" hull "$T/good/config.resolved.yaml" --out "$T/again" > /dev/null 2>&1 || { echo "FAIL resolved config does not re-run"; fail=1; }
  cmp -s "$T/good/offsets.csv" "$T/again/offsets.csv" || { echo "FAIL resolved config gives a different hull"; fail=1; }
}

# bad NAME EXPECTED-SUBSTRING CONFIG-TEXT
bad() {
  local name="$1" expect="$2" text="$3"
  printf '%s\n' "$text" > "$T/$name.yaml"
  "$BIN" hull "$T/$name.yaml" --out "$T/out_$name" > "$T/$name.out" 2> "$T/$name.err"
  local rc=$?
  local lines
  lines=$(wc -l < "$T/$name.err")
  if [ $rc -ne 1 ]; then echo "FAIL $name: exit code $rc (want 1)"; fail=1; fi
  if [ "$lines" -ne 1 ]; then echo "FAIL $name: $lines lines on stderr (want 1): $(cat "$T/$name.err")"; fail=1; fi
  if ! grep -q "^hullopt: error: " "$T/$name.err"; then echo "FAIL $name: no 'hullopt: error:' prefix"; fail=1; fi
  if ! grep -qF -- "$expect" "$T/$name.err"; then echo "FAIL $name: message lacks '$expect': $(cat "$T/$name.err")"; fail=1; fi
}

P='type: catamaran, displacement_t: 1000, L_over_B: 11, B_over_T: 2, Cb: 0.4, Cp: 0.69, Cwp: 0.76, LCB_pct_L: -6.4, LCF_pct_L: -8.3'
printf 'x_m,y_m,z_m\n0,0,0\n0,0.1\n' > "$T/malformed.csv"
printf 'x_m,y_m,z_m\n0,0,0\n0,0.1,0.3\n1,0,0\n1,0.1,0.1\n' > "$T/low.csv"
printf 'x_m,y_m,z_m\n0,0,0\n0,0.1,nan\n' > "$T/nan.csv"
: > "$T/empty.stl"
head -c 100 /dev/zero > "$T/trunc.stl"

good
bad missing_key   "missing required key 'hull.parametric.Cwp'" "hull:
  parametric: {type: catamaran, displacement_t: 1000, L_over_B: 11, B_over_T: 2, Cb: 0.4, Cp: 0.69, LCB_pct_L: 0, LCF_pct_L: 0}"
bad wrong_type    "must be a number" "hull:
  parametric: {$P, keel_rise: lots}"
bad unknown_key   "unknown key 'hull.parametric.LCG'" "hull:
  parametric: {$P, LCG: 1}"
bad negative      "hull.parametric.displacement_t' = -1000: must be > 0" "hull:
  parametric: {type: catamaran, displacement_t: -1000, L_over_B: 11, B_over_T: 2, Cb: 0.4, Cp: 0.69, Cwp: 0.76, LCB_pct_L: 0, LCF_pct_L: 0}"
bad nan_value     "NaN" "hull:
  parametric: {$P, keel_rise: .nan}"
bad cp_one        "Cp' = 1.02: must lie in (0, 1)" "hull:
  parametric: {type: catamaran, displacement_t: 1000, L_over_B: 11, B_over_T: 2, Cb: 0.4, Cp: 1.02, Cwp: 0.76, LCB_pct_L: 0, LCF_pct_L: 0}"
bad cm_over_one   "Cm = Cb/Cp" "hull:
  parametric: {type: catamaran, displacement_t: 1000, L_over_B: 11, B_over_T: 2, Cb: 0.7, Cp: 0.6, Cwp: 0.76, LCB_pct_L: 0, LCF_pct_L: 0}"
bad swath         "impossible SWATH" "hull:
  parametric: {type: swath, displacement_t: 1000, L_over_B: 14, B_over_T: 2, Cb: 0.5, Cp: 0.75, Cwp: 0.6, LCB_pct_L: -5, LCF_pct_L: -5, strut_ratio: 0.95}"
bad malformed_row "malformed.csv:3: malformed row" "hull:
  offsets_csv: $T/malformed.csv
  draught_m: 0.15"
bad csv_nan       "nan.csv:3: z_m = 'nan' must be a finite number" "hull:
  offsets_csv: $T/nan.csv
  draught_m: 0.15"
bad no_crossing   "no waterline crossing" "hull:
  offsets_csv: $T/low.csv
  draught_m: 0.15"
bad empty_stl     "STL file is empty" "hull:
  stl: $T/empty.stl
  draught_m: 0.1"
bad trunc_stl     "truncated or corrupt binary STL" "hull:
  stl: $T/trunc.stl
  draught_m: 0.1"
bad no_file       "hull.offsets_csv' = $T/does_not_exist.csv: no such file" "hull:
  offsets_csv: $T/does_not_exist.csv
  draught_m: 0.15"
bad speed_units   "give exactly one of Fn, kn, m_s" "hull:
  parametric: {$P}
speed: {kn: 40, m_s: 20}"
bad yaml_syntax   "YAML syntax error" "hull: [unclosed"
bad attitude_deck "key 'hull.attitude'" "hull:
  parametric: {$P}
  attitude: { sinkage_m: 2.5 }"
bad attitude_trim "hull.attitude.trim_deg" "hull:
  parametric: {$P}
  attitude: { trim_deg: -9 }"
bad attitude_key  "unknown key 'hull.attitude.heel_deg'" "hull:
  parametric: {$P}
  attitude: { heel_deg: 1 }"
bad infeasible_wp "nearest feasible: LCF_pct_L = " "hull:
  parametric: {type: catamaran, displacement_t: 1000, L_over_B: 11, B_over_T: 2, Cb: 0.4, Cp: 0.69, Cwp: 0.9, LCB_pct_L: -6.4, LCF_pct_L: -8}"
bad on_infeasible "must be one of" "hull:
  parametric: {$P, on_infeasible: clamp}"
# A running attitude: hydrostatics.json carries the running hull beside the hull at rest.
printf 'hull:\n  parametric: {%s}\n  attitude: { sinkage_m: 0.05, trim_deg: 0.5 }\n' "$P" > "$T/att.yaml"
"$BIN" hull "$T/att.yaml" --out "$T/att" > /dev/null 2>&1 || { echo "FAIL attitude config refused"; fail=1; }
grep -q '"running_attitude"' "$T/att/hydrostatics.json" || { echo "FAIL hydrostatics.json lacks running_attitude"; fail=1; }
# The nearest feasible waterplane, built on request and recorded.
printf 'hull:\n  parametric: {type: catamaran, displacement_t: 1000, L_over_B: 11, B_over_T: 2, Cb: 0.4, Cp: 0.69, Cwp: 0.9, LCB_pct_L: -6.4, LCF_pct_L: -8, on_infeasible: nearest}\n' > "$T/near.yaml"
"$BIN" hull "$T/near.yaml" --out "$T/near" > "$T/near.log" 2>&1 || { echo "FAIL on_infeasible: nearest refused: $(cat "$T/near.log")"; fail=1; }
grep -q 'LCF_pct_L -8 -> ' "$T/near/hydrostatics.json" || { echo "FAIL hydrostatics.json lacks the adjustment"; fail=1; }
grep -q 'adjusted: ' "$T/near.log" || { echo "FAIL stdout lacks the adjustment"; fail=1; }
"$BIN" hull "$T/nowhere.yaml" --out "$T/x" 2> "$T/nocfg.err"; rc=$?
[ $rc -eq 1 ] && grep -q "cannot open config file" "$T/nocfg.err" || { echo "FAIL missing config: rc $rc $(cat "$T/nocfg.err")"; fail=1; }

[ $fail -eq 0 ] && echo "hull_bad_inputs: all checks passed"
exit $fail
