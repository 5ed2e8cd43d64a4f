#!/usr/bin/env bash
# Reproducibility with the real objective: the default campaign (configs/optimize-catamaran.yaml: parametric
# catamaran → time-domain strip RAOs → MSI), cut to 2 multistart runs of 10 evaluations, logs an identical
# history.csv (every column but wall_time_s, 17 significant digits) with 1 and 2 OpenMP threads and under
# `mpirun -n 2` (the multistart runs spread over the ranks) when an MPI build of hullopt is given as $2; and a
# run killed with SIGKILL and resumed ends with the same history.
# Usage: bash tests/cli/campaign_parallel_msi.sh /path/to/hullopt [/path/to/hullopt-built-with-MPI]
set -u
HULLOPT=${1:?usage: $0 /path/to/hullopt [mpi-binary]}
HULLOPT_MPI=${2:-$HULLOPT}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }
sed -e 's/max_evaluations: [0-9]*/max_evaluations: 10\n  starts: 2/' configs/optimize-catamaran.yaml > "$work/campaign.yaml"
grep -q 'starts: 2' "$work/campaign.yaml" || fail "could not cut the default campaign down"
strip() { awk -F, 'NR==1{for(i=1;i<=NF;i++) if($i=="wall_time_s") w=i} {s=""; for(i=1;i<=NF;i++) if(i!=w) s=s (s==""?"":",") $i; print s}' "$1"; }
"$HULLOPT" optimize "$work/campaign.yaml" --out "$work/t1" --threads 1 --quiet || fail "1 thread"
"$HULLOPT" optimize "$work/campaign.yaml" --out "$work/t2" --threads 2 --quiet || fail "2 threads"
rows=$(($(wc -l < "$work/t1/history.csv") - 1))
[ "$rows" -ge 15 ] || fail "expected about 21 evaluations (baseline + 2 runs of 10), got $rows"
feasible=$(awk -F, 'NR==1{for(i=1;i<=NF;i++) if($i=="feasible") f=i; next} $f==1{n++} END{print n+0}' "$work/t1/history.csv")
[ "$feasible" -ge 1 ] || fail "no feasible evaluation in the history"
diff <(strip "$work/t1/history.csv") <(strip "$work/t2/history.csv") > /dev/null || fail "1 and 2 threads differ"
echo "ok: history.csv of the MSI campaign ($rows evaluations) identical with 1 and 2 threads"
# explore over the same box (the default config's samples/method keys), 6 Sobol samples, 1 and 2 threads.
sed -e 's/samples: [0-9]*/samples: 6/' configs/optimize-catamaran.yaml > "$work/explore.yaml"
"$HULLOPT" explore "$work/explore.yaml" --out "$work/x1" --threads 1 --quiet || fail "explore 1 thread"
"$HULLOPT" explore "$work/explore.yaml" --out "$work/x2" --threads 2 --quiet || fail "explore 2 threads"
[ "$(wc -l < "$work/x1/samples.csv")" -eq 7 ] || fail "explore: expected 6 samples"
diff <(strip "$work/x1/samples.csv") <(strip "$work/x2/samples.csv") > /dev/null || fail "explore: 1 and 2 threads differ"
echo "ok: samples.csv of the MSI campaign identical with 1 and 2 threads"
# The plots name the objective with its unit and the design variables readably.
grep -q 'mean MSI over 2 seas \[%\]' "$work/x1/scatter.svg" || fail "scatter.svg: objective label without unit"
grep -q 'LCF \[% L\]' "$work/x1/scatter.svg" || fail "scatter.svg: LCF label"
grep -q 'LCF_pct_L' "$work/x1/scatter.svg" && fail "scatter.svg: raw key LCF_pct_L"

# Kill/resume on the real objective (the analytic-objective version with more kill points is
# optimize_kill_resume.sh): SIGKILL at a random moment, restart with the same command, same history as t1.
"$HULLOPT" optimize "$work/campaign.yaml" --out "$work/k" --threads 1 --quiet &
pid=$!
sleep "$(awk -v s="$RANDOM" 'BEGIN{srand(s); printf "%.2f", 0.3 + 2.0 * rand()}')"
kill -9 "$pid" 2> /dev/null
wait "$pid" 2> /dev/null
killed_rows=$(($( (cat "$work/k/history.csv" 2> /dev/null || true) | wc -l) - 1))
"$HULLOPT" optimize "$work/campaign.yaml" --out "$work/k" --threads 1 --quiet || fail "resume after SIGKILL"
diff <(strip "$work/t1/history.csv") <(strip "$work/k/history.csv") > /dev/null || fail "resumed history differs"
echo "ok: killed after $killed_rows logged rows, resumed: history identical to the uninterrupted run"
if command -v mpirun > /dev/null && "$HULLOPT_MPI" --version | grep -q mpi; then
  if mpirun --allow-run-as-root --oversubscribe -n 2 "$HULLOPT_MPI" optimize "$work/campaign.yaml" \
       --out "$work/m2" --threads 1 --quiet > "$work/mpi.log" 2>&1; then
    diff <(strip "$work/t1/history.csv") <(strip "$work/m2/history.csv") > /dev/null || fail "mpirun -n 2 differs"
    grep -q '"mpi_ranks": 2' "$work/m2/summary.json" || fail "summary does not show 2 ranks"
    echo "ok: history.csv of the MSI campaign identical under mpirun -n 2"
    mpirun --allow-run-as-root --oversubscribe -n 2 "$HULLOPT_MPI" explore "$work/explore.yaml" --out "$work/xm" \
      --threads 1 --quiet > "$work/mpi_x.log" 2>&1 || { cat "$work/mpi_x.log" >&2; fail "mpirun explore"; }
    diff <(strip "$work/x1/samples.csv") <(strip "$work/xm/samples.csv") > /dev/null || fail "explore: mpirun -n 2 differs"
    echo "ok: samples.csv of the MSI campaign identical under mpirun -n 2"
  else
    echo "SKIP: mpirun does not run here:"; head -3 "$work/mpi.log"
  fi
else
  echo "SKIP: MPI part (no MPI build of hullopt given, or no mpirun)"
fi
echo "PASS"
