#!/usr/bin/env bash
# `hullopt evaluate` with `operability.polar` end to end on a coarse Delft 372 model (10 sections x 6 panels,
# 8 frequencies), by the oblique-sea strip theory (method strip_theory_stf): operability_polar.csv has a row per (speed, heading) with the documented columns, shares in
# [0, 1], following seas at speed marked (empty values, a note) and computed at zero speed; the SVG is written
# with head seas labelled and the hatching of the cells not computed; the viscous roll damping (default ikeda:
# for the catamaran the demihulls' Cs term, flagged) is stated and its flags reach the CSV's notes, stderr, the
# SVG and summary.json, and with solver.roll_damping: none nothing is flagged; by the time-domain strip method
# (the default) the zero-speed cells are not computed (a note) and the speed below the method's Froude range is
# flagged; a polar on RAO files is refused.
set -euo pipefail
HULLOPT=${1:?usage: evaluate_polar.sh /path/to/hullopt}
HULLOPT=$(cd "$(dirname "$HULLOPT")" && pwd)/$(basename "$HULLOPT")
ROOT=$(cd "$(dirname "$0")/../.." && pwd)
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

printf 'Hs_m\\Tz_s,2.5,3.5\n0.05,0.3,0.2\n0.15,0.2,0.3\n' > "$TMP/route.csv"
cat > "$TMP/polar.yaml" <<YAML
hull: { offsets_csv: $ROOT/data/delft372/delft372_offsets.csv, draught_m: 0.15, hulls: 2, spacing_m: 0.70 }
speed: { Fn: 0.5 }
water: { rho_kg_m3: 1000 }
mass: { kg_m: 0.34, kxx_m: 0.3 }
solver: { method: strip_theory_stf, sections: 10, panels: 6, adaptive_grid: off,
          frequencies: { range: { quantity: omega_rad_s, from: 2.0, to: 9.0, count: 8 } } }
seas: [ { Hs_m: 0.1, Tz_s: 2.5 } ]
operability:
  scatter_csv: route.csv
  criteria: [ { msi_max_pct: 20 } ]
  polar:
    speeds_kn: [0, 4]
    headings_deg: [0, 90, 135, 180]
    criteria:
      - { rms_vertical_accel_max_g: 0.1, position: forward }
      - { rms_lateral_accel_max_g: 0.05, position: lcg, z_m: 0.2, name: lateral }
      - { roll_rms_max_deg: 4 }
      - { msi_max_pct: 20 }
YAML
(cd "$TMP" && "$HULLOPT" evaluate polar.yaml --out out > stdout.txt 2> stderr.txt) \
  || fail "evaluate with a polar failed: $(cat "$TMP/stderr.txt")"
[ -s "$TMP/out/operability_polar.svg" ] || fail "no operability_polar.svg"
grep -q "head seas" "$TMP/out/operability_polar.svg" || fail "the SVG has no head-seas label"
grep -q 'url(#hatch)' "$TMP/out/operability_polar.svg" || fail "the SVG does not hatch the cells not computed"
/usr/bin/python3 - "$TMP/out/operability_polar.csv" <<'PY' || fail "operability_polar.csv"
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
head = list(rows[0].keys())
assert head[:3] == ["speed_kn", "wave_direction_deg", "operability"], head
assert head[-1] == "note" and "share_lateral" in head, head
assert len(rows) == 8, len(rows)
for r in rows:
    kn, beta = float(r["speed_kn"]), float(r["wave_direction_deg"])
    if kn > 0 and beta == 0:  # 4 kn = 2.06 m/s: ω_e = 0 at g/U = 4.8 rad/s, inside the grid (to 9 rad/s)
        assert r["operability"] == "" and "encounter frequency <= 0" in r["note"], r
    else:  # the catamaran's roll damping flagged in every computed cell (Ikeda does not cover a demihull pair)
        assert r["note"].startswith("warning: roll damping: ") and "demihull pair" in r["note"], r
        op = float(r["operability"])
        assert 0.0 <= op <= 1.0, r
        for k in head[3:-1]:
            assert op <= float(r[k]) + 1e-12, (k, r)  # all criteria together hold no more often than each
PY
grep -q "operability polar" "$TMP/stdout.txt" || fail "no polar lines on stdout"
grep -q "^hullopt: warning: .*operability polar: roll damping: Ikeda's monohull formulae do not cover a demihull pair" \
  "$TMP/stderr.txt" || fail "the roll damping's flag is not on stderr"
