#pragma once
// The seakeeping objective of a campaign from its config: the base design and the objective block.
//
//   optimize:
//     objective: { measure: msi, position: mean, sea_weights: [1, 1] }   # defaults shown
//       measure: msi [%] | rms_accel [g] | P_E_kW (effective power at the design speed, resistance/)
//                | scatter_msi [%] (scatter-weighted mean MSI over the operability: block's diagram)
//                | downtime_pct [% of time] (100 - time `criterion` is met; criterion: <name> | all);
//       position: mean | forward | lcg | transom
//   operability: { scatter_csv: ..., criteria: [...] }   # io/config/operability_config.h; for the two
//                                                        # operability measures, whose cells replace the
//                                                        # seas: list
//   resistance: { form_factor: 1.0, ... }   # optional model options, no speed lists
//                                           # (io/config/resistance_config.h)
//   seas: [...]                         # io/config/seas_config.h
//   mass: { kyy_over_L: 0.25, kg_over_T: 1.0 }   # optional; mass = displacement, LCG = LCB always
//   solver: { Cs: 0.065, sections: 40, panels: 14 }
//
// Constraints may name the quantities of evaluation/msi_evaluator.h (e.g. P_E_max_kW: 12000).
#include <memory>

#include "io/config/yaml_map.h"
#include "optimizer/campaign.h"
#include "optimizer/evaluator.h"

namespace hullopt::io {

/// Builds the MSI evaluator from the config (consumes hull, water, speed, solver, seas, msi, mass and the
/// objective block). The base design is built once here, so a bad base config fails before any evaluation.
/// Throws InputError.
std::unique_ptr<opt::Evaluator> ReadMsiObjective(YamlMap& root, YamlMap& objective,
                                                 const opt::CampaignDefinition& campaign);

}  // namespace hullopt::io
