#!/usr/bin/env bash
# report.html of hullopt design, evaluate and of a campaign (optimize) is self-contained: no external reference of any kind (no URL scheme, no
# protocol-relative //, no src= or <link, no @import, url( only to a fragment of the page or data:), one <html>,
# as many </svg> as <svg, and the sections a reader needs: the seakeeping verdict, the defaults taken, each warning
# once, the campaign's warnings about its best design and the active set.
set -u
bin="$1"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*"; exit 1; }

check() {  # $1 report.html
  local f="$1"
  [ -s "$f" ] || fail "$f missing"
  ! grep -qiE 'https?:|<link|@import|src=' "$f" || fail "$f: external reference: $(grep -oiE '.{20}(https?:|<link|@import|src=).{20}' "$f" | head -1)"
  ! grep -oiE 'url\([^)]*\)' "$f" | grep -qvE 'url\((#|data:)' || fail "$f: url( to something else than a fragment or data:"
  ! grep -q '//' "$f" || fail "$f: '//' (a protocol-relative reference)"
  [ "$(grep -o '<html' "$f" | wc -l)" -eq 1 ] || fail "$f: not one <html>"
  [ "$(grep -o '<svg' "$f" | wc -l)" -eq "$(grep -o '</svg>' "$f" | wc -l)" ] || fail "$f: unclosed <svg>"
  for s in 'Hydrostatics' 'Body plan' 'RAOs' 'MSI per sea and position' 'Warnings' 'Inputs'; do
    grep -q "$s" "$f" || fail "$f: no section '$s'"
  done
}

"$bin" design configs/davis-holloway-2003/hull04_DUT372.yaml --out "$tmp/d" > "$tmp/d.out" 2>&1 || fail "design fails"
check "$tmp/d/report.html"
# The verdict against the shipped criteria, and every default taken with its effect.
for s in 'Seakeeping verdict: NORDFORSK 1987' 'Highest Hs up to which each criterion holds' 'Defaults taken' \
         'solver.Cs = 0 (default)' 'mass.kyy_m = 0.25 L' 'mass.kg_m = T' 'solver.frequencies:' 'seas: the sea-state line'; do
  grep -qF "$s" "$tmp/d/report.html" || fail "design report: no '$s'"
done
grep -q '^verdict: hull04_DUT372: ' "$tmp/d.out" || fail "design: no verdict line on stdout"
# Each warning once: hull 9 (SW1) carries several.
"$bin" design configs/davis-holloway-2003/hull09_SW1.yaml --out "$tmp/w" > /dev/null 2> "$tmp/w.err" || fail "design SW1 fails"
grep -q 'hullopt: warning:' "$tmp/w.err" || fail "design SW1: no warning (the test needs one)"
[ -z "$(grep 'hullopt: warning:' "$tmp/w.err" | sort | uniq -d)" ] || fail "design: a warning printed twice"
[ "$(grep -o '<li>design' "$tmp/w/report.html" | wc -l)" -eq "$(grep -c 'hullopt: warning:' "$tmp/w.err")" ] ||
  fail "design: report.html and stderr list different warnings"
# evaluate writes report.html with the verdict of its designs.
"$bin" evaluate configs/davis-holloway-2003/hull04_DUT372.yaml --out "$tmp/e" > /dev/null 2>&1 || fail "evaluate fails"
[ -s "$tmp/e/report.html" ] || fail "evaluate: no report.html"
grep -q 'Seakeeping verdict' "$tmp/e/report.html" || fail "evaluate report: no verdict"
"$bin" design configs/delft372_offsets.yaml --out "$tmp/o" > /dev/null 2>&1 || fail "design (offsets) fails"
check "$tmp/o/report.html"
# A campaign folder: baseline beside best, convergence and variables.
sed -e 's/max_evaluations: 300 .*/max_evaluations: 8/' -e 's/sections: 40 .*/sections: 20/' \
    -e 's/panels: 14 .*/panels: 8/' configs/optimize-catamaran.yaml > "$tmp/opt.yaml"
"$bin" optimize "$tmp/opt.yaml" --out "$tmp/c" > /dev/null 2>&1 || fail "short optimize fails"
f="$tmp/c/report.html"
[ -s "$f" ] || fail "campaign: no report.html"
! grep -qiE 'https?:|<link|@import|src=|//' "$f" || fail "campaign report: external reference"
! grep -oiE 'url\([^)]*\)' "$f" | grep -qvE 'url\((#|data:)' || fail "campaign report: url( not a fragment"
[ "$(grep -o '<svg' "$f" | wc -l)" -eq "$(grep -o '</svg>' "$f" | wc -l)" ] || fail "campaign report: unclosed <svg>"
for s in 'baseline MSI' 'best MSI' 'Body plans' 'Convergence and variables' 'Optimisation history' \
         'Seakeeping verdict' 'Active set at the best design'; do
  grep -q "$s" "$f" || fail "campaign report: no '$s'"
done
# The campaign's warnings about its best design reach the report.
if grep -q '"best_warning"' "$tmp/c/summary.json"; then
  ! grep -q 'No warnings.' "$f" || fail "campaign report: 'No warnings.' while summary.json has a best_warning"
  grep -q 'best design (evaluation' "$f" || fail "campaign report: the best design's warning is missing"
fi
echo "PASS"
