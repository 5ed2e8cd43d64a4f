# Sourced by the CLI tests that run every command on the repository's example configs away from the repository
# root: example_tree DEST copies configs/, examples/ and data/ (from the working folder, the repository root)
# into DEST, keeping their relative layout so that every relative path in a config still points at its file
# relative to that config's folder, and coarsens the solver settings of the copies (20 sections x 8 panels,
# few frequencies, few evaluations) so that each command takes a second or so. It also adds a config with an
# operability block whose scatter diagram is named relative to the config.
#
# RUNS: one line per run, "command config-path-relative-to-DEST" (the commands and configs the tests cover).
RUNS="hull configs/delft372_offsets.yaml
hull examples/hull_catamaran.yaml
section examples/section_delft372_station.yaml
section examples/section_semicircle.yaml
rao examples/rao_delft372.yaml
coefficients examples/coefficients_delft372.yaml
evaluate examples/evaluate_from_rao_csv.yaml
evaluate examples/evaluate_operability.yaml
evaluate configs/davis-holloway-2003.yaml
evaluate configs/davis-holloway-2003/hull02_NPL5b_seas.yaml
optimize configs/optimize-catamaran.yaml
optimize examples/optimize_analytic_demo.yaml
explore configs/optimize-catamaran.yaml
explore examples/explore_analytic_demo.yaml
calibrate examples/calibrate_delft372.yaml
calibrate examples/calibrate_synthetic.yaml
resistance examples/resistance_delft372.yaml
resistance examples/resistance_catamaran.yaml
design configs/delft372_offsets.yaml"

example_tree() {
  local dest="$1"
  mkdir -p "$dest" && cp -r configs examples data "$dest"/ || return 1
  local c="$dest/configs" e="$dest/examples"
  # Strip solver: 20 sections x 8 panels; few frequencies; few evaluations and samples.
  sed -i 's/count: 45 }/count: 7 }/' "$e/rao_delft372.yaml"
  sed -i 's/sections: 40/sections: 20/; s/panels: 14/panels: 8/; s/count: 49 }/count: 6 }/' \
    "$e/coefficients_delft372.yaml"
  sed -i 's/solver: { sections: 40, panels: 14 }/solver: { sections: 20, panels: 8 }/' "$e/calibrate_delft372.yaml"
  sed -i 's/^  sections: 40 .*/  sections: 20/; s/^  panels: 14 .*/  panels: 8/; s/max_evaluations: 300 .*/max_evaluations: 5/;
          s/samples: 200 .*/samples: 4/' "$c/optimize-catamaran.yaml"
  sed -i 's/max_evaluations: 300 .*/max_evaluations: 20/' "$e/optimize_analytic_demo.yaml"
  # The 14-hull study: two designs (a nested config each, one with on_infeasible: nearest), coarse solver.
  sed -i '/{ config: davis-holloway-2003\/hull\(0[13-9]\|1[02-4]\)_/d' "$c/davis-holloway-2003.yaml"
  for h in hull02_NPL5b hull11_SW3; do
    printf 'solver: { sections: 20, panels: 8, frequencies: { lambda_over_L: [0.8, 1.2, 1.6, 2.0, 2.6, 3.4] } }\n' \
      >> "$c/davis-holloway-2003/$h.yaml"
  done
  # One design computed from its hull config, named after the file.
  { cat "$c/davis-holloway-2003/hull02_NPL5b.yaml"; printf 'seas:\n  - { spectrum: jonswap, Hs_m: 3.0, Tz_s: 7.5 }\n'; } \
    > "$c/davis-holloway-2003/hull02_NPL5b_seas.yaml"
  # Operability: a two-cell scatter diagram beside the config.
  printf '# Hs by Tz, probabilities\nHs_m\\Tz_s,5.5,7.5\n1.0,0.6,0\n3.0,0,0.4\n' > "$e/data/scatter_two_cells.csv"
  { sed '/^seas:/,$d' "$e/evaluate_from_rao_csv.yaml"
    printf 'seas:\n  - { spectrum: jonswap, Hs_m: 3.0, Tz_s: 7.5 }\nreport: { plots: false }\n'
    printf 'operability: { scatter_csv: data/scatter_two_cells.csv, criteria: [ { msi_max_pct: 20 } ] }\n'
  } > "$e/evaluate_operability.yaml"
}
