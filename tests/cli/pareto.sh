#!/usr/bin/env bash
# hullopt optimize with optimize.pareto: bad sweep definitions exit 1 with one line naming the key and the
# rule, before any evaluation; a small sweep (10 x 6 sections x panels, 3 points, 2 starts of at most 12
# evaluations) writes a front whose every point is, recomputed here from all the logs, the best design feasible
# for its limit, non-increasing, and re-runnable from front_NN.yaml (the default catamaran's front:
# docs/resistance.md).
set -u
BIN="$1"
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
fail=0
bad() {  # bad NAME EXPECTED SED-EXPRESSION
  local name="$1" expect="$2" expr="$3"
  sed -e "$expr" configs/optimize-catamaran.yaml > "$T/$name.yaml"
  "$BIN" optimize "$T/$name.yaml" --out "$T/out_$name" --quiet > "$T/$name.out" 2> "$T/$name.err"
  local rc=$?
  [ $rc -eq 1 ] || { echo "FAIL $name: exit code $rc (want 1)"; fail=1; }
  [ "$(wc -l < "$T/$name.err")" -eq 1 ] || { echo "FAIL $name: want one line: $(cat "$T/$name.err")"; fail=1; }
  grep -qF -- "$expect" "$T/$name.err" || { echo "FAIL $name: lacks '$expect': $(cat "$T/$name.err")"; fail=1; }
  [ -e "$T/out_$name/anchor/history.csv" ] && { echo "FAIL $name: evaluated before refusing"; fail=1; }
}
C='s/  constraints: { L_max_m: 75 }/  constraints: { L_max_m: 75 }\n'
bad one_point "at least 2 points" "${C}  pareto: { quantity: P_E_kW, points: 1, to: 11000 }/"
bad quantity "quantity" "${C}  pareto: { quantity: MSI, points: 8, to: 11000 }/"
bad range "must be > from" "${C}  pareto: { quantity: P_E_kW, points: 8, from: 11000, to: 10000 }/"
bad no_to "to" "${C}  pareto: { quantity: P_E_kW, points: 8 }/"
bad constrained "already constrains" 's/  constraints: { L_max_m: 75 }/  constraints: { L_max_m: 75, P_E_max_kW: 12000 }\n  pareto: { quantity: P_E_kW, points: 8, to: 11000 }/'
bad unknown "tooo" "${C}  pareto: { quantity: P_E_kW, points: 8, to: 11000, tooo: 1 }/"
sed -e 's/  sections: 40 .*/  sections: 10/' -e 's/  panels: 14 .*/  panels: 6/' \
    -e 's/  max_evaluations: 300 .*/  max_evaluations: 12/' \
    -e "${C}  pareto: { quantity: P_E_kW, points: 3, to: 10900, starts: 2 }/" \
    configs/optimize-catamaran.yaml > "$T/small.yaml"
"$BIN" optimize "$T/small.yaml" --out "$T/small" --quiet > "$T/small.log" 2>&1 ||
  { echo "FAIL small sweep: $(cat "$T/small.log")"; fail=1; }
python3 - "$T/small" <<'PY' || fail=1
import csv, glob, sys
d = sys.argv[1]
front = list(csv.DictReader(open(d + "/pareto.csv")))
logs = {}
for path in sorted(glob.glob(d + "/point_*/history.csv")):
    logs[path.split("/")[-2]] = list(csv.DictReader(open(path)))
prev = None
for r in front[1:]:
    lim = float(r["limit_P_E_kW"])
    best = min((float(x["objective"]), k, x["evaluation"]) for k, rows in logs.items() for x in rows
               if x["feasible"] == "1" and (float(x["P_E_kW"]) - lim) / lim <= 1e-6)
    if abs(best[0] - float(r["objective"])) > 1e-9 * best[0]:
        print("FAIL %s: front %s, best feasible of the logs %r" % (r["point"], r["objective"], best)); sys.exit(1)
    src = [x for x in logs[r["run_dir"]] if x["evaluation"] == r["evaluation"]][0]
    if src["feasible"] != "1" or float(src["P_E_kW"]) > lim * (1 + 1e-6):
        print("FAIL %s: its design is not feasible for the limit" % r["point"]); sys.exit(1)
    if prev is not None and float(r["objective"]) > prev:
        print("FAIL %s: the front rises" % r["point"]); sys.exit(1)
    prev = float(r["objective"])
if len(front) != 4 or len(logs) != 3:
    print("FAIL: %d front rows, %d point logs" % (len(front), len(logs))); sys.exit(1)
PY
sed 's/  max_evaluations: 12$/  max_evaluations: 1/' "$T/small/front_02.yaml" > "$T/front_02.yaml"
"$BIN" optimize "$T/front_02.yaml" --out "$T/front_02" --quiet > "$T/front.log" 2>&1 ||
  { echo "FAIL front_02.yaml: $(cat "$T/front.log")"; fail=1; }
want=$(awk -F, '$1 == "point_02" { print $3 }' "$T/small/pareto.csv")
got=$(python3 -c "import json,sys; print('%.10g' % json.load(open(sys.argv[1]))['baseline_objective'])" "$T/front_02/summary.json")
[ "$want" = "$got" ] || { echo "FAIL front_02.yaml re-evaluates to $got, pareto.csv has $want"; fail=1; }
[ $fail -eq 0 ] && echo "pareto CLI: all checks passed"
exit $fail
