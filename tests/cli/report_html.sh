#!/usr/bin/env bash
# report.html of hullopt design and of a campaign (optimize) is self-contained: no external reference of any kind (no URL scheme, no
# protocol-relative //, no src= or <link, no @import, url( only to a fragment of the page or data:), one <html>,
# as many </svg> as <svg, and the sections a reader needs.
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

"$bin" design configs/davis-holloway-2003/hull04_DUT372.yaml --out "$tmp/d" > /dev/null 2>&1 || fail "design fails"
check "$tmp/d/report.html"
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
for s in 'baseline MSI' 'best MSI' 'Body plans' 'Convergence and variables' 'Optimisation history'; do
  grep -q "$s" "$f" || fail "campaign report: no '$s'"
done
echo "PASS"
