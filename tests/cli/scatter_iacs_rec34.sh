#!/usr/bin/env bash
# The IACS Rec. 34 North Atlantic scatter diagram (data/iacs-rec34): the transcribed cells against the table's
# own printed SUM row and column and against the cells of a second copy of the table (the Recommendation's
# text, rows 0.5-3.5 and the start of 4.5), then `hullopt evaluate` on it (examples/operability_north_atlantic.yaml):
# the diagram passes the probability-sum rule in per_100000, the operability outputs are consistent with their
# own cells (probabilities summing to 1, the weighted MSI and each criterion's time recomputed from
# operability.csv), and read in the wrong unit the same file is refused.
set -u
BIN="$1"
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
fail=0
CSV="$PWD/data/iacs-rec34/north_atlantic_hs_tz.csv"
PY=/usr/bin/python3
$PY - "$CSV" <<'PYEOF' || fail=1
import csv, sys
rows = [r for r in csv.reader(open(sys.argv[1])) if r and not r[0].startswith("#")]
tz = [float(t) for t in rows[0][1:]]
hs = [float(r[0]) for r in rows[1:]]
cell = [[float(x) if x else 0.0 for x in r[1:]] for r in rows[1:]]
ok = True
if hs != [0.5 + i for i in range(17)] or tz != [1.5 + j for j in range(18)]:
    print("FAIL classes: Hs %r Tz %r" % (hs, tz)); ok = False
# The table's printed SUM column (per Hs row) and SUM row (per Tz column), as printed (integers).
row_sum = [3050, 22575, 23810, 19128, 13289, 8328, 4806, 2586, 1309, 626, 285, 124, 51, 21, 8, 3, 1]
col_sum = [0, 0, 1, 165, 2091, 9280, 19922, 24879, 20870, 12898, 6245, 2479, 837, 247, 66, 16, 3, 1]
# Printed sums are integers rounded from unrounded cells, the cells rounded to 0.1: |diff| <= 0.5 + 0.05 n.
def check(name, values, printed):
    global ok
    for k, (v, p) in enumerate(zip(values, printed)):
        n = sum(1 for x in v if x > 0)
        if abs(sum(v) - p) > 0.5 + 0.05 * n + 1e-9:
            print("FAIL %s %d: cells sum to %.1f, the table prints %d" % (name, k, sum(v), p)); ok = False
check("row", cell, row_sum)
check("column", [[r[j] for r in cell] for j in range(18)], col_sum)
if abs(sum(map(sum, cell)) - 100000.0) > 0.5:
    print("FAIL total %.2f, not 100000" % sum(map(sum, cell))); ok = False
# Second copy (the Recommendation's own text): rows Hs 0.5-3.5 in full, Hs 4.5 up to Tz 7.5.
second = {
  0: [0.0, 0.0, 1.3, 133.7, 865.6, 1186.0, 634.2, 186.3, 36.9, 5.6, 0.7, 0.1, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0],
  1: [0.0, 0.0, 0.0, 29.3, 986.0, 4976.0, 7738.0, 5569.7, 2375.7, 703.5, 160.7, 30.5, 5.1, 0.8, 0.1, 0.0, 0.0, 0.0],
  2: [0.0, 0.0, 0.0, 2.2, 197.5, 2158.8, 6230.0, 7449.5, 4860.4, 2066.0, 644.5, 160.2, 33.7, 6.3, 1.1, 0.2, 0.0, 0.0],
  3: [0.0, 0.0, 0.0, 0.2, 34.9, 695.5, 3226.5, 5675.0, 5099.1, 2838.0, 1114.1, 337.7, 84.3, 18.2, 3.5, 0.6, 0.1, 0.0],
  4: [0.0, 0.0, 0.0, 0.0, 6.0, 196.1, 1354.3],
}
for i, v in second.items():
    for j, x in enumerate(v):
        if cell[i][j] != x:
            print("FAIL Hs %.1f Tz %.1f: %.1f, the second copy %.1f" % (hs[i], tz[j], cell[i][j], x)); ok = False
sys.exit(0 if ok else 1)
PYEOF

"$BIN" evaluate examples/operability_north_atlantic.yaml --out "$T/na" > "$T/na.log" 2>&1 ||
  { echo "FAIL evaluate: $(cat "$T/na.log")"; fail=1; }
$PY - "$T/na" "$CSV" <<'PYEOF' || fail=1
import csv, json, sys
d, src = sys.argv[1], sys.argv[2]
op = json.load(open(d + "/operability.json"))
rows = list(csv.DictReader(open(d + "/operability.csv")))
n_src = sum(1 for r in csv.reader(open(src)) if r and not r[0].startswith("#") and r[0][0].isdigit()
            for x in r[1:] if x and float(x) > 0)
ok = True
if op["cells"] != n_src or len(rows) != n_src:
    print("FAIL cells: json %d, csv %d, diagram %d non-empty" % (op["cells"], len(rows), n_src)); ok = False
p = [float(r["probability"]) for r in rows]
if abs(sum(p) - 1.0) > 1e-9:
    print("FAIL probabilities sum to %.12f" % sum(p)); ok = False
des = op["designs"][0]
# operability.csv prints 10 significant digits: relative 1e-8.
w = sum(pi * float(r["msi_mean_pct"]) for pi, r in zip(p, rows)) / sum(p)
if abs(w - des["weighted_mean_msi_pct"]) > 1e-8 * w:
    print("FAIL weighted MSI %.10g, recomputed %.10g" % (des["weighted_mean_msi_pct"], w)); ok = False
for name, t in des["criterion_time_pct"].items():
    want = 100.0 * sum(pi for pi, r in zip(p, rows) if r["met_" + name] == "1")
    if abs(t - want) > 1e-7:
        print("FAIL %s: %.9f %% of the time, recomputed %.9f" % (name, t, want)); ok = False
allmet = 100.0 * sum(pi for pi, r in zip(p, rows) if all(r["met_" + k] == "1" for k in des["criterion_time_pct"]))
if abs(des["all_criteria_time_pct"] - allmet) > 1e-7:
    print("FAIL all criteria %.9f, recomputed %.9f" % (des["all_criteria_time_pct"], allmet)); ok = False
print("IACS Rec. 34 North Atlantic: weighted mean MSI %.2f %%, %s" % (des["weighted_mean_msi_pct"],
      ", ".join("%s %.2f %%" % kv for kv in sorted(des["criterion_time_pct"].items()))))
sys.exit(0 if ok else 1)
PYEOF

# The same file read as per mille sums to 100, not 1: refused with one line naming the rule.
sed -e 's/per_100000/per_mille/' -e "s#\.\./data/#$PWD/data/#" examples/operability_north_atlantic.yaml > "$T/unit.yaml"
"$BIN" evaluate "$T/unit.yaml" --out "$T/unit" > "$T/unit.out" 2> "$T/unit.err"
rc=$?
[ $rc -eq 1 ] || { echo "FAIL wrong unit: exit code $rc (want 1)"; fail=1; }
grep -F "hullopt: error:" "$T/unit.err" > "$T/unit.errline"
[ "$(wc -l < "$T/unit.errline")" -eq 1 ] || { echo "FAIL wrong unit: want one error line: $(cat "$T/unit.err")"; fail=1; }
grep -qF -- "probabilities sum to 100, not 1" "$T/unit.errline" ||
  { echo "FAIL wrong unit: lacks the sum rule: $(cat "$T/unit.err")"; fail=1; }
exit $fail
