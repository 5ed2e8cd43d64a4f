#!/usr/bin/env bash
# --profile on the campaign commands: where the evaluations' time goes.
# - optimize of the default catamaran cut down (12 x 6 sections x panels, 3 evaluations of which 2 computed:
#   run 0 starts at the base design, evaluation 0, and reuses it): stderr holds the
#   profile table (every stage, other, log_io, total) also with --quiet; summary.json's `profile` has the
#   same stages; the ship-physics stages have time (hull generation, attitude, panelling, kernel build, periodic
#   solve, seas, resistance); the oblique path's has none (head seas); the stages plus `other` equal the mean
#   of history.csv's wall_time_s (the stages are timed inside the evaluation that wall_time_s times);
# - explore with --profile on an analytic objective: every ship stage 0, the time in `other`;
# - without --profile: no table, no `profile` key; the logs are the same with and without it.
# Usage: bash tests/cli/campaign_profile.sh /path/to/hullopt
set -u
HULLOPT=${1:?usage: $0 /path/to/hullopt}
ROOT=$(cd "$(dirname "$0")/../.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failed=0
fail() { echo "FAIL: $*" >&2; failed=1; }
sed -e 's/  sections: 40 .*/  sections: 12/' -e 's/  panels: 14 .*/  panels: 6/' \
    -e 's/  max_evaluations: 300 .*/  max_evaluations: 2/' \
    "$ROOT/configs/optimize-catamaran.yaml" > "$work/ship.yaml"
grep -q 'max_evaluations: 2' "$work/ship.yaml" || fail "could not cut the default campaign down"
"$HULLOPT" optimize "$work/ship.yaml" --out "$work/p" --quiet --no-plots --profile > "$work/p.out" 2> "$work/p.err" \
  || fail "optimize --profile: $(cat "$work/p.err")"
"$HULLOPT" optimize "$work/ship.yaml" --out "$work/n" --quiet --no-plots > "$work/n.out" 2> "$work/n.err" \
  || fail "optimize: $(cat "$work/n.err")"
for stage in hull_generation hydrostatics_attitude panelling kernel_build periodic_solve oblique_solve spectra_msi \
             resistance other log_io total; do
  grep -Eq "^  $stage +[0-9.]+ ms" "$work/p.err" || fail "stderr has no profile line for $stage: $(cat "$work/p.err")"
done
grep -q '^profile: 2 evaluations computed' "$work/p.err" || fail "profile header: $(head -1 "$work/p.err")"
grep -q 'profile' "$work/n.err" && fail "profile printed without --profile"
grep -q '"profile"' "$work/n/summary.json" && fail "summary.json has a profile without --profile"
source "$ROOT/tests/support/cli_campaign.sh"  # strip
cmp -s <(strip "$work/p/history.csv") <(strip "$work/n/history.csv") || fail "history.csv differs with --profile"
python3 - "$work/p/summary.json" "$work/p/history.csv" <<'PY' || fail "summary.json profile"
import csv, json, sys
p = json.load(open(sys.argv[1]))["profile"]
ms = p["mean_ms_per_evaluation"]
assert p["evaluations_computed"] == 2, p
for s in ("hull_generation", "hydrostatics_attitude", "panelling", "kernel_build", "periodic_solve",
          "spectra_msi", "resistance"):
    assert ms[s] > 0, (s, ms)
assert ms["oblique_solve"] == 0, ms
rows = list(csv.DictReader(open(sys.argv[2])))
# Three rows, two computed: evaluation 0 (the base design) and run 0's first step, the same design, which
# reuses it (wall time 0, not counted).
assert len(rows) == 3, len(rows)
wall = 1e3 * sum(float(r["wall_time_s"]) for r in rows) / 2
stages = sum(v for k, v in ms.items() if k != "log_io")
# The stages and `other` are the evaluation's wall time split; the clock is read a few times more inside the
# evaluation than around it: 1 % covers that.
assert abs(stages - wall) <= 0.01 * wall, (stages, wall)
assert abs(p["mean_total_ms"] - (stages + ms["log_io"])) <= 1e-9 * p["mean_total_ms"], p
PY
cat > "$work/analytic.yaml" <<'YAML'
# hullopt explore
explore:
  samples: 8
  method: sobol
  variables: { x1: [0, 1], x2: [0, 1] }
  start: { x1: 0.5, x2: 0.5 }
  objective: { analytic: sphere, eval_delay_ms: 5 }
YAML
"$HULLOPT" explore "$work/analytic.yaml" --out "$work/a" --no-plots --profile --threads 2 > "$work/a.out" 2> "$work/a.err" \
  || fail "explore --profile: $(cat "$work/a.err")"
python3 - "$work/a/summary.json" <<'PY' || fail "analytic profile"
import json, sys
p = json.load(open(sys.argv[1]))["profile"]
ms = p["mean_ms_per_evaluation"]
assert p["evaluations_computed"] == 8, p
assert all(ms[s] == 0 for s in ms if s not in ("other", "log_io")), ms
assert ms["other"] >= 5, ms  # eval_delay_ms: 5
PY
[ "$failed" = 0 ] && echo PASS
exit "$failed"
