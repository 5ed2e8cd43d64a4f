#!/usr/bin/env bash
# Every row of docs/bad-inputs.md, end to end: a bad or implausible input to each command exits with the stated
# code and a one-line message naming the key/line and the rule; a documented warning case exits 0 with the
# warning on stderr and in the output file named. `--table` prints the markdown rows of docs/bad-inputs.md
# instead of checking quietly. Usage: bad_inputs_table.sh HULLOPT [--table]
set -u
BIN="$1"
TABLE="${2:-}"
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
fail=0
n=0

# run NAME EXPECT_RC EXPECT_SUBSTRING WARN_FILE -- COMMAND ARGS... (WARN_FILE: "-" or an output file that must
# also hold EXPECT_SUBSTRING; {T} in args is the scratch folder)
run() {
  local name="$1" rc_want="$2" expect="$3" warn_file="$4"
  shift 5
  local args=()
  for a in "$@"; do args+=("${a//\{T\}/$T}"); done
  "$BIN" "${args[@]}" > "$T/$name.out" 2> "$T/$name.err"
  local rc=$?
  n=$((n + 1))
  local msg
  msg=$(grep -m1 -E "^hullopt: (error|warning)" "$T/$name.err" || head -1 "$T/$name.err")
  local ok=1
  if [ "$rc" -ne "$rc_want" ]; then echo "FAIL $name: exit $rc (want $rc_want): $(cat "$T/$name.err")"; ok=0; fi
  if ! grep -qF -- "$expect" "$T/$name.err"; then echo "FAIL $name: stderr lacks '$expect': $(head -3 "$T/$name.err")"; ok=0; fi
  if [ "$rc_want" -ne 0 ]; then
    local lines; lines=$(wc -l < "$T/$name.err")
    [ "$lines" -eq 1 ] || { echo "FAIL $name: $lines lines on stderr (want 1)"; ok=0; }
    grep -q "^hullopt: error: " "$T/$name.err" || { echo "FAIL $name: no 'hullopt: error:' prefix"; ok=0; }
  fi
  if [ "$warn_file" != "-" ]; then
    local wf="${warn_file//\{T\}/$T}"
    grep -qF -- "$expect" "$wf" 2>/dev/null || { echo "FAIL $name: warning '$expect' not in $warn_file"; ok=0; }
  fi
  [ $ok -eq 1 ] || fail=1
  local shown="${msg//$T\//}"
  shown="${shown//$PWD\//}"  # files of the repository, named from its root
  shown="${shown//|/\\|}"
  printf '| %d | `%s` | %s | %d | %s |\n' "$n" "$1" "$DESC" "$rc" "$shown" >> "$T/rows.md"
}

# ---- inputs -----------------------------------------------------------------------------------------------
P='type: catamaran, displacement_t: 1000, L_over_B: 11, B_over_T: 2, Cb: 0.4, Cp: 0.69, Cwp: 0.76, LCB_pct_L: -6.4, LCF_pct_L: -8.3'
Q="$P, stations: 21, section_points: 10"
SOLVER='solver: { sections: 10, panels: 6, frequencies: { lambda_over_L: [1.0, 1.5, 2.0] } }'
D372="offsets_csv: $PWD/data/delft372/delft372_offsets.csv, draught_m: 0.15, hulls: 2, spacing_m: 0.70"
w() { printf '%s\n' "$2" > "$T/$1.yaml"; }
awk -F, 'NR == 1 { print; next } { printf "%g,%g,%g\n", $1 * 1000, $2 * 1000, $3 * 1000 }' \
  data/delft372/delft372_offsets.csv > "$T/offsets_mm.csv"
awk -F, 'NR == 2 { print $1 "," $2 ",-1e300"; next } { print }' data/delft372/delft372_offsets.csv > "$T/keel_huge.csv"
printf 'solid s\n facet normal 0 0 1\n  outer loop\n   vertex 0 0 -1e308\n   vertex 1 0 0\n   vertex 0 1 0\n  endloop\n endfacet\nendsolid s\n' > "$T/huge.stl"
R=examples/data/synthetic_catamaran_rao.csv
awk -F, 'NR == 5 { $4 = "1e300" } { print }' OFS=, "$R" > "$T/rao_huge.csv"
awk -F, 'NR == 9 { $1 = $1 * 1.2 } { print }' OFS=, "$R" > "$T/rao_mixed.csv"
head -3 "$R" > "$T/rao_one_row.csv"
grep -v '^#' "$R" | cut -d, -f1-4 > "$T/rao_no_pitch.csv"
grep -v '^#' "$R" | awk 'NR == 1 { print "wave_direction_deg," $0; next } { print "120," $0 }' > "$T/rao_heading.csv"
EV="name: x
hull_extent: { cg_to_transom_m: 18.0, cg_to_bow_m: 24.0 }
speed: { kn: 40 }
seas: [ { Hs_m: 1.0, Tz_s: 5.0 } ]"
head -2 data/delft372/delft372_tank_rao_fn075.csv > "$T/tank_one_row.csv"
CAL_MODEL='model: { synthetic_oscillator: { heave_natural_rad_s: 8.1, pitch_natural_rad_s: 8.4, heave_zeta0: 0.1, pitch_zeta0: 0.2, heave_zeta_per_Cs: 2.0, pitch_zeta_per_Cs: 2.0, length_m: 3.0 } }'
OPT="hull: { parametric: { $Q } }
water: { rho_kg_m3: 1025, g_m_s2: 9.81 }
speed: { kn: 40 }
seas: [ { Hs_m: 1.0, Tz_s: 5.0 } ]"

