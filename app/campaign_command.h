#pragma once
// The campaign commands (`hullopt optimize`, `hullopt explore`) over the campaign library (campaign/
// run_campaign.h): their command-line options, progress bar, messages on stderr and result lines on stdout.
#include <functional>
#include <string>

#include "app/cli_app.h"
#include "app/commands.h"
#include "io/config/campaign_config.h"

namespace hullopt::app {

/// The command-line options every campaign command has.
struct CampaignCliOptions {
  std::string config;  ///< campaign YAML
  std::string out;     ///< output folder
  int threads = 0;     ///< OpenMP threads per process (0 = the OpenMP default)
  bool quiet = false;  ///< no progress or result lines
  bool no_plots = false;  ///< no SVG figures and no report.html (the numbers only)
  int chunk = 0;       ///< explore: samples per MPI rank and round (0 = 2 x threads)
  bool profile = false;   ///< the cost split of the evaluations on stderr and in summary.json
};

/// Registers a campaign command, `hullopt NAME CONFIG --out DIR --threads N [more options] --quiet --no-plots
/// --profile`; run(options)
/// runs under the output folder's lock. more_options adds the command's own options (after --threads).
CLI::App* AddCampaignCommand(CLI::App& app, const CommandText& text,
                             std::function<void(const CampaignCliOptions&)> run,
                             const std::function<void(CLI::App*)>& more_options = nullptr);

/// Runs the campaign (campaign::RunCampaign over the MPI ranks of this process, with --force as given): a
/// progress bar and messages on stderr, the result lines on stdout unless quiet, report.html unless no_plots,
/// the cost split on stderr with profile (also when quiet).
void RunCampaignCommand(io::CampaignCommand command, const CampaignCliOptions& options);

}  // namespace hullopt::app
