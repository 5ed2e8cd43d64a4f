#!/usr/bin/env bash
# `resolution_check` of `hullopt evaluate`: a design that is not converged at its strip resolution is flagged
# in msi.csv, summary.json and on stderr; a converged one is not. At 20 sections x 8 panels the SWATH SW3
# (strut over a bulb: 8 panels cannot follow it) moves its heave peak by about 6% when refined to 40 x 16,
# the catamaran NPL 5b by under 1% and its MSI by about 0.2 points (docs/study-14-hulls.md, convergence table).
# The refusal of a check beyond the solver's limits and of a bad tolerance is checked too. The figures are those
# of the fixed 60-frequency grid (solver.adaptive_grid: off), where the convergence table was measured.
set -euo pipefail
HULLOPT=${1:?usage: evaluate_resolution_check.sh /path/to/hullopt}
HULLOPT=$(cd "$(dirname "$HULLOPT")" && pwd)/$(basename "$HULLOPT")
ROOT=$(cd "$(dirname "$0")/../.." && pwd)
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

write_study() {  # $1 file, $2 sections, $3 panels, then extra lines on stdin
  for h in hull02_NPL5b hull11_SW3; do
    { cat "$ROOT/configs/davis-holloway-2003/$h.yaml"; printf 'solver: { sections: %s, panels: %s, adaptive_grid: off }\n' "$2" "$3"; } \
      > "$TMP/$h.yaml"
  done
  { cat <<YAML
designs:
  - { config: hull02_NPL5b.yaml, name: NPL5b, group: catamaran, Cs: 0.065 }
  - { config: hull11_SW3.yaml, name: SW3, group: SWATH, Cs: 0.026 }
seas:
  - sea_state_line: { Hs_m: [1.0, 3.0], gamma: 3.3 }
YAML
    cat; } > "$1"
}

write_study "$TMP/study.yaml" 20 8 <<< "resolution_check: { enabled: true }"
(cd "$TMP" && "$HULLOPT" evaluate study.yaml --out out > stdout.txt 2> stderr.txt) || fail "evaluate with the check failed: $(cat "$TMP/stderr.txt")"

# SW3 flagged everywhere, NPL5b nowhere.
grep -q "design 'SW3': resolution check: not converged at 20 sections x 8 panels: at 40 x 16" "$TMP/stderr.txt" \
  || fail "no resolution warning for SW3 on stderr: $(cat "$TMP/stderr.txt")"
grep -q "NPL5b': resolution check" "$TMP/stderr.txt" && fail "NPL5b flagged: $(cat "$TMP/stderr.txt")"
# (Rows to a file first: `grep -q` in a pipe may end before its writer, whose SIGPIPE fails the pipeline.)
grep '^SW3,' "$TMP/out/msi.csv" > "$TMP/sw3_rows.csv"; grep '^NPL5b,' "$TMP/out/msi.csv" > "$TMP/npl_rows.csv"
grep -q "resolution check: not converged" "$TMP/sw3_rows.csv" || fail "SW3 rows of msi.csv not flagged"
grep -q "resolution check" "$TMP/npl_rows.csv" && fail "NPL5b rows of msi.csv flagged"
/usr/bin/python3 - "$TMP/out/summary.json" <<'PY' || fail "summary.json"
import json, sys
j = json.load(open(sys.argv[1]))
d = {x["name"]: x["resolution_check"] for x in j["designs"]}
assert d["SW3"]["converged"] is False, d["SW3"]
assert d["NPL5b"]["converged"] is True, d["NPL5b"]
assert (d["SW3"]["sections"], d["SW3"]["panels"], d["SW3"]["fine_sections"], d["SW3"]["fine_panels"]) == (20, 8, 40, 16)
# Tolerances of the check (1 point, 3 %) against the figures of the convergence table: SW3's heave peak
# moves by more than 3 %, NPL5b's by less than 1 % and its MSI by less than 0.5 points.
assert abs(d["SW3"]["heave_peak_change"]) > 0.03, d["SW3"]
assert abs(d["NPL5b"]["heave_peak_change"]) < 0.01 and d["NPL5b"]["max_msi_change_pct"] < 0.5, d["NPL5b"]
assert any("SW3" in w and "resolution check" in w for w in j["warnings"]), j["warnings"]
PY

# Without the key nothing is checked and no design carries a resolution_check block.
write_study "$TMP/plain.yaml" 20 8 < /dev/null
(cd "$TMP" && "$HULLOPT" evaluate plain.yaml --out out_plain > /dev/null 2> stderr_plain.txt) || fail "plain evaluate failed"
grep -q "resolution_check" "$TMP/out_plain/summary.json" && fail "resolution_check written without the key"

# Bad inputs: a check beyond the solver's limits, a tolerance out of range.
write_study "$TMP/big.yaml" 20 40 <<< "resolution_check: { enabled: true, factor: 3 }"
set +e; msg=$(cd "$TMP" && "$HULLOPT" evaluate big.yaml --out out_big 2>&1); rc=$?; set -e
[ $rc -eq 1 ] || fail "factor beyond the panel limit: exit $rc"
echo "$msg" | grep -q "resolution_check.factor 3 asks for 60 sections x 120 panels, beyond the solver's 400 x 100" \
  || fail "factor message: $msg"
write_study "$TMP/tol.yaml" 20 8 <<< "resolution_check: { enabled: true, msi_tolerance_pct: 0 }"
set +e; msg=$(cd "$TMP" && "$HULLOPT" evaluate tol.yaml --out out_tol 2>&1); rc=$?; set -e
[ $rc -eq 1 ] || fail "zero tolerance: exit $rc"
echo "$msg" | grep -q "msi_tolerance_pct.*must be in (0, 100\] percentage points" || fail "tolerance message: $msg"
echo "evaluate_resolution_check: ok"
