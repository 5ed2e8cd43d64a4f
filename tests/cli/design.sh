#!/usr/bin/env bash
# hullopt design end to end: every Table 1 config, the Delft 372 offsets config and a campaign's best.yaml run
# unchanged with the defaults (exit 0, every output written, no non-finite number in them), and
# config.resolved.yaml re-runs to the same msi.csv.
set -u
bin="$1"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*"; exit 1; }

check_outputs() {  # $1 folder
  for f in hydrostatics.json bodyplan.svg rao.csv rao.svg msi.csv summary.json config.resolved.yaml VERSION \
           report.html accel_per_m.svg; do
    [ -s "$1/$f" ] || fail "$1: $f missing or empty"
  done
  ! grep -qiE '(^|[^a-z])(nan|inf)([^a-z]|$)' "$1/msi.csv" "$1/rao.csv" || fail "$1: non-finite number in msi.csv or rao.csv"
  ! grep -qiE '\b(nan|inf|infinity)\b' "$1/summary.json" "$1/hydrostatics.json" || fail "$1: non-finite number in JSON"
  [ "$(grep -c ',mean,' "$1/msi.csv")" -ge 1 ] || fail "$1: msi.csv has no mean rows"
}

for cfg in configs/davis-holloway-2003/hull*.yaml configs/delft372_offsets.yaml; do
  n=$(basename "$cfg" .yaml)
  "$bin" design "$cfg" --out "$tmp/$n" > "$tmp/$n.log" 2>&1 || fail "$n: exit non-zero: $(tail -1 "$tmp/$n.log")"
  check_outputs "$tmp/$n"
done
# Six seas of the sea-state line x (forward, lcg, transom, mean) by default.
[ "$(grep -c '^hull04_DUT372,' "$tmp/hull04_DUT372/msi.csv")" -eq 24 ] || fail "default seas/positions: expected 24 rows"

# Re-run of the resolved config: the same msi.csv, the design keeping its name.
for n in hull04_DUT372 delft372_offsets; do
  "$bin" design "$tmp/$n/config.resolved.yaml" --out "$tmp/$n.rerun" > /dev/null 2>&1 || fail "$n: resolved config does not re-run"
  cmp -s <(grep -v '^#' "$tmp/$n/msi.csv" | sed "s/^$n,/X,/") \
         <(grep -v '^#' "$tmp/$n.rerun/msi.csv" | sed "s/^$n,/X,/") || fail "$n: re-run msi.csv differs"
done

# A campaign's best.yaml, unchanged (its optimize block is skipped with a note).
sed -e 's/max_evaluations: 300 .*/max_evaluations: 8/' -e 's/sections: 40 .*/sections: 20/' \
    -e 's/panels: 14 .*/panels: 8/' configs/optimize-catamaran.yaml > "$tmp/opt.yaml"
"$bin" optimize "$tmp/opt.yaml" --out "$tmp/opt" > /dev/null 2>&1 || fail "short optimize fails"
"$bin" design "$tmp/opt/best.yaml" --out "$tmp/best" > /dev/null 2> "$tmp/best.err" || fail "best.yaml: $(tail -1 "$tmp/best.err")"
check_outputs "$tmp/best"
"$bin" design "$tmp/opt.yaml" --out "$tmp/campaign_config" > /dev/null 2> "$tmp/cc.err" || fail "campaign config refused"
grep -q "key 'optimize' belongs to another command: skipped" "$tmp/cc.err" || fail "no note for the skipped optimize block"

# Overrides: a given seas list and mass are used.
{ cat configs/davis-holloway-2003/hull02_NPL5b.yaml; echo "seas: [ { spectrum: jonswap, Hs_m: 2.0, Tz_s: 6.5 } ]"; \
  echo "mass: { kyy_m: 18.0 }"; } > "$tmp/over.yaml"
"$bin" design "$tmp/over.yaml" --out "$tmp/over" > /dev/null 2>&1 || fail "override config fails"
[ "$(grep -c '^over,' "$tmp/over/msi.csv")" -eq 4 ] || fail "seas override not used"
grep -q 'kyy_m: 18' "$tmp/over/config.resolved.yaml" || fail "mass override not recorded"

# evaluate takes a single hull config with the same defaults and gives the same MSI.
"$bin" evaluate configs/davis-holloway-2003/hull04_DUT372.yaml --out "$tmp/ev" > /dev/null 2>&1 || fail "evaluate on a hull config fails"
cmp -s <(grep -v '^#' "$tmp/ev/msi.csv") <(grep -v '^#' "$tmp/hull04_DUT372/msi.csv") || fail "evaluate and design differ"
echo "PASS"