# ---- cases: DESC is the table's description ----------------------------------------------------------------
DESC='offsets in millimetres (draught in metres)'
w mm "hull: { offsets_csv: $T/offsets_mm.csv, draught_m: 0.15, hulls: 2, spacing_m: 700 }"
run offsets_mm 1 "probably in millimetres" - -- hull "$T/mm.yaml" --out "$T/o1"
DESC='`length_m: 0.5` on a 3 m model (Cb would be 2.4)'
w short "hull: { $D372, length_m: 0.5 }"
run length_short 1 "length_m = 0.5 m is not within a factor" - -- hull "$T/short.yaml" --out "$T/o2"
DESC='`length_m: 300` on a 3 m model (Cp would be 0)'
w long "hull: { $D372, length_m: 300 }"
run length_long 1 "length_m = 300 m is not within a factor" - -- hull "$T/long.yaml" --out "$T/o3"
DESC='offsets with a keel at z = -1e300'
w keel "hull: { offsets_csv: $T/keel_huge.csv, draught_m: 0.15, hulls: 2, spacing_m: 0.7 }"
run keel_huge 1 "is not a hull coordinate" - -- hull "$T/keel.yaml" --out "$T/o4"
DESC='ASCII STL vertex at z = -1e308'
w stl "hull: { stl: $T/huge.stl, draught_m: 0.15 }"
run stl_huge 1 "is not a hull coordinate" - -- hull "$T/stl.yaml" --out "$T/o5"
DESC='`spacing_over_L: 0.01`: demihulls overlap (hull)'
w overlap "hull: { parametric: { $P, spacing_over_L: 0.01 } }"
run overlap_hull 1 "the hulls overlap" - -- hull "$T/overlap.yaml" --out "$T/o6"
DESC='`spacing_over_L: 0.01`: demihulls overlap (rao)'
w overlap_rao "hull: { parametric: { $Q, spacing_over_L: 0.01 } }
speed: { Fn: 0.8 }
$SOLVER"
run overlap_rao 1 "the hulls overlap" - -- rao "$T/overlap_rao.yaml" --out "$T/o7"
DESC='`spacing_m` smaller than the demihull beam (offsets)'
w overlap_file "hull: { offsets_csv: $PWD/data/delft372/delft372_offsets.csv, draught_m: 0.15, hulls: 2, spacing_m: 0.1, length_m: 3.0 }"
run overlap_file 1 "the hulls overlap" - -- hull "$T/overlap_file.yaml" --out "$T/o8"
DESC='`mass_kg` ten times the displacement (rao)'
w heavy "hull: { $D372, length_m: 3.0 }
mass: { mass_kg: 870.7 }
water: { rho_kg_m3: 1000, g_m_s2: 9.81 }
speed: { Fn: 0.75 }
$SOLVER"
run mass_heavy 1 "key 'mass.mass_kg' = 870.7" - -- rao "$T/heavy.yaml" --out "$T/o9"
DESC='`mass_kg` ten times the displacement (hull)'
run mass_heavy_hull 1 "the hull would float at another draught" - -- hull "$T/heavy.yaml" --out "$T/o10"
DESC='`mass_kg` 10 % off with `accept_mass_mismatch: true` (warning case)'
w heavy_ok "hull: { $D372, length_m: 3.0 }
mass: { mass_kg: 95, accept_mass_mismatch: true }
water: { rho_kg_m3: 1000, g_m_s2: 9.81 }
speed: { Fn: 0.75 }
$SOLVER"
run mass_accepted 0 "accepted by mass.accept_mass_mismatch" "{T}/o11/rao.csv" -- rao "$T/heavy_ok.yaml" --out "$T/o11"
DESC='`kyy_m` of 2 L'
w kyy "hull: { $D372, length_m: 3.0 }
mass: { kyy_m: 6.0 }
water: { rho_kg_m3: 1000, g_m_s2: 9.81 }
speed: { Fn: 0.75 }
$SOLVER"
run kyy_big 1 "key 'mass.kyy_m' = 6.0" - -- rao "$T/kyy.yaml" --out "$T/o12"
DESC='`kg_m` of 10 m on a 3 m model'
w kg "hull: { $D372, length_m: 3.0 }
mass: { kg_m: 10 }"
run kg_big 1 "key 'mass.kg_m' = 10" - -- hull "$T/kg.yaml" --out "$T/o13"
DESC='`kg_m: -1` (below the baseline)'
w kgneg "hull: { $D372, length_m: 3.0 }
mass: { kg_m: -1 }"
run kg_negative 1 "key 'mass.kg_m' = -1" - -- hull "$T/kgneg.yaml" --out "$T/o14"
DESC='`Cb: 1.2`'
w cb "hull: { parametric: { type: catamaran, displacement_t: 1000, L_over_B: 11, B_over_T: 2, Cb: 1.2, Cp: 0.69, Cwp: 0.76, LCB_pct_L: 0, LCF_pct_L: 0 } }"
run cb_over_one 1 "Cb' = 1.2: must lie in (0, 1)" - -- hull "$T/cb.yaml" --out "$T/o15"
DESC='`Cb > Cp` (Cm > 1)'
w cm "hull: { parametric: { type: catamaran, displacement_t: 1000, L_over_B: 11, B_over_T: 2, Cb: 0.7, Cp: 0.6, Cwp: 0.76, LCB_pct_L: 0, LCF_pct_L: 0 } }"
run cm_over_one 1 "Cm = Cb/Cp" - -- hull "$T/cm.yaml" --out "$T/o16"
DESC='`LCB_pct_L: 30` (outside the hull range)'
w lcb "hull: { parametric: { type: catamaran, displacement_t: 1000, L_over_B: 11, B_over_T: 2, Cb: 0.4, Cp: 0.69, Cwp: 0.76, LCB_pct_L: 30, LCF_pct_L: 0 } }"
run lcb_out 1 "LCB_pct_L' = 30: must lie in (-25, 25)" - -- hull "$T/lcb.yaml" --out "$T/o17"
DESC='duplicate key'
w dup "hull:
  parametric: { $P }
water: { rho_kg_m3: 1025 }
water: { rho_kg_m3: 1000 }"
run duplicate_key 1 ":4: duplicate key 'water'" - -- hull "$T/dup.yaml" --out "$T/o18"
DESC='a second YAML document'
w twodocs "hull:
  parametric: { $P }
---
hull: { parametric: { $P } }"
run second_document 1 ":4: a second YAML document" - -- hull "$T/twodocs.yaml" --out "$T/o19"
DESC='non-scalar key `? [x]`'
w seqkey "hull:
  parametric: { $P }
? [x]
: 1"
run sequence_key 1 ":3: a key must be plain text (this one is a sequence)" - -- hull "$T/seqkey.yaml" --out "$T/o20"
DESC='fuzz-found `variables: {!L_over_B: [8, 16], B_over_T: [1A.4, 2.6]}`'
w fuzz_tag "$OPT
optimize:
  variables: {!L_over_B: [8, 16], B_over_T: [1A.4, 2.6]}"
run fuzz_tagged_key 1 ":6: a key must be plain text" - -- optimize "$T/fuzz_tag.yaml" --out "$T/o21"
DESC='`variables: { [a]: [0, 1] }`'
w seqvar "$OPT
optimize:
  variables: { [a]: [0, 1] }"
run sequence_variable 1 ":6: a key must be plain text (this one is a sequence)" - -- optimize "$T/seqvar.yaml" --out "$T/o22"
DESC='`B_over_T: [1A.4, 2.6]` bounds'
w badnum "$OPT
optimize:
  variables: { B_over_T: [1A.4, 2.6] }"
