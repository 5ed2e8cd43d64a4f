#!/usr/bin/env bash
# `hullopt section`: bad configs give one clear error line naming the key and exit 1, never a crash; a good
# config writes section.csv with the contract header and section.svg.
set -u
BIN="$1"
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
fail=0

# expect_error NAME EXPECTED_SUBSTRING YAML
expect_error() {
  local name="$1" expect="$2" yaml="$3"
  printf '%s\n' "$yaml" > "$TMP/$name.yaml"
  local err rc
  err=$("$BIN" section "$TMP/$name.yaml" --out "$TMP/out_$name" 2>&1 >/dev/null)
  rc=$?
  if [ "$rc" -ne 1 ]; then
    echo "FAIL $name: exit code $rc (want 1): $err"; fail=1; return
  fi
  if ! grep -q -- "$expect" <<<"$err"; then
    echo "FAIL $name: message lacks '$expect': $err"; fail=1; return
  fi
  if [ "$(wc -l <<<"$err")" -ne 1 ]; then
    echo "FAIL $name: message is not one line: $err"; fail=1; return
  fi
  echo "ok   $name: $err"
}

FREQ='  frequencies: { omega_rad_s: [1.0, 2.0] }'
expect_error unknown_shape "section.shape" "section:
  shape: hexagon
$FREQ"
expect_error negative_radius "section.radius_m" "section:
  shape: semicircle
  radius_m: -1
$FREQ"
expect_error missing_radius "radius_m" "section:
  shape: semicircle
$FREQ"
expect_error rectangle_missing_draught "section.draught_m" "section:
  shape: rectangle
  beam_m: 2
$FREQ"
expect_error lewis_impossible "section.area_coefficient" "section:
  shape: lewis
  beam_m: 2
  draught_m: 1
  area_coefficient: 0.2
$FREQ"
expect_error lewis_out_of_range "section.area_coefficient" "section:
  shape: lewis
  beam_m: 2
  draught_m: 1
  area_coefficient: 1.5
$FREQ"
expect_error odd_panels "section.panels" "section:
  shape: semicircle
  radius_m: 1
  panels: 15
$FREQ"
expect_error overlap "section.spacing_m" "section:
  shape: semicircle
  radius_m: 1
  count: 2
  spacing_m: 1.5
$FREQ"
expect_error missing_spacing "spacing_m" "section:
  shape: semicircle
  radius_m: 1
  count: 2
$FREQ"
expect_error zero_count "section.count" "section:
  shape: semicircle
  radius_m: 1
  count: 0
$FREQ"
expect_error negative_omega "section.frequencies.omega_rad_s" "section:
  shape: semicircle
  radius_m: 1
  frequencies: { omega_rad_s: [1.0, -2.0] }"
expect_error bad_range "section.frequencies.omega_max_rad_s" "section:
  shape: semicircle
  radius_m: 1
  frequencies: { omega_min_rad_s: 2.0, omega_max_rad_s: 1.0, count: 5 }"
expect_error list_and_range "section.frequencies.omega_rad_s" "section:
  shape: semicircle
  radius_m: 1
  frequencies: { omega_rad_s: [1.0], count: 5 }"
expect_error unknown_method "section.method" "section:
  shape: semicircle
  radius_m: 1
  method: [strip_theory]
$FREQ"
expect_error offsets_not_yet "offsets" "section:
  shape: offsets
  offsets_csv: data/delft372/delft372_offsets.csv
  x_m: 1.5
  draught_m: 0.15
$FREQ"
expect_error misspelt_key "section.radius" "section:
  shape: semicircle
  radius_m: 1
  radius: 2
$FREQ"
expect_error shape_key_not_used "section.beam_m" "section:
  shape: semicircle
  radius_m: 1
  beam_m: 2
$FREQ"
expect_error bad_water "water.rho_kg_m3" "section:
  shape: semicircle
  radius_m: 1
$FREQ
water: { rho_kg_m3: 0 }"
expect_error no_section_block "section" "water: { rho_kg_m3: 1000 }"
expect_error empty_file "config file is empty" ""
err=$("$BIN" section "$TMP/nope.yaml" --out "$TMP/o" 2>&1); rc=$?
if [ $rc -ne 1 ]; then echo "FAIL missing file: exit $rc: $err"; fail=1; else echo "ok   missing file: $err"; fi

# A good run: two semicircles in one strip.
cat > "$TMP/good.yaml" <<'YAML'
section:
  shape: semicircle
  radius_m: 1.0
  count: 2
  spacing_m: 3.0
  panels: 14
  frequencies: { omega_rad_s: [1.0, 2.0, 3.0] }
YAML
if ! "$BIN" section "$TMP/good.yaml" --out "$TMP/good" >/dev/null; then echo "FAIL good run"; fail=1; fi
if [ "$(head -1 "$TMP/good/section.csv")" != "method,omega_rad_s,a33_kg_per_m,b33_kg_per_m_s" ]; then
  echo "FAIL section.csv header: $(head -1 "$TMP/good/section.csv")"; fail=1
fi
if [ "$(grep -c '^frequency_domain,' "$TMP/good/section.csv")" -ne 3 ]; then echo "FAIL section.csv rows"; fail=1; fi
if grep -qi 'nan\|inf' "$TMP/good/section.csv"; then echo "FAIL non-finite values in section.csv"; fail=1; fi
for f in section.svg config.resolved.yaml VERSION; do
  [ -s "$TMP/good/$f" ] || { echo "FAIL missing $f"; fail=1; }
done
exit $fail
