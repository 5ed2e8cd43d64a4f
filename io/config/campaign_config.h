#pragma once
// Reading the `optimize:` / `explore:` block of a campaign config (docs/campaigns.md) into an
// opt::CampaignDefinition, with line-numbered errors.
//
//   optimize:
//     algorithm: LN_COBYLA          # NLopt name, derivative-free (LN_*, GN_*)
//     max_evaluations: 200          # per multistart run
//     xtol_rel: 1.0e-6              # optional, <= 0 disables
//     ftol_rel: 1.0e-8              # optional, <= 0 disables
//     starts: 1                     # multistart runs; run 0 starts at the base design
//     seed: 1                       # start points, stochastic algorithms, LHS
//     variables: { L_over_B: [8, 16], Cp: [0.55, 0.75] }    # [lower, upper]
//     start: { L_over_B: 11.0 }     # optional; default: the value in hull.parametric
//     constraints: { L_max_m: 75, Cvp_min: 0.5 }           # <quantity>_max|_min[_unit]: limit
//     objective: { ... }            # read by the evaluator factory (campaign/evaluator_factory.h)
//     samples: 200                  # explore only
//     method: sobol                 # explore only: sobol | lhs
//
// `hullopt explore` reads an `explore:` block if there is one, else the `optimize:` block; keys of the other
// command (algorithm, samples, ...) are accepted and ignored so one config serves both.
#include <yaml-cpp/yaml.h>

#include <optional>
#include <string>

#include "io/config/yaml_map.h"
#include "optimizer/campaign.h"

namespace hullopt::io {

enum class CampaignCommand { kOptimize, kExplore };

struct ExploreOptions {
  int samples = 100;             ///< designs to evaluate
  std::string method = "sobol";  ///< sobol | lhs
};

struct CampaignConfig {
  opt::CampaignDefinition definition;  ///< known_quantities still empty: filled from the evaluator
  ExploreOptions explore;
  std::string block;  ///< "optimize" or "explore": the block read
  /// Per variable: "hull.parametric" if its base value came from the base hull, else "<block>.start".
  std::vector<std::string> start_source;
};

/// Reads the campaign block of `root` (marking it consumed; the `objective` key is left for the evaluator
/// factory: *block_out receives the block's map for that). raw_root is the same file as a plain YAML tree,
/// used to look up base values in hull.parametric without consuming the hull block (the evaluator reads it).
/// Throws InputError for a missing block, wrong types, or a missing base value.
CampaignConfig ReadCampaignConfig(YamlMap& root, const YAML::Node& raw_root, CampaignCommand command,
                                  std::optional<YamlMap>* block_out);

/// Throws InputError "file: <block>: <message>" unless definition.IsValid; also checks explore options.
void ValidateCampaign(const CampaignConfig& config, CampaignCommand command, const std::string& file);

}  // namespace hullopt::io
