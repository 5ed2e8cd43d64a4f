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
expect_error offsets_x_outside "section.x_m" "section:
  shape: offsets
  offsets_csv: $PWD/data/delft372/delft372_offsets.csv
  x_m: 3.5
  draught_m: 0.15
$FREQ"
expect_error offsets_missing_x "x_m" "section:
  shape: offsets
  offsets_csv: $PWD/data/delft372/delft372_offsets.csv
  draught_m: 0.15
$FREQ"
expect_error offsets_missing_file "no_such_offsets.csv" "section:
  shape: offsets
  offsets_csv: no_such_offsets.csv
  x_m: 1.5
  draught_m: 0.15
$FREQ"
expect_error offsets_bad_draught "section.draught_m" "section:
  shape: offsets
  offsets_csv: $PWD/data/delft372/delft372_offsets.csv
  x_m: 1.5
  draught_m: 0
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
# A station of an offsets file against the closed-form shape: a prism whose stations are half-circles of
# radius 1 m (91 points each, centre on the waterline at draught 1 m) gives the semicircle's coefficients. The
# two contours differ only in how finely the arc is sampled (91 points against 400), which moves the panel
# end points by O((π/180)²) of R, so 0.2% is a generous bound; a wrong station, draught shift or orientation
# changes them by tens of per cent.
python3 - "$TMP/circle_offsets.csv" <<'PY'
import math, sys
with open(sys.argv[1], "w") as f:
    f.write("x_m,y_m,z_m\n")
    for x in (0.0, 2.0):
        for i in range(91):
            a = math.pi / 2 * i / 90  # from the keel (y = 0, z = 0) to the waterline (y = 1, z = 1)
            f.write("%.1f,%.12f,%.12f\n" % (x, math.sin(a), 1 - math.cos(a)))
PY
for shape in semicircle offsets; do
  if [ $shape = semicircle ]; then body="  radius_m: 1.0"; else
    body="  offsets_csv: $TMP/circle_offsets.csv
  x_m: 1.0
  draught_m: 1.0"; fi
  printf 'section:\n  shape: %s\n%s\n  panels: 14\n  method: [frequency_domain, time_domain]\n  frequencies: { omega_rad_s: [1.0, 2.0, 3.0] }\n' \
    "$shape" "$body" > "$TMP/$shape.yaml"
  "$BIN" section "$TMP/$shape.yaml" --out "$TMP/$shape" > /dev/null || { echo "FAIL $shape run"; fail=1; }
done
if paste -d, "$TMP/semicircle/section.csv" "$TMP/offsets/section.csv" | awk -F, 'NR > 1 {
     for (c = 3; c <= 4; ++c) { d = $c - $(c + 4); if (d < 0) d = -d; s = $c < 0 ? -$c : $c;
       if (d > 0.002 * s + 1e-9) { print "differ: " $0; bad = 1 } } } END { exit bad }'; then
  echo "ok   offsets station equals the semicircle within 0.2%"
else
  echo "FAIL offsets station against the semicircle"; fail=1
fi
exit $fail