run bad_number 1 "element 1 = 1A.4 is not a number" - -- optimize "$T/badnum.yaml" --out "$T/o23"
DESC='a folder given as the config file'
mkdir -p "$T/adir"
run config_is_folder 1 "is a folder, not a config file" - -- hull "$T/adir" --out "$T/o24"
DESC='config file that does not exist'
run config_missing 1 "cannot open config file" - -- rao "$T/nope.yaml" --out "$T/o25"
DESC='empty config file'
: > "$T/empty.yaml"
run config_empty 1 "config file is empty" - -- hull "$T/empty.yaml" --out "$T/o26"
DESC='YAML syntax error'
printf 'hull: { parametric: [\n' > "$T/syntax.yaml"
run yaml_syntax 1 "YAML syntax error" - -- hull "$T/syntax.yaml" --out "$T/o27"
DESC='`solver.sections: 100000` (would exhaust memory)'
w sections "hull: { parametric: { $Q } }
speed: { Fn: 0.8 }
solver: { sections: 100000, frequencies: { lambda_over_L: [1.0] } }"
run sections_huge 1 "key 'solver.sections' = 100000: must lie in [2, 400]" - -- rao "$T/sections.yaml" --out "$T/o28"
DESC='`solver.panels: 1000`'
w panels "hull: { parametric: { $Q } }
speed: { Fn: 0.8 }
solver: { panels: 1000, frequencies: { lambda_over_L: [1.0] } }"
run panels_huge 1 "key 'solver.panels' = 1000: must be even and in [4, 100]" - -- rao "$T/panels.yaml" --out "$T/o29"
DESC='`sections: 40.5`'
w sections_frac "hull: { parametric: { $Q } }
speed: { Fn: 0.8 }
solver: { sections: 40.5, frequencies: { lambda_over_L: [1.0] } }"
run sections_fraction 1 "must be a whole number" - -- rao "$T/sections_frac.yaml" --out "$T/o30"
DESC='frequency range `count: 100000`'
w freqs "hull: { parametric: { $Q } }
speed: { Fn: 0.8 }
solver: { frequencies: { range: { quantity: lambda_over_L, from: 0.5, to: 3, count: 100000 } } }"
run frequencies_huge 1 "key 'solver.frequencies.range.count' = 100000: must lie in [1, 1000]" - -- rao "$T/freqs.yaml" --out "$T/o31"
DESC='`hull.stations: 99999` (would write a 138 MB file)'
w stations "hull: { $D372, length_m: 3.0, stations: 99999 }"
run stations_huge 1 "key 'hull.stations' = 99999: must be 0 (keep the file's stations) or in [3, 1001]" - -- hull "$T/stations.yaml" --out "$T/o32"
DESC='`parametric.stations: 99999`'
w pstations "hull: { parametric: { $P, stations: 99999 } }"
run parametric_stations_huge 1 "must be odd and in [11, 1001]" - -- hull "$T/pstations.yaml" --out "$T/o33"
DESC='`max_evaluations: 1e12`'
w maxev "$OPT
optimize: { variables: { L_over_B: [8, 16] }, max_evaluations: 1e12 }"
run max_evaluations_huge 1 "key 'optimize.max_evaluations' = 1e12: must lie in [1, 1000000]" - -- optimize "$T/maxev.yaml" --out "$T/o34"
DESC='`starts: 0`'
w starts "$OPT
optimize: { variables: { L_over_B: [8, 16] }, starts: 0 }"
run starts_zero 1 "key 'optimize.starts' = 0: must lie in [1, 1000]" - -- optimize "$T/starts.yaml" --out "$T/o35"
DESC='explore `samples: 1e9`'
w samples "$OPT
explore: { variables: { L_over_B: [8, 16] }, samples: 1e9 }"
run samples_huge 1 "key 'explore.samples' = 1e9: must lie in [1, 1000000]" - -- explore "$T/samples.yaml" --out "$T/o36"
DESC='`explore --threads 100000`'
w explore_ok "$OPT
explore: { variables: { L_over_B: [8, 16] }, samples: 2 }"
run threads_huge 1 "--threads 100000: must lie in [0, 256]" - -- explore "$T/explore_ok.yaml" --out "$T/o37" --threads 100000
DESC='`optimize --threads -3`'
w opt_ok "$OPT
optimize: { variables: { L_over_B: [8, 16] }, max_evaluations: 2 }"
run threads_negative 1 "--threads -3: must lie in [0, 256]" - -- optimize "$T/opt_ok.yaml" --out "$T/o38" --threads -3
DESC='`explore --chunk -1`'
run chunk_negative 1 "--chunk -1: must be >= 0" - -- explore "$T/explore_ok.yaml" --out "$T/o39" --chunk -1
DESC='explore into a folder written by `hull`'
"$BIN" hull examples/hull_catamaran.yaml --out "$T/hull_out" > /dev/null 2>&1
run explore_into_hull_folder 1 "holds the output of 'hullopt hull'" - -- explore "$T/explore_ok.yaml" --out "$T/hull_out"
DESC='rao into a folder written by `hull`'
run rao_into_hull_folder 1 "holds the output of 'hullopt hull'" - -- rao examples/rao_delft372.yaml --out "$T/hull_out"
DESC='rao.csv with `heave_amp` 1e300 (would give MSI 0 %)'
w ev_huge "rao_csv: $T/rao_huge.csv
$EV"
run rao_csv_huge 1 "rao_huge.csv:5: column 'heave_amp' = 1e300 is not a response amplitude" - -- evaluate "$T/ev_huge.yaml" --out "$T/o42"
DESC='rao.csv with one row at another speed (names that row)'
w ev_mixed "rao_csv: $T/rao_mixed.csv
$EV"
run rao_csv_mixed_speed 1 "rao_mixed.csv:9: omega_e_rad_s implies speed" - -- evaluate "$T/ev_mixed.yaml" --out "$T/o43"
DESC='rao.csv with one frequency row'
w ev_one "rao_csv: $T/rao_one_row.csv
$EV"
run rao_csv_one_row 1 "needs at least 2 frequency rows" - -- evaluate "$T/ev_one.yaml" --out "$T/o44"
DESC='rao.csv without the pitch columns'
w ev_nopitch "rao_csv: $T/rao_no_pitch.csv
$EV"
run rao_csv_no_pitch 1 "header lacks column 'heave_phase_deg'" - -- evaluate "$T/ev_nopitch.yaml" --out "$T/o45"
DESC='section spacing smaller than the section beam'
w sec "section: { shape: semicircle, radius_m: 1.0, count: 2, spacing_m: 1.5, panels: 28, method: [frequency_domain], frequencies: { omega_min_rad_s: 0.5, omega_max_rad_s: 5.5, count: 3 } }
water: { rho_kg_m3: 1025, g_m_s2: 9.81 }"
run section_overlap 1 "the sections would overlap" - -- section "$T/sec.yaml" --out "$T/o46"
DESC='calibrate with a single tank row (warning case)'
w cal1 "speed: { Fn: 0.75 }
calibrate: { data: [$T/tank_one_row.csv], mode: single, Cs_initial: 0.024, $CAL_MODEL }"
run calibrate_one_row 0 "only 2 data point(s) for 1 fitted parameter(s)" "{T}/o47/calibration.json" -- calibrate "$T/cal1.yaml" --out "$T/o47"
DESC='calibrate data file missing'
w cal_missing "speed: { Fn: 0.75 }
calibrate: { data: [$T/none.csv], mode: single, $CAL_MODEL }"
run calibrate_missing_data 1 "none.csv" - -- calibrate "$T/cal_missing.yaml" --out "$T/o48"

