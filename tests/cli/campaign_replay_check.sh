#!/usr/bin/env bash
# Resume checks every logged row against what the campaign implies before replaying it: an edited objective
# (last row: the spot recomputation; a middle row: the objective the row's variables imply), an edited
# `feasible`, a non-finite number, a refused row with values, a variable outside its bounds, a duplicated
# (run, step) - each refused with the file, line and column, the file left untouched. An intact log resumes.
# The MSI part (per-sea columns; objective = weighted mean of the seas) uses a small 2-sample explore.
# Usage: bash tests/cli/campaign_replay_check.sh /path/to/hullopt
set -u
HULLOPT=${1:?usage: $0 /path/to/hullopt}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failed=0
fail() { echo "FAIL: $*" >&2; failed=1; }  # carry on: every check reports
cat > "$work/opt.yaml" <<'YAML'
# hullopt optimize
optimize:
  algorithm: LN_COBYLA
  max_evaluations: 40
  seed: 3
  variables: { x1: [-2, 2], x2: [-2, 2] }
  start: { x1: -0.5, x2: 0.5 }
  constraints: { radius_sq_max: 1.0 }
  objective: { analytic: rosenbrock }
YAML
"$HULLOPT" optimize "$work/opt.yaml" --out "$work/good" --quiet || fail "first run failed"
rows=$(( $(wc -l < "$work/good/history.csv") - 1 ))
"$HULLOPT" optimize "$work/opt.yaml" --out "$work/good" --quiet || fail "an intact log was refused"
grep -q '"computed_evaluations": 0' "$work/good/summary.json" || fail "intact log not replayed"

col() { head -1 "$1" | tr ',' '\n' | grep -nx "$2" | cut -d: -f1; }
# expect_refused NAME LINE COLUMN AWK-EDIT MESSAGE-PATTERN: edit field COLUMN of line LINE, re-run, expect exit 1
expect_refused() {
  local name=$1 line=$2 column=$3 value=$4 pattern=$5
  rm -rf "$work/$name"; cp -r "$work/good" "$work/$name"
  local c; c=$(col "$work/$name/history.csv" "$column")
  awk -F, -v OFS=, -v l="$line" -v c="$c" -v v="$value" 'NR==l{$c=v} {print}' "$work/good/history.csv" > "$work/$name/history.csv"
  cp "$work/$name/history.csv" "$work/$name/edited.csv"
  "$HULLOPT" optimize "$work/opt.yaml" --out "$work/$name" --quiet 2> "$work/$name.err" &&
    fail "$name: edited log accepted"
  grep -q "history.csv:$line: column '$column'.*$pattern" "$work/$name.err" ||
    { cat "$work/$name.err" >&2; fail "$name: refusal does not name line $line, column $column and the rule"; }
  cmp -s "$work/$name/history.csv" "$work/$name/edited.csv" || fail "$name: the refused log was modified"
  echo "ok: $name refused: $(cut -c1-160 "$work/$name.err")"
}
last=$((rows + 1))
mid=$((rows / 2 + 1))
expect_refused last_objective "$last" objective 20.0 "give"
expect_refused middle_objective "$mid" objective 20.0 "variables give"
expect_refused last_quantity "$last" radius_sq 0.123 "the design gives .*spot check"
expect_refused nan_objective "$mid" objective nan "must be finite"
expect_refused inf_quantity "$mid" radius_sq inf "must be finite"
expect_refused feasible_word "$mid" feasible yes "must be 0 or 1"
expect_refused negative_time "$mid" wall_time_s -1 "finite time"
expect_refused out_of_bounds "$mid" x1 7 "outside the variable's bounds"
# The feasible column of an infeasible row must be refused too: find one.
inf_line=$(awk -F, -v c="$(col "$work/good/history.csv" feasible)" 'NR>1 && $c==0 {print NR; exit}' "$work/good/history.csv")
feas_line=$(awk -F, -v c="$(col "$work/good/history.csv" feasible)" 'NR>1 && $c==1 {print NR; exit}' "$work/good/history.csv")
[ -n "$inf_line" ] && [ -n "$feas_line" ] || fail "the test campaign needs feasible and infeasible rows"
expect_refused infeasible_marked "$inf_line" feasible 1 "own values give"
expect_refused feasible_unmarked "$feas_line" feasible 0 "own values give"

# A duplicated row (same run and step twice, renumbered).
rm -rf "$work/dup"; cp -r "$work/good" "$work/dup"
{ head -n "$last" "$work/good/history.csv"; tail -1 "$work/good/history.csv" | sed "s/^[0-9]*,/$rows,/"; } > "$work/dup/history.csv"
"$HULLOPT" optimize "$work/opt.yaml" --out "$work/dup" --quiet 2> "$work/dup.err" && fail "duplicated row accepted"
grep -q "history.csv:$((last + 1)): column 'step'.*logged twice" "$work/dup.err" || { cat "$work/dup.err" >&2; fail "duplicate not named"; }
echo "ok: duplicated row refused"

