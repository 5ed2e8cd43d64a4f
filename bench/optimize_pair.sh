#!/usr/bin/env bash
# Wall time of the shipped optimize campaign (configs/optimize-catamaran.yaml: LN_COBYLA from the NPL-5b-like
# catamaran, 40 x 14, one start) with two hullopt binaries run in turn, so that both see the same machine load:
# ROUNDS rounds of (before, after), each a whole `hullopt optimize ... --quiet --no-plots` into a fresh folder
# with --threads THREADS. STARTS > 1 sets optimize.starts (multistart runs, which an optimize run spreads over its
# threads). Prints every round, the medians and the paired ratio, the load average before and after, and checks
# that both binaries logged the same history.csv (every column but wall_time_s).
# Usage: HULLOPT_BEFORE=/path/to/old/hullopt bash bench/optimize_pair.sh [ROUNDS=3] [STARTS=1] [THREADS=2]
#        (after: $HULLOPT, default build/app/hullopt)
set -euo pipefail
rounds=${1:-3}
starts=${2:-1}
threads=${3:-2}
root=$(cd "$(dirname "$0")/.." && pwd)
after=${HULLOPT:-$root/build/app/hullopt}
before=${HULLOPT_BEFORE:?set HULLOPT_BEFORE to the binary to compare with}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
if [ "$starts" -gt 1 ]; then
  sed -e "s/^  algorithm: LN_COBYLA/  algorithm: LN_COBYLA\n  starts: $starts/" "$root/configs/optimize-catamaran.yaml" > "$work/c.yaml"
  grep -q "starts: $starts" "$work/c.yaml" || { echo "optimize_pair: could not set starts" >&2; exit 1; }
else
  cp "$root/configs/optimize-catamaran.yaml" "$work/c.yaml"
fi
one() {  # binary, folder -> wall seconds
  local s e
  s=$(date +%s.%N)
  "$1" optimize "$work/c.yaml" --out "$2" --threads "$threads" --quiet --no-plots > "$work/log" 2>&1 \
    || { cat "$work/log" >&2; exit 1; }
  e=$(date +%s.%N)
  echo "$e - $s" | bc -l
}
median_of() { sort -n | awk '{a[NR] = $1} END {print (NR % 2 ? a[(NR + 1) / 2] : (a[NR / 2] + a[NR / 2 + 1]) / 2)}'; }
strip() { awk -F, 'NR==1{for(i=1;i<=NF;i++) if($i=="wall_time_s") w=i} {s=""; for(i=1;i<=NF;i++) if(i!=w) s=s (s==""?"":",") $i; print s}' "$1"; }
echo "shipped optimize campaign, starts $starts, --threads $threads, $(nproc) cores; load average before: $(cut -d' ' -f1-3 /proc/loadavg)"
: > "$work/runs"
for ((i = 0; i < rounds; ++i)); do
  b=$(one "$before" "$work/b$i")
  a=$(one "$after" "$work/a$i")
  echo "$b $a" >> "$work/runs"
  printf '  round %d: before %6.2f s, after %6.2f s (%d evaluations)\n' "$i" "$b" "$a" $(($(wc -l < "$work/a$i/history.csv") - 1))
  cmp -s <(strip "$work/b$i/history.csv") <(strip "$work/a$i/history.csv") \
    || { echo "optimize_pair: the two binaries logged different histories" >&2; exit 1; }
done
echo "median wall: before $(awk '{print $1}' "$work/runs" | median_of) s, after $(awk '{print $2}' "$work/runs" | median_of) s;" \
  "median paired ratio before/after $(awk '{print $1 / $2}' "$work/runs" | median_of)"
echo "load average after: $(cut -d' ' -f1-3 /proc/loadavg)"
