#!/usr/bin/env bash
# Kill/resume: a campaign killed with SIGKILL at a random moment (twice) and restarted with the same command
# ends with exactly the history of an uninterrupted run: same rows, none lost, none duplicated, nothing that
# was logged recomputed; the killed and resumed runs use 2 threads, so the two multistart runs run side by side
# (CampaignRunner::Split) and the second one's rows wait for the first. Also: an incomplete last line is
# discarded, and a changed config is refused.
# Usage: bash tests/cli/optimize_kill_resume.sh /path/to/hullopt
set -u
HULLOPT=${1:?usage: $0 /path/to/hullopt}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

source "$(dirname "$0")/../support/cli_campaign.sh"
write_rosenbrock_campaign "$work/slow.yaml" 15 120
write_rosenbrock_campaign "$work/fast.yaml" 0 120

# Reference: uninterrupted (the delay does not change any value, only the time).
"$HULLOPT" optimize "$work/fast.yaml" --out "$work/ref" --quiet || fail "reference run failed"

# Interrupted run: SIGKILL at a random moment, twice (more if a kill came before the first row, e.g. on a
# loaded machine), then let it finish.
kills=0
for attempt in 1 2 3 4 5 6; do
  "$HULLOPT" optimize "$work/slow.yaml" --out "$work/run" --threads 2 --quiet &
  pid=$!
  sleep "$(( attempt / 3 )).$(( (RANDOM % 9) + 1 ))$(( RANDOM % 10 ))"
  kill -9 "$pid" 2>/dev/null
  wait "$pid" 2>/dev/null
  rows=0
  [ -f "$work/run/history.csv" ] && rows=$(( $(wc -l < "$work/run/history.csv") - 1 ))
  echo "killed after $rows rows (attempt $attempt)"
  [ "$rows" -gt 0 ] && kills=$((kills + 1))
  [ "$kills" -ge 2 ] && break
done
[ "$kills" -ge 1 ] || fail "could not interrupt the campaign after it had logged rows"
# Simulate a kill in the middle of writing a row.
rows_before=$(( $(wc -l < "$work/run/history.csv") - 1 ))
printf '%s' "$rows_before,0.12345,0.6" >> "$work/run/history.csv"
"$HULLOPT" optimize "$work/slow.yaml" --out "$work/run" --threads 2 2> "$work/resume.log" > /dev/null || {
  cat "$work/resume.log" >&2; fail "resumed run failed"; }
grep -q "resuming: $rows_before evaluations" "$work/resume.log" || { cat "$work/resume.log" >&2; fail "no resume message"; }
grep -q "incomplete last row" "$work/resume.log" || fail "truncated last row not reported"

# Compare all columns except wall_time_s.
strip "$work/ref/history.csv" > "$work/ref.rows"
strip "$work/run/history.csv" > "$work/run.rows"
diff -q "$work/ref.rows" "$work/run.rows" > /dev/null || { diff "$work/ref.rows" "$work/run.rows" | head >&2; fail "histories differ"; }
n=$(( $(wc -l < "$work/ref.rows") - 1 ))
dups=$(cut -d, -f1 "$work/run.rows" | sort | uniq -d | wc -l)
[ "$dups" -eq 0 ] || fail "duplicated evaluation numbers"
grep -q "\"replayed_evaluations\": $rows_before" "$work/run/summary.json" || fail "summary does not report $rows_before replayed"
grep -q "\"best_objective\"" "$work/run/summary.json" || fail "summary.json without best_objective"
[ -f "$work/run/best.yaml" ] || fail "no best.yaml"

# Same command again: everything replayed, nothing appended.
"$HULLOPT" optimize "$work/slow.yaml" --out "$work/run" --quiet || fail "rerun failed"
[ "$(strip "$work/run/history.csv" | wc -l)" -eq $((n + 1)) ] || fail "rerun appended rows"
grep -q "\"computed_evaluations\": 0" "$work/run/summary.json" || fail "rerun recomputed evaluations"

# Changed config: refused before any evaluation.
sed 's/max_evaluations: 120/max_evaluations: 130/' "$work/slow.yaml" > "$work/changed.yaml"
if "$HULLOPT" optimize "$work/changed.yaml" --out "$work/run" 2> "$work/changed.log"; then fail "changed config accepted"; fi
grep -q "different config" "$work/changed.log" || { cat "$work/changed.log" >&2; fail "unclear message for changed config"; }
grep -q "first difference: key 'optimize.max_evaluations': '120' before, now '130'" "$work/changed.log" ||
  { cat "$work/changed.log" >&2; fail "the refusal does not name the changed key"; }
[ "$(strip "$work/run/history.csv" | wc -l)" -eq $((n + 1)) ] || fail "changed config touched the history"
echo "PASS: $n evaluations, resumed after kills with $rows_before logged rows; identical to the uninterrupted run"
