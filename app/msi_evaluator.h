#pragma once
// The seakeeping objective of a campaign: free design variables → parametric hull at fixed displacement →
// RAOs by the time-domain strip method → rms accelerations and MSI in the campaign's seas.
//
//   optimize:
//     objective: { measure: msi, position: mean, sea_weights: [1, 1] }   # defaults shown
//       measure: msi [%] | rms_accel [g] | P_E_kW (effective power at the design speed, resistance/);
//       position: mean | forward | lcg | transom
//   resistance: { form_factor: 1.0, ... }   # optional model options (io/resistance_config.h), no speed lists
//   seas: [...]                         # io/seas_config.h
//   mass: { kyy_over_L: 0.25, kg_over_T: 1.0 }   # optional; mass = displacement, LCG = LCB always
//   solver: { Cs: 0.065, sections: 40, panels: 14 }
//
// Quantities for constraints: L_m, B_m, T_m, B_overall_m, displacement_t, Cb, Cp, Cwp, Cvp, Fr, GM_T_m, GM_L_m,
// and the calm-water resistance at the design speed R_T_kN, R_W_kN, P_E_kW (e.g. P_E_max_kW: 12000).
#include <memory>

#include "io/yaml_map.h"
#include "optimizer/campaign.h"
#include "optimizer/evaluator.h"

namespace hullopt::app {

/// Builds the MSI evaluator from the config (consumes hull, water, speed, solver, seas, msi, mass and the
/// objective block). Throws io::InputError for bad input, before any evaluation.
std::unique_ptr<opt::Evaluator> MakeMsiEvaluator(io::YamlMap& root, io::YamlMap& objective,
                                                 const opt::CampaignDefinition& campaign);

}  // namespace hullopt::app
