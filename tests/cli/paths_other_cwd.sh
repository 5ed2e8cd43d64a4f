#!/usr/bin/env bash
# Paths in a config are relative to the folder of that config, whatever the working folder: every command runs
# the example configs (tests/cli/lib/example_tree.sh, a copy of configs/, examples/ and data/ in a temporary
# tree) from a working folder that is neither the repository nor the config's folder, the config named by a
# relative path. A path that is right relative to the working folder but not to the config's folder (the rule
# of earlier versions) is refused with one line naming the key, the text written and the path it resolved to.
# Usage: bash tests/cli/paths_other_cwd.sh /path/to/hullopt   (from the repository root)
set -u
BIN=$(realpath "$1")
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
fail=0
. tests/cli/lib/example_tree.sh
example_tree "$T/tree" || { echo "FAIL: cannot build the example tree"; exit 1; }
mkdir -p "$T/elsewhere"

# 1. Every command from another working folder, the config named relative to it.
i=0
while read -r cmd cfg; do
  i=$((i + 1))
  (cd "$T/elsewhere" && "$BIN" "$cmd" "../tree/$cfg" --out "out/$i-$cmd" > "$T/$i.log" 2>&1) ||
    { echo "FAIL $cmd $cfg from another folder: $(tail -1 "$T/$i.log")"; fail=1; }
done <<< "$RUNS"

# 2. The old rule: the config moved one folder down and run from its old folder, so that each relative path
#    still holds from the working folder but no longer from the config's folder.
# old_rule COMMAND CONFIG KEY [SED]: CONFIG relative to the tree; KEY the key the message must name; SED an
# optional edit of the moved copy (to make an earlier path absolute, so that the error is about KEY).
old_rule() {
  local cmd="$1" cfg="$2" key="$3" edit="${4:-}" dir base
  dir=$(dirname "$T/tree/$cfg") base=$(basename "$cfg")
  mkdir -p "$dir/moved"
  sed "$edit" "$T/tree/$cfg" > "$dir/moved/$base"
  (cd "$dir" && "$BIN" "$cmd" "moved/$base" --out "$T/old/$cmd-$base" > "$T/old.out" 2> "$T/old.err")
  local rc=$? msg
  msg=$(cat "$T/old.err")
  if [ $rc -ne 1 ]; then echo "FAIL old rule $cmd $cfg: exit $rc (want 1): $msg"; fail=1; return; fi
  [ "$(wc -l < "$T/old.err")" -eq 1 ] || { echo "FAIL old rule $cmd $cfg: not one line: $msg"; fail=1; }
  for want in "key '$key'" "no such file $T/tree/" "relative to the config's folder, $dir/moved)"; do
    grep -qF -- "$want" "$T/old.err" || { echo "FAIL old rule $cmd $cfg: message lacks \"$want\": $msg"; fail=1; }
  done
  rm -rf "$dir/moved"
}
D=$T/tree/data/delft372
old_rule hull configs/delft372_offsets.yaml hull.offsets_csv
old_rule section examples/section_delft372_station.yaml section.offsets_csv
old_rule rao examples/rao_delft372.yaml hull.offsets_csv
old_rule coefficients examples/coefficients_delft372.yaml compare.forced_heave_csv \
  "s|offsets_csv: ../data/delft372/|offsets_csv: $D/|"
old_rule evaluate examples/evaluate_from_rao_csv.yaml rao_csv
old_rule evaluate examples/evaluate_operability.yaml operability.scatter_csv \
  "s|rao_csv: data/|rao_csv: $T/tree/examples/data/|"
old_rule evaluate configs/davis-holloway-2003.yaml 'designs[0].config'
old_rule calibrate examples/calibrate_synthetic.yaml calibrate.data
old_rule calibrate examples/calibrate_delft372.yaml calibrate.data "s|offsets_csv: ../data/delft372/|offsets_csv: $D/|"
old_rule resistance examples/resistance_delft372.yaml hull.offsets_csv
# An STL hull named beside its config.
mkdir -p "$T/stl/hulls"
cp tests/fuzz/corpus/stl/box_ascii.stl "$T/stl/hulls/box.stl"
printf 'hull: { stl: hulls/box.stl, draught_m: 0.5 }\n' > "$T/stl/box.yaml"
(cd "$T/elsewhere" && "$BIN" hull ../stl/box.yaml --out stl > "$T/stl.log" 2>&1) ||
  { echo "FAIL stl beside its config: $(tail -1 "$T/stl.log")"; fail=1; }
grep -q "stl: $T/stl/hulls/box.stl" "$T/elsewhere/stl/config.resolved.yaml" ||
  { echo "FAIL stl: config.resolved.yaml lacks the absolute path"; fail=1; }
# A nested design config resolves its own paths against its own folder.
mkdir -p "$T/nest/designs"
sed 's|offsets_csv: ../data/|offsets_csv: ../../tree/data/|' "$T/tree/examples/rao_delft372.yaml" > "$T/nest/designs/d372.yaml"
printf 'designs:\n  - { config: designs/d372.yaml, name: d372 }\nseas:\n  - { spectrum: jonswap, Hs_m: 0.05, Tz_s: 2.0 }\nreport: { plots: false }\n' \
  > "$T/nest/study.yaml"
(cd "$T/elsewhere" && "$BIN" evaluate ../nest/study.yaml --out nest > "$T/nest.log" 2>&1) ||
  { echo "FAIL nested config's own paths: $(tail -1 "$T/nest.log")"; fail=1; }
[ $fail -eq 0 ] && echo "ok: $i runs of $(echo "$RUNS" | cut -d" " -f1 | sort -u | wc -l) commands from another working folder; 10 old-rule paths refused"
exit $fail