DESC='`draught_m: 1e300`'
w draught "hull: { offsets_csv: $PWD/data/delft372/delft372_offsets.csv, draught_m: 1e300 }"
run draught_huge 1 "key 'hull.draught_m' = 1e300: is not a hull dimension" - -- hull "$T/draught.yaml" --out "$T/o49"
DESC='`displacement_t: 1e12`'
w disp "hull: { parametric: { type: catamaran, displacement_t: 1e12, L_over_B: 11, B_over_T: 2, Cb: 0.4, Cp: 0.69, Cwp: 0.76, LCB_pct_L: 0, LCF_pct_L: 0 } }"
run displacement_huge 1 "must be <= 1e7 t" - -- hull "$T/disp.yaml" --out "$T/o50"
DESC='Table 1 SW1 SWATH: an 11 m/m heave resonance (warning case)'
{ sed -n '/^hull:/,/^speed:/p' configs/davis-holloway-2003/hull09_SW1.yaml
  echo "solver: { sections: 20, panels: 8, frequencies: { range: { quantity: lambda_over_L, from: 0.5, to: 4, count: 30 } } }"; } > "$T/sw1.yaml"
run sw1_resonance 0 "heave RAO peaks at" "{T}/o51/rao.csv" -- rao "$T/sw1.yaml" --out "$T/o51"
DESC='trihull at the documented maxima `sections: 400, panels: 100` (cost estimate 14 GiB)'
{ sed -n '/^hull:/,/^water:/p' configs/davis-holloway-2003/hull12_TRIa.yaml
  echo "speed: { kn: 40 }"
  echo "solver: { sections: 400, panels: 100, frequencies: { lambda_over_L: [1.0, 2.0] } }"; } > "$T/tri_max.yaml"
run cost_refused 1 "exceeds the limit of 8 GiB: solver.sections = 400 and solver.panels = 100 drive it" - -- rao "$T/tri_max.yaml" --out "$T/o52"
DESC='rao into a folder written by rao with another config'
"$BIN" rao "$T/sw1.yaml" --out "$T/o53" > /dev/null 2>&1
{ sed 's/sections: 20/sections: 24/' "$T/sw1.yaml"; echo "name: sw1"; } > "$T/sw1_24.yaml"  # same name, other strips
run other_config 1 "run with a different config (first difference: key 'solver.sections': '20' before, now '24')" - -- rao "$T/sw1_24.yaml" --out "$T/o53"

DESC='`coefficients` with `path: time_marching` (no periodic steady state to take coefficients from)'
w coef_marching "hull: { parametric: { $P } }
speed: { kn: 40 }
solver: { path: time_marching, sections: 10, panels: 6, frequencies: { lambda_over_L: [1.0, 2.0] } }"
run coef_marching 1 "path: time_marching marches one history and has none" - -- coefficients "$T/coef_marching.yaml" --out "$T/o54"
DESC='`resistance` from a speed of zero'
w res_zero "hull: { parametric: { $P } }
resistance: { speed_range_kn: { from: 0, to: 45, step: 2.5 } }"
run res_zero 1 "speed must be > 0" - -- resistance "$T/res_zero.yaml" --out "$T/o55"
DESC='`resistance` with a form factor 1 + k below 1'
w res_k "hull: { parametric: { $P } }
resistance: { speed_range_kn: { from: 10, to: 45, step: 2.5 }, form_factor: 0.5 }"
run res_form_factor 1 "1 + k must be in [1, 2]" - -- resistance "$T/res_k.yaml" --out "$T/o56"
DESC='`design` of a hull config without a speed'
w design_nospeed "hull: { parametric: { $P } }"
run design_no_speed 1 "missing required key 'speed'" - -- design "$T/design_nospeed.yaml" --out "$T/o57"
DESC='`design` in a sea of zero-crossing period 1 s'
w design_tz "hull: { parametric: { $P } }
speed: { kn: 40 }
seas: [ { spectrum: jonswap, Hs_m: 3, Tz_s: 1.0, gamma: 3.3 } ]"
run design_tz 1 "zero-crossing period must be within 2..25 s" - -- design "$T/design_tz.yaml" --out "$T/o58"
DESC='`design` with both `mass.kyy_m` and the campaigns'"'"' `mass.kyy_over_L`'
w design_kyy "hull: { parametric: { $P } }
speed: { kn: 40 }
mass: { kyy_m: 5, kyy_over_L: 0.25 }"
run design_kyy 1 "give kyy_m or kyy_over_L, not both" - -- design "$T/design_kyy.yaml" --out "$T/o59"
printf 'Hs_m\\Tz_s,5.5,7.5\n1.0,0.6,\n3.0,,0.3\n' > "$T/route_09.csv"
printf 'Hs_m\\Tz_s,5.5\n1.0,1\n' > "$T/route_one.csv"
DESC='campaign objective `measure: scatter_msi` without an `operability:` block'
w op_none "$OPT
optimize: { variables: { L_over_B: [8, 16] }, objective: { measure: scatter_msi } }"
run op_none 1 "needs an operability: block" - -- optimize "$T/op_none.yaml" --out "$T/o60"
DESC='campaign objective `measure: downtime_pct` naming no criterion of the `operability:` block'
w op_crit "$OPT
operability: { scatter_csv: route_one.csv, criteria: [ { msi_max_pct: 20, name: comfort } ] }
optimize: { variables: { L_over_B: [8, 16] }, objective: { measure: downtime_pct, criterion: comfrt } }"
run op_criterion 1 "key 'optimize.objective.criterion'" - -- optimize "$T/op_crit.yaml" --out "$T/o61"
DESC='campaign operability objective on a scatter diagram whose probabilities sum to 0.9'
w op_sum "$OPT
operability: { scatter_csv: route_09.csv, criteria: [ { msi_max_pct: 20 } ] }
optimize: { variables: { L_over_B: [8, 16] }, objective: { measure: scatter_msi } }"
run op_sum 1 "probabilities sum to 0.9, not 1" - -- explore "$T/op_sum.yaml" --out "$T/o62"
DESC='`sea_weights` with the operability objective `measure: scatter_msi`'
w op_weights "$OPT
operability: { scatter_csv: route_one.csv, criteria: [ { msi_max_pct: 20 } ] }
optimize: { variables: { L_over_B: [8, 16] }, objective: { measure: scatter_msi, sea_weights: [1] } }"
run op_weights 1 "the cells' probabilities weight them" - -- optimize "$T/op_weights.yaml" --out "$T/o63"

