#!/usr/bin/env bash
# Campaigns with an operability objective (optimize.objective.measure: scatter_msi | downtime_pct) on a
# three-cell scatter diagram, at 10 x 6 sections x panels so the runs take seconds:
# - explore, scatter_msi: samples.csv has one MSI column per cell, and every row's objective equals
#   sum(p_i MSI_i) / sum(p_i) recomputed here from those columns and the probabilities of the CSV;
# - the same run resumed replays every row (nothing recomputed); a row whose objective was edited is refused
#   by the journal check, naming the line and column;
# - optimize, downtime_pct: every row's objective equals 100 x the probability of the cells whose MSI exceeds
#   the criterion's limit (an MSI criterion at the objective's position), recomputed from the cell columns.
# Usage: bash tests/cli/campaign_operability.sh /path/to/hullopt
set -u
HULLOPT=${1:?usage: $0 /path/to/hullopt}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failed=0
fail() { echo "FAIL: $*" >&2; failed=1; }
# Per mille, as route tables are often printed: 500 + 350 + 150.
cat > "$work/route.csv" <<'CSV'
# three cells, parts per thousand
Hs_m\Tz_s,5.5,7.5
1.0,500,
2.0,350,
3.0,,150
CSV
sed -e 's/  sections: 40 .*/  sections: 10/' -e 's/  panels: 14 .*/  panels: 6/' \
    -e 's/  max_evaluations: 300 .*/  max_evaluations: 14/' -e 's/  samples: 200 .*/  samples: 6/' \
    -e 's/  objective: .*/  objective: { measure: scatter_msi, position: mean }/' \
    configs/optimize-catamaran.yaml > "$work/explore.yaml"
cat >> "$work/explore.yaml" <<'YAML'
operability:
  scatter_csv: route.csv
  probabilities: per_mille
  criteria:
    - { msi_max_pct: 20, position: mean, name: comfort }
YAML
sed -e 's/  objective: .*/  objective: { measure: downtime_pct, criterion: comfort }/' "$work/explore.yaml" \
    > "$work/optimize.yaml"

# check_rows FILE MODE: MODE msi (weighted mean) or downtime (limit 20 %); probabilities from route.csv.
check_rows() {
  python3 - "$1" "$2" "$work/route.csv" <<'PY'
import csv, sys
path, mode, route = sys.argv[1:]
lines = [l for l in open(route) if l.strip() and not l.startswith("#")]
periods = [float(t) for t in lines[0].strip().split(",")[1:]]
cells = {}
for l in lines[1:]:
    f = l.strip().split(",")
    for j, v in enumerate(f[1:]):
        if v:
            cells["msi_pct_Hs%g_Tz%g" % (float(f[0]), periods[j])] = float(v) / 1000.0
rows = list(csv.DictReader(open(path)))
missing = [c for c in cells if c not in rows[0]]
if missing:
    print("FAIL %s: no column %s" % (path, missing)); sys.exit(1)
checked = 0
seen = set()
for r in rows:
    if r["objective"] == "nan":
        continue
    msi = {c: float(r[c]) for c in cells}
    if mode == "msi":
        want = sum(p * msi[c] for c, p in cells.items()) / sum(cells.values())
        tol = 1e-12 * abs(want)  # sums in another order: a few ulps
    else:
        seen.add(round(100.0 * sum(p for c, p in cells.items() if msi[c] > 20.0) / sum(cells.values()), 6))
        want = 100.0 * sum(p for c, p in cells.items() if msi[c] > 20.0) / sum(cells.values())
        tol = 1e-9
    got = float(r["objective"])
    if abs(got - want) > tol:
        print("FAIL %s: evaluation %s objective %r, recomputed from the cells %r" % (path, r["evaluation"], got, want))
        sys.exit(1)
    checked += 1
if mode == "downtime" and len(seen) < 2:
    print("FAIL %s: every row has the same downtime %r: the cells never cross the limit" % (path, seen)); sys.exit(1)
if checked < 3:
    print("FAIL %s: only %d evaluated rows" % (path, checked)); sys.exit(1)
print("%s: %d rows, objective = %s recomputed from %d cells" % (path.split("/")[-2], checked, mode, len(cells)))
PY
}

"$HULLOPT" explore "$work/explore.yaml" --out "$work/ex" --quiet > "$work/ex.log" 2>&1 ||
  fail "explore run: $(cat "$work/ex.log")"
check_rows "$work/ex/samples.csv" msi || failed=1
grep -q '"best_objective"' "$work/ex/summary.json" || fail "explore: no best_objective in summary.json"

"$HULLOPT" explore "$work/explore.yaml" --out "$work/ex" --quiet > "$work/ex2.log" 2>&1 ||
  fail "resume refused an intact log: $(cat "$work/ex2.log")"
grep -q '"computed_evaluations": 0' "$work/ex/summary.json" || fail "resume recomputed rows"

# Edit a middle row's objective: the journal check recomputes it from the row's cell columns.
cp -r "$work/ex" "$work/ed"
c=$(head -1 "$work/ed/samples.csv" | tr ',' '\n' | grep -nx objective | cut -d: -f1)
awk -F, -v OFS=, -v c="$c" 'NR==3{$c=12.5} {print}' "$work/ex/samples.csv" > "$work/ed/samples.csv"
"$HULLOPT" explore "$work/explore.yaml" --out "$work/ed" --quiet > "$work/ed.log" 2>&1 &&
  fail "an edited objective was accepted"
grep -q "samples.csv:3: column 'objective'" "$work/ed.log" || fail "edited objective: $(cat "$work/ed.log")"

"$HULLOPT" optimize "$work/optimize.yaml" --out "$work/op" --quiet > "$work/op.log" 2>&1 ||
  fail "optimize run: $(cat "$work/op.log")"
check_rows "$work/op/history.csv" downtime || failed=1

[ $failed -eq 0 ] && echo "campaign operability CLI: all checks passed"
exit $failed
