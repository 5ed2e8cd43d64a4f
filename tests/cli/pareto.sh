#!/usr/bin/env bash
# hullopt optimize with optimize.pareto: bad sweep definitions exit 1 with one line naming the key and the
# rule, before any evaluation (the sweep itself is run and reported in docs/resistance.md).
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
[ $fail -eq 0 ] && echo "pareto CLI: all checks passed"
exit $fail
