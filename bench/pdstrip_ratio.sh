#!/usr/bin/env bash
# Whole-process time of `hullopt rao` against PDStrip on the same hull, paired runs in one sitting.
#
# The case: the Delft 372 demihull alone (data/delft372), 40 sections, 14 panels per section in hullopt and
# 15 offset points (14 segments) per whole section in PDStrip, 37 wavelengths (lambda/L 0.5 to 3.0), one speed
# (Fn 0.75), one thread. PDStrip also solves following seas (it always pairs mu with 180 - mu); hullopt solves
# head seas only. Each round runs PDStrip once and hullopt once, alternating, so load on the machine falls on
# both alike; the medians of ROUNDS rounds (default 5) of wall time and of CPU time (user + system) are printed
# with their ratios and the core count.
#
# PDStrip is built outside CI from its public source (Söding and Bertram; github.com/eriove/pdstrip):
#   gfortran -O2 -o pdstrip pdstrip.f90        (gfortran 12 on Debian 12; the repository's Makefile uses -g)
# Its symmetric half-section input stops in the program's own contour check, so scripts/pdstrip_input.py writes
# whole sections (docs/performance.md, "Against PDStrip").
#
# Usage: PDSTRIP=/path/to/pdstrip bash bench/pdstrip_ratio.sh [ROUNDS]
#        (hullopt binary: $HULLOPT, default build/app/hullopt; HULLOPT_BEFORE=/path/to/another/hullopt adds its
#        run to every round, e.g. a build from before a change, and prints its medians and the ratio beside them)
# Times come from wait4(2) (wall from a monotonic clock around it, CPU = user + system from the child's rusage,
# both to the microsecond), so a hullopt run of a few tens of milliseconds is resolved.
set -euo pipefail
cd "$(dirname "$0")/.."
rounds=${1:-5}
pdstrip=${PDSTRIP:?set PDSTRIP to a PDStrip binary built from its public source (see the header of this script)}
hullopt=$(realpath "${HULLOPT:-build/app/hullopt}")
before=""
[ -n "${HULLOPT_BEFORE:-}" ] && before=$(realpath "$HULLOPT_BEFORE")
pdstrip=$(realpath "$pdstrip")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

L=3.0
U=$(L=$L python3 -c 'import math, os; print("%.6f" % (0.75 * math.sqrt(9.81 * float(os.environ["L"]))))')
lams=$(python3 -c 'print(" ".join("%.6f" % (0.5 + 2.5 * i / 36) for i in range(37)))')
wavelengths=$(L=$L LAMS="$lams" python3 -c 'import os; print(" ".join("%.6f" % (float(os.environ["L"]) * float(x)) for x in os.environ["LAMS"].split()))')
python3 scripts/pdstrip_input.py data/delft372/delft372_offsets.csv "$work/pd" --draught 0.15 --sections 40 \
  --points 8 --speed "$U" --mass-t 0.043535 --xg 1.41 --zg 0.34 --kyy 0.782 --kxx 0.10 --rho 1.0 \
  --wavelengths $wavelengths
cat > "$work/demihull.yaml" <<EOF
hull:
  offsets_csv: $PWD/data/delft372/delft372_offsets.csv
  draught_m: 0.15
  length_m: $L
mass: { mass_kg: 43.535, lcg_m_from_ap: 1.41, kyy_m: 0.782, kg_m: 0.34 }
water: { rho_kg_m3: 1000, g_m_s2: 9.81 }
speed: { m_s: $U }
solver:
  sections: 40
  panels: 14
  Cs: 0.024
  adaptive_grid: off
  frequencies: { lambda_over_L: [$(echo $lams | sed 's/ /, /g')] }
EOF

timed() {  # out-file, command...: appends "wall cpu" of one run, in seconds
  local out=$1; shift
  python3 -c '
import os, subprocess, sys, time
start = time.perf_counter()
child = subprocess.Popen(sys.argv[1:], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
_, status, usage = os.wait4(child.pid, 0)
wall = time.perf_counter() - start
if status != 0: sys.exit(1)
print("%.6f %.6f" % (wall, usage.ru_utime + usage.ru_stime))' "$@" >> "$out" || { echo "failed: $*" >&2; exit 1; }
}
for r in $(seq "$rounds"); do
  rm -rf "$work/h"
  (cd "$work/pd" && timed "$work/pdstrip.times" env OMP_NUM_THREADS=1 "$pdstrip" pdstrip.inp)
  grep -q "Abs" "$work/pd/pdstrip.out" || { echo "PDStrip wrote no transfer functions:" >&2; tail -3 "$work/pd/pdstrip.out" >&2; exit 1; }
  timed "$work/hullopt.times" env OMP_NUM_THREADS=1 "$hullopt" rao "$work/demihull.yaml" --out "$work/h" --quiet --no-plots
  if [ -n "$before" ]; then
    rm -rf "$work/b"
    timed "$work/before.times" env OMP_NUM_THREADS=1 "$before" rao "$work/demihull.yaml" --out "$work/b" --quiet --no-plots
  fi
done
median() { sort -g | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }
pw=$(cut -d' ' -f1 "$work/pdstrip.times" | median); pc=$(cut -d' ' -f2 "$work/pdstrip.times" | median)
hw=$(cut -d' ' -f1 "$work/hullopt.times" | median); hc=$(cut -d' ' -f2 "$work/hullopt.times" | median)
echo "Delft 372 demihull, 40 sections x 14 panels, 37 wavelengths, Fn 0.75, one thread, $rounds paired rounds," \
  "$(nproc --all) cores, load $(cut -d' ' -f1 /proc/loadavg)"
printf '%-8s median wall %8.4f s  median CPU %8.4f s\n' PDStrip "$pw" "$pc" hullopt "$hw" "$hc"
awk -v pw="$pw" -v pc="$pc" -v hw="$hw" -v hc="$hc" \
  'BEGIN { printf "ratio PDStrip / hullopt: wall %.0fx, CPU %.0fx\n", pw / hw, pc / hc }'
if [ -n "$before" ]; then
  bw=$(cut -d' ' -f1 "$work/before.times" | median); bc=$(cut -d' ' -f2 "$work/before.times" | median)
  printf '%-8s median wall %8.4f s  median CPU %8.4f s  (HULLOPT_BEFORE=%s)\n' before "$bw" "$bc" "$before"
  awk -v pw="$pw" -v pc="$pc" -v hw="$bw" -v hc="$bc" \
    'BEGIN { printf "ratio PDStrip / before: wall %.0fx, CPU %.0fx\n", pw / hw, pc / hc }'
fi
