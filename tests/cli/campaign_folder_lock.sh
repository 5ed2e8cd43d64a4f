#!/usr/bin/env bash
# One writer per output folder: two campaigns started at once on one folder, one is refused at once (naming the
# other's pid, command and start time) and the other's history equals an uninterrupted run's in a separate
# folder; a run killed with SIGKILL while holding the lock is restarted (the stale lock is taken over with a
# note and the campaign resumes to the same history); other commands are refused on a locked folder; a run
# refused for its config leaves no folder behind.
# Usage: bash tests/cli/campaign_folder_lock.sh /path/to/hullopt [mpi-binary]
set -u
HULLOPT=${1:?usage: $0 /path/to/hullopt [mpi-binary]}
HULLOPT_MPI=${2:-}
work=$(mktemp -d)
trap 'kill $(jobs -p) 2>/dev/null; rm -rf "$work"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }
source "$(dirname "$0")/../support/cli_campaign.sh"
write_rosenbrock_campaign "$work/slow.yaml" 15 80
write_rosenbrock_campaign "$work/fast.yaml" 0 80
"$HULLOPT" optimize "$work/fast.yaml" --out "$work/ref" --quiet || fail "reference run failed"

# Two at once.
"$HULLOPT" optimize "$work/slow.yaml" --out "$work/both" --quiet > "$work/a.out" 2> "$work/a.err" &
pa=$!
"$HULLOPT" optimize "$work/slow.yaml" --out "$work/both" --quiet > "$work/b.out" 2> "$work/b.err" &
pb=$!
wait "$pa"; ra=$?
wait "$pb"; rb=$?
echo "exit codes: $ra $rb"
if [ "$ra" -eq 0 ] && [ "$rb" -ne 0 ]; then win=$pa; lose=b
elif [ "$rb" -eq 0 ] && [ "$ra" -ne 0 ]; then win=$pb; lose=a
else cat "$work"/a.err "$work"/b.err >&2; fail "expected exactly one of two concurrent runs to be refused (exit $ra, $rb)"; fi
grep -q "the output folder is in use by another hullopt process (pid $win on host .*, hullopt optimize, started 20" \
  "$work/$lose.err" || { cat "$work/$lose.err" >&2; fail "the refusal does not name the running process"; }
[ "$(wc -l < "$work/$lose.err")" -eq 1 ] || { cat "$work/$lose.err" >&2; fail "refusal is not one line"; }
diff <(strip "$work/ref/history.csv") <(strip "$work/both/history.csv") > /dev/null ||
  { diff <(strip "$work/ref/history.csv") <(strip "$work/both/history.csv") | head >&2; fail "history of the winner differs from an uninterrupted run"; }
echo "ok: concurrent run refused, naming pid $win; the other's history equals the uninterrupted run's"

# Refused at once: a second process on a folder in use exits before the first has finished.
"$HULLOPT" optimize "$work/slow.yaml" --out "$work/busy" --quiet &
pbusy=$!
for _ in $(seq 50); do [ -s "$work/busy/hullopt.lock" ] && break; sleep 0.1; done
t0=$(date +%s.%N)
"$HULLOPT" hull "$work/slow.yaml" --out "$work/busy" 2> "$work/hull.err" && fail "hull ran in a folder in use"
grep -q "in use by another hullopt process (pid $pbusy" "$work/hull.err" || { cat "$work/hull.err" >&2; fail "hull refusal unclear"; }
kill -0 "$pbusy" 2>/dev/null || fail "the campaign finished before the refusal could be tested"
awk -v a="$t0" -v b="$(date +%s.%N)" 'BEGIN{exit !(b-a < 2)}' || fail "refusal took more than 2 s"

# SIGKILL while holding the lock, then restart: the stale lock is taken over and the campaign resumes. The
# kill waits until the journal holds a few rows (on a quiet machine the refusal above is over before the
# first evaluation is logged, and a run killed then has nothing to resume).
for _ in $(seq 300); do
  [ -f "$work/busy/history.csv" ] && [ "$(grep -vc '^#' "$work/busy/history.csv")" -ge 4 ] && break
  sleep 0.02
done
kill -0 "$pbusy" 2>/dev/null || fail "the campaign finished before it could be killed"
kill -9 "$pbusy"; wait "$pbusy" 2>/dev/null
[ -s "$work/busy/hullopt.lock" ] || fail "the killed run's lock file does not name it"
"$HULLOPT" optimize "$work/slow.yaml" --out "$work/busy" > /dev/null 2> "$work/resume.err" ||
  { cat "$work/resume.err" >&2; fail "restart after kill -9 failed"; }
grep -q "took over the lock left by pid $pbusy .*no longer running" "$work/resume.err" ||
  { cat "$work/resume.err" >&2; fail "no note about the stale lock"; }
grep -q "resuming:" "$work/resume.err" || { cat "$work/resume.err" >&2; fail "did not resume"; }
diff <(strip "$work/ref/history.csv") <(strip "$work/busy/history.csv") > /dev/null || fail "resumed history differs"
[ -s "$work/busy/hullopt.lock" ] && fail "lock file still names a holder after a clean exit"
echo "ok: killed run restarted, stale lock taken over, history equals the uninterrupted run's"

# A run refused for its config leaves no folder.
printf 'optimize:\n  algorithm: LN_NOPE\n' > "$work/bad.yaml"
"$HULLOPT" optimize "$work/bad.yaml" --out "$work/never" 2> /dev/null && fail "bad config accepted"
[ -e "$work/never" ] && fail "a refused run left a folder"

# MPI: only rank 0 takes the lock; two ranks in one folder work, and both stop (no hang) when it is in use.
if [ -n "$HULLOPT_MPI" ] && command -v mpirun > /dev/null && "$HULLOPT_MPI" --version | grep -q mpi &&
   timeout 60 mpirun --allow-run-as-root --oversubscribe -n 2 "$HULLOPT_MPI" --version > /dev/null 2>&1; then
  mpi() { timeout 120 mpirun --allow-run-as-root --oversubscribe -n 2 "$HULLOPT_MPI" "$@"; }
  mpi optimize "$work/fast.yaml" --out "$work/mpi" --threads 1 --quiet > "$work/mpi.log" 2>&1 ||
    { cat "$work/mpi.log" >&2; fail "mpirun -n 2 optimize failed"; }
  diff <(strip "$work/ref/history.csv") <(strip "$work/mpi/history.csv") > /dev/null || fail "MPI history differs"
  "$HULLOPT" optimize "$work/slow.yaml" --out "$work/mpibusy" --quiet &
  pm=$!
  for _ in $(seq 50); do [ -s "$work/mpibusy/hullopt.lock" ] && break; sleep 0.1; done
  mpi optimize "$work/slow.yaml" --out "$work/mpibusy" --threads 1 --quiet > "$work/mpibusy.log" 2>&1 &&
    fail "mpirun ran in a folder in use"
  grep -q "in use by another hullopt process (pid $pm" "$work/mpibusy.log" ||
    { cat "$work/mpibusy.log" >&2; fail "MPI refusal unclear"; }
  wait "$pm" || fail "the serial run failed while an MPI run was refused"
  echo "ok: mpirun -n 2 in one folder; refused (all ranks stopped) on a folder in use"
else
  echo "SKIP: MPI part (no MPI binary or mpirun)"
fi
echo "PASS: folder lock"
