#!/usr/bin/env bash
# End-to-end checks of `hullopt calibrate` (docs/calibration.md): the demo config runs and writes the contract
# files; the three fit modes run; bad data and bad configs exit 1 with a one-line error naming file, line/key
# and rule.
# Usage: bash tests/cli/calibrate.sh /path/to/hullopt   (from the repo root)
set -u
HULLOPT=${1:?usage: calibrate.sh /path/to/hullopt}
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
fail=0
check() { if ! eval "$2"; then echo "FAIL: $1"; fail=1; fi; }
DELFT=$PWD/data/delft372/delft372_tank_rao_fn075.csv
MODEL='model: { synthetic_oscillator: { heave_natural_rad_s: 8.1, pitch_natural_rad_s: 8.4 } }'

# 1. The demo example: contract files and keys.
"$HULLOPT" calibrate examples/calibrate_synthetic.yaml --out "$T/demo" > "$T/demo.log" 2>&1
check "demo exits 0" '[ $? -eq 0 ]'
for f in calibration.json calibration_report.txt calibration_plot.svg calibrated_solver.yaml config.resolved.yaml VERSION; do
  check "demo writes $f" "[ -s '$T/demo/$f' ]"
done
for k in '"Cs":' '"Cs_std_error":' '"rms_residual":' '"reduced_chi_square":' '"residuals":' '"relative_error_after":'; do
  check "calibration.json has $k" "grep -q '$k' '$T/demo/calibration.json'"
done
check "solver snippet has Cs" "grep -Eq '^  Cs: [0-9.]+' '$T/demo/calibrated_solver.yaml'"
check "svg is an svg" "grep -q '<svg' '$T/demo/calibration_plot.svg'"
check "brief report printed" "grep -q 'Cs calibration (single): Cs = ' '$T/demo.log'"

# 2. per_speed with two speeds in two files, and linear_in_parameter across two hulls.
sed 's/^0.75,/0.5,/' "$DELFT" > "$T/fn05.csv"
cat > "$T/per_speed.yaml" <<YAML
calibrate:
  speeds_Fn: [0.5, 0.75]
  data: [$DELFT, $T/fn05.csv]
  mode: per_speed
  $MODEL
YAML
"$HULLOPT" calibrate "$T/per_speed.yaml" --out "$T/ps" > "$T/ps.log" 2>&1
check "per_speed exits 0 ($(tail -1 "$T/ps.log"))" '[ $? -eq 0 ]'
check "per_speed writes one snippet per speed" "[ -s '$T/ps/calibrated_solver_Fn0.5.yaml' ] && [ -s '$T/ps/calibrated_solver_Fn0.75.yaml' ]"
cat > "$T/linear.yaml" <<YAML
speed: { Fn: 0.75 }
calibrate:
  mode: linear_in_parameter
  parameter_name: B_over_T
  hulls:
    - { name: A, parameter: 1.5, data: [$DELFT], $MODEL }
    - { name: B, parameter: 2.5, data: [$DELFT], model: { synthetic_oscillator: { heave_zeta0: 0.05 } } }
YAML
"$HULLOPT" calibrate "$T/linear.yaml" --out "$T/lin" > "$T/lin.log" 2>&1
check "linear_in_parameter exits 0 ($(tail -1 "$T/lin.log"))" '[ $? -eq 0 ]'
check "linear law in the snippet" "grep -q 'law: Cs = .* B_over_T' '$T/lin/calibrated_solver_A_Fn0.75.yaml'"

