// hullopt explore CONFIG --out DIR: evaluate a Sobol or Latin-hypercube sample of the design box in parallel
// (OpenMP threads, MPI ranks), log samples.csv in sample order (identical for any thread/rank count), and
// estimate the sensitivity of the objective to each variable; resumable like optimize. The campaign itself is
// campaign::RunCampaign (campaign/run_campaign.h).
#include <CLI/CLI.hpp>
#include <memory>

#include "app/campaign_command.h"
#include "app/commands.h"

namespace hullopt::app {

void AddExploreCommand(CLI::App& app) {
  auto chunk = std::make_shared<int>(0);
  AddCampaignCommand(
      app,
      {"explore",
       "Evaluate a Sobol or Latin-hypercube sample of the design space in parallel and estimate sensitivities "
       "(resumable; mpirun -n N spreads samples over ranks)",
       "campaign YAML (explore: or optimize: block, with samples and method)", "config",
       "output folder (samples.csv, summary.json, sensitivity.csv)"},
      [chunk](const CampaignCliOptions& o) {
        CampaignCliOptions one = o;
        one.chunk = *chunk;
        RunCampaignCommand(io::CampaignCommand::kExplore, one);
      },
      [chunk](CLI::App* cmd) {
        cmd->add_option("--chunk", *chunk, "samples per MPI rank and round (0 = 2 x threads)");
      });
}

}  // namespace hullopt::app
