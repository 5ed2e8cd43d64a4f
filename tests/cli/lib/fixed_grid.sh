# Sourced by the CLI tests that compare results with values recorded on fixed frequency grids: fixed_grid_tree
# DEST copies configs/, examples/, data/ and tests/data/ (from the working folder, the repository root) into
# DEST, keeping their relative layout so that every relative path in a config still points at its file, and
# turns the adaptive frequency grid off in every copied config (solver.adaptive_grid: off: a `solver:` block
# gets the key as its first entry; a hull config of the 14-hull study, which has none, gets the block), so that
# the runs compute exactly the grids the values were recorded on.
fixed_grid_tree() {
  local dest="$1" f
  mkdir -p "$dest/tests"
  cp -r configs examples data "$dest/"
  cp -r tests/data "$dest/tests/"
  while IFS= read -r f; do
    if grep -q '^solver:' "$f"; then
      sed -i -e 's/^solver: *{ */solver: { adaptive_grid: off, /' -e 's/^solver: *$/solver:\n  adaptive_grid: off/' "$f"
    elif grep -q '^hull:' "$f"; then
      printf 'solver: { adaptive_grid: off }\n' >> "$f"
    fi
  done < <(find "$dest" -name '*.yaml')
}
