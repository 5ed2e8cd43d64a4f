#!/usr/bin/env bash
# Sets up, builds and runs the main job: the 14 hulls of Davis & Holloway (2003) Table 1 at 1000 t and 40 kn
# (configs/davis-holloway-2003/), one output folder each under out/main/, and a summary table.
# A config whose header says "# expected: refused" documents a published combination that cannot be met;
# its refusal is reported, any other failure fails the job.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
bash scripts/build.sh
mkdir -p out/main
status=0
printf '%-18s %s\n' "hull" "result" > out/main/summary.txt
for cfg in configs/davis-holloway-2003/hull*.yaml; do
  name=$(basename "$cfg" .yaml)
  if msg=$(./build/app/hullopt hull "$cfg" --out "out/main/$name" 2>&1); then
    printf '%-18s %s\n' "$name" "$(echo "$msg" | sed -n 2p | sed 's/^ *//')" >> out/main/summary.txt
  elif grep -q '^# expected: refused' "$cfg"; then
    printf '%-18s refused as documented: %s\n' "$name" "$msg" >> out/main/summary.txt
  else
    printf '%-18s FAILED: %s\n' "$name" "$msg" >> out/main/summary.txt
    status=1
  fi
done
cat out/main/summary.txt
exit $status
