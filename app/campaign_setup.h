#pragma once
// Loading and checking a campaign config for `hullopt optimize` / `hullopt explore`: everything that can be
// wrong with the input is reported here, before any evaluation.
#include <yaml-cpp/yaml.h>

#include <memory>
#include <string>

#include "io/campaign_config.h"
#include "optimizer/evaluator.h"

namespace hullopt::app {

struct LoadedCampaign {
  io::CampaignConfig config;
  YAML::Node raw;           ///< the config file as written (base for best.yaml)
  YAML::Node resolved;      ///< resolved tree (config.resolved.yaml)
  std::string config_hash;  ///< io::TextHash of the emitted resolved tree
  std::unique_ptr<opt::Evaluator> evaluator;
};

/// Reads, validates and builds the evaluator. Throws io::InputError with a one-line message.
LoadedCampaign LoadCampaign(const std::string& config_file, io::CampaignCommand command);

/// Number of OpenMP threads to use: `requested` if > 0, else the OpenMP default (1 without OpenMP).
int ResolveThreads(int requested);

}  // namespace hullopt::app
