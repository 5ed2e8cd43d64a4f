#include "campaign/campaign_setup.h"

#ifdef _OPENMP
#include <omp.h>
#endif

#include <optional>

#include "campaign/evaluator_factory.h"
#include "campaign/run_campaign.h"
#include "io/config/campaign_outputs.h"
#include "io/config/run_cost.h"
#include "io/report/evaluation_report.h"
#include "io/formats/input_error.h"
#include "evaluation/msi_evaluator.h"

namespace hullopt::campaign {

namespace {

/// The config's root mapping: the file as loaded, or a copy of the tree (built from values, e.g. Python dicts,
/// whose keys are text and unique by construction: no YAML text to check for duplicate or tagged keys).
io::YamlMap RootOf(const CampaignSpec& spec) {
  if (!spec.config_file.empty()) return io::YamlMap::LoadFile(spec.config_file);
  if (!spec.config.IsMap()) throw io::InputError(spec.source + ": the config must be a mapping of key: value pairs");
  return io::YamlMap(YAML::Clone(spec.config), "", spec.source, YAML::Node(YAML::NodeType::Map));
}

}  // namespace

LoadedCampaign LoadCampaign(const CampaignSpec& spec) {
  const io::CampaignCommand command = spec.command;
  const std::string& config_file = spec.Name();
  LoadedCampaign out;
  io::YamlMap root = RootOf(spec);
  out.raw = YAML::Clone(root.raw());
  std::optional<io::YamlMap> block;
  out.config = io::ReadCampaignConfig(root, out.raw, command, &block);
  out.evaluator = MakeEvaluator(root, *block, out.config.definition);
  out.resolution = io::ReadResolutionCheck(root);
  if (out.resolution.enabled && !dynamic_cast<eval::ResolutionCheckable*>(out.evaluator.get()))
    throw io::InputError(root.Where("resolution_check") + ": needs the seakeeping objective (an analytic "
                         "objective has no strip resolution to check)");
  block->Finish();
  root.Finish();
  eval::CheckBaseDesign(*out.evaluator);  // the base design built once the whole config has been checked
  out.config.definition.known_quantities = out.evaluator->QuantityNames();
  out.config.definition.known_variables = out.evaluator->VariableNames();
  io::ValidateCampaign(out.config, command, config_file);
  out.resolved = root.resolved();
  // The check refines the report of the best design, not the evaluations: switching it on or off resumes the
  // same campaign.
  YAML::Node identity = YAML::Clone(out.resolved);
  identity.remove("resolution_check");
  YAML::Emitter em;
  em << identity;
  out.config_hash = io::TextHash(em.c_str());
  return out;
}

int ResolveThreads(int requested) {
  // More threads than this is no faster on any machine hullopt targets, and each costs a stack.
  constexpr int kMaxThreads = 256;
  if (requested < 0 || requested > kMaxThreads)
    throw io::InputError("--threads " + std::to_string(requested) + ": must lie in [0, " +
                         std::to_string(kMaxThreads) + "] (0 = the OpenMP default)");
  if (requested > 0) return requested;
#ifdef _OPENMP
  return omp_get_max_threads();
#else
  return 1;
#endif
}

CampaignWarnings CollectWarnings(const std::vector<opt::EvaluationRecord>& records) {
  CampaignWarnings w;
  for (std::size_t i = 0; i < records.size(); ++i) {
    const auto& r = records[i].result;
    if (!r.produced || r.warning.empty()) continue;
    if (w.count++ == 0) w.first_evaluation = static_cast<long>(i), w.first_message = r.warning;
  }
  return w;
}

std::string ReportWarnings(const std::vector<opt::EvaluationRecord>& records, long best,
                           const std::string& history_file, nlohmann::json* summary) {
  const CampaignWarnings w = CollectWarnings(records);
  (*summary)["evaluations_with_warning"] = w.count;
  if (best >= 0 && !records[best].result.warning.empty()) (*summary)["best_warning"] = records[best].result.warning;
  if (w.count == 0) return "";
  return "hullopt: warning: " + std::to_string(w.count) + " of " + std::to_string(records.size()) +
         " evaluations carry a warning (message column of " + history_file + "); first, evaluation " +
         std::to_string(w.first_evaluation) + ": " + w.first_message;
}

std::string CheckBestResolution(const LoadedCampaign& campaign, const std::vector<double>& x, long evaluation,
                                nlohmann::json* summary) {
  if (!campaign.resolution.enabled) return "";
  auto* checkable = dynamic_cast<eval::ResolutionCheckable*>(campaign.evaluator.get());
  if (!checkable) return "";
  const sk::ResolutionCheck r = checkable->CheckResolution(x, campaign.resolution.factor, campaign.resolution.options);
  nlohmann::json j = io::ResolutionCheckJson(r);
  j["evaluation"] = evaluation;
  (*summary)["resolution_check"] = j;
  if (r.converged) return "";
  const std::string warning = "resolution check of the best design (evaluation " + std::to_string(evaluation) +
                              "): " + r.warning;
  (*summary)["resolution_warning"] = warning;
  return warning;
}

std::string CheckCampaignCost(const std::string& command, const YAML::Node& resolved, const std::string& block,
                              long evaluations, const std::string& count_key, int parallel, bool force) {
  const YAML::Node objective = resolved[block] ? resolved[block]["objective"] : YAML::Node();
  if (objective && objective.IsMap() && objective["analytic"]) return "";
  // 60: the sea-evaluation grid when solver.frequencies is absent (app/design_case.h EvaluationFrequencies).
  io::StripWork work = io::StripWorkFromResolved(resolved, 60);
  // An objective over headings (anything but none or [180]) solves every heading by the oblique path.
  const YAML::Node headings = objective && objective.IsMap() ? objective["headings_deg"] : YAML::Node();
  if (headings && headings.IsSequence() && !(headings.size() == 1 && headings[0].as<double>(0.0) == 180.0))
    work.headings = static_cast<int>(headings.size());
  work.kernels = evaluations;
  work.count_key = count_key;
  work.parallel = parallel;
  work.parallel_key = "--threads";
  return io::CheckRunCostLine(command, work, force);
}

}  // namespace hullopt::campaign
