#include "campaign/evaluator_factory.h"

#include "io/config/msi_objective_config.h"
#include "io/formats/input_error.h"
#include "optimizer/analytic_objectives.h"

namespace hullopt::campaign {

std::unique_ptr<opt::Evaluator> MakeEvaluator(io::YamlMap& root, io::YamlMap& block,
                                              const opt::CampaignDefinition& campaign) {
  io::YamlMap objective = block.MapOrEmpty("objective");
  if (!objective.Has("analytic")) return io::ReadMsiObjective(root, objective, campaign);
  opt::AnalyticObjectiveOptions o;
  o.function = objective.Choice("analytic", opt::AnalyticFunctionNames());
  o.dimension = static_cast<int>(campaign.variables.size());
  o.eval_delay_ms = objective.Number("eval_delay_ms", o.eval_delay_ms);
  o.refuse_above_sum = objective.Number("refuse_above_sum", o.refuse_above_sum);
  o.warn_above_sum = objective.Number("warn_above_sum", o.warn_above_sum);
  objective.Finish();
  std::string error;
  if (!o.IsValid(&error)) throw io::InputError(block.Where("objective") + ": " + error);
  // The analytic objective ignores the ship description; accept a full config so demos can reuse one.
  for (const char* k : {"hull", "mass", "speed", "water", "solver", "seas", "section", "calibrate", "resistance"})
    root.Skip(k);
  return std::make_unique<opt::AnalyticEvaluator>(o);
}

}  // namespace hullopt::campaign
