#!/usr/bin/env bash
# End-to-end: `hullopt evaluate` from synthetic rao.csv files: msi.csv columns and rows, summary.json, plots,
# resolved config; bad inputs (Hs <= 0, Tz outside 2..25 s, gamma < 1, a point outside the hull, an empty sea
# list, a missing RAO column) fail with exit 1 and a one-line error naming the key.
set -euo pipefail
HULLOPT=${1:?usage: evaluate.sh /path/to/hullopt}
HULLOPT=$(cd "$(dirname "$HULLOPT")" && pwd)/$(basename "$HULLOPT")
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

# Synthetic catamaran-like RAOs at 40 kn: heave 1/(1 - r^2 + 2 i z r), r = omega_e/1.7, z = 0.25 (peak 2);
# pitch per kA -i/(1 - r^2 + 2 i z r), r = omega_e/1.5, z = 0.37 (follows the wave slope at low frequency).
make_rao() {  # $1 file, $2 heave natural frequency
  awk -v wn="$2" 'BEGIN {
    U = 40 * 1852 / 3600; g = 9.81; pi = 3.14159265358979;
    print "# synthetic RAOs for the evaluate CLI test";
    print "omega_e_rad_s,omega_rad_s,lambda_over_L,heave_amp,heave_phase_deg,pitch_amp,pitch_phase_deg";
    for (i = 0; i < 60; i++) {
      w = 0.2 + 3.0 * i / 59; we = w + w * w * U / g;
      r = we / wn; re = 1 - r * r; im = 2 * 0.25 * r; d = re * re + im * im;
      hr = re / d; hi = -im / d;
      r = we / 1.5; re = 1 - r * r; im = 2 * 0.37 * r; d = re * re + im * im;
      pr = -(-im / d); pi_ = -(re / d);   # -i * (re - i im)/d
      lam = 2 * pi * g / (w * w) / 40;
      printf "%.8g,%.8g,%.6g,%.8g,%.6g,%.8g,%.6g\n", we, w, lam, sqrt(hr*hr + hi*hi), atan2(hi, hr) * 180 / pi,
             sqrt(pr*pr + pi_*pi_), atan2(pi_, pr) * 180 / pi;
    } }' > "$1"
}
make_rao "$TMP/rao.csv" 1.7
make_rao "$TMP/rao_b.csv" 1.3

cat > "$TMP/one.yaml" <<YAML
# hullopt evaluate
rao_csv: rao.csv
name: synthetic
hull_extent: { cg_to_transom_m: 18.0, cg_to_bow_m: 24.0 }
speed: { kn: 40 }
seas:
  - sea_state_line: { Hs_m: [0.5, 1.0, 1.5, 2.0, 2.5, 3.0] }
positions:
  points: [ { name: bridge, x_from_cg_m: 15.0 } ]
YAML
"$HULLOPT" evaluate "$TMP/one.yaml" --out "$TMP/out1" > "$TMP/log1" || fail "evaluate one design"
for f in msi.csv summary.json config.resolved.yaml VERSION encounter_spectra.svg raos.svg accel_per_m.svg \
         accel_per_m_vs_Hs.svg msi_vs_Hs.svg; do
  [ -s "$TMP/out1/$f" ] || fail "missing $f"
done
[ "$(head -1 "$TMP/out1/msi.csv")" = "design,Hs_m,Tz_s,position,x_from_cg_m,rms_accel_g,msi_pct,notes" ] ||
  fail "msi.csv header"
# 6 seas x (forward, lcg, transom, bridge, mean) + header
[ "$(wc -l < "$TMP/out1/msi.csv")" -eq 31 ] || fail "msi.csv rows: $(wc -l < "$TMP/out1/msi.csv")"
grep -q '^synthetic,3,7.5,forward,10.8,' "$TMP/out1/msi.csv" || fail "forward row at 0.6 x 18 m"
grep -q '^synthetic,1,5.5,transom,-18,' "$TMP/out1/msi.csv" || fail "transom row"
grep -q '^synthetic,3,7.5,mean,,' "$TMP/out1/msi.csv" || fail "mean row"
# MSI is a percentage and no value is NaN.
awk -F, 'NR > 1 && ($7 < 0 || $7 > 100 || $6 <= 0) { bad = 1 } END { exit bad }' "$TMP/out1/msi.csv" ||
  fail "msi out of range"
! grep -qi 'nan' "$TMP/out1/msi.csv" || fail "NaN in msi.csv"
grep -q '"model": "lloyd"' "$TMP/out1/summary.json" || fail "summary msi model"
grep -q '"peak_omega_e_rad_s"' "$TMP/out1/summary.json" || fail "summary peak"
grep -q 'Tz_s: 7.5' "$TMP/out1/config.resolved.yaml" && fail "resolved config should keep the line form" || true
grep -q 'sea_state_line' "$TMP/out1/config.resolved.yaml" || fail "resolved config"
grep -q '<svg' "$TMP/out1/msi_vs_Hs.svg" || fail "svg"
# The resolved config re-runs from another folder and gives the same table.
(cd / && "$HULLOPT" evaluate "$TMP/out1/config.resolved.yaml" --out "$TMP/out1b" > /dev/null) ||
  fail "re-run of config.resolved.yaml"
