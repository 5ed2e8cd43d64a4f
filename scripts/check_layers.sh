#!/usr/bin/env bash
# Checks the module graph: a file may include only headers of its own layer or of layers below it in this order
# (docs/developer-guide.md). Prints every edge that runs up a layer and exits 1 if there is one.
set -euo pipefail
cd "$(dirname "$0")/.."
layers=(parametric_hull resistance seakeeping/green seakeeping/sections seakeeping/strip seakeeping/motions seas optimizer calibration/fit evaluation calibration/model
        io/formats io/config io/report calibration campaign app)
rank_of() {  # rank of a path's layer, or -1 for paths outside the layered modules
  local p=$1 i best=-1 bestlen=0
  for i in "${!layers[@]}"; do
    local l=${layers[$i]}
    if [[ $p == "$l"/* && ${#l} -gt $bestlen ]]; then best=$i; bestlen=${#l}; fi
  done
  echo "$best"
}
bad=0
while IFS= read -r file; do
  fr=$(rank_of "$file")
  [ "$fr" -lt 0 ] && continue
  while IFS= read -r inc; do
    ir=$(rank_of "$inc")
    [ "$ir" -lt 0 ] && continue
    if [ "$ir" -gt "$fr" ]; then echo "up-layer include: $file -> $inc"; bad=1; fi
  done < <(sed -n 's/^#include "\([^"]*\)".*/\1/p' "$file")
done < <(find parametric_hull resistance seakeeping seas optimizer calibration evaluation io campaign app -name '*.h' -o -name '*.cpp' -o -name '*.c' | sort)
[ $bad -eq 0 ] && echo "module graph: no include runs up a layer"
exit $bad