# 3. Bad input: exit 1, "hullopt: error:" and the expected words.
expect_error() {  # name, config text, expected substring
  printf '%s\n' "$2" > "$T/$1.yaml"
  "$HULLOPT" calibrate "$T/$1.yaml" --out "$T/out_$1" > "$T/$1.log" 2>&1
  local rc=$?
  check "$1: exit 1 (got $rc)" "[ $rc -eq 1 ]"
  if ! grep -q '^hullopt: error: ' "$T/$1.log" || ! grep -qF -- "$3" "$T/$1.log"; then
    echo "FAIL: $1: expected message containing: $3"
    echo "      got: $(head -c 300 "$T/$1.log")"
    fail=1
  fi
  check "$1: no output folder" "[ ! -e '$T/out_$1' ]"
}
cfg() { printf 'speed: { Fn: 0.75 }\ncalibrate:\n  data: [%s]\n  %s\n%s' "$1" "$MODEL" "${2:-}"; }
printf 'Fn,lambda_over_L,heave_rao\n0.75,1.0,0.5\n' > "$T/nocol.csv"
expect_error missing_column "$(cfg "$T/nocol.csv")" "nocol.csv:1: missing column 'pitch_rao'"
printf 'Fn,lambda_over_L,heave_rao,pitch_rao\n0.75,1.0,0.5,0.4\n0.75,1.2,-0.5,0.4\n' > "$T/neg.csv"
expect_error negative_rao "$(cfg "$T/neg.csv")" "neg.csv:3: column 'heave_rao' = -0.5: an RAO magnitude must be >= 0"
printf 'Fn,lambda_over_L,heave_rao,pitch_rao\n0.75,1.0,n/a,0.4\n' > "$T/text.csv"
expect_error non_numeric "$(cfg "$T/text.csv")" "text.csv:2: column 'heave_rao' = 'n/a': not a number"
printf 'Fn,lambda_over_L,heave_rao,pitch_rao\n0.75,1.0,0.5,0.4\n0.6,1.0,0.5,0.4\n' > "$T/speed.csv"
expect_error undefined_speed "$(cfg "$T/speed.csv")" "speed.csv:3: column 'Fn' = 0.6: not a speed of the config"
printf 'Fn,lambda_over_L,heave_rao,pitch_rao\n0.75,1.0,0.5,0.4\n' > "$T/one.csv"
expect_error too_few_points "$(cfg "$T/one.csv" '  weights: { pitch: 0 }')" "1 residual(s) for 1 fitted parameter(s)"
: > "$T/empty.csv"
expect_error empty_file "$(cfg "$T/empty.csv")" "empty.csv: empty file"
expect_error unknown_key "$(cfg "$DELFT" '  Cs_inital: 0.03')" "unknown key 'calibrate.Cs_inital'"
expect_error speed_in_knots "$(printf 'speed: { kn: 20 }\ncalibrate:\n  data: [%s]\n  %s\n' "$DELFT" "$MODEL")" "give the speed as Fn"
expect_error bad_mode "$(cfg "$DELFT" '  mode: everything')" "one of: single, per_speed, linear_in_parameter"
expect_error negative_weight "$(cfg "$DELFT" '  weights: { heave: -1 }')" "calibrate.weights.heave' = -1: must be >= 0"
expect_error no_model "$(printf 'speed: { Fn: 0.75 }\ncalibrate:\n  data: [%s]\n' "$DELFT")" "missing required key 'hull'"
expect_error missing_file "$(cfg "$T/nope.csv")" "nope.csv': no such file"

# 4. hullopt runs the command in hullopt-calibrate beside it: without that executable, exit 3 and one line naming it.
mkdir "$T/alone" && cp "$HULLOPT" "$T/alone/hullopt"
"$T/alone/hullopt" calibrate examples/calibrate_synthetic.yaml --out "$T/alone/out" > "$T/alone.log" 2>&1
rc=$?
check "without hullopt-calibrate: exit 3 (got $rc)" "[ $rc -eq 3 ]"
check "without hullopt-calibrate: one line naming it ($(head -c 200 "$T/alone.log"))" \
  "[ \$(wc -l < '$T/alone.log') -eq 1 ] && grep -q '^hullopt: internal error: cannot run $T/alone/hullopt-calibrate' '$T/alone.log'"

[ $fail -eq 0 ] && echo "cli calibrate: all checks passed"
exit $fail
