#include "app/campaign_setup.h"

#ifdef _OPENMP
#include <omp.h>
#endif

#include <cstdio>
#include <optional>

#include "app/evaluator_factory.h"
#include "io/config/campaign_outputs.h"
#include "io/report/evaluation_report.h"
#include "io/formats/input_error.h"
#include "evaluation/msi_evaluator.h"

namespace hullopt::app {

LoadedCampaign LoadCampaign(const std::string& config_file, io::CampaignCommand command) {
  LoadedCampaign out;
  io::YamlMap root = io::YamlMap::LoadFile(config_file);
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

void ReportWarnings(const std::vector<opt::EvaluationRecord>& records, long best, const std::string& history_file,
                    bool quiet, nlohmann::json* summary) {
  const CampaignWarnings w = CollectWarnings(records);
  (*summary)["evaluations_with_warning"] = w.count;
  if (best >= 0 && !records[best].result.warning.empty()) (*summary)["best_warning"] = records[best].result.warning;
  if (quiet || w.count == 0) return;
  std::fprintf(stderr,
               "hullopt: warning: %ld of %zu evaluations carry a warning (message column of %s); first, "
               "evaluation %ld: %s\n",
               w.count, records.size(), history_file.c_str(), w.first_evaluation, w.first_message.c_str());
}

std::string CheckBestResolution(const LoadedCampaign& campaign, const std::vector<double>& x, long evaluation,
                                bool quiet, nlohmann::json* summary) {
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
  if (!quiet) std::fprintf(stderr, "hullopt: warning: %s\n", warning.c_str());
  return warning;
}

}  // namespace hullopt::app
