#pragma once
// Loading and checking a campaign config (optimize, explore): everything that can be wrong with the input is
// reported here, before any evaluation.
#include <nlohmann/json.hpp>
#include <yaml-cpp/yaml.h>

#include <memory>
#include <string>
#include <vector>

#include "io/config/campaign_config.h"
#include "io/config/resolution_check_config.h"
#include "optimizer/evaluation_record.h"
#include "optimizer/evaluator.h"

namespace hullopt::campaign {
struct CampaignSpec;
}

namespace hullopt::campaign {

struct LoadedCampaign {
  io::CampaignConfig config;
  YAML::Node raw;           ///< the config file as written (base for best.yaml)
  YAML::Node resolved;      ///< resolved tree (config.resolved.yaml)
  std::string config_hash;  ///< io::TextHash of the emitted resolved tree
  std::unique_ptr<opt::Evaluator> evaluator;
  io::ResolutionCheckConfig resolution;  ///< `resolution_check:` (checks the best design at the end)
};

/// Reads, validates and builds the evaluator. Throws io::InputError with a one-line message.
LoadedCampaign LoadCampaign(const CampaignSpec& spec);

/// Number of OpenMP threads to use: `requested` if > 0, else the OpenMP default (1 without OpenMP).
int ResolveThreads(int requested);

/// Evaluations of a campaign whose design was produced with a warning (opt::EvalResult::warning).
struct CampaignWarnings {
  long count = 0;
  long first_evaluation = -1;  ///< -1 when count is 0
  std::string first_message;
};
CampaignWarnings CollectWarnings(const std::vector<opt::EvaluationRecord>& records);
/// Adds "evaluations_with_warning" (and, when the best design has one, "best_warning") to a summary; returns
/// "" or one line naming the count, the first such evaluation and its warning.
std::string ReportWarnings(const std::vector<opt::EvaluationRecord>& records, long best,
                           const std::string& history_file, nlohmann::json* summary);

/// With the campaign's `resolution_check` on, re-runs the design at x (its best) at the finer resolution and adds
/// a "resolution_check" block to the summary; a design that is not converged adds "resolution_warning" to the
/// summary. Returns that warning ("" when converged or the check is off).
std::string CheckBestResolution(const LoadedCampaign& campaign, const std::vector<double>& x, long evaluation,
                                nlohmann::json* summary);

/// io::CheckRunCostLine for a campaign whose resolved config is `resolved` and campaign block `block`: at most
/// `evaluations` designs (each one kernel and one sweep over the sea frequencies; the number is set by
/// count_key), `parallel` of them at a time. "" for an analytic objective (no strip solver).
std::string CheckCampaignCost(const std::string& command, const YAML::Node& resolved, const std::string& block,
                              long evaluations, const std::string& count_key, int parallel, bool force);

}  // namespace hullopt::campaign