cmp -s "$TMP/out1/msi.csv" "$TMP/out1b/msi.csv" || fail "re-run gives a different msi.csv"

cat > "$TMP/two.yaml" <<YAML
# hullopt evaluate
designs:
  - { name: a, group: catamaran, rao_csv: rao.csv, cg_to_transom_m: 18, cg_to_bow_m: 24,
      parameters: { Fr: 0.8, Cvp: 0.62, B_over_T: 2.0 } }
  - { name: b, group: swath, rao_csv: rao_b.csv, cg_to_transom_m: 20, cg_to_bow_m: 26,
      parameters: { Fr: 0.7, Cvp: 0.75, B_over_T: 1.5 } }
seas:
  - { spectrum: jonswap, Hs_m: 3.0, Tz_s: 7.5, gamma: 3.3 }
  - { spectrum: jonswap, Hs_m: 1.0, Tp_s: 7.0 }
  - { spectrum: bretschneider, Hs_m: 2.0, Tz_s: 6.5 }
msi: { model: mccauley_1976, exposure_h: 1.0 }
YAML
"$HULLOPT" evaluate "$TMP/two.yaml" --out "$TMP/out2" > "$TMP/log2" || fail "evaluate two designs"
for f in msi_vs_Fr.svg msi_vs_Cvp.svg msi_vs_B_over_T.svg; do [ -s "$TMP/out2/$f" ] || fail "missing $f"; done
[ "$(wc -l < "$TMP/out2/msi.csv")" -eq 25 ] || fail "two-design rows"
grep -q '"model": "mccauley_1976"' "$TMP/out2/summary.json" || fail "msi option"

# Bad inputs: exit 1, one line "hullopt: error: ..." naming the key and rule.
expect_error() {  # $1 label, $2 yaml body, $3 text expected in the message
  printf '%s\n' "$2" > "$TMP/bad.yaml"
  set +e
  "$HULLOPT" evaluate "$TMP/bad.yaml" --out "$TMP/outbad" > /dev/null 2> "$TMP/err"
  local rc=$?
  set -e
  [ $rc -eq 1 ] || fail "$1: exit code $rc (want 1): $(cat "$TMP/err")"
  grep -q '^hullopt: error: ' "$TMP/err" || fail "$1: no error line: $(cat "$TMP/err")"
  grep -q -- "$3" "$TMP/err" || fail "$1: message lacks '$3': $(cat "$TMP/err")"
  [ "$(wc -l < "$TMP/err")" -eq 1 ] || fail "$1: error is not one line"
}
BASE='rao_csv: rao.csv
hull_extent: { cg_to_transom_m: 18.0, cg_to_bow_m: 24.0 }'
expect_error "Hs <= 0" "$BASE
seas: [ { Hs_m: 0.0, Tz_s: 7.5 } ]" "Hs_m = 0: significant wave height must be > 0"
expect_error "Hs < 0 on the line" "$BASE
seas: [ { sea_state_line: { Hs_m: [1.0, -0.5] } } ]" "element 2: Hs_m = -0.5"
expect_error "Tz too small" "$BASE
seas: [ { Hs_m: 1.0, Tz_s: 1.5 } ]" "Tz_s = 1.5: zero-crossing period must be within 2..25 s"
expect_error "Tz too large" "$BASE
seas: [ { Hs_m: 1.0, Tz_s: 30 } ]" "seas\[0\].Tz_s"
expect_error "gamma < 1" "$BASE
seas: [ { Hs_m: 1.0, Tz_s: 6, gamma: 0.5 } ]" "gamma = 0.5: JONSWAP peak enhancement must be within 1..10"
expect_error "empty seas" "$BASE
seas: []" "key 'seas'.*must not be an empty list"
expect_error "point outside the hull" "$BASE
seas: [ { Hs_m: 1.0, Tz_s: 6 } ]
positions: { points: [ { name: mast, x_from_cg_m: 30 } ] }" "'mast': x_from_cg_m = 30 is outside the hull"
expect_error "both Tz and Tp" "$BASE
seas: [ { Hs_m: 1.0, Tz_s: 6, Tp_s: 8 } ]" "exactly one of Tz_s and Tp_s"
expect_error "unknown key" "$BASE
seas: [ { Hs_m: 1.0, Tz_s: 6, Tzz: 3 } ]" "Tzz"
expect_error "speed mismatch" "$BASE
speed: { kn: 30 }
seas: [ { Hs_m: 1.0, Tz_s: 6 } ]" "implies 20.578 m/s"
head -2 "$TMP/rao.csv" > "$TMP/short.csv"; sed -i 's/pitch_phase_deg//' "$TMP/short.csv"
expect_error "missing RAO column" "rao_csv: short.csv
hull_extent: { cg_to_transom_m: 18.0, cg_to_bow_m: 24.0 }
seas: [ { Hs_m: 1.0, Tz_s: 6 } ]" "lacks column 'pitch_phase_deg'"
echo "evaluate CLI: all checks passed"