# ---- the validity envelope (evaluation/validity_envelope.cpp) ------------------------------------------------
SMALL='solver: { sections: 10, panels: 6, frequencies: { lambda_over_L: [1.0, 1.5, 2.0] } }'
SEA='seas: [ { Hs_m: 1.0, Tz_s: 5.0 } ]'
DESC='`design`: a 1 t catamaran at 40 kn (Fn 2.55, Fn_vol 6.6: planing)'
w env_1t "hull: { parametric: { type: catamaran, displacement_t: 1, L_over_B: 11, B_over_T: 2, Cb: 0.4, Cp: 0.69, Cwp: 0.76, LCB_pct_L: -6.4, LCF_pct_L: -8.3, stations: 21, section_points: 10 } }
speed: { kn: 40 }
solver: { sections: 10, panels: 6 }
$SEA"
run env_1t 1 "key 'speed': Fn_vol = 6.597" - -- design "$T/env_1t.yaml" --out "$T/e64"
DESC='`speed: { Fn: 3 }`'
w env_fn3 "hull: { parametric: { $Q } }
speed: { Fn: 3 }
$SMALL"
run env_fn3 1 "key 'speed': Fn_vol = " - -- rao "$T/env_fn3.yaml" --out "$T/e65"
DESC='`speed: { m_s: 74 }`'
w env_74 "hull: { parametric: { $Q } }
speed: { m_s: 74 }
$SMALL"
run env_74 1 "key 'speed': Fn_vol = 7.502 (U 74 m/s = 143.8 kn, V^(1/3) 9.918 m) is outside the method's validity envelope [0, 6]" - -- rao "$T/env_74.yaml" --out "$T/e66"
DESC='40 kn given as `m_s: 40` (warning case)'
w env_kn_ms "hull: { parametric: { $Q } }
speed: { m_s: 40 }
$SMALL"
run env_kn_ms 0 "Fn_vol = 4.055" "{T}/e67/rao.csv" -- rao "$T/env_kn_ms.yaml" --out "$T/e67"
DESC='`design` in Hs 30 m at Tz 5 s (JONSWAP: Tp 6.4 s, steepness 0.46)'
w env_hs30 "hull: { parametric: { $Q } }
speed: { kn: 40 }
solver: { sections: 10, panels: 6 }
seas: [ { Hs_m: 30, Tz_s: 5 } ]"
run env_hs30 1 "key 'seas[0].Hs_m' = 30: Hs/lambda_p = 0.4647" - -- design "$T/env_hs30.yaml" --out "$T/e68"
DESC='`evaluate` in Hs 12 m at Tz 7.5 s: steep sea and rms acceleration above 1 g (warning case)'
printf '%s\n' "name: steep" "hull_extent: { cg_to_transom_m: 18.0, cg_to_bow_m: 24.0 }" "speed: { kn: 40 }" \
  "seas: [ { Hs_m: 12.0, Tz_s: 7.5 } ]" "rao_csv: $PWD/$R" > "$T/env_steep.yaml"
run env_steep 0 "Hs/lambda_p = 0.08" "{T}/e69/summary.json" -- evaluate "$T/env_steep.yaml" --out "$T/e69"
for f in "$T/env_steep.err" "$T/e69/summary.json"; do  # the second flag of this run
  grep -qF "rms a/g = 1.774" "$f" || { echo "FAIL env_steep: rms acceleration above 1 g not flagged in $f"; fail=1; }
