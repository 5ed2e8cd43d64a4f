#!/usr/bin/env bash
# Every command's config.resolved.yaml re-runs to the same result: each example config (tests/cli/lib/
# example_tree.sh: a copy of configs/, examples/ and data/ with coarse solver settings) is run from one working
# folder, then its config.resolved.yaml from another (/) into a new folder, and the main outputs are compared:
#   - CSV files: data rows byte-identical; the comment lines ('#') are left out of the comparison because they
#     name the source files; the "# hull: NAME" line must be the same (the name, by default the config's or
#     offsets file's, is recorded in config.resolved.yaml); the wall_time_s column of history.csv and samples.csv is left out (timing).
#   - JSON files: every value identical except the timings wall_time_s and fit_seconds.
#   - calibrated_solver*.yaml: identical apart from comment lines.
#   - a message that names the config file to edit (e.g. "extend solver.frequencies in FILE") names the file
#     run, so the two config paths are read as one in the JSON comparison.
# A campaign's best design is compared through summary.json (its variables and objective).
# The resolved config re-run into its own output folder is accepted as the same config (exit 0).
# Usage: bash tests/cli/resolved_rerun.sh /path/to/hullopt   (from the repository root)
set -u
BIN=$(realpath "$1")
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
fail=0
. tests/cli/lib/example_tree.sh
example_tree "$T/tree" || { echo "FAIL: cannot build the example tree"; exit 1; }
mkdir -p "$T/first_cwd"
PY=/usr/bin/python3

csv_data() {  # file: data rows without the comment lines and the wall_time_s column
  awk -F, -v OFS=, '/^#/ { next }
    !seen++ { for (i = 1; i <= NF; ++i) if ($i == "wall_time_s") skip = i }
    { out = ""; sep = ""; for (i = 1; i <= NF; ++i) if (i != skip) { out = out sep $i; sep = OFS }; print out }' "$1"
}
same_json() {  # a b config-a config-b: equal but for the timings and the config file named
  $PY - "$@" <<'PYEOF'
import json, sys
def strip(v, config):
    if isinstance(v, dict):
        return {k: strip(x, config) for k, x in v.items() if k not in ("wall_time_s", "fit_seconds")}
    if isinstance(v, list):
        return [strip(x, config) for x in v]
    if isinstance(v, str):
        return v.replace(config, "CONFIG")
    return v
a, b = (strip(json.load(open(p)), c) for p, c in zip(sys.argv[1:3], sys.argv[3:5]))
sys.exit(0 if a == b else 1)
PYEOF
}

i=0
compared=0
while read -r cmd cfg; do
  i=$((i + 1))
  name="$i-$cmd-$(basename "$cfg" .yaml)"
  one="$T/out/$name" two="$T/again/$name"
  (cd "$T/first_cwd" && "$BIN" "$cmd" "$T/tree/$cfg" --out "$one" > "$T/$name.log" 2>&1) ||
    { echo "FAIL $name: first run: $(tail -1 "$T/$name.log")"; fail=1; continue; }
  (cd / && "$BIN" "$cmd" "$one/config.resolved.yaml" --out "$two" > "$T/$name.again.log" 2>&1) ||
    { echo "FAIL $name: config.resolved.yaml does not re-run: $(tail -1 "$T/$name.again.log")"; fail=1; continue; }
  cmp -s <(sed 1d "$one/config.resolved.yaml") <(sed 1d "$two/config.resolved.yaml") ||
    { echo "FAIL $name: the re-run's config.resolved.yaml differs"; fail=1; }
  n=0
  for f in "$one"/*.csv "$one"/*.json "$one"/calibrated_solver*.yaml; do
    [ -e "$f" ] || continue
    b=$(basename "$f")
    [ -e "$two/$b" ] || { echo "FAIL $name: the re-run wrote no $b"; fail=1; continue; }
    case "$b" in
      # The design's name is recorded in the resolved config, so the re-run's "# hull:" line names it too.
      *.csv) cmp -s <(csv_data "$f") <(csv_data "$two/$b") &&
               cmp -s <(grep '^# hull: ' "$f") <(grep '^# hull: ' "$two/$b") ;;
      *.json) same_json "$f" "$two/$b" "$T/tree/$cfg" "$one/config.resolved.yaml" ;;
      *.yaml) cmp -s <(grep -v '^#' "$f") <(grep -v '^#' "$two/$b") ;;
    esac || { echo "FAIL $name: $b differs after the re-run"; fail=1; }
    n=$((n + 1))
  done
  [ "$n" -gt 0 ] || { echo "FAIL $name: no output compared"; fail=1; }
  compared=$((compared + n))
  # The resolved config into its own folder: the same config, accepted.
  (cd / && "$BIN" "$cmd" "$one/config.resolved.yaml" --out "$one" > "$T/$name.same.log" 2>&1) ||
    { echo "FAIL $name: config.resolved.yaml refused in its own folder: $(tail -1 "$T/$name.same.log")"; fail=1; }
done <<< "$RUNS"
[ "$i" -ge 18 ] || { echo "FAIL: only $i runs"; fail=1; }
for c in hull section rao coefficients evaluate optimize explore calibrate resistance design; do
  grep -q "^$c " <<< "$RUNS" || { echo "FAIL: no run of $c"; fail=1; }
done
[ $fail -eq 0 ] && echo "ok: $i runs of $(echo "$RUNS" | cut -d" " -f1 | sort -u | wc -l) commands re-run from config.resolved.yaml; $compared output files compared"
exit $fail
