#!/usr/bin/env bash
# Bad campaign inputs give one clear error line and exit 1 before any evaluation: no history.csv is written.
# Usage: bash tests/cli/campaign_bad_inputs.sh /path/to/hullopt
set -u
HULLOPT=${1:?usage: $0 /path/to/hullopt}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0

expect_error() {  # $1 name, $2 expected message part, $3 command (optimize|explore), stdin: the optimize block
  local cfg="$work/$1.yaml" out="$work/out_$1"
  { echo "# hullopt $3"; echo "optimize:"; cat; } > "$cfg"
  "$HULLOPT" "$3" "$cfg" --out "$out" > "$work/$1.out" 2> "$work/$1.err"
  local rc=$?
  if [ $rc -ne 1 ]; then echo "FAIL $1: exit code $rc, expected 1" >&2; failures=$((failures + 1)); return; fi
  if ! grep -q -- "$2" "$work/$1.err"; then
    echo "FAIL $1: message lacks '$2':" >&2; cat "$work/$1.err" >&2; failures=$((failures + 1)); return
  fi
  if [ -f "$out/history.csv" ] || [ -f "$out/samples.csv" ]; then
    echo "FAIL $1: an evaluation log was written" >&2; failures=$((failures + 1)); return
  fi
  echo "ok $1: $(head -1 "$work/$1.err")"
}

expect_error unknown_variable "unknown design variable 'L_over_Q'" optimize <<'Y'
  variables: { x1: [-2, 2], L_over_Q: [1, 2] }
  start: { x1: 0, L_over_Q: 1.5 }
  objective: { analytic: sphere }
Y
expect_error misspelt_key "unknown key 'optimize.max_evals'" optimize <<'Y'
  max_evals: 10
  variables: { x1: [-2, 2] }
  start: { x1: 0 }
  objective: { analytic: sphere }
Y
expect_error inverted_bounds "variables.x1: bounds \[2, -2\] are inverted" optimize <<'Y'
  variables: { x1: [2, -2] }
  start: { x1: 0 }
  objective: { analytic: sphere }
Y
expect_error empty_bounds "are empty" optimize <<'Y'
  variables: { x1: [1, 1] }
  start: { x1: 1 }
  objective: { analytic: sphere }
Y
expect_error unknown_algorithm "'LN_COBYLAA' is not an NLopt algorithm" optimize <<'Y'
  algorithm: LN_COBYLAA
  variables: { x1: [-2, 2] }
  start: { x1: 0 }
  objective: { analytic: sphere }
Y
expect_error global_polish "polish.algorithm 'GN_ISRES' must be a derivative-free local" optimize <<'Y'
  algorithm: GN_ISRES
  polish: { algorithm: GN_ISRES }
  variables: { x1: [-2, 2] }
  start: { x1: 0 }
  objective: { analytic: sphere }
Y
expect_error polish_misspelt "unknown key 'optimize.polish.max_evals'" optimize <<'Y'
  algorithm: GN_ISRES
  polish: { algorithm: LN_COBYLA, max_evals: 10 }
  variables: { x1: [-2, 2] }
  start: { x1: 0 }
  objective: { analytic: sphere }
Y
expect_error start_outside "start value 3 is outside the bounds" optimize <<'Y'
  variables: { x1: [-2, 2] }
  start: { x1: 3 }
  objective: { analytic: sphere }
Y
expect_error infeasible_start "base design (start point) violates radius_sq_max" optimize <<'Y'
  variables: { x1: [-2, 2], x2: [-2, 2] }
  start: { x1: 1.5, x2: 1.5 }
  constraints: { radius_sq_max: 1.0 }
  objective: { analytic: sphere }
Y
expect_error contradictory "contradict each other" optimize <<'Y'
  variables: { x1: [-2, 2], x2: [-2, 2] }
  start: { x1: 0, x2: 0 }
  constraints: { sum_max: 1.0, sum_min: 2.0 }
  objective: { analytic: sphere }
Y
expect_error unknown_quantity "unknown quantity 'GM_T_m'" optimize <<'Y'
  variables: { x1: [-2, 2] }
  start: { x1: 0 }
  constraints: { GM_T_min_m: 1.0 }
  objective: { analytic: sphere }
Y
expect_error gradient_algorithm "needs gradients" optimize <<'Y'
  algorithm: LD_MMA
  variables: { x1: [-2, 2] }
  start: { x1: 0 }
  objective: { analytic: sphere }
Y
expect_error bad_method "must be one of: sobol, lhs" explore <<'Y'
  method: random
  variables: { x1: [-2, 2] }
  start: { x1: 0 }
  objective: { analytic: sphere }
Y
expect_error no_objective "missing required key 'seas'" optimize <<'Y'
  variables: { x1: [-2, 2] }
  start: { x1: 0 }
Y
[ $failures -eq 0 ] || { echo "FAIL: $failures bad-input cases" >&2; exit 1; }
echo "PASS: every bad campaign refused before any evaluation"
