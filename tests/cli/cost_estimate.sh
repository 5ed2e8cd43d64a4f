#!/usr/bin/env bash
# The cost estimate before the strip-solver work (io/config/run_cost.h, docs/bad-inputs.md "Cost estimate"):
# every run prints one estimate line on stderr; a config within the documented maxima whose estimate is beyond
# 8 GiB or 1 h is refused at once (exit 1) naming the numbers and the key that drives it; --force runs it. The
# --force case is a campaign whose max_evaluations bound is huge but which converges after a few dozen
# evaluations. Usage: cost_estimate.sh HULLOPT
set -u
BIN="$1"
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
fail=0
check() { if ! eval "$2"; then echo "FAIL: $1"; fail=1; fi; }

# 1. An ordinary run (well under a minute and 1 GiB): no estimate line, no refusal.
"$BIN" rao examples/rao_delft372.yaml --out "$T/rao" > /dev/null 2> "$T/rao.err"
rc=$?
check "rao example runs (exit $rc)" '[ $rc -eq 0 ]'
check "rao example prints no estimate line" '[ "$(grep -c "cost estimate" "$T/rao.err")" -eq 0 ]'

# 2. A trihull at the documented maxima (400 sections x 100 panels): memory operators of about 14 GiB.
{ sed -n '/^hull:/,/^water:/p' configs/davis-holloway-2003/hull12_TRIa.yaml
  echo "speed: { kn: 40 }"
  echo "solver: { sections: 400, panels: 100, frequencies: { lambda_over_L: [1.0, 2.0] } }"; } > "$T/tri.yaml"
start=$(date +%s)
"$BIN" rao "$T/tri.yaml" --out "$T/tri" > /dev/null 2> "$T/tri.err"
rc=$?
took=$(( $(date +%s) - start ))
check "maxima trihull refused with exit 1 (got $rc: $(cat "$T/tri.err"))" '[ $rc -eq 1 ]'
check "refusal is one line" '[ "$(wc -l < "$T/tri.err")" -eq 1 ]'
for s in "hullopt: error: rao: cost estimate:" "estimated memory" "exceeds the limit of 8 GiB" \
         "solver.sections = 400 and solver.panels = 100 drive it" "give --force"; do
  check "refusal names '$s'" 'grep -qF -- "$s" "$T/tri.err"'
done
check "refused before the work (took ${took} s)" '[ $took -le 20 ]'
check "refusal leaves no folder" '[ ! -e "$T/tri" ]'

# 3. A campaign bounded by max_evaluations 1000000 (about 8 h by the estimate) that converges in a few dozen.
cat > "$T/opt.yaml" <<YAML
hull:
  parametric: { type: catamaran, displacement_t: 1000, L_over_B: 11.0, B_over_T: 2.0, Cb: 0.40, Cp: 0.69,
                Cwp: 0.76, LCB_pct_L: -6.4, LCF_pct_L: -8.3, transom_immersion: 0.3, spacing_over_L: 0.25 }
water: { rho_kg_m3: 1025, g_m_s2: 9.81 }
speed: { kn: 40 }
solver: { Cs: 0.065, sections: 20, panels: 8 }
seas: [ { spectrum: jonswap, Hs_m: 1.0, Tz_s: 5.5, gamma: 3.3 } ]
optimize:
  algorithm: LN_COBYLA
  max_evaluations: 1000000
  xtol_rel: 1.0e-3
  variables: { L_over_B: [10, 12] }
  objective: { measure: msi, position: mean }
YAML
"$BIN" optimize "$T/opt.yaml" --out "$T/opt" --quiet > /dev/null 2> "$T/opt.err"
rc=$?
check "huge max_evaluations refused with exit 1 (got $rc: $(cat "$T/opt.err"))" '[ $rc -eq 1 ]'
check "refusal names the count key" 'grep -qF "estimated time" "$T/opt.err" && grep -qF "optimize.starts x max_evaluations drives it" "$T/opt.err"'
"$BIN" optimize "$T/opt.yaml" --out "$T/opt" --quiet --force > /dev/null 2> "$T/opt_force.err"
rc=$?
check "--force runs it (exit $rc: $(cat "$T/opt_force.err"))" '[ $rc -eq 0 ]'
check "--force is noted on the estimate line" 'grep -qF "running because of --force" "$T/opt_force.err"'
rows=$(grep -vc '^#' "$T/opt/history.csv")
check "the forced campaign converged early ($rows rows)" '[ "$rows" -gt 2 ] && [ "$rows" -lt 500 ]'

# 4. An explore over five headings by the oblique-sea strip theory at 40 x 14 (each design about 40 s of one
# core, 200 samples): refused, the headings on the estimate line and the sample count named (the time-domain
# method's estimate for the same campaign, within the limits, is checked in tests/unit/test_run_cost.cpp).
sed -e 's/solver: { Cs: 0.065, sections: 20, panels: 8 }/solver: { Cs: 0.065, sections: 40, panels: 14, method: strip_theory_stf }/' \
    -e 's/^optimize:/explore:/' -e 's/  max_evaluations: 1000000/  samples: 200/' -e '/algorithm:\|xtol_rel/d' \
    -e 's/  objective: { measure: msi, position: mean }/  objective: { measure: msi, position: mean, headings_deg: [180, 165, 150, 135, 120] }/' \
    "$T/opt.yaml" > "$T/ex_stf.yaml"
"$BIN" explore "$T/ex_stf.yaml" --out "$T/ex_stf" --quiet > /dev/null 2> "$T/ex_stf.err"
rc=$?
check "explore over 5 headings by STF refused with exit 1 (got $rc: $(cat "$T/ex_stf.err"))" '[ $rc -eq 1 ]'
check "the refusal counts the headings and names the samples" \
  'grep -qF "x 5 headings" "$T/ex_stf.err" && grep -qF "explore.samples drives it" "$T/ex_stf.err"'

[ $fail -eq 0 ] && echo "cost_estimate: refusal, --force and the estimate line behave as documented"
exit $fail
