#!/usr/bin/env bash
# hullopt evaluate with an `operability:` block: a one-cell scatter diagram reproduces evaluate's mean MSI of
# the same sea exactly (same digits in operability.json and summary.json); a two-cell diagram weights the cells
# by probability and counts the time each criterion is met; bad diagrams and criteria exit 1 with one line.
set -u
BIN="$1"
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
fail=0
RAO="$PWD/examples/data/synthetic_catamaran_rao.csv"
base() {  # base SEAS-YAML
  printf 'rao_csv: %s\nname: cat\nhull_extent: { cg_to_transom_m: 18.0, cg_to_bow_m: 24.0 }\nspeed: { kn: 40 }\nseas: %s\nreport: { plots: false }\n' "$RAO" "$1"
}
printf '# one cell\nHs_m\\Tz_s,7.5\n3.0,1\n' > "$T/one.csv"
{ base '[ { spectrum: jonswap, Hs_m: 3.0, Tz_s: 7.5 } ]'
  printf 'operability: { scatter_csv: %s, criteria: [ { msi_max_pct: 20 }, { nordforsk: transit_passengers, position: lcg } ] }\n' "$T/one.csv"; } > "$T/one.yaml"
"$BIN" evaluate "$T/one.yaml" --out "$T/one" > "$T/one.log" 2>&1 || { echo "FAIL one-cell run: $(cat "$T/one.log")"; fail=1; }
PY=/usr/bin/python3
$PY - "$T/one" <<'PYEOF' || fail=1
import json, sys
d = sys.argv[1]
op = json.load(open(d + "/operability.json"))
sm = json.load(open(d + "/summary.json"))
def find_mean(node):
    if isinstance(node, dict):
        if "mean_msi_pct" in node: return node["mean_msi_pct"]
        for v in node.values():
            r = find_mean(v)
            if r is not None: return r
    if isinstance(node, list):
        for v in node:
            r = find_mean(v)
            if r is not None: return r
    return None
a = op["designs"][0]["weighted_mean_msi_pct"]; b = find_mean(sm)
if repr(a) != repr(b):
    print("FAIL one-cell MSI %r != evaluate %r" % (a, b)); sys.exit(1)
t = op["designs"][0]["criterion_time_pct"]
if sorted(t.values())[0] not in (0.0, 100.0):
    print("FAIL one-cell criterion times must be 0 or 100: %r" % t); sys.exit(1)
PYEOF
# Two cells, 0.25 and 0.75: the weighted mean is 0.25 MSI(1 m) + 0.75 MSI(3 m) of evaluate's own two seas.
printf 'Hs_m\\Tz_s,5.5,7.5\n1.0,0.25,\n3.0,,0.75\n' > "$T/two.csv"
{ base '[ { spectrum: jonswap, Hs_m: 1.0, Tz_s: 5.5 }, { spectrum: jonswap, Hs_m: 3.0, Tz_s: 7.5 } ]'
  printf 'operability: { scatter_csv: %s, criteria: [ { msi_max_pct: 30 } ] }\n' "$T/two.csv"; } > "$T/two.yaml"
"$BIN" evaluate "$T/two.yaml" --out "$T/two" > "$T/two.log" 2>&1 || { echo "FAIL two-cell run: $(cat "$T/two.log")"; fail=1; }
$PY - "$T/two" <<'PYEOF' || fail=1
import json, sys, csv
d = sys.argv[1]
op = json.load(open(d + "/operability.json"))
rows = [r for r in csv.DictReader(open(d + "/msi.csv")) if r["position"] == "mean"]
m1 = float([r for r in rows if float(r["Hs_m"]) == 1.0][0]["msi_pct"]); m3 = float([r for r in rows if float(r["Hs_m"]) == 3.0][0]["msi_pct"])
w = op["designs"][0]["weighted_mean_msi_pct"]
# msi.csv keeps 6 significant digits: relative 1e-5
if abs(w - (0.25 * m1 + 0.75 * m3)) > 1e-5 * w:
    print("FAIL two-cell weighting %g vs %g" % (w, 0.25 * m1 + 0.75 * m3)); sys.exit(1)