done
DESC='`Cs: 100`'
w env_cs "hull: { parametric: { $Q } }
speed: { kn: 40 }
solver: { Cs: 100, sections: 10, panels: 6, frequencies: { lambda_over_L: [1.0, 1.5, 2.0] } }"
run env_cs 1 "key 'solver.Cs' = 100: Cs = 100 is outside the method's validity envelope [0, 1]" - -- rao "$T/env_cs.yaml" --out "$T/e70"
DESC='`Cs: 0.5` (warning case)'
w env_cs_flag "hull: { parametric: { $Q } }
speed: { kn: 40 }
solver: { Cs: 0.5, sections: 10, panels: 6, frequencies: { lambda_over_L: [1.0, 1.5, 2.0] } }"
run env_cs_flag 0 "Cs = 0.5 is outside the usual range [0, 0.2]" "{T}/e71/rao.csv" -- rao "$T/env_cs_flag.yaml" --out "$T/e71"
DESC='`g_m_s2: 1`'
w env_g "hull: { parametric: { $Q } }
water: { rho_kg_m3: 1025, g_m_s2: 1 }
speed: { kn: 40 }
solver: { sections: 10, panels: 6 }
$SEA"
run env_g 1 "key 'water.g_m_s2' = 1: g = 1 is outside the method's validity envelope [9.5, 10.5]" - -- design "$T/env_g.yaml" --out "$T/e72"
DESC='`g_m_s2: 10` (warning case)'
w env_g10 "hull: { parametric: { $P } }
water: { rho_kg_m3: 1025, g_m_s2: 10 }"
run env_g10 0 "g = 10 is outside the usual range [9.78, 9.84]" "{T}/e73/hydrostatics.json" -- hull "$T/env_g10.yaml" --out "$T/e73"
DESC='`section` with `rho_kg_m3: 1.025` (t/m^3)'
w env_sec_rho "section: { shape: semicircle, radius_m: 1.0, panels: 28, method: [frequency_domain], frequencies: { omega_min_rad_s: 0.5, omega_max_rad_s: 5.5, count: 3 } }
water: { rho_kg_m3: 1.025, g_m_s2: 9.81 }"
run env_sec_rho 1 "key 'water.rho_kg_m3' = 1.025: rho = 1.025 is outside the method's validity envelope [900, 1100]" - -- section "$T/env_sec_rho.yaml" --out "$T/e74"
DESC='`section` with `g_m_s2: 9.0`'
w env_sec_g "section: { shape: semicircle, radius_m: 1.0, panels: 28, method: [frequency_domain], frequencies: { omega_min_rad_s: 0.5, omega_max_rad_s: 5.5, count: 3 } }
water: { rho_kg_m3: 1025, g_m_s2: 9.0 }"
run env_sec_g 1 "key 'water.g_m_s2' = 9.0: g = 9 is outside" - -- section "$T/env_sec_g.yaml" --out "$T/e75"
DESC='demihulls 16 km apart (`spacing_m: 16000`)'
w env_far "hull: { offsets_csv: $PWD/data/delft372/delft372_offsets.csv, draught_m: 0.15, hulls: 2, spacing_m: 16000 }"
run env_far 1 "key 'hull': hull spacing/L = 5" - -- hull "$T/env_far.yaml" --out "$T/e76"
DESC='`spacing_over_L: 1.0` (warning case)'
w env_wide "hull: { parametric: { $P, spacing_over_L: 1.0 } }"
run env_wide 0 "hull spacing/L = 1 (" "{T}/e77/hydrostatics.json" -- hull "$T/env_wide.yaml" --out "$T/e77"
DESC='LCG 17 m forward of the LCB (static trim 5.7 deg)'
w env_lcg "hull: { parametric: { $Q } }
mass: { lcg_m_from_ap: 46.0 }
speed: { kn: 40 }
$SMALL"
run env_lcg 1 "key 'mass.lcg_m_from_ap': static trim (deg) = 5.735" - -- rao "$T/env_lcg.yaml" --out "$T/e78"
DESC='LCG 3 m forward of the LCB (warning case)'
w env_lcg_flag "hull: { parametric: { $P } }
mass: { lcg_m_from_ap: 32.0 }"
run env_lcg_flag 0 "static trim (deg) = 1.007" "{T}/e79/hydrostatics.json" -- hull "$T/env_lcg_flag.yaml" --out "$T/e79"
DESC='`kg_m: 25` on a hull 4.9 m deep'
w env_kg "hull: { parametric: { $P } }
mass: { kg_m: 25 }"
run env_kg 1 "key 'mass.kg_m': KG/D = 5.1" - -- hull "$T/env_kg.yaml" --out "$T/e80"
DESC='`kg_m: 12` on a hull 4.9 m deep (warning case)'
w env_kg_flag "hull: { parametric: { $P } }
mass: { kg_m: 12 }"
run env_kg_flag 0 "KG/D = 2.4" "{T}/e81/hydrostatics.json" -- hull "$T/env_kg_flag.yaml" --out "$T/e81"
DESC='an STL and its draught both in millimetres (a 60 km hull)'
stl_box() {  # stl_box FILE L B D: a closed box, x 0..L, y -B/2..B/2, z 0..D
  local f="$1" L="$2" b; b=$(awk "BEGIN { print $3 / 2 }"); local D="$4"
  tri() { printf ' facet normal 0 0 0\n  outer loop\n   vertex %s\n   vertex %s\n   vertex %s\n  endloop\n endfacet\n' "$1" "$2" "$3"; }
  { echo "solid box"
    tri "0 -$b 0" "$L -$b 0" "$L $b 0"; tri "0 -$b 0" "$L $b 0" "0 $b 0"
    tri "0 -$b $D" "$L $b $D" "$L -$b $D"; tri "0 -$b $D" "0 $b $D" "$L $b $D"
    tri "0 -$b 0" "0 -$b $D" "$L -$b $D"; tri "0 -$b 0" "$L -$b $D" "$L -$b 0"
    tri "0 $b 0" "$L $b $D" "0 $b $D"; tri "0 $b 0" "$L $b 0" "$L $b $D"
    tri "0 -$b 0" "0 $b $D" "0 -$b $D"; tri "0 -$b 0" "0 $b 0" "0 $b $D"
    tri "$L -$b 0" "$L -$b $D" "$L $b $D"; tri "$L -$b 0" "$L $b $D" "$L $b 0"
    echo "endsolid box"; } > "$f"
}
stl_box "$T/box_mm.stl" 60000 6000 4000
w env_stl_mm "hull: { stl: $T/box_mm.stl, draught_m: 2000 }"
run env_stl_mm 1 "key 'hull': L = 6e+04" - -- hull "$T/env_stl_mm.yaml" --out "$T/e82"
DESC='`calibrate` started at `Cs_initial: 50`'
w env_cal50 "speed: { Fn: 0.75 }
calibrate: { data: [$PWD/data/delft372/delft372_tank_rao_fn075.csv], mode: single, Cs_initial: 50, $CAL_MODEL }"
run env_cal50 1 "key 'calibrate.Cs_initial' = 50: Cs = 50 is outside the method's validity envelope [0, 1]" - -- calibrate "$T/env_cal50.yaml" --out "$T/e83"
DESC='`calibrate` whose fitted Cs is not physical (warning case: not converged, no calibrated_solver.yaml)'
w env_cal_wild "speed: { Fn: 0.75 }
calibrate: { data: [$PWD/data/delft372/delft372_tank_rao_fn075.csv], mode: single, Cs_initial: 0.05, model: { synthetic_oscillator: { heave_natural_rad_s: 8.1, pitch_natural_rad_s: 8.4, heave_zeta0: 0.01, pitch_zeta0: 0.01, heave_zeta_per_Cs: 0.05, pitch_zeta_per_Cs: 0.05, length_m: 3.0 } } }"
run env_cal_wild 0 "the fit is not converged to a physical Cs" "{T}/e84/calibration.json" -- calibrate "$T/env_cal_wild.yaml" --out "$T/e84"
[ ! -e "$T/e84/calibrated_solver.yaml" ] || { echo "FAIL env_cal_wild: calibrated_solver.yaml written for an unphysical fit"; fail=1; }
grep -q '"converged": false' "$T/e84/calibration.json" 2>/dev/null || { echo "FAIL env_cal_wild: calibration.json does not say converged false"; fail=1; }
DESC='`resistance` up to 150 kn'
w env_res "hull: { parametric: { $P } }
resistance: { speeds_kn: [30, 150] }"
run env_res 1 "key 'resistance': Fn = 3.019 (U 77.17 m/s = 150 kn, L 66.58 m) is outside the method's validity envelope [0, 3]" - -- resistance "$T/env_res.yaml" --out "$T/e85"
DESC='`explore` with `g_m_s2: 1`'
w env_explore_g "${OPT/g_m_s2: 9.81/g_m_s2: 1}
$SMALL
explore: { variables: { L_over_B: [8, 16] }, samples: 2 }"
run env_explore_g 1 "key 'water.g_m_s2' = 1" - -- explore "$T/env_explore_g.yaml" --out "$T/e86"
DESC='`coefficients` with `Cs: 100`'
w env_coef_cs "hull: { parametric: { $P } }
speed: { kn: 40 }
solver: { Cs: 100, sections: 10, panels: 6, frequencies: { lambda_over_L: [1.0, 2.0] } }"
run env_coef_cs 1 "key 'solver.Cs' = 100" - -- coefficients "$T/env_coef_cs.yaml" --out "$T/e87"
DESC='`evaluate` from a rao.csv with `water: { g_m_s2: 1 }`'
printf '%s\n' "name: g1" "hull_extent: { cg_to_transom_m: 18.0, cg_to_bow_m: 24.0 }" "speed: { kn: 40 }" \
  "water: { g_m_s2: 1 }" "$SEA" "rao_csv: $PWD/$R" > "$T/env_eval_g.yaml"