# MSI objective: the per-sea columns and the objective they imply.
cat > "$work/msi.yaml" <<'YAML'
# hullopt explore
hull:
  parametric: { type: catamaran, section_style: round_bilge, displacement_t: 1000, L_over_B: 11.0, B_over_T: 2.0,
                Cb: 0.40, Cp: 0.69, Cwp: 0.76, LCB_pct_L: -6.4, LCF_pct_L: -8.3, transom_immersion: 0.3,
                spacing_over_L: 0.25 }
speed: { kn: 40 }
solver: { Cs: 0.065, sections: 12, panels: 6 }
seas:
  - { spectrum: jonswap, Hs_m: 1.0, Tz_s: 5.5, gamma: 3.3 }
  - { spectrum: jonswap, Hs_m: 3.0, Tz_s: 7.5, gamma: 3.3 }
explore:
  samples: 3
  method: lhs
  variables: { L_over_B: [10, 12] }
  objective: { measure: msi, position: mean, sea_weights: [1, 1] }
YAML
"$HULLOPT" explore "$work/msi.yaml" --out "$work/msi" --quiet 2> "$work/msi.err" || { cat "$work/msi.err" >&2; fail "MSI explore failed"; }
sea=$(awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) if ($i ~ /^msi_pct_Hs1/) { print $i; exit } }' "$work/msi/samples.csv")
for edit in "nan:must be finite" "0.5:give"; do
  v=${edit%%:*}; pat=${edit#*:}
  rm -rf "$work/msi_$v"; cp -r "$work/msi" "$work/msi_$v"
  c=$(col "$work/msi/samples.csv" "$sea")
  awk -F, -v OFS=, -v c="$c" -v v="$v" 'NR==3{$c=v} {print}' "$work/msi/samples.csv" > "$work/msi_$v/samples.csv"
  "$HULLOPT" explore "$work/msi.yaml" --out "$work/msi_$v" --quiet 2> "$work/msi_$v.err" && fail "MSI: edited sea column ($v) accepted"
  grep -q "samples.csv:3: column '\(objective\|$sea\)'.*$pat" "$work/msi_$v.err" ||
    { cat "$work/msi_$v.err" >&2; fail "MSI: edited sea column ($v) not named"; }
  echo "ok: MSI sea column $v refused: $(cut -c1-160 "$work/msi_$v.err")"
done
# A consistent edit (sea value and objective together) of the last row passes every row rule; the spot
# recomputation catches it.
rm -rf "$work/msi_consistent"; cp -r "$work/msi" "$work/msi_consistent"
c=$(col "$work/msi/samples.csv" "$sea"); co=$(col "$work/msi/samples.csv" objective)
awk -F, -v OFS=, -v c="$c" -v co="$co" 'NR==4{$c=sprintf("%.17g", $c + 1); $co=sprintf("%.17g", $co + 0.5)} {print}' \
  "$work/msi/samples.csv" > "$work/msi_consistent/samples.csv"
"$HULLOPT" explore "$work/msi.yaml" --out "$work/msi_consistent" --quiet 2> "$work/msi_consistent.err" && fail "MSI: consistent edit accepted"
grep -q "samples.csv:4: column '\(objective\|$sea\)'.*the design gives.*spot check" "$work/msi_consistent.err" ||
  { cat "$work/msi_consistent.err" >&2; fail "MSI: consistent edit of the last row not caught by the spot check"; }
echo "ok: MSI consistent edit refused: $(cut -c1-200 "$work/msi_consistent.err")"
# A consistent edit of a row the spot sample does not cover, making it the best: the best rows are recomputed
# too, so the edited row is refused instead of being reported as the best design.
sed 's/samples: 3/samples: 8/' "$work/msi.yaml" > "$work/msi8.yaml"
"$HULLOPT" explore "$work/msi8.yaml" --out "$work/msi8" --quiet 2> "$work/msi8.err" || { cat "$work/msi8.err" >&2; fail "MSI explore (8 samples) failed"; }
rm -rf "$work/msi8_best"; cp -r "$work/msi8" "$work/msi8_best"
# Line 7 is sample 5: the spot sample of 8 rows is samples 0, 2, 4 and 7.
awk -F, -v OFS=, 'NR == 1 { for (i = 1; i <= NF; ++i) { if ($i ~ /^msi_pct_/) s[i] = 1; if ($i == "objective") o = i } }
                  NR == 7 { for (i in s) $i = "0.01"; $o = "0.01" } { print }' \
  "$work/msi8/samples.csv" > "$work/msi8_best/samples.csv"
"$HULLOPT" explore "$work/msi8.yaml" --out "$work/msi8_best" --quiet 2> "$work/msi8_best.err" &&
  fail "MSI: a row edited to be the best was accepted (and reported as the best design)"
grep -q "samples.csv:7: column .*the design gives.*spot check" "$work/msi8_best.err" ||
  { cat "$work/msi8_best.err" >&2; fail "MSI: the edited best row is not named"; }
echo "ok: edited best row refused: $(cut -c1-200 "$work/msi8_best.err")"
[ "$failed" -eq 0 ] || exit 1
echo "PASS: replay checks"
