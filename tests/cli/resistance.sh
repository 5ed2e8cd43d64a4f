#!/usr/bin/env bash
# hullopt resistance end to end: the example writes resistance.csv (units in the header, finite numbers,
# R_T = R_V + R_W + R_H, P_E = R_T U), resistance.svg, config.resolved.yaml that re-runs to the same table;
# bad inputs exit 1 with one line naming the key and the rule.
set -u
BIN="$1"
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
fail=0

"$BIN" resistance examples/resistance_catamaran.yaml --out "$T/good" > "$T/good.log" 2> "$T/good.err" ||
  { echo "FAIL good config: $(cat "$T/good.log" "$T/good.err")"; fail=1; }
for f in resistance.csv resistance.svg config.resolved.yaml VERSION; do
  [ -s "$T/good/$f" ] || { echo "FAIL missing $f"; fail=1; }
done
grep -q '^speed_kn,speed_m_s,Fn,Re,C_F,S_m2,R_F_kN,R_V_kN,R_W_kN,R_H_kN,R_T_kN,C_W,C_T,P_E_kW,' "$T/good/resistance.csv" ||
  { echo "FAIL resistance.csv header"; fail=1; }
grep -qiE 'nan|inf' <(grep -v '^#' "$T/good/resistance.csv" | cut -d, -f1-16) && { echo "FAIL non-finite numbers"; fail=1; }
# Sums: R_T = R_V + R_W + R_H and P_E = R_T U (relative 1e-6: the CSV keeps 8 significant digits).
awk -F, '!/^#/ && NR>1 && $1 != "speed_kn" { if (($11 - $8 - $9 - $10)^2 > (1e-6*$11)^2 || ($14 - $11*$2)^2 > (1e-6*$14)^2) { print "FAIL sums at " $1 " kn"; bad=1 } } END { exit bad }' "$T/good/resistance.csv" || fail=1
[ "$(grep -vc '^#' "$T/good/resistance.csv")" -eq 16 ] || { echo "FAIL want 15 speeds"; fail=1; }
"$BIN" resistance "$T/good/config.resolved.yaml" --out "$T/again" > /dev/null 2>&1 || { echo "FAIL resolved config does not re-run"; fail=1; }
cmp -s <(grep -v '^#' "$T/good/resistance.csv") <(grep -v '^#' "$T/again/resistance.csv") || { echo "FAIL resolved config gives a different table"; fail=1; }

# bad NAME EXPECTED-SUBSTRING RESISTANCE-BLOCK
H='hull: { parametric: { type: catamaran, displacement_t: 1000, L_over_B: 11, B_over_T: 2, Cb: 0.4, Cp: 0.69, Cwp: 0.76, LCB_pct_L: -6.4, LCF_pct_L: -8.3 } }'
bad() {
  local name="$1" expect="$2" text="$3"
  printf '%s\n%s\n' "$H" "$text" > "$T/$name.yaml"
  "$BIN" resistance "$T/$name.yaml" --out "$T/out_$name" > "$T/$name.out" 2> "$T/$name.err"
  local rc=$?
  if [ $rc -ne 1 ]; then echo "FAIL $name: exit code $rc (want 1)"; fail=1; fi
  if [ "$(wc -l < "$T/$name.err")" -ne 1 ]; then echo "FAIL $name: want one line: $(cat "$T/$name.err")"; fail=1; fi
  grep -qF -- "$expect" "$T/$name.err" || { echo "FAIL $name: message lacks '$expect': $(cat "$T/$name.err")"; fail=1; }
  [ -e "$T/out_$name/resistance.csv" ] && { echo "FAIL $name: wrote resistance.csv"; fail=1; }
}
bad zero_speed "speeds_kn" 'resistance: { speeds_kn: [0, 10] }'
bad zero_fn "must be > 0" 'resistance: { speeds_Fn: [0.0] }'
bad zero_range "from" 'resistance: { speed_range_kn: { from: 0, to: 10, step: 1 } }'
bad decreasing "strictly increasing" 'resistance: { speeds_kn: [20, 10] }'
bad two_lists "one of" 'resistance: { speeds_kn: [20], speeds_Fn: [0.5] }'
bad form_factor "form_factor" 'resistance: { speeds_kn: [20], form_factor: 0.8 }'
bad viscosity "kinematic_viscosity_m2_s" 'resistance: { speeds_kn: [20], kinematic_viscosity_m2_s: 1 }'
bad michell "lambda_max" 'resistance: { speeds_kn: [20], michell: { lambda_max: 2 } }'
bad unknown "form_factr" 'resistance: { speeds_kn: [20], form_factr: 1.1 }'
bad no_speed "speeds_kn" 'resistance: { form_factor: 1.1 }'
bad zero_design_speed "speed" 'speed: { kn: 0 }'
[ $fail -eq 0 ] && echo "resistance CLI: all checks passed"
exit $fail