run env_eval_g 1 "key 'water.g_m_s2' = 1" - -- evaluate "$T/env_eval_g.yaml" --out "$T/e88"

DESC='`explore` resumed with one samples.csv row edited consistently (objective and per-sea MSI) to be the best'
w env_resume "hull: { parametric: { $Q } }
speed: { kn: 40 }
solver: { sections: 10, panels: 6 }
seas: [ { Hs_m: 1.0, Tz_s: 5.5 }, { Hs_m: 3.0, Tz_s: 7.5 } ]
explore: { samples: 8, method: lhs, variables: { L_over_B: [10, 12] }, objective: { measure: msi, position: mean, sea_weights: [1, 1] } }"
"$BIN" explore "$T/env_resume.yaml" --out "$T/e89" --quiet > /dev/null 2>&1
# Line 7 is sample 5, outside the spot sample of 8 rows (samples 0, 2, 4, 7).
awk -F, -v OFS=, 'NR == 1 { for (i = 1; i <= NF; ++i) { if ($i ~ /^msi_pct_/) s[i] = 1; if ($i == "objective") o = i } }
                  NR == 7 { for (i in s) $i = "0.01"; $o = "0.01" } { print }' "$T/e89/samples.csv" > "$T/edited.csv"
mv "$T/edited.csv" "$T/e89/samples.csv"
run env_resume 1 "samples.csv:7: column 'objective' = 0.01: the design gives" - -- explore "$T/env_resume.yaml" --out "$T/e89" --quiet

# Headings (solver.headings_deg, rao only): outside [0, 360), roll without KG, a method without headings.
HD="hull: { $D372 }
mass: { mass_kg: 87.07, lcg_m_from_ap: 1.41, kyy_m: 0.782, kg_m: 0.34 }
speed: { Fn: 0.5 }
water: { rho_kg_m3: 1000 }"
w head_360 "$HD
solver: { method: strip_theory_stf, sections: 10, panels: 6, headings_deg: [180, 360], frequencies: { lambda_over_L: [1.0, 2.0] } }"
DESC='`solver.headings_deg: [180, 360]`'
run head_360 1 "key 'solver.headings_deg'" - -- rao "$T/head_360.yaml" --out "$T/o90"
w head_nokg "hull: { $D372 }
mass: { mass_kg: 87.07, lcg_m_from_ap: 1.41, kyy_m: 0.782 }
speed: { Fn: 0.5 }
water: { rho_kg_m3: 1000 }
solver: { method: strip_theory_stf, sections: 10, panels: 6, headings_deg: [180, 90], frequencies: { lambda_over_L: [1.0, 2.0] } }"
DESC='`solver.headings_deg` without `mass.kg_m` (roll needs KG)'
run head_nokg 1 "give mass.kg_m" - -- rao "$T/head_nokg.yaml" --out "$T/o91"
w head_tds "$HD
solver: { method: time_domain_strip, kernel: impulsive, sections: 10, panels: 6, headings_deg: [180, 90], frequencies: { lambda_over_L: [1.0, 2.0] } }"
DESC='`solver.headings_deg` with `kernel: impulsive`'
run head_tds 1 "with the time-domain strip method needs kernel: transient_green" - -- rao "$T/head_tds.yaml" --out "$T/o92"
# Viscous roll damping (solver.roll_damping, rao with headings): an unknown model, the keys without headings, an
# amplitude beyond the linearisation, and a hull the model does not cover (flagged in every output).
w roll_model "$HD
solver: { method: strip_theory_stf, sections: 10, panels: 6, headings_deg: [90], roll_damping: viscous, frequencies: { lambda_over_L: [1.0, 2.0] } }"
DESC='`solver.roll_damping: viscous`'
run roll_model 1 "key 'solver.roll_damping'" - -- rao "$T/roll_model.yaml" --out "$T/o93"
w roll_nohead "$HD
solver: { method: strip_theory_stf, sections: 10, panels: 6, roll_damping: ikeda, frequencies: { lambda_over_L: [1.0, 2.0] } }"
DESC='`solver.roll_damping` without `solver.headings_deg`'
run roll_nohead 1 "applies with solver.headings_deg only" - -- rao "$T/roll_nohead.yaml" --out "$T/o94"
w roll_amp "$HD
solver: { method: strip_theory_stf, sections: 10, panels: 6, headings_deg: [90], roll_amplitude_deg: 45, frequencies: { lambda_over_L: [1.0, 2.0] } }"
DESC='`solver.roll_amplitude_deg: 45`'
run roll_amp 1 "key 'solver.roll_amplitude_deg'" - -- rao "$T/roll_amp.yaml" --out "$T/o95"
w roll_cat "$HD
solver: { method: strip_theory_stf, sections: 10, panels: 6, headings_deg: [90], frequencies: { lambda_over_L: [1.0, 2.0] } }"
DESC='roll damping of the Delft 372 catamaran (warning case: Ikeda does not cover a demihull pair)'
run roll_cat 0 "do not cover a demihull pair" "{T}/o96/rao.csv" -- rao "$T/roll_cat.yaml" --out "$T/o96"
w roll_mono "hull: { parametric: { type: monohull, section_style: round_bilge, displacement_t: 1000, L_over_B: 11.9, B_over_T: 4.51, Cb: 0.39, Cp: 0.60, Cwp: 0.66, LCB_pct_L: -9.6, LCF_pct_L: -15.5, transom_immersion: 0.3, transom_beam_ratio: 1.0, keel_rise: 0.3 } }
mass: { kg_m: 4.0 }
speed: { kn: 40 }
solver: { method: strip_theory_stf, sections: 10, panels: 6, headings_deg: [90], frequencies: { lambda_over_L: [1.0, 2.0] } }"
DESC='roll damping of the Table 1 monohull MONa (warning case: Cb 0.39, Cm 0.65 outside Ikeda'"'"'s fitted range)'
run roll_mono 0 "Cb = 0.39 is outside the range [0.5, 0.85]" "{T}/o97/rao.csv" -- rao "$T/roll_mono.yaml" --out "$T/o97"

