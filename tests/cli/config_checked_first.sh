#!/usr/bin/env bash
# A config is read and checked whole before any design is built: an error in its last block is the error
# reported, even when the design's own blocks (read first) hold a fault that only building the design finds.
# Here two faults only a build finds: an LCG far off the hull (checked against the generated hull) and
# solver.steady_flow: on (the running attitude solved in calm water) beside a given hull.attitude. A command
# that generated the hull or solved calm water before reading its last block would name one of them instead
# of the misspelt key. No output folder is written.
set -u
bin="$1"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*"; exit 1; }

design() {  # $1: solver keys added, $2: the LCG [m from AP] (1.0e6: off the hull; empty: no mass block)
  cat <<YAML
hull:
  parametric: { type: catamaran, section_style: round_bilge, displacement_t: 1000, L_over_B: 11.0, B_over_T: 2.0,
                Cb: 0.40, Cp: 0.69, Cwp: 0.76, LCB_pct_L: -6.4, LCF_pct_L: -8.3, transom_immersion: 0.3,
                spacing_over_L: 0.25 }
  attitude: { trim_deg: 1.0 }
water: { rho_kg_m3: 1025, g_m_s2: 9.81 }
speed: { kn: 40 }
solver: { Cs: 0.065, sections: 12, panels: 6, steady_flow: on$1 }
YAML
  [ -n "$2" ] && echo "mass: { lcg_m_from_ap: $2 }"
  return 0
}

refused_at() {  # $1: command, $2: config file, $3: the key the message must name
  local out="$tmp/out-$1"
  if "$bin" "$1" "$2" --out "$out" > "$tmp/$1.out" 2> "$tmp/$1.err"; then fail "$1: config with a misspelt key accepted"; fi
  grep -q "$3" "$tmp/$1.err" || fail "$1: the message does not name $3: $(cat "$tmp/$1.err")"
  grep -q "steady_flow\|lcg_m_from_ap" "$tmp/$1.err" &&
    fail "$1: the design was built before the last block was read: $(cat "$tmp/$1.err")"
  [ -e "$out" ] && fail "$1: output folder written for a refused config"
  return 0
}

# Each fault is refused when the config is otherwise sound (the traps are armed).
design ", frequencies: { omega_rad_s: [0.8, 1.2] }" 1.0e6 > "$tmp/armed_lcg.yaml"
"$bin" rao "$tmp/armed_lcg.yaml" --out "$tmp/armed" 2> "$tmp/armed.err" && fail "an LCG off the hull accepted"
grep -q "mass.lcg_m_from_ap" "$tmp/armed.err" || fail "the LCG refusal changed: $(cat "$tmp/armed.err")"
design ", frequencies: { omega_rad_s: [0.8, 1.2] }" 40 > "$tmp/armed_sf.yaml"
"$bin" rao "$tmp/armed_sf.yaml" --out "$tmp/armed" 2> "$tmp/armed.err" && fail "steady_flow beside hull.attitude accepted"
grep -q "steady_flow" "$tmp/armed.err" || fail "the steady_flow / hull.attitude refusal changed: $(cat "$tmp/armed.err")"

{ design ", frequencies: { omega_rad_s: [0.8, 1.2] }" 1.0e6
  echo "compare: { tank_rao_csv: $PWD/data/delft372/delft372_tank_rao_fn075.csv, lable: tank }"; } > "$tmp/rao.yaml"
refused_at rao "$tmp/rao.yaml" "compare.lable"

{ design ", frequencies: { omega_rad_s: [0.8, 1.2] }" 1.0e6
  echo "compare: { trim_sinkag: zero }"; } > "$tmp/coefficients.yaml"
refused_at coefficients "$tmp/coefficients.yaml" "compare.trim_sinkag"

# design and evaluate fill the default frequency grid from the hull: the check comes first all the same.
{ design "" 1.0e6; echo "seas: [ { Hs_m: 1.0, Tz_s: 5.5 } ]"; echo "positions: { pointz: [] }"; } > "$tmp/design.yaml"
refused_at design "$tmp/design.yaml" "positions.pointz"
refused_at evaluate "$tmp/design.yaml" "positions.pointz"

# A campaign builds its base design once the whole config is read (its mass block has the ratios only).
{ design "" ""
  cat <<YAML
seas: [ { Hs_m: 1.0, Tz_s: 5.5 } ]
explore:
  variables: { L_over_B: [10, 12] }
  objective: { measure: msi, position: mean }
  samples: 2
resolution_check: { enabledd: true }
YAML
} > "$tmp/explore.yaml"
refused_at explore "$tmp/explore.yaml" "resolution_check.enabledd"
# calibrate builds the hull and one strip kernel per speed once the whole config is read.
{ design "" 1.0e6 | grep -v '^speed:'  # the speeds are calibrate's
  echo "calibrate: { speeds_Fn: [0.75], data: [$PWD/data/delft372/delft372_tank_rao_fn075.csv] }"
  echo "reprot: { plots: false }"; } > "$tmp/calibrate.yaml"
refused_at calibrate "$tmp/calibrate.yaml" "reprot"
echo "config_checked_first: ok"
