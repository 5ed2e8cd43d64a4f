#pragma once
// The one place the campaign commands (optimize, explore) get their objective from. To plug in the MSI
// objective, extend MakeEvaluator: read `objective` (block) and the hull/mass/speed/water/solver/seas blocks
// (root), and return an opt::Evaluator that builds the hull from the free variables, computes RAOs and MSI.
#include <memory>

#include "io/config/yaml_map.h"
#include "optimizer/campaign.h"
#include "optimizer/evaluator.h"

namespace hullopt::campaign {

/// root: the whole config; block: the campaign block (optimize:/explore:) whose `objective` key selects the
/// objective; campaign: variables (in order) and constraints as read. Currently supports only the analytic
/// test/demo objective `objective: { analytic: sphere|rosenbrock|rastrigin|linear, eval_delay_ms: 0,
/// refuse_above_sum: 1e300, warn_above_sum: 1e300 }`; with it the physics blocks of root are ignored. Throws io::InputError.
std::unique_ptr<opt::Evaluator> MakeEvaluator(io::YamlMap& root, io::YamlMap& block,
                                              const opt::CampaignDefinition& campaign);

}  // namespace hullopt::campaign