# The operability polar (evaluate's operability.polar): headings outside [0, 360), roll without KG, RAO files.
PO="hull: { $D372 }
speed: { Fn: 0.5 }
water: { rho_kg_m3: 1000 }
solver: { sections: 10, panels: 6, frequencies: { lambda_over_L: [1.0, 2.0] } }
seas: [ { Hs_m: 0.1, Tz_s: 2.5 } ]"
printf 'Hs_m\\Tz_s,2.5\n0.1,1\n' > "$T/route_model.csv"
w polar_360 "$PO
mass: { kg_m: 0.34 }
operability: { scatter_csv: route_model.csv, criteria: [ { msi_max_pct: 20 } ],
               polar: { speeds_kn: [2], headings_deg: [180, 360], criteria: [ { roll_rms_max_deg: 4 } ] } }"
DESC='`operability.polar.headings_deg: [180, 360]`'
run polar_360 1 "key 'operability.polar.headings_deg'" - -- evaluate "$T/polar_360.yaml" --out "$T/o98"
w polar_nokg "$PO
operability: { scatter_csv: route_model.csv, criteria: [ { msi_max_pct: 20 } ],
               polar: { speeds_kn: [2], headings_deg: [180], criteria: [ { roll_rms_max_deg: 4 } ] } }"
DESC='`operability.polar` without `mass.kg_m` (roll needs KG)'
run polar_nokg 1 "give mass.kg_m" - -- evaluate "$T/polar_nokg.yaml" --out "$T/o99"
w polar_speed "$PO
mass: { kg_m: 0.34 }
operability: { scatter_csv: route_model.csv, criteria: [ { msi_max_pct: 20 } ],
               polar: { speeds_kn: [-5], headings_deg: [180], criteria: [ { roll_rms_max_deg: 4 } ] } }"
DESC='`operability.polar.speeds_kn: [-5]`'
run polar_speed 1 "key 'operability.polar.speeds_kn'" - -- evaluate "$T/polar_speed.yaml" --out "$T/o100"
w polar_roll_at "$PO
mass: { kg_m: 0.34 }
operability: { scatter_csv: route_model.csv, criteria: [ { msi_max_pct: 20 } ],
               polar: { speeds_kn: [2], headings_deg: [180], criteria: [ { roll_rms_max_deg: 4, position: lcg } ] } }"
DESC='a roll criterion of the polar given a position'
run polar_roll_at 1 "roll has no position" - -- evaluate "$T/polar_roll_at.yaml" --out "$T/o101"
DESC='campaign objective `headings_deg: [180, 360]`'
w obj_head_360 "$OPT
optimize: { variables: { L_over_B: [8, 16] }, objective: { measure: msi, headings_deg: [180, 360] } }"
run obj_head_360 1 "key 'optimize.objective.headings_deg'" - -- optimize "$T/obj_head_360.yaml" --out "$T/o102"
DESC='campaign objective `heading_weights: [1, -1]`'
w obj_hw_neg "$OPT
optimize: { variables: { L_over_B: [8, 16] }, objective: { headings_deg: [180, 150], heading_weights: [1, -1] } }"
run obj_hw_neg 1 "key 'optimize.objective.heading_weights'" - -- optimize "$T/obj_hw_neg.yaml" --out "$T/o103"
DESC='campaign objective `heading_weights: [0, 0]`'
w obj_hw_zero "$OPT
optimize: { variables: { L_over_B: [8, 16] }, objective: { headings_deg: [180, 150], heading_weights: [0, 0] } }"
run obj_hw_zero 1 "at least one weight must be > 0" - -- explore "$T/obj_hw_zero.yaml" --out "$T/o104"
DESC='campaign objective with 2 headings and 3 `heading_weights`'
w obj_hw_count "$OPT
optimize: { variables: { L_over_B: [8, 16] }, objective: { headings_deg: [180, 150], heading_weights: [1, 1, 1] } }"
run obj_hw_count 1 "needs one weight per heading" - -- optimize "$T/obj_hw_count.yaml" --out "$T/o105"
DESC='campaign objective heading 45 deg (quartering seas) at 40 kn'
w obj_head_45 "$OPT
optimize: { variables: { L_over_B: [8, 16] }, objective: { headings_deg: [180, 45] } }"
run obj_head_45 1 "at speed the headings must lie in [90, 270]" - -- optimize "$T/obj_head_45.yaml" --out "$T/o106"
DESC='campaign objective `headings_deg` with `measure: P_E_kW`'
w obj_head_pe "$OPT
optimize: { variables: { L_over_B: [8, 16] }, objective: { measure: P_E_kW, headings_deg: [150] } }"
run obj_head_pe 1 "applies to measure: msi or rms_accel only" - -- optimize "$T/obj_head_pe.yaml" --out "$T/o107"
DESC='rao.csv of `rao` with headings: a 120 deg row (read as head seas it would be another speed)'
w ev_heading "rao_csv: $T/rao_heading.csv
$EV"
run rao_csv_heading 1 "rao_heading.csv:2: wave_direction_deg = 120: a RAO file is read for head seas" - -- evaluate "$T/ev_heading.yaml" --out "$T/o108"

# Not a row: without a mass block, hydrostatics.json's KG is the documented default, the draught.
w nomass "hull: { parametric: { $P } }"
if "$BIN" hull "$T/nomass.yaml" --out "$T/nomass" > /dev/null 2>&1; then
  kg=$(sed -n 's/^ *"kg_m": \([^,]*\),*/\1/p' "$T/nomass/hydrostatics.json")
  t=$(sed -n 's/^ *"T_m": \([^,]*\),*/\1/p' "$T/nomass/hydrostatics.json")
  [ "$kg" = "$t" ] || { echo "FAIL no mass block: kg_m $kg is not the draught $t"; fail=1; }
else
  echo "FAIL no mass block: hull refused it"; fail=1
fi

if [ "$TABLE" = "--table" ]; then cat "$T/rows.md"; fi
if [ $fail -ne 0 ]; then echo "bad_inputs_table: failures among $n cases"; exit 1; fi
# The table in the docs is the one these cases print, message for message.
DOC="$(dirname "$0")/../../docs/bad-inputs.md"
if [ "$TABLE" != "--table" ] && ! diff <(grep -E '^\| [0-9]+ \|' "$DOC") "$T/rows.md" > "$T/doc.diff"; then
  echo "FAIL docs/bad-inputs.md differs from the messages (< doc, > now; regenerate the rows with --table):"
  cat "$T/doc.diff"
  exit 1
fi
[ "$TABLE" = "--table" ] || echo "bad_inputs_table: all $n cases behave as docs/bad-inputs.md states, message for message"
exit 0