want = 100.0 * ((0.25 if m1 <= 30 else 0) + (0.75 if m3 <= 30 else 0))
got = op["designs"][0]["criterion_time_pct"]["msi_max_30.00pct_mean"]
if abs(got - want) > 1e-9:
    print("FAIL criterion time %g want %g" % (got, want)); sys.exit(1)
PYEOF

DEFAULT_CRITERIA='[ { msi_max_pct: 20 } ]'
bad() {  # bad NAME EXPECTED CSV-TEXT [CRITERIA]
  local name="$1" expect="$2" csvtext="$3" crit="$DEFAULT_CRITERIA"
  [ $# -ge 4 ] && crit="$4"
  printf '%b' "$csvtext" > "$T/$name.csv"
  { base '[ { spectrum: jonswap, Hs_m: 3.0, Tz_s: 7.5 } ]'; printf 'operability: { scatter_csv: %s, criteria: %s }\n' "$T/$name.csv" "$crit"; } > "$T/$name.yaml"
  "$BIN" evaluate "$T/$name.yaml" --out "$T/out_$name" > "$T/$name.out" 2> "$T/$name.err"
  local rc=$?
  [ $rc -eq 1 ] || { echo "FAIL $name: exit code $rc (want 1)"; fail=1; }
  [ "$(wc -l < "$T/$name.err")" -eq 1 ] || { echo "FAIL $name: want one line: $(cat "$T/$name.err")"; fail=1; }
  grep -qF -- "$expect" "$T/$name.err" || { echo "FAIL $name: lacks '$expect': $(cat "$T/$name.err")"; fail=1; }
}
bad sum "sum to 0.9" 'Hs_m\\Tz_s,7.5\n3.0,0.9\n'
bad negative "must be >= 0" 'Hs_m\\Tz_s,5.5,7.5\n3.0,-0.1,1.1\n'
bad tz_range "Tz" 'Hs_m\\Tz_s,30\n3.0,1\n'
bad header "Hs_m\\Tz_s" 'Hs,7.5\n3.0,1\n'
bad nonnumber "is not a number" 'Hs_m\\Tz_s,7.5\n3.0,abc\n'
bad position "position" 'Hs_m\\Tz_s,7.5\n3.0,1\n' '[ { msi_max_pct: 20, position: galley } ]'
bad two_kinds "exactly one" 'Hs_m\\Tz_s,7.5\n3.0,1\n' '[ { msi_max_pct: 20, rms_accel_max_g: 0.1 } ]'
bad nordforsk "nordforsk" 'Hs_m\\Tz_s,7.5\n3.0,1\n' '[ { nordforsk: sleeping } ]'
# A bad scatter file is reported before the strip work: a design computed at 200 x 60 (about 2.7 min of kernel
# on one core) with a missing scatter file must fail at once (60 s leaves a margin of 2.7 even on a slow machine).
cat > "$T/heavy.yaml" <<YAML
hull: { offsets_csv: $PWD/data/delft372/delft372_offsets.csv, draught_m: 0.15, length_m: 3.0, hulls: 2, spacing_m: 0.70 }
mass: { mass_kg: 87.07, lcg_m_from_ap: 1.41, kyy_m: 0.782 }
speed: { Fn: 0.75 }
water: { rho_kg_m3: 1000 }
solver: { sections: 200, panels: 60 }
seas: [ { spectrum: jonswap, Hs_m: 0.1, Tz_s: 2.5 } ]
operability: { scatter_csv: $T/nowhere.csv, criteria: [ { msi_max_pct: 20 } ] }
report: { plots: false }
YAML
timeout 60 "$BIN" evaluate "$T/heavy.yaml" --out "$T/heavy" > /dev/null 2> "$T/heavy.err"
rc=$?
[ $rc -eq 1 ] || { echo "FAIL heavy design with a missing scatter file: exit code $rc (want 1 at once; 124 = still computing)"; fail=1; }
grep -q "operability.scatter_csv" "$T/heavy.err" || { echo "FAIL heavy: message lacks the key: $(cat "$T/heavy.err")"; fail=1; }
[ $fail -eq 0 ] && echo "operability CLI: all checks passed"
exit $fail
