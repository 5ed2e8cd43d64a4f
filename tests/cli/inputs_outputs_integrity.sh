#!/usr/bin/env bash
# The last silent wrong answers: evaluate honours solver.frequencies of a design config and its warning names
# the key that sets the range; calibrate refuses overflowing tank RAOs (1e200, 1e308) with the rule; invalid
# UTF-8 in a config (a design name) is refused with its line and no output is written; an output that cannot
# be written whole leaves nothing half-written; a speed below the 2D+t method's validity range (Fn 0.1) is
# flagged in every output (stderr, rao.csv header comments, summary.json, the campaign log's message column).
# Usage: bash tests/cli/inputs_outputs_integrity.sh /path/to/hullopt   (from the repo root)
set -u
HULLOPT=${1:?usage: $0 /path/to/hullopt}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failed=0
fail() { echo "FAIL: $*" >&2; failed=1; }  # carry on: every check reports
design() {  # $1 file, $2 speed line, $3 extra solver keys
  { grep -v "^speed:" configs/davis-holloway-2003/hull02_NPL5b.yaml
    echo "$2"
    printf 'solver: { sections: 12, panels: 6, Cs: 0.065%s }\n' "$3"; } > "$1"
}
seas='seas:
  - { spectrum: jonswap, Hs_m: 3.0, Tz_s: 7.5, gamma: 3.3 }'

# 1. evaluate honours solver.frequencies (a narrow omega range 0.6..1.0 rad/s leaves out wave energy).
design "$work/narrow.yaml" 'speed: { kn: 40 }' ', frequencies: { range: { quantity: omega_rad_s, from: 0.6, to: 1.0, count: 9 } }'
{ cat "$work/narrow.yaml"; echo "$seas"; } > "$work/eval_narrow.yaml"
"$HULLOPT" evaluate "$work/eval_narrow.yaml" --out "$work/narrow" > /dev/null 2> "$work/narrow.err" ||
  { cat "$work/narrow.err" >&2; fail "evaluate with solver.frequencies failed"; }
grep -q "the RAO table (omega 0.6..1 rad/s) leaves out" "$work/narrow.err" ||
  { cat "$work/narrow.err" >&2; fail "solver.frequencies ignored (the grid is not 0.6..1 rad/s)"; }
grep -q "extend solver.frequencies in $work/eval_narrow.yaml" "$work/narrow.err" ||
  { cat "$work/narrow.err" >&2; fail "the warning does not name the key that sets the range"; }
grep -q "omega 0.6..1 rad/s" "$work/narrow/summary.json" || fail "summary.json lacks the warning"
echo "ok: evaluate used solver.frequencies: $(grep -m1 'leaves out' "$work/narrow.err" | cut -c1-200)"
# Through a designs: list as well.
printf 'designs:\n  - { config: %s, name: narrow }\n%s\n' "$work/narrow.yaml" "$seas" > "$work/eval_list.yaml"
"$HULLOPT" evaluate "$work/eval_list.yaml" --out "$work/list" > /dev/null 2> "$work/list.err" || fail "designs list failed"
grep -q "omega 0.6..1 rad/s" "$work/list.err" || { cat "$work/list.err" >&2; fail "designs: solver.frequencies ignored"; }

# 2. calibrate: overflowing tank RAOs are refused with the rule.
for big in 1e200 1e308; do
  awk -F, -v OFS=, -v b="$big" 'NR==3{$6=b} {print}' data/delft372/delft372_tank_rao_fn075.csv > "$work/tank_$big.csv"
  sed "s|\.\./data/delft372/delft372_tank_rao_fn075.csv|$work/tank_$big.csv|" examples/calibrate_synthetic.yaml > "$work/cal_$big.yaml"
  "$HULLOPT" calibrate "$work/cal_$big.yaml" --out "$work/cal_$big" > "$work/cal_$big.out" 2> "$work/cal_$big.err" &&
    fail "calibrate accepted a pitch RAO of $big"
  grep -q "tank_$big.csv:3: column 'pitch_rao' = 1e+${big#1e}: must be <= 100" "$work/cal_$big.err" ||
    { cat "$work/cal_$big.err" "$work/cal_$big.out" >&2; fail "calibrate $big: no rule named"; }
  [ -e "$work/cal_$big/calibrated_solver.yaml" ] && fail "calibrate $big wrote calibrated_solver.yaml"
done
echo "ok: calibrate refuses tank RAOs 1e200 and 1e308: $(cat "$work/cal_1e200.err")"

