// hullopt optimize CONFIG --out DIR: minimise the campaign objective over the free design variables with an
// NLopt algorithm (multistart, constraints), resumable, spread over MPI ranks by multistart run; the campaign
// itself is campaign::RunCampaign (campaign/run_campaign.h).
#include "app/campaign_command.h"
#include "app/commands.h"

namespace hullopt::app {

void AddOptimizeCommand(CLI::App& app) {
  AddCampaignCommand(
      app,
      {"optimize",
       "Minimise the campaign objective over the free design variables (NLopt; resumable: re-run the same "
       "command to continue an interrupted campaign; mpirun -n N spreads multistart runs over ranks)",
       "campaign YAML (optimize: block)", "config", "output folder (history.csv, best.yaml, summary.json)"},
      // One lock on the campaign folder for the whole run (a Pareto sweep's runs live inside it).
      [](const CampaignCliOptions& o) { RunCampaignCommand(io::CampaignCommand::kOptimize, o); });
}

}  // namespace hullopt::app
