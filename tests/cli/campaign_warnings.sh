#!/usr/bin/env bash
# Warnings of evaluated designs (e.g. near-singular strip sections) reach the campaign's outputs: each such
# row of history.csv / samples.csv keeps its numbers and has "warning: ..." in `message`; summary.json counts
# them; one line on stderr names the count and the first; a resumed campaign reads them back as evaluated
# designs (not refusals), so replay and the count are unchanged.
# Usage: bash tests/cli/campaign_warnings.sh /path/to/hullopt
set -u
HULLOPT=${1:?usage: $0 /path/to/hullopt}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

for cmd in optimize explore; do
  extra="max_evaluations: 60"
  [ "$cmd" = explore ] && extra="samples: 32"
  cat > "$work/$cmd.yaml" <<YAML
$cmd:
  $extra
  variables: { x1: [-2, 2], x2: [-2, 2] }
  start: { x1: -0.5, x2: 0.5 }
  objective: { analytic: sphere, warn_above_sum: 0.0 }
YAML
done

check() {  # $1 command, $2 log file name
  local out="$work/$1" log="$work/$1/$2"
  "$HULLOPT" "$1" "$work/$1.yaml" --out "$out" --quiet 2> "$work/$1.err" || fail "$1 failed: $(cat "$work/$1.err")"
  local warned; warned=$(grep -c ',warning: sum of the variables' "$log")
  [ "$warned" -gt 0 ] || fail "$1: no warned rows in $2"
  # Warned rows keep a finite objective (column after the two variables) and are not marked refused.
  awk -F, 'NR > 1 && $NF ~ /^warning: / && ($4 == "nan" || $4 == "") { exit 1 }' "$log" ||
    fail "$1: a warned row lost its objective"
  grep -q "\"evaluations_with_warning\": $warned" "$out/summary.json" ||
    fail "$1: summary.json does not count $warned warned evaluations: $(grep warning "$out/summary.json")"
  # --quiet silences the stderr line; without it the line names the count.
  "$HULLOPT" "$1" "$work/$1.yaml" --out "$out" 2> "$work/$1.err2" > /dev/null || fail "$1 resume failed"
  grep -q "hullopt: warning: $warned of .* evaluations carry a warning" "$work/$1.err2" ||
    fail "$1: no warning line on stderr: $(cat "$work/$1.err2")"
  grep -q "\"computed_evaluations\": 0" "$out/summary.json" || fail "$1: resume recomputed evaluations"
  grep -q "\"evaluations_with_warning\": $warned" "$out/summary.json" || fail "$1: resume changed the count"
}
check optimize history.csv
check explore samples.csv
echo "campaign warnings: all checks passed"