# 3. Invalid UTF-8 in a design name: refused at input with the line; nothing written.
make_rao() {
  awk 'BEGIN { print "omega_e_rad_s,omega_rad_s,lambda_over_L,heave_amp,heave_phase_deg,pitch_amp,pitch_phase_deg";
    for (i = 0; i < 30; i++) { w = 0.2 + 2.8 * i / 29; we = w + w * w * 20.58 / 9.81;
      printf "%.8g,%.8g,%.6g,1,0,1,-90\n", we, w, 2 * 3.14159265 * 9.81 / (w * w) / 40 } }' > "$1"
}
make_rao "$work/rao.csv"
printf 'rao_csv: rao.csv\nname: "caf\xe9"\nhull_extent: { cg_to_transom_m: 18, cg_to_bow_m: 22 }\n%s\n' "$seas" > "$work/utf.yaml"
"$HULLOPT" evaluate "$work/utf.yaml" --out "$work/utf" > /dev/null 2> "$work/utf.err"; rc=$?
[ "$rc" -eq 1 ] || { cat "$work/utf.err" >&2; fail "invalid UTF-8 name: exit $rc (want 1)"; }
grep -q "utf.yaml:2: invalid UTF-8 (byte 0xE9" "$work/utf.err" || { cat "$work/utf.err" >&2; fail "UTF-8 error without line"; }
[ -e "$work/utf" ] && fail "a refused run left an output folder"
echo "ok: invalid UTF-8 refused: $(cat "$work/utf.err")"

# 4. An output that cannot be written (summary.json is a folder) fails with exit 1, no temporary left behind.
printf 'rao_csv: rao.csv\nname: ok\nhull_extent: { cg_to_transom_m: 18, cg_to_bow_m: 22 }\n%s\n' "$seas" > "$work/ok.yaml"
mkdir -p "$work/blocked/summary.json/x"
"$HULLOPT" evaluate "$work/ok.yaml" --out "$work/blocked" > /dev/null 2> "$work/blocked.err" && fail "write over a folder succeeded"
grep -q "summary.json: write failed" "$work/blocked.err" || { cat "$work/blocked.err" >&2; fail "unclear write error"; }
ls -A "$work/blocked" | grep -q '\.tmp-' && fail "a temporary file was left behind"
echo "ok: failed write reported, no partial file: $(cat "$work/blocked.err")"

# 5. Fn 0.1 is outside the method's validity range: flagged in every output.
design "$work/slow.yaml" 'speed: { Fn: 0.1 }' ', frequencies: { lambda_over_L: [0.5, 1.0, 2.0] }'
"$HULLOPT" rao "$work/slow.yaml" --out "$work/rao_slow" > /dev/null 2> "$work/rao_slow.err" || fail "rao at Fn 0.1 failed"
grep -q "warning: .*Fn 0.1 is below the validity range of the 2D+t strip method (Fn >= 0.40" "$work/rao_slow.err" ||
  { cat "$work/rao_slow.err" >&2; fail "rao: no validity warning on stderr"; }
grep -q "^# .*Fn 0.1 is below the validity range" "$work/rao_slow/rao.csv" || fail "rao.csv: no validity warning in the header"
grep -q "lambda/L above 1.46" "$work/rao_slow/rao.csv" || fail "rao.csv: lambda/L 2.0 above the long-wave limit at Fn 0.1 not flagged"
design "$work/fast.yaml" 'speed: { Fn: 0.8 }' ', frequencies: { lambda_over_L: [0.5, 1.0, 2.0] }'
"$HULLOPT" rao "$work/fast.yaml" --out "$work/rao_fast" > /dev/null 2> "$work/rao_fast.err" || fail "rao at Fn 0.8 failed"
grep -q "validity" "$work/rao_fast.err" "$work/rao_fast/rao.csv" && fail "Fn 0.8 flagged"
{ cat "$work/slow.yaml"; echo "$seas"; } > "$work/eval_slow.yaml"
"$HULLOPT" evaluate "$work/eval_slow.yaml" --out "$work/eval_slow" > /dev/null 2> "$work/eval_slow.err" || fail "evaluate at Fn 0.1 failed"
grep -q "Fn 0.1 is below the validity range" "$work/eval_slow.err" || fail "evaluate: no warning on stderr"
grep -q "Fn 0.1 is below the validity range" "$work/eval_slow/summary.json" || fail "evaluate: no warning in summary.json"
{ cat "$work/slow.yaml"; echo "$seas"; cat <<'YAML'
explore:
  samples: 2
  method: lhs
  variables: { L_over_B: [10, 12] }
  objective: { measure: msi, position: mean }
YAML
} > "$work/explore_slow.yaml"
"$HULLOPT" explore "$work/explore_slow.yaml" --out "$work/explore_slow" > /dev/null 2> "$work/explore_slow.err" || fail "explore at Fn 0.1 failed"
grep -q "warning: .*Fn 0.1.* is below the validity range" "$work/explore_slow/samples.csv" || fail "explore: samples.csv message lacks the warning"
grep -q '"evaluations_with_warning": 2' "$work/explore_slow/summary.json" || fail "explore: summary.json does not count the warnings"
grep -q "below the validity range" "$work/explore_slow.err" || fail "explore: no warning on stderr"
echo "ok: Fn 0.1 flagged in rao (stderr, rao.csv), evaluate (stderr, summary.json), explore (samples.csv, summary.json, stderr)"
[ "$failed" -eq 0 ] || exit 1
echo PASS