grep -q "operability polar: roll damping: the demihulls' Cs term is zero here (zero speed).*(at 0 kn)" \
  "$TMP/stderr.txt" || fail "the zero-speed flag does not name its speed"
grep -q "Roll damping: the demihulls&#39; Cs heave damping" "$TMP/out/operability_polar.svg" \
  || fail "the SVG does not state the roll damping"
grep -q "demihull pair" "$TMP/out/summary.json" || fail "summary.json does not carry the roll damping's flag"

# solver.roll_damping: none: potential roll damping only, nothing flagged.
sed -e 's/adaptive_grid: off,/adaptive_grid: off, roll_damping: none,/' -e 's/speeds_kn: \[0, 4\]/speeds_kn: [4]/' \
  "$TMP/polar.yaml" > "$TMP/none.yaml"
(cd "$TMP" && "$HULLOPT" evaluate none.yaml --out out_none > /dev/null 2> err_none.txt) \
  || fail "evaluate with roll_damping: none failed: $(cat "$TMP/err_none.txt")"
grep -q "Roll damping: potential only" "$TMP/out_none/operability_polar.svg" || fail "none: the SVG"
! grep -q "operability polar: roll damping" "$TMP/err_none.txt" || fail "none: a roll damping flag"
/usr/bin/python3 - "$TMP/out_none/operability_polar.csv" <<'PY' || fail "none: operability_polar.csv"
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
assert len(rows) == 4, len(rows)
assert all(r["note"] == "" or "encounter frequency <= 0" in r["note"] for r in rows), rows
PY

# The time-domain strip method (the default): no zero speed (the hull passing through the strips), 4 kn
# (Fn 0.39) below its Froude range, flagged in every computed cell and starred in the plot.
sed -e 's/method: strip_theory_stf, //' "$TMP/polar.yaml" > "$TMP/td.yaml"
(cd "$TMP" && "$HULLOPT" evaluate td.yaml --out out_td > /dev/null 2> err_td.txt) \
  || fail "evaluate with the time-domain method failed: $(cat "$TMP/err_td.txt")"
grep -q "The time-domain strip method (periodic steady state, Cs = 0 in heave and pitch)" \
  "$TMP/out_td/operability_polar.svg" || fail "td: the SVG does not name the method"
grep -q ">4 kn \*<" "$TMP/out_td/operability_polar.svg" && grep -q "outside the method&#39;s validity range\|outside the method's validity range" \
  "$TMP/out_td/operability_polar.svg" || fail "td: the SVG does not star the speed below the Froude range"
! grep -q ">0 kn \*<" "$TMP/out_td/operability_polar.svg" || fail "td: the SVG stars the speed not computed"
grep -q "operability polar: Fn 0.3[0-9]* is below the validity range of the 2D+t strip method.*(at 4 kn)" \
  "$TMP/err_td.txt" || fail "td: the Froude range flag does not name its speed"
/usr/bin/python3 - "$TMP/out_td/operability_polar.csv" <<'PY' || fail "td: operability_polar.csv"
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
assert len(rows) == 8, len(rows)
for r in rows:
    kn, beta = float(r["speed_kn"]), float(r["wave_direction_deg"])
    if kn == 0:
        assert r["operability"] == "" and "needs a forward speed" in r["note"], r
    elif beta == 0:
        assert r["operability"] == "" and "encounter frequency <= 0" in r["note"], r
    else:
        assert "below the validity range" in r["note"], r
        assert 0.0 <= float(r["operability"]) <= 1.0, r
PY

# RAO files have no oblique-sea motions: the polar is refused there.
cp "$ROOT/examples/data/synthetic_catamaran_rao.csv" "$TMP/rao.csv"
cat > "$TMP/from_csv.yaml" <<YAML
rao_csv: rao.csv
hull_extent: { cg_to_transom_m: 18.0, cg_to_bow_m: 24.0 }
seas: [ { Hs_m: 1.0, Tz_s: 5.5 } ]
operability:
  scatter_csv: route.csv
  criteria: [ { msi_max_pct: 20 } ]
  polar: { speeds_kn: [10], headings_deg: [180], criteria: [ { roll_rms_max_deg: 4 } ] }
YAML
if (cd "$TMP" && "$HULLOPT" evaluate from_csv.yaml --out out2 > /dev/null 2> err2.txt); then
  fail "a polar on RAO files was accepted"
fi
grep -q "key 'operability.polar': the polar computes the motions in oblique seas" "$TMP/err2.txt" \
  || fail "unexpected message: $(cat "$TMP/err2.txt")"
echo "evaluate_polar: ok"
