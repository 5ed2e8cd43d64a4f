#include "campaign/run_campaign.h"

#include <memory>

#include "campaign/campaign_kinds.h"
#include "campaign/pareto_sweep.h"
#include "io/formats/input_error.h"

namespace hullopt::campaign {

CampaignSpec CampaignSpec::FromFile(io::CampaignCommand command, const std::string& file) {
  CampaignSpec s;
  s.command = command;
  s.config_file = file;
  return s;
}

CampaignSpec CampaignSpec::FromTree(io::CampaignCommand command, const YAML::Node& config, const std::string& source) {
  CampaignSpec s;
  s.command = command;
  s.config = config;
  s.source = source;
  return s;
}

bool CampaignRunOptions::IsValid(std::string* error) const {
  auto fail = [&](const std::string& e) {
    if (error) *error = e;
    return false;
  };
  if (out.empty()) return fail("out: the output folder must be given");
  if (max_evaluations < 0)
    return fail("max_evaluations = " + std::to_string(max_evaluations) + ": must be >= 0 (0 = no limit)");
  // threads and chunk are checked where they are used (ResolveThreads, campaign/campaign_setup.h; the explore
  // campaign's CheckOptions), in the words of the command line's --threads and --chunk.
  return true;
}

namespace {

std::unique_ptr<CampaignKind> MakeKind(const CampaignSpec& spec, const CampaignRunOptions& options) {
  if (spec.command == io::CampaignCommand::kExplore) return MakeExploreCampaign(options.chunk);
  return MakeOptimizeCampaign();
}

}  // namespace

CampaignResult RunCampaign(const CampaignSpec& spec, const CampaignRunOptions& options) {
  const YAML::Node& tree = spec.config;
  if (spec.config_file.empty() && tree.IsMap() && tree["optimize"] && tree["optimize"].IsMap() &&
      tree["optimize"]["pareto"])
    throw io::InputError(spec.source + ": key 'optimize.pareto': a Pareto sweep runs from a config file (it "
                         "writes its points' configs beside their folders); give the config as a file");
  if (spec.command != io::CampaignCommand::kOptimize || spec.config_file.empty() ||
      !HasParetoSweep(spec.config_file)) {
    auto kind = MakeKind(spec, options);
    return RunKind(*kind, spec, options);
  }
  // A Pareto sweep: ordinary optimize campaigns, one per point, inside the output folder.
  CampaignResult last;
  std::string texts, profiles;
  // The points follow each other (each starts from the front so far); a point's multistart runs share the
  // threads (CampaignRunner::Split).
  auto run_optimize = [&](const std::string& config, const std::string& out) {
    CampaignRunOptions one = options;
    one.out = out;
    auto kind = MakeOptimizeCampaign();
    last = RunKind(*kind, CampaignSpec::FromFile(io::CampaignCommand::kOptimize, config), one);
    texts += last.text;
    if (options.profile) profiles += out + ": " + last.profile_text;
    if (!last.complete) throw EvaluationLimitReached{};
  };
  try {
    last.sweep = RunParetoSweep(spec.config_file, options.out, run_optimize) + "\n";
  } catch (const EvaluationLimitReached&) {
  }
  last.text = texts;
  if (options.profile) last.profile_text = profiles;
  return last;
}

}  // namespace hullopt::campaign
