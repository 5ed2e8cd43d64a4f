#pragma once
// The `solver:` and `mass:` sections of a config (docs/config-reference.md) for `hullopt rao` and the
// commands that compute RAOs.
//
// solver:
//   method: time_domain_strip        # | strip_theory_stf
//   sections: 40                     # strip steps along the hull (2 to 400)
//   panels: 14                       # panels per wetted section of one body (even, 4 to 100)
//   Cs: 0.024                        # sectional damping coefficient (>= 0)
//   hydrodynamic_fraction: 0.2       # time marching: weight of the hydrodynamic acceleration (0 < w <= 1)
//   path: periodic                   # | time_marching
//   time_scheme: weighted_average_trapezoid  # | paper_single_pass: time_marching's step kinematics (a
//                                    # non-default value with path: periodic is an error)
//   interaction: true                # multihull bodies share the strips (false: one demihull alone)
//   stations: cell_faces             # | cell_midpoints: where the strip steps sit (docs/ship-motions.md)
//   sectional_force: momentum        # | pressure: the reference paper's written form (docs/theory.md)
//   adaptive_grid: on                # | off: refine the frequencies until the RAO peaks and the MSI converge
//   adaptive_grid_max_passes: 6      # refinement passes at most (1 to 50)
//   adaptive_grid_max_frequencies: 400  # frequencies in the refined grid at most (3 to 1000)
//   frequencies: { lambda_over_L: [0.6, 0.8, 1.0] }   # or omega_rad_s / omega_e_rad_s lists, or
//                { range: { quantity: omega_e_rad_s, from: 2.0, to: 12.0, count: 60 } }
// mass:                              # defaults from the hull's hydrostatics
//   mass_kg: 87.07                   # default: displacement
//   lcg_m_from_ap: 1.41              # default: LCB
//   kyy_m: 0.782                     # default: 0.25 L
//   kg_m: 0.34                       # default: the draught (not used by heave/pitch)
//   accept_mass_mismatch: false      # true: a mass more than 2 % from the displacement is a warning, not an
//                                    # error (docs/bad-inputs.md)
#include <string>

#include "evaluation/design_spec.h"
#include "evaluation/solver_settings.h"
#include "io/config/yaml_map.h"
#include "parametric_hull/hull_form.h"
#include "parametric_hull/hydrostatics.h"
#include "seakeeping/motions/frequency_list.h"
#include "seakeeping/motions/rao_solver.h"
#include "seakeeping/strip/strip_kernel.h"
#include "seakeeping/strip/strip_operators.h"

namespace hullopt::io {

/// The solver section read straight into the solver's own options (enums, not names).
using SolverConfig = eval::SolverSettings;

/// Reads and validates `solver` (consumes its keys; call solver.Finish() afterwards or let this do it).
/// Without frequencies_required, `frequencies` may be absent (commands that choose their own grid).
/// Throws InputError "file:line: key 'solver.x' = v: rule".
SolverConfig ParseSolverConfig(YamlMap& solver, bool frequencies_required = true);

/// The campaigns' mass ratios: k_yy / L in (0.05, 0.5) and KG / T in (0, 10). Each reads `key` (default
/// `default_value`) and fails naming the key and the rule outside its range.
double ReadKyyOverL(YamlMap& mass, double default_value);
double ReadKgOverT(YamlMap& mass, double default_value);

/// Reads `mass` without the hull: the values given, checked by the rules that need no hull (signs, ratio
/// ranges, one of each pair, no unknown key); the defaults are left to eval::ResolveMass (placeholders in the
/// resolved tree until RecordResolvedMass).
eval::MassSpec ParseMassSpec(YamlMap& mass);
/// Fills the resolved `mass` map's defaults with the values the hull gave them.
void RecordResolvedMass(YAML::Node resolved_mass, const eval::MassSpec& spec,
                        const hull::MassProperties& mass);

/// Reads `mass` with defaults from the hydrostatics (recorded in the resolved config). Throws InputError for
/// non-positive mass or radius of gyration, an LCG outside the hull's length, and the refusals of the mass
/// plausibility rules (parametric_hull/plausibility.h): a mass more than 2 % from the displaced mass (unless
/// `accept_mass_mismatch: true`), k_yy outside [0.1, 0.5] L, KG outside (0, 0.5 L]. Their warnings are
/// appended to *warnings.
hull::MassProperties ParseMassConfig(YamlMap& mass, const hull::Hydrostatics& hs,
                                     std::vector<std::string>* warnings = nullptr);

}  // namespace hullopt::io
